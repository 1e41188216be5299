// Parts, gaps and threading poses (body_parts.hpp, threading_poses.hpp): gaps measured against
// bodies built in the test (boxes end to end, a square ring), poses checked with FCL's own box
// shapes (not the planner's collision world), and on the generated interlocked links a seeded run
// that connects with the threading poses and not without them.
#include "body_parts.hpp"
#include "experiment.hpp"
#include "ompl_app_problem.hpp"
#include "problem.hpp"
#include "threading_poses.hpp"

#include <acd/algo/shapes.hpp>

#include <fcl/narrowphase/collision.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using acd::Vec3;

/// A bar from `lo` to `hi` split at x = -gap/2 .. gap/2: two boxes end to end.
acd::TriMesh barWithGap(double gap) {
  return acd::concatenate({acd::shapes::box({-1.0, -0.1, -0.1}, {-gap / 2, 0.1, 0.1}),
                           acd::shapes::box({gap / 2, -0.1, -0.1}, {1.0, 0.1, 0.1})});
}

/// A square ring in the xy-plane: outer side 1.4, bars 0.2 thick, as four overlapping boxes
/// (the way the generated problems draw it): the hole is 1.0 across, its axis z.
acd::TriMesh squareRing() {
  return acd::concatenate({acd::shapes::box({-0.7, -0.7, -0.1}, {-0.5, 0.7, 0.1}),
                           acd::shapes::box({0.5, -0.7, -0.1}, {0.7, 0.7, 0.1}),
                           acd::shapes::box({-0.7, -0.7, -0.1}, {0.7, -0.5, 0.1}),
                           acd::shapes::box({-0.7, 0.5, -0.1}, {0.7, 0.7, 0.1})});
}

bool parallel(const Vec3& a, const Vec3& b, double tol) { return std::abs(std::abs(a.normalized().dot(b.normalized())) - 1) < tol; }

TEST(BodyParts, BarsEndToEndHaveOneGapOpenOnEverySide) {
  const acd::TriMesh bar = barWithGap(0.3);
  const planner::BodyParts body = planner::bodyParts(bar, {}, 0.05, 5.0);
  ASSERT_EQ(body.parts.size(), 2u);
  ASSERT_EQ(body.gaps.size(), 1u);
  const planner::PartGap& g = body.gaps[0];
  EXPECT_NEAR(g.width, 0.3, 1e-9);
  EXPECT_TRUE(parallel(g.direction, Vec3::UnitX(), 1e-9)) << g.direction.transpose();
  EXPECT_LT(g.middle.norm(), 1e-9) << g.middle.transpose();
  EXPECT_TRUE(g.through.isZero());  // end to end: open on every side
  for (const planner::BodyPart& p : body.parts) {
    EXPECT_TRUE(parallel(p.axes.col(0), Vec3::UnitX(), 1e-9));
    EXPECT_NEAR(p.halfExtent[0], 0.425, 1e-9);
    EXPECT_NEAR(p.halfExtent[1], 0.1, 1e-9);
    EXPECT_NEAR(p.halfExtent[2], 0.1, 1e-9);
  }
  // Wider than the widest gap asked for: none.
  EXPECT_TRUE(planner::bodyParts(bar, {}, 0.05, 0.29).gaps.empty());
}

TEST(BodyParts, ARingsGapsAreItsHoleAndTheWayThroughIsItsAxis) {
  const planner::BodyParts ring = planner::bodyParts(squareRing(), {}, 0.05, 3.0);
  ASSERT_GE(ring.parts.size(), 4u);
  // No gap between pieces of one solid: every gap is the hole, 1.0 across between opposite bars.
  ASSERT_GE(ring.gaps.size(), 2u);
  int acrossTheHole = 0;
  for (const planner::PartGap& g : ring.gaps) {
    EXPECT_GE(g.width, 1.0 - 1e-6);
    if (std::abs(g.width - 1.0) > 1e-6) continue;
    ++acrossTheHole;
    EXPECT_LT(g.middle.norm(), 1e-9) << g.middle.transpose();  // the hole's centre, not a corner
    EXPECT_TRUE(parallel(g.through, Vec3::UnitZ(), 1e-9)) << g.through.transpose();
  }
  EXPECT_EQ(acrossTheHole, 2);
}

/// FCL's boxes: is the robot bar (half extents 0.7, 0.1, 0.1, centred at its origin) at `pose`
/// clear of the two boxes of barWithGap(0.3)?
bool clearOfTheGappedBar(const planner::Pose& pose) {
  const auto robot = std::make_shared<fcl::Boxd>(1.4, 0.2, 0.2);
  const auto half = std::make_shared<fcl::Boxd>(0.85, 0.2, 0.2);
  fcl::Transform3d r = fcl::Transform3d::Identity();
  r.linear() = pose.orientation.toRotationMatrix();
  r.translation() = pose.position;
  for (double x : {-0.575, 0.575}) {
    fcl::Transform3d o = fcl::Transform3d::Identity();
    o.translation() = Vec3(x, 0, 0);
    fcl::CollisionRequestd request;
    fcl::CollisionResultd result;
    if (fcl::collide(robot.get(), r, half.get(), o, request, result) > 0) return false;
  }
  return true;
}

TEST(ThreadingPoses, ABarThroughAGapLiesAcrossItAndClearOfIt) {
  // The robot is a bar 1.4 long, 0.2 thick; the obstacle a bar with a 0.3 gap. The robot fits
  // the gap across either thin axis; its long axis is along no part of the gap (end to end).
  planner::BodyParts robot = planner::bodyParts(acd::shapes::box({-0.7, -0.1, -0.1}, {0.7, 0.1, 0.1}), {}, 0.05, 3.0);
  planner::BodyParts obstacles = planner::bodyParts(barWithGap(0.3), {}, 0.05, 3.0);
  ASSERT_EQ(robot.parts.size(), 1u);
  const planner::ThreadingPoses threading(robot, obstacles);
  ASSERT_EQ(threading.threadings().size(), 2u);  // the robot's two thin axes across the one gap
  ompl::RNG rng(7);
  int clear = 0, inTheGap = 0;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const planner::Pose pose = threading.sample(rng, 0.0);
    const Eigen::Matrix3d R = pose.orientation.toRotationMatrix();
    // Untilted: the robot's long axis lies in the gap's plane (x = 0), a thin axis along x.
    EXPECT_LT(std::abs((R * Vec3::UnitX()).x()), 1e-9);
    EXPECT_TRUE(parallel(R * Vec3::UnitY(), Vec3::UnitX(), 1e-9) || parallel(R * Vec3::UnitZ(), Vec3::UnitX(), 1e-9));
    clear += clearOfTheGappedBar(pose);
    // Its axis meets the plane x = 0 inside the gap's 0.2 x 0.2 window.
    const Vec3 c = pose.position, d = R * Vec3::UnitX();
    for (double s = -0.7; s <= 0.7; s += 0.01) {
      const Vec3 p = c + s * d;
      if (std::abs(p.x()) < 0.15 && std::abs(p.y()) < 0.1 && std::abs(p.z()) < 0.1) {
        ++inTheGap;
        break;
      }
    }
  }
  // The poses put the robot in the gap, mostly clear of the bar; uniformly random poses near the
  // bar would almost never do either.
  EXPECT_GT(inTheGap, n / 4);
  EXPECT_GT(clear, n / 2);
}

TEST(ThreadingPoses, ABarThroughTheRobotsHoleRunsAlongItsAxis) {
  // The robot is the square ring; the obstacle a long bar along z. Threaded untilted, the ring's
  // axis (its z) lies along the bar and the bar passes the hole's middle.
  planner::BodyParts robot = planner::bodyParts(squareRing(), {}, 0.05, 3.0);
  planner::BodyParts obstacles = planner::bodyParts(acd::shapes::box({-0.1, -0.1, -2}, {0.1, 0.1, 2}), {}, 0.05, 3.0);
  const planner::ThreadingPoses threading(robot, obstacles);
  ASSERT_FALSE(threading.threadings().empty());
  ompl::RNG rng(11);
  for (int i = 0; i < 200; ++i) {
    const planner::Pose pose = threading.sample(rng, 0.0);
    const Eigen::Matrix3d R = pose.orientation.toRotationMatrix();
    EXPECT_TRUE(parallel(R * Vec3::UnitZ(), Vec3::UnitZ(), 1e-9));
    // The hole's centre (the ring's origin) near the bar's axis: within the jitter (a quarter of
    // the hole's width per direction) and on the bar's length.
    const Vec3 centre = pose.position;
    EXPECT_LT(std::hypot(centre.x(), centre.y()), 1.5);
    EXPECT_LT(std::abs(centre.z()), 2.0 + 1.5);
  }
}

TEST(ThreadingPoses, InterlockedLinksConnectWithThreadingPosesAndNotWithout) {
  // The generated alpha-puzzle-like problem: 300 milestones, six seeded trials; with the
  // threading poses the link is separated in at least four, without them (the openings only) in
  // at most one.
  const planner::Scenario s =
      planner::loadOmplAppProblem(std::string(PLANNER_SCENARIO_DIR) + "/generated/ompl_app/alpha_links.cfg");
  const planner::Preprocessing pre = planner::preprocess(s);
  EXPECT_EQ(pre.robotParts.parts.size(), 4u);  // the four bars of the moving link
  ASSERT_FALSE(pre.obstacleParts.gaps.empty());
  EXPECT_NEAR(pre.obstacleParts.gaps.front().width, 0.3, 1e-6);  // the fixed link's gap
  planner::PlanningProblem with(s, pre.freeSpace, pre.openings, pre.solids);
  with.useThreading(pre.robotParts, pre.obstacleParts);
  ASSERT_NE(with.threading(), nullptr);
  planner::PlanningProblem without(s, pre.freeSpace, pre.openings, pre.solids);
  int connectedWith = 0, connectedWithout = 0;
  for (int trial = 0; trial < 6; ++trial) {
    connectedWith += planner::runTrial(with, "acd", 300, trial).outcome.connected;
    connectedWithout += planner::runTrial(without, "acd", 300, trial).outcome.connected;
  }
  EXPECT_GE(connectedWith, 4);
  EXPECT_LE(connectedWithout, 1);
}

}  // namespace
