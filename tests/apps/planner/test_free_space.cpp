// Free space, openings of its ACD, and the collision test on generated environments with
// known answers.
#include "collision_world.hpp"
#include "free_space.hpp"
#include "openings.hpp"

#include <acd/decompose.hpp>
#include <acd/algo/inside.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

namespace {

using acd::Vec3;
using acd::shapes::box;

/// A wall x in [x0, x1] across the workspace [0,10]x[0,6]x[0,6], with a square hole
/// [y0, y1] x [z0, z1], as four slabs.
std::vector<acd::TriMesh> wallWithHole(double x0, double x1, double y0, double y1, double z0, double z1) {
  return {box(Vec3(x0, 0, 0), Vec3(x1, y0, 6)), box(Vec3(x0, y1, 0), Vec3(x1, 6, 6)),
          box(Vec3(x0, y0, 0), Vec3(x1, y1, z0)), box(Vec3(x0, y0, z1), Vec3(x1, y1, 6))};
}

const acd::Box3 kWorkspace{Vec3(0, 0, 0), Vec3(10, 6, 6)};

TEST(FreeSpace, BoxMinusWallHasTheRightVolumeAndIsClosed) {
  const auto wall = wallWithHole(4.75, 5.25, 1.0, 2.0, 3.5, 4.5);
  const planner::FreeSpace fs = planner::buildFreeSpace(kWorkspace, wall, {});
  ASSERT_TRUE(fs.ok) << fs.error;
  EXPECT_TRUE(acd::isClosedOriented(fs.mesh));
  EXPECT_NEAR(acd::signedVolume(fs.mesh), 360.0 - 0.5 * (36.0 - 1.0), 1e-9);
  EXPECT_EQ(acd::splitEdgeConnected(fs.mesh).size(), 1u);  // the hole joins the rooms
}

TEST(FreeSpace, OverlappingObstaclesAndAFloatingIsland) {
  // Two overlapping boxes (union volume 1.5) and a box floating in the middle (a cavity).
  const std::vector<acd::TriMesh> obstacles{box(Vec3(0, 0, 0), Vec3(1, 1, 1)), box(Vec3(0.5, 0, 0), Vec3(1.5, 1, 1)),
                                            box(Vec3(4, 2, 2), Vec3(5, 3, 3))};
  const planner::FreeSpace fs = planner::buildFreeSpace(kWorkspace, obstacles, {});
  ASSERT_TRUE(fs.ok) << fs.error;
  EXPECT_NEAR(acd::signedVolume(fs.mesh), 360.0 - 1.5 - 1.0, 1e-9);
  EXPECT_EQ(acd::splitEdgeConnected(fs.mesh).size(), 2u);
}

TEST(FreeSpace, ObstaclesMeetingAlongAnEdgeAreHandledOrRefusedClearly) {
  // Two boxes sharing only an edge: the free space is not a manifold there.
  const std::vector<acd::TriMesh> obstacles{box(Vec3(2, 2, 0), Vec3(3, 3, 6)), box(Vec3(3, 3, 0), Vec3(4, 4, 6))};
  const planner::FreeSpace fs = planner::buildFreeSpace(kWorkspace, obstacles, {"a", "b"});
  if (fs.ok) {
    EXPECT_TRUE(acd::isClosedOriented(fs.mesh));
    EXPECT_NEAR(acd::signedVolume(fs.mesh), 360.0 - 12.0, 1e-9);
  } else {
    EXPECT_NE(fs.error.find("manifold"), std::string::npos) << fs.error;
  }
}

TEST(FreeSpace, OpenObstacleIsRefusedByName) {
  acd::TriMesh open = box(Vec3(1, 1, 1), Vec3(2, 2, 2));
  open.faces.pop_back();
  const planner::FreeSpace fs = planner::buildFreeSpace(kWorkspace, {open}, {"lid"});
  EXPECT_FALSE(fs.ok);
  EXPECT_NE(fs.error.find("lid"), std::string::npos) << fs.error;
}

TEST(Openings, WallWithHoleGivesOpeningsInTheHole) {
  // An off-centre hole, so that a centre found by symmetry would be wrong.
  const double y0 = 1.0, y1 = 2.0, z0 = 3.5, z1 = 4.5;
  const planner::FreeSpace fs = planner::buildFreeSpace(kWorkspace, wallWithHole(4.75, 5.25, y0, y1, z0, z1), {});
  ASSERT_TRUE(fs.ok) << fs.error;
  acd::DecomposeOptions options;  // as the planner decomposes the free space (experiment.cpp)
  options.tau = 0.05;
  options.mergeScope = acd::MergeScope::Component;
  options.invariant = false;
  const acd::Decomposition d = acd::decompose(fs.mesh, options);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  std::vector<acd::TriMesh> parts;
  for (const auto& c : d.components) parts.push_back(c.mesh);
  ASSERT_GE(parts.size(), 2u);
  const auto openings = planner::extractOpenings(fs.mesh, parts);
  ASSERT_FALSE(openings.empty());
  // The largest openings are the hole (the rooms are convex, so any other cut is in the hole too).
  int inHole = 0;
  for (const planner::Opening& o : openings) {
    SCOPED_TRACE(o.centroid.transpose());
    EXPECT_GT(o.area, 0);
    EXPECT_NEAR(o.normal.norm(), 1.0, 1e-9);
    const bool centreInHole = o.centroid.x() >= 4.75 - 1e-9 && o.centroid.x() <= 5.25 + 1e-9 && o.centroid.y() > y0 &&
                              o.centroid.y() < y1 && o.centroid.z() > z0 && o.centroid.z() < z1;
    EXPECT_TRUE(centreInHole);
    inHole += centreInHole;
    // A cut across the passage: normal along x, area of the hole, corners within the hole.
    EXPECT_NEAR(std::abs(o.normal.x()), 1.0, 1e-9);
    EXPECT_NEAR(o.area, (y1 - y0) * (z1 - z0), 1e-9);
    EXPECT_GE(o.extentLo.y(), y0 - 1e-9);
    EXPECT_LE(o.extentHi.y(), y1 + 1e-9);
    EXPECT_GE(o.extentLo.z(), z0 - 1e-9);
    EXPECT_LE(o.extentHi.z(), z1 + 1e-9);
    // The normal points from a into b.
    const acd::InsideTest inB(parts[o.b]);
    EXPECT_TRUE(inB.inside(o.centroid + 1e-3 * o.normal));
  }
  EXPECT_GE(inHole, 1);
}

TEST(Openings, ConvexFreeSpaceHasNone) {
  const acd::TriMesh whole = box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_TRUE(planner::extractOpenings(whole, {whole}).empty());
  // Two halves of a box: one opening, the square between them.
  const auto openings = planner::extractOpenings(whole, {box(Vec3(0, 0, 0), Vec3(0.5, 1, 1)), box(Vec3(0.5, 0, 0), Vec3(1, 1, 1))});
  ASSERT_EQ(openings.size(), 1u);
  EXPECT_TRUE(openings[0].centroid.isApprox(Vec3(0.5, 0.5, 0.5), 1e-12));
  EXPECT_TRUE(openings[0].normal.isApprox(Vec3(1, 0, 0), 1e-12));
  EXPECT_NEAR(openings[0].area, 1.0, 1e-12);
}

TEST(CollisionWorld, RobotWhollyInsideAnObstacleIsInvalid) {
  const planner::FreeSpace fs = planner::buildFreeSpace(kWorkspace, {box(Vec3(2, 2, 2), Vec3(5, 5, 5))}, {});
  ASSERT_TRUE(fs.ok) << fs.error;
  planner::Robot robot;
  robot.kind = planner::RobotKind::Box;
  robot.size = Vec3(0.5, 0.4, 0.3);
  robot.mesh = box(-0.5 * robot.size, 0.5 * robot.size);
  const planner::CollisionWorld world(fs.mesh, robot);
  const Eigen::Quaterniond id = Eigen::Quaterniond::Identity();
  EXPECT_FALSE(world.valid(Vec3(3.5, 3.5, 3.5), id));  // deep inside: no surface contact at all
  EXPECT_FALSE(world.valid(Vec3(2.1, 3.5, 3.5), id));  // straddling the obstacle's face
  EXPECT_TRUE(world.valid(Vec3(1.5, 3.5, 3.5), id));
  EXPECT_FALSE(world.valid(Vec3(0.1, 3.5, 3.5), id));  // through the workspace boundary
}

TEST(CollisionWorld, ObstacleWhollyInsideTheRobotIsInvalid) {
  // A small floating obstacle that the robot can swallow without touching its surface.
  const planner::FreeSpace fs = planner::buildFreeSpace(kWorkspace, {box(Vec3(3, 3, 3), Vec3(3.1, 3.1, 3.1))}, {});
  ASSERT_TRUE(fs.ok) << fs.error;
  for (planner::RobotKind kind : {planner::RobotKind::Sphere, planner::RobotKind::Box, planner::RobotKind::Mesh}) {
    planner::Robot robot;
    robot.kind = kind;
    robot.radius = 1.0;
    robot.size = Vec3(1, 1, 1);
    robot.mesh = kind == planner::RobotKind::Mesh ? acd::shapes::icosphere(Vec3::Zero(), 1.0, 2) : box(-0.5 * robot.size, 0.5 * robot.size);
    const planner::CollisionWorld world(fs.mesh, robot);
    EXPECT_FALSE(world.valid(Vec3(3.05, 3.05, 3.05), Eigen::Quaterniond::Identity())) << static_cast<int>(kind);
    EXPECT_TRUE(world.valid(Vec3(6, 3.05, 3.05), Eigen::Quaterniond::Identity())) << static_cast<int>(kind);
  }
}

TEST(CollisionWorld, OrientationMatters) {
  // A 0.6-wide slot between two blocks: a 1.0 x 0.2 x 0.2 bar fits lengthwise, not across.
  const planner::FreeSpace fs = planner::buildFreeSpace(
      kWorkspace, {box(Vec3(4, 0, 0), Vec3(6, 2.7, 6)), box(Vec3(4, 3.3, 0), Vec3(6, 6, 6))}, {});
  ASSERT_TRUE(fs.ok) << fs.error;
  planner::Robot robot;
  robot.kind = planner::RobotKind::Box;
  robot.size = Vec3(1.0, 0.2, 0.2);
  robot.mesh = box(-0.5 * robot.size, 0.5 * robot.size);
  const planner::CollisionWorld world(fs.mesh, robot);
  EXPECT_TRUE(world.valid(Vec3(5, 3, 3), Eigen::Quaterniond::Identity()));
  EXPECT_FALSE(world.valid(Vec3(5, 3, 3), Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()))));
}

}  // namespace
