// Mesh obstacles and robots from files, COLLADA through assimp; planar (SE(2)) robots.
#include "experiment.hpp"
#include "problem.hpp"
#include "scenario.hpp"

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <helpers.hpp>

#include <gtest/gtest.h>

#include <fstream>

namespace {

using acd::Vec3;

/// A unit cube [0,1]^3 as a minimal COLLADA 1.4.1 document, outward triangles.
std::string colladaCube() {
  const acd::TriMesh cube = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::string positions, indices;
  for (const Vec3& p : cube.vertices)
    positions += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + " ";
  for (const acd::Face& f : cube.faces)
    indices += std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + " ";
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="cube" name="cube"><mesh>
      <source id="cube-pos"><float_array id="cube-pos-array" count=")" + std::to_string(3 * cube.vertices.size()) + R"(">)" + positions + R"(</float_array>
        <technique_common><accessor source="#cube-pos-array" count=")" + std::to_string(cube.vertices.size()) + R"(" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <vertices id="cube-vtx"><input semantic="POSITION" source="#cube-pos"/></vertices>
      <triangles count=")" + std::to_string(cube.faces.size()) + R"("><input semantic="VERTEX" source="#cube-vtx" offset="0"/><p>)" + indices + R"(</p></triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="scene">
    <node id="n"><instance_geometry url="#cube"/></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";
}

TEST(MeshInput, ColladaObstacleLoadsThroughAssimp) {
  acdtest::TempDir dir("planner_dae");
  std::ofstream(dir / "cube.dae") << colladaCube();
  const acd::ReadResult m = acd::readMesh(dir / "cube.dae");
  ASSERT_TRUE(m.status.ok()) << m.status.message;
  const acd::Box3 b = acd::boundingBox(m.mesh);
  EXPECT_TRUE(b.lo.isApprox(Vec3(0, 0, 0), 1e-6) || b.lo.norm() < 1e-6);
  EXPECT_TRUE(b.hi.isApprox(Vec3(1, 1, 1), 1e-6));
  // As an obstacle in a scenario, scaled and moved: a closed solid of the right volume.
  const std::string text = R"(
workspace: {min: [0, 0, 0], max: [4, 4, 4]}
obstacles:
  - mesh: cube.dae
    scale: 2
    translate: [1, 1, 0]
robot: {type: point}
start: {position: [0.5, 0.5, 0.5]}
goal: {position: [3.5, 3.5, 3.5]}
samplers: [uniform]
)";
  const planner::Scenario s = planner::parseScenario(text, "dae.yaml", dir.path().string());
  ASSERT_EQ(s.obstacles.size(), 1u);
  EXPECT_NEAR(acd::signedVolume(s.obstacles[0].triangles), 8.0, 1e-6);
  const planner::Preprocessing pre = planner::preprocess(s);
  EXPECT_NEAR(acd::signedVolume(pre.freeSpace), 64.0 - 8.0, 1e-6);
}

TEST(MeshInput, BrokenColladaIsNamed) {
  acdtest::TempDir dir("planner_dae_bad");
  std::ofstream(dir / "broken.dae") << "<COLLADA>not really</COLLADA>";
  const acd::ReadResult m = acd::readMesh(dir / "broken.dae");
  EXPECT_FALSE(m.status.ok());
  EXPECT_NE(m.status.message.find("broken.dae"), std::string::npos);
}

TEST(MeshInput, MeshRobotsReferencePointMayLieOutsideIt) {
  // OMPL.app's reference point is the mean of the vertices, outside a ring or a U: accepted,
  // and the point location uses a point inside the robot instead.
  acdtest::TempDir dir("planner_robot");
  acd::writeMesh(dir / "bar.off", acd::shapes::box(Vec3(-0.5, -0.1, -0.1), Vec3(0.5, 0.1, 0.1)));
  const std::string base = R"(
workspace: {min: [0, 0, 0], max: [4, 4, 4]}
robot: {type: mesh, mesh: bar.off}
start: {position: [1, 1, 1]}
goal: {position: [3, 3, 3]}
)";
  const planner::Scenario s = planner::parseScenario(base, "robot.yaml", dir.path().string());
  EXPECT_EQ(s.robot.kind, planner::RobotKind::Mesh);
  EXPECT_NEAR(s.robot.boundingRadius(), std::sqrt(0.25 + 0.01 + 0.01), 1e-9);
  ASSERT_EQ(s.robot.insidePoints.size(), 1u);
  EXPECT_TRUE(s.robot.insidePoints[0].isZero());  // the reference point, where it is inside
  std::string shifted = base;
  shifted.replace(shifted.find("mesh: bar.off}"), 14, "mesh: bar.off, translate: [2, 0, 0]}");
  const planner::Scenario t = planner::parseScenario(shifted, "robot.yaml", dir.path().string());
  ASSERT_EQ(t.robot.insidePoints.size(), 1u);
  const Vec3 p = t.robot.insidePoints[0];
  EXPECT_TRUE(p.x() > 1.5 && p.x() < 2.5 && std::abs(p.y()) < 0.1 && std::abs(p.z()) < 0.1) << p.transpose();
  EXPECT_NEAR(t.robot.boundingRadius(), std::sqrt(2.5 * 2.5 + 0.01 + 0.01), 1e-9);
}

TEST(MeshInput, FreeSpaceGivenDirectly) {
  // A U-shaped free space (two arms on a base): its ACD cuts the arms off the base.
  acdtest::TempDir dir("planner_free");
  acd::writeMesh(dir / "u.off", acd::shapes::uShape());
  const acd::Box3 b = acd::boundingBox(acd::shapes::uShape());
  const std::string text = R"(
free_space: u.off
robot: {type: point}
start: {position: [)" + std::to_string(b.lo.x() + 0.5) + ", " + std::to_string(b.hi.y() - 0.5) + ", " + std::to_string(b.center().z()) + R"(]}
goal: {position: [)" + std::to_string(b.hi.x() - 0.5) + ", " + std::to_string(b.hi.y() - 0.5) + ", " + std::to_string(b.center().z()) + R"(]}
samplers: [acd]
acd: {tau: 0.05}
)";
  const planner::Scenario s = planner::parseScenario(text, "u.yaml", dir.path().string());
  EXPECT_TRUE(s.freeSpaceGiven);
  EXPECT_TRUE(s.workspace.lo.isApprox(b.lo) && s.workspace.hi.isApprox(b.hi));
  const planner::Preprocessing pre = planner::preprocess(s);
  EXPECT_EQ(pre.freeSpaceMethod, "given");
  EXPECT_GE(pre.components.size(), 2u);
  EXPECT_FALSE(pre.openings.empty());
  planner::PlanningProblem problem(s, pre.freeSpace, pre.openings);
  // The point robot must go down one arm, across the base and up the other.
  EXPECT_TRUE(planner::runTrial(problem, "acd", 100, 0).outcome.connected);
}

TEST(Planar, Se2RobotSamplesValidStatesAtItsHeight) {
  // A bar in a plane at z = 0.5 between two slabs leaving a 0.5-wide slot.
  const std::string text = R"(
workspace: {min: [0, 0, 0], max: [6, 3, 1]}
obstacles:
  - box: {min: [2.8, 0.0, 0.0], max: [3.2, 1.25, 1.0]}
  - box: {min: [2.8, 1.75, 0.0], max: [3.2, 3.0, 1.0]}
robot: {type: box, size: [1.0, 0.3, 0.3], planar: true}
start: {position: [1, 1.5, 0.5], yaw_deg: 90}
goal: {position: [5, 1.5, 0.5], yaw_deg: 0}
samplers: [uniform, acd]
)";
  const planner::Scenario s = planner::parseScenario(text, "planar.yaml", ".");
  const planner::Preprocessing pre = planner::preprocess(s);
  planner::PlanningProblem problem(s, pre.freeSpace, pre.openings);
  auto* state = problem.si()->allocState();
  for (const std::string name : {"uniform", "acd"}) {
    problem.seeds()->reset(1);
    problem.useSampler(name);
    auto sampler = problem.si()->allocValidStateSampler();
    int n = 0;
    for (int i = 0; i < 50; ++i) {
      if (!sampler->sample(state)) continue;
      ++n;
      const Vec3 p = problem.position(state);
      EXPECT_DOUBLE_EQ(p.z(), 0.5);
      // Turned only about z.
      EXPECT_NEAR((problem.orientation(state) * Vec3::UnitZ()).z(), 1.0, 1e-12);
      EXPECT_TRUE(problem.world().valid(p, problem.orientation(state)));
    }
    EXPECT_GT(n, 25) << name;
  }
  problem.si()->freeState(state);
  // The slot is 0.5 wide, the bar 1.0 long: crossing means turning lengthwise. acd does it.
  int connected = 0;
  for (int trial = 0; trial < 3; ++trial) connected += planner::runTrial(problem, "acd", 150, trial).outcome.connected;
  EXPECT_GE(connected, 2);
}

TEST(Planar, StartMayOnlyTurnAboutZ) {
  const std::string text = R"(
workspace: {min: [0, 0, 0], max: [6, 3, 1]}
robot: {type: box, size: [1.0, 0.3, 0.3], planar: true}
start: {position: [1, 1.5, 0.5], orientation: [0.7071068, 0.7071068, 0, 0]}
goal: {position: [5, 1.5, 0.5]}
)";
  try {
    planner::parseScenario(text, "planar.yaml", ".");
    FAIL() << "no error";
  } catch (const planner::ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("only turn about z"), std::string::npos) << e.what();
  }
}

}  // namespace
