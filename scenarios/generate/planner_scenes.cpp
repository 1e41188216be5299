// planner_scenes DIR: writes the planner's soup scenes (scenes.hpp) as COLLADA through assimp,
// <name>_env.dae and <name>_robot.dae each. The scenarios in scenarios/ expect them in
// scenarios/generated (docs/PLANNER.md).
#include "collada_export.hpp"
#include "scenes.hpp"

#include <filesystem>
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
  for (const scenes::Scene& s : scenes::allScenes()) {
    for (const auto& [suffix, soup] : {std::pair{"_env.dae", &s.environment}, {"_robot.dae", &s.robot}}) {
      const std::string error = scenes::writeCollada((dir / (s.name + suffix)).string(), *soup);
      if (!error.empty()) {
        std::cerr << "planner_scenes: cannot write " << error << "\n";
        return 3;
      }
    }
  }
  return 0;
}
