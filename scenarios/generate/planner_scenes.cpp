// planner_scenes DIR: writes the planner's soup scenes (scenes.hpp) as COLLADA through assimp,
// <name>_env.dae and <name>_robot.dae each, and OMPL.app problems (ompl_app_problems.hpp) as
// DIR/ompl_app/<name>.cfg beside their meshes. The scenarios in scenarios/ expect them in
// scenarios/generated (docs/PLANNER.md).
#include "collada_export.hpp"
#include "ompl_app_problems.hpp"
#include "scenes.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 2 || std::string(argv[1]).rfind("-", 0) == 0) {
    std::cerr << "usage: planner_scenes OUTPUT_DIR  (writes <scene>_env.dae and <scene>_robot.dae)\n";
    return 1;
  }
  const std::filesystem::path dir(argv[1]);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    std::cerr << "planner_scenes: cannot create " << dir.string() << (ec ? ": " + ec.message() : "") << "\n";
    return 3;
  }
  auto write = [&](const std::filesystem::path& folder, const scenes::Scene& s) {
    for (const auto& [suffix, soup] : {std::pair{"_env.dae", &s.environment}, {"_robot.dae", &s.robot}}) {
      const std::string error = scenes::writeCollada((folder / (s.name + suffix)).string(), *soup);
      if (!error.empty()) {
        std::cerr << "planner_scenes: cannot write " << error << "\n";
        return false;
      }
    }
    return true;
  };
  for (const scenes::Scene& s : scenes::allScenes())
    if (!write(dir, s)) return 3;
  // OMPL.app problem files with their meshes, in DIR/ompl_app.
  const std::filesystem::path app = dir / "ompl_app";
  std::filesystem::create_directories(app, ec);
  for (const scenes::OmplAppProblem& p : scenes::omplAppProblems()) {
    if (!write(app, p.scene)) return 3;
    std::ofstream((app / (p.scene.name + ".cfg")).string()) << "# " << p.what << "\n" << p.cfg;
  }
  return 0;
}
