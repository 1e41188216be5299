// The planner command: a small run writes its table and files; bad scenarios exit 2 with
// one line naming the problem.
#include <helpers.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>

namespace {

const char* kScenario = R"(
name: cli
workspace: {min: [0, 0, 0], max: [4, 2, 2]}
obstacles:
  - box: {min: [1.9, 0.0, 0.0], max: [2.1, 0.95, 2.0]}
  - box: {min: [1.9, 1.05, 0.0], max: [2.1, 2.0, 2.0]}
  - box: {min: [1.9, 0.95, 0.0], max: [2.1, 1.05, 0.95]}
  - box: {min: [1.9, 0.95, 1.05], max: [2.1, 1.05, 2.0]}
robot: {type: point}
start: {position: [0.3, 0.3, 0.3]}
goal: {position: [3.7, 1.7, 1.7]}
samplers: [uniform, acd]
samples: 100
trials: 3
sweep: [50, 100]
sweep_trials: 2
seed: 11
)";

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(PlannerCli, SmallRunWritesTableJsonLogAndPath) {
  acdtest::TempDir dir("planner_cli");
  write(dir / "s.yaml", kScenario);
  const auto run = acdtest::runTool(PLANNER_BIN, acdtest::quote(dir / "s.yaml") + " --sweep -o " + acdtest::quote(dir / "out"), dir);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("acd"), std::string::npos);
  EXPECT_NE(run.out.find("uniform"), std::string::npos);
  EXPECT_NE(run.out.find("95% CI"), std::string::npos);
  EXPECT_NE(run.out.find("ACD preprocessing"), std::string::npos);
  EXPECT_TRUE(run.err.empty()) << run.err;  // no progress when stderr is not a terminal
  const auto j = nlohmann::json::parse(acdtest::slurp(dir / "out/results.json"));
  ASSERT_EQ(j["samplers"].size(), 2u);
  for (const auto& s : j["samplers"]) {
    EXPECT_EQ(s["trials"], 3);
    EXPECT_LE(s["ci95"][0].get<double>(), s["success_rate"].get<double>());
    EXPECT_GE(s["ci95"][1].get<double>(), s["success_rate"].get<double>());
  }
  EXPECT_EQ(j["sweep"].size(), 4u);
  const std::string log = acdtest::slurp(dir / "out/benchmark.log");
  EXPECT_NE(log.find("2 planners"), std::string::npos);
  EXPECT_NE(log.find("geometric_PRM_acd"), std::string::npos);
  EXPECT_NE(log.find("3 runs"), std::string::npos);
  EXPECT_NE(log.find("solved BOOLEAN"), std::string::npos);
  EXPECT_EQ(log.back(), '\n');
  EXPECT_NE(acdtest::slurp(dir / "out/sweep.csv").find("acd,100,2,"), std::string::npos);
  // The best path: start first, goal last (x y z per line for a point robot).
  std::ifstream path(dir / "out/best_path.txt");
  std::vector<std::array<double, 3>> states;
  std::array<double, 3> p{};
  while (path >> p[0] >> p[1] >> p[2]) states.push_back(p);
  ASSERT_GE(states.size(), 2u);
  EXPECT_NEAR(states.front()[0], 0.3, 1e-9);
  EXPECT_NEAR(states.back()[0], 3.7, 1e-9);
}

TEST(PlannerCli, MilestonesTo90PercentAndOmplPlanners) {
  acdtest::TempDir dir("planner_cli_search");
  // The goal moved so that the straight line from the start no longer runs through the hole.
  std::string text = kScenario;
  text.replace(text.find("[3.7, 1.7, 1.7]"), 15, "[3.7, 0.3, 1.7]");
  write(dir / "s.yaml", text);
  const auto run = acdtest::runTool(PLANNER_BIN, acdtest::quote(dir / "s.yaml") +
                                        " --no-fixed --n90 --n90-start 25 --n90-max 400 --n90-trials 3"
                                        " --race --time-limit 0.5 --runs 2 -o " + acdtest::quote(dir / "out"), dir);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("milestones to 90 % success"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("RRTConnect"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("95% CI"), std::string::npos) << "no fixed-N table with --no-fixed";
  // n90.csv: one row per sampler; the acd sampler gets through the pinhole within 400.
  const std::string n90 = acdtest::slurp(dir / "out/n90.csv");
  EXPECT_EQ(std::count(n90.begin(), n90.end(), '\n'), 3) << n90;
  EXPECT_EQ(n90.find("acd,,"), std::string::npos) << n90;
  const std::string points = acdtest::slurp(dir / "out/n90_points.csv");
  EXPECT_NE(points.find("\nuniform,25,3,"), std::string::npos) << points;
  EXPECT_NE(points.find("\nacd,25,3,"), std::string::npos) << points;
  const std::string race = acdtest::slurp(dir / "out/race.csv");
  for (const char* planner : {"PRM,2,", "RRTConnect,2,", "KPIECE1,2,", "PRM_acd,2,"})
    EXPECT_NE(race.find(planner), std::string::npos) << race;
  EXPECT_NE(acdtest::slurp(dir / "out/ompl_benchmark.log").find("geometric_RRTConnect"), std::string::npos);
  EXPECT_FALSE(acdtest::slurp(dir / "out/free_space_acd.obj").empty());
  const auto lonely = acdtest::runTool(PLANNER_BIN, acdtest::quote(dir / "s.yaml") + " --no-fixed", dir);
  EXPECT_EQ(lonely.code, 2);
  EXPECT_NE(lonely.err.find("--no-fixed needs"), std::string::npos) << lonely.err;
}

TEST(PlannerCli, BadScenariosExitTwoNamingTheProblem) {
  acdtest::TempDir dir("planner_cli_bad");
  struct Case {
    std::string from, to, expected;
  };
  const std::vector<Case> cases{
      {"seed: 11", "sead: 11", "unknown key 'sead'"},
      {"robot: {type: point}", "robot: {type: mesh, mesh: missing_robot.stl}", "missing_robot.stl"},
      {"start: {position: [0.3, 0.3, 0.3]}", "start: {position: [2.0, 0.3, 0.3]}", "start pose is not valid: the robot lies outside the free space"},
      {"goal: {position: [3.7, 1.7, 1.7]}", "goal: {position: [2.0, 1.7, 1.7]}", "goal pose is not valid: the robot lies outside the free space"},
  };
  for (const Case& c : cases) {
    std::string text = kScenario;
    text.replace(text.find(c.from), c.from.size(), c.to);
    write(dir / "bad.yaml", text);
    const auto run = acdtest::runTool(PLANNER_BIN, acdtest::quote(dir / "bad.yaml") + " -o " + acdtest::quote(dir / "out"), dir);
    EXPECT_EQ(run.code, 2) << c.expected;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
  const auto missing = acdtest::runTool(PLANNER_BIN, acdtest::quote(dir / "nope.yaml"), dir);
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("nope.yaml"), std::string::npos);
  write(dir / "good.yaml", kScenario);
  const auto badOption = acdtest::runTool(PLANNER_BIN, acdtest::quote(dir / "good.yaml") + " --no-such-option", dir);
  EXPECT_EQ(badOption.code, 1);
  // The output folder cannot be a file: refused before any trial runs.
  write(dir / "afile", "x");
  const auto badOut = acdtest::runTool(PLANNER_BIN, acdtest::quote(dir / "good.yaml") + " -o " + acdtest::quote(dir / "afile"), dir);
  EXPECT_EQ(badOut.code, 5);  // the programs' shared code for "cannot write output" (apps/cli)
  EXPECT_NE(badOut.err.find("output folder"), std::string::npos) << badOut.err;
}

/// A unit cube as COLLADA with the given triangle indices (12 triangles' worth).
std::string colladaCube(const std::string& indices) {
  return "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
         "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
         "<library_geometries><geometry id=\"g\"><mesh>\n"
         "<source id=\"p\"><float_array id=\"pa\" count=\"24\">0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1</float_array>\n"
         "<technique_common><accessor source=\"#pa\" count=\"8\" stride=\"3\">\n"
         "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/>\n"
         "</accessor></technique_common></source>\n"
         "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/></vertices>\n"
         "<triangles count=\"12\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/><p>" +
         indices +
         "</p></triangles>\n"
         "</mesh></geometry></library_geometries>\n"
         "<library_visual_scenes><visual_scene id=\"s\"><node id=\"n\"><instance_geometry url=\"#g\"/></node>"
         "</visual_scene></library_visual_scenes><scene><instance_visual_scene url=\"#s\"/></scene>\n"
         "</COLLADA>\n";
}

#if defined(__SANITIZE_ADDRESS__)
#define PLANNER_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PLANNER_UNDER_ASAN 1
#endif
#endif

// A letter glued to a number in <p> ("1x0") makes Debian's assimp allocate about 19 GB over two
// minutes (docs/FUZZING.md). The planner reads scene files in the acd command's capped child
// process, so such an obstacle is a one-line refusal within seconds, not an abort.
TEST(PlannerCli, AMalformedSceneIsRefusedNotFatal) {
#ifdef PLANNER_UNDER_ASAN
  GTEST_SKIP() << "the child's memory cap cannot be tested under AddressSanitizer (it reserves address space)";
#endif
  acdtest::TempDir dir("planner_cli_scene");
  std::ofstream(dir / "bomb.dae", std::ios::binary)
      << colladaCube("0 1x0 3 1 4 5 7 4 7 6 0 1 5 0 5 4 2 6 7 2 7 3 0 4 6 0 6 2 1 3 7 1 7 5");
  std::string text = kScenario;
  const std::string from = "obstacles:\n";
  text.replace(text.find(from), from.size(), from + "  - mesh: bomb.dae\n    translate: [0.5, 0.5, 0.5]\n    scale: 0.2\n");
  write(dir / "s.yaml", text);
  const auto run = acdtest::runTool(PLANNER_BIN, acdtest::quote(dir / "s.yaml") + " -o " + acdtest::quote(dir / "out"), dir);
  EXPECT_EQ(run.code, 2) << run.err;
  EXPECT_NE(run.err.find("bomb.dae: cannot read: the scene reader (assimp) needed more than"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  // A well-formed scene goes through the same child and plans.
  std::ofstream(dir / "cube.dae", std::ios::binary)
      << colladaCube("0 2 3 0 3 1 4 5 7 4 7 6 0 1 5 0 5 4 2 6 7 2 7 3 0 4 6 0 6 2 1 3 7 1 7 5");
  std::string good = text;
  good.replace(good.find("bomb.dae"), 8, "cube.dae");
  write(dir / "good.yaml", good);
  const auto ok = acdtest::runTool(PLANNER_BIN, acdtest::quote(dir / "good.yaml") + " -t 1 -o " + acdtest::quote(dir / "out"), dir);
  EXPECT_EQ(ok.code, 0) << ok.err;
}

}  // namespace

TEST(PlannerCli, OmplAppProblemFileRacesTheListedPlanners) {
  // planner_list.cfg (generated, a CTest fixture) lists rrtconnect with range 0.5 and aps.
  acdtest::TempDir dir("planner_cli_cfg");
  const std::string cfg = std::string(PLANNER_SCENARIO_DIR) + "/generated/ompl_app/planner_list.cfg";
  const auto run = acdtest::runTool(PLANNER_BIN, acdtest::quote(cfg) + " --race --no-fixed --time-limit 2 --runs 2"
                                        " --planners PRM_acd,RRTConnect_cfg2 -q -o " + acdtest::quote(dir / "out"), dir);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("'aps' is not raced"), std::string::npos) << run.err;
  const std::string race = acdtest::slurp(dir / "out/race.csv");
  EXPECT_NE(race.find("\nRRTConnect_cfg2,2,"), std::string::npos) << race;
  EXPECT_NE(race.find("\nPRM_acd,2,"), std::string::npos) << race;
  EXPECT_EQ(race.find("KPIECE1"), std::string::npos) << race;
  const std::string runs = acdtest::slurp(dir / "out/race_runs.csv");
  EXPECT_EQ(std::count(runs.begin(), runs.end(), '\n'), 5) << runs;
  EXPECT_NE(acdtest::slurp(dir / "out/ompl_benchmark.log").find("geometric_RRTConnect_cfg2"), std::string::npos);
  const auto unknown = acdtest::runTool(PLANNER_BIN, acdtest::quote(cfg) + " --race --no-fixed --planners Nope -q -o " +
                                                         acdtest::quote(dir / "out2"), dir);
  EXPECT_EQ(unknown.code, 3) << unknown.err;
  EXPECT_NE(unknown.err.find("unknown planner 'Nope'"), std::string::npos) << unknown.err;
}
