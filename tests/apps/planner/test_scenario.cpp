// Scenario files: the shipped ones parse; every kind of mistake gives one error naming it.
#include "experiment.hpp"
#include "problem.hpp"
#include "scenario.hpp"

#include <acd/algo/inside.hpp>

#include <helpers.hpp>

#include <gtest/gtest.h>

#include <fstream>

namespace {

using planner::ScenarioError;

const char* kValid = R"(
name: tiny
workspace: {min: [0, 0, 0], max: [4, 2, 2]}
obstacles:
  - box: {min: [1.9, 0, 0], max: [2.1, 2, 2]}
robot: {type: sphere, radius: 0.1}
start: {position: [0.5, 1, 1]}
goal: {position: [3.5, 1, 1]}
samplers: [uniform, acd]
samples: 50
trials: 3
prm: {neighbors: 8, resolution: 0.01}
acd: {tau: 0.1, spread: 0.2, uniform_fraction: 0.2}
seed: 7
)";

/// The error message of parsing `text`, or "" when it parses.
std::string errorOf(const std::string& text) {
  try {
    planner::parseScenario(text, "test.yaml", ".");
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(Scenario, ValidFileGivesItsValues) {
  const planner::Scenario s = planner::parseScenario(kValid, "test.yaml", ".");
  EXPECT_EQ(s.name, "tiny");
  EXPECT_EQ(s.obstacles.size(), 1u);
  EXPECT_EQ(s.robot.kind, planner::RobotKind::Sphere);
  EXPECT_DOUBLE_EQ(s.robot.radius, 0.1);
  EXPECT_EQ(s.samplers, (std::vector<std::string>{"uniform", "acd"}));
  EXPECT_EQ(s.samples, 50);
  EXPECT_EQ(s.trials, 3);
  EXPECT_EQ(s.prm.neighbors, 8);
  EXPECT_DOUBLE_EQ(s.acd.tau, 0.1);
  EXPECT_DOUBLE_EQ(s.acd.uniformFraction, 0.2);
  EXPECT_EQ(s.seed, 7u);
  EXPECT_TRUE(s.goal.position.isApprox(acd::Vec3(3.5, 1, 1)));
}

TEST(Scenario, ShippedScenariosParse) {
  for (const char* name : {"narrow.yaml", "narrow_wide.yaml", "maze.yaml", "bugtrap.yaml"}) {
    SCOPED_TRACE(name);
    const planner::Scenario s = planner::loadScenario(std::string(PLANNER_SCENARIO_DIR) + "/" + name);
    EXPECT_FALSE(s.obstacles.empty());
    EXPECT_FALSE(s.expected.empty()) << "each shipped scenario documents its expected outcome";
  }
}

TEST(Scenario, UnknownKeyIsNamed) {
  EXPECT_NE(errorOf(replaced(kValid, "seed: 7", "seeds: 7")).find("unknown key 'seeds'"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "radius: 0.1}", "radius: 0.1, colour: red}")).find("unknown key 'robot.colour'"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "neighbors: 8", "neighbours: 8")).find("'prm.neighbours'"), std::string::npos);
}

TEST(Scenario, MissingMeshFileIsNamed) {
  const std::string text = replaced(kValid, "- box: {min: [1.9, 0, 0], max: [2.1, 2, 2]}", "- mesh: no_such_wall.off");
  const std::string error = errorOf(text);
  EXPECT_NE(error.find("no_such_wall.off"), std::string::npos) << error;
  EXPECT_NE(error.find("not found"), std::string::npos) << error;
  EXPECT_NE(error.find("obstacles[0].mesh"), std::string::npos) << error;
}

TEST(Scenario, MissingScenarioFileIsNamed) {
  try {
    planner::loadScenario("/nonexistent/dir/scenario.yaml");
    FAIL() << "no error";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scenario.yaml"), std::string::npos);
  }
}

TEST(Scenario, BadValuesAreNamed) {
  EXPECT_NE(errorOf(replaced(kValid, "samplers: [uniform, acd]", "samplers: [uniform, magic]")).find("unknown sampler 'magic'"),
            std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "radius: 0.1", "radius: -1")).find("'robot.radius' must be positive"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "samples: 50", "samples: many")).find("'samples'"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "max: [4, 2, 2]", "max: [4, 2]")).find("'workspace.max'"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "type: sphere", "type: blob")).find("'robot.type'"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "goal: {position: [3.5, 1, 1]}", "")).find("missing key 'goal'"), std::string::npos);
  EXPECT_NE(errorOf(replaced(kValid, "[0.5, 1, 1]", "[-3, 1, 1]")).find("'start' position is outside"), std::string::npos);
  EXPECT_NE(errorOf("workspace: [1, 2").find("not valid YAML"), std::string::npos);
  EXPECT_EQ(errorOf(kValid), "");
}

/// The start or the goal in collision: found when the problem is set up, named.
std::string problemErrorOf(const std::string& text) {
  try {
    const planner::Scenario s = planner::parseScenario(text, "test.yaml", ".");
    const planner::Preprocessing pre = planner::preprocess(s);
    planner::PlanningProblem problem(s, pre.freeSpace, pre.openings, pre.solids);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "";
}

TEST(Scenario, StartOrGoalInCollisionIsNamed) {
  EXPECT_EQ(problemErrorOf(kValid), "");
  // Reference point in the wall: the sphere touches the wall's triangles (FCL says so first).
  const std::string inWall = problemErrorOf(replaced(kValid, "[0.5, 1, 1]", "[2.0, 1, 1]"));
  EXPECT_NE(inWall.find("start pose is not valid: the robot touches obstacles[0]"), std::string::npos) << inWall;
  // Reference point free, but the sphere reaches into the wall.
  const std::string reaches = problemErrorOf(replaced(kValid, "[3.5, 1, 1]", "[2.15, 1, 1]"));
  EXPECT_NE(reaches.find("goal pose is not valid: the robot touches obstacles[0]"), std::string::npos) << reaches;
}

TEST(Scenario, FloatingObstacleIsAHoleOfTheAcd) {
  // A box floating in the middle of the workspace: a cavity of the free space. The free space
  // is cut through it before the ACD, so that no component covers the box.
  const std::string floating = replaced(kValid, "max: [2.1, 2, 2]}", "max: [2.1, 2, 2]}\n  - box: {min: [3, 0.8, 0.8], max: [3.2, 1.2, 1.2]}");
  const planner::Scenario s = planner::parseScenario(floating, "test.yaml", ".");
  const planner::Preprocessing pre = planner::preprocess(s);
  EXPECT_EQ(pre.cavities, 1);
  EXPECT_GE(pre.freeSpacePieces, 2);
  double volume = 0;
  for (const acd::TriMesh& c : pre.components) {
    volume += acd::signedVolume(c);
    EXPECT_FALSE(acd::InsideTest(c).inside(acd::Vec3(3.1, 1.0, 1.0)));
  }
  EXPECT_NEAR(volume, acd::signedVolume(pre.freeSpace), 1e-6 * volume);
  EXPECT_NEAR(acd::signedVolume(pre.freeSpace), 16 - 0.8 - 0.2 * 0.4 * 0.4, 1e-9);
  EXPECT_EQ(problemErrorOf(floating), "");
}

}  // namespace
