// Samplers return only valid states (checked by an independent exact test), trials are
// deterministic, and on a small narrow-passage problem acd connects where uniform does not.
#include "acd_sampler.hpp"
#include "experiment.hpp"
#include "problem.hpp"
#include "scenario.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using acd::Vec3;

/// The paper's situation in small: a rigid bar and a wall with a square hole.
const char* kNarrowBox = R"(
name: narrow_small
workspace: {min: [0, 0, 0], max: [6, 3, 3]}
obstacles:
  - box: {min: [2.8, 0.0, 0.0], max: [3.2, 1.1, 3.0]}
  - box: {min: [2.8, 1.9, 0.0], max: [3.2, 3.0, 3.0]}
  - box: {min: [2.8, 1.1, 0.0], max: [3.2, 1.9, 1.1]}
  - box: {min: [2.8, 1.1, 1.9], max: [3.2, 1.9, 3.0]}
robot: {type: box, size: [1.0, 0.6, 0.25]}
start: {position: [1.0, 1.0, 1.0]}
goal: {position: [5.0, 2.0, 2.0]}
acd: {tau: 0.05}
)";

struct Slab {
  Vec3 lo, hi;
};

/// Exact overlap of an oriented box (centre c, rotation R, half sizes h) with an axis-aligned
/// box: separating axis theorem over the 15 candidate axes.
bool overlaps(const Vec3& c, const Eigen::Matrix3d& R, const Vec3& h, const Slab& s) {
  const Vec3 sc = 0.5 * (s.lo + s.hi), sh = 0.5 * (s.hi - s.lo), d = c - sc;
  std::vector<Vec3> axes;
  for (int i = 0; i < 3; ++i) axes.push_back(Vec3::Unit(i)), axes.push_back(R.col(i));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) axes.push_back(Vec3::Unit(i).cross(R.col(j)));
  for (const Vec3& a : axes) {
    if (a.squaredNorm() < 1e-18) continue;
    const double rBox = h.x() * std::abs(a.dot(R.col(0))) + h.y() * std::abs(a.dot(R.col(1))) + h.z() * std::abs(a.dot(R.col(2)));
    const double rSlab = sh.x() * std::abs(a.x()) + sh.y() * std::abs(a.y()) + sh.z() * std::abs(a.z());
    if (std::abs(a.dot(d)) > rBox + rSlab) return false;
  }
  return true;
}

/// Independent validity: the robot box inside the workspace and touching no obstacle box.
bool exactlyFree(const planner::Scenario& s, const Vec3& p, const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d R = q.toRotationMatrix();
  const Vec3 h = 0.5 * s.robot.size;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
    const Vec3 x = p + R * sign.cwiseProduct(h);
    if ((x.array() < s.workspace.lo.array()).any() || (x.array() > s.workspace.hi.array()).any()) return false;
  }
  for (const planner::Obstacle& o : s.obstacles) {
    const acd::Box3 b = acd::boundingBox(o.triangles);
    if (overlaps(p, R, h, {b.lo, b.hi})) return false;
  }
  return true;
}

class Samplers : public ::testing::Test {
 protected:
  void SetUp() override {
    scenario_ = planner::parseScenario(kNarrowBox, "narrow_small.yaml", ".");
    pre_ = planner::preprocess(scenario_);
    problem_ = std::make_unique<planner::PlanningProblem>(scenario_, pre_.freeSpace, pre_.openings);
  }
  planner::Scenario scenario_;
  planner::Preprocessing pre_;
  std::unique_ptr<planner::PlanningProblem> problem_;
};

TEST_F(Samplers, OpeningsAreTheHole) {
  ASSERT_GE(pre_.openings.size(), 1u);
  for (const planner::Opening& o : pre_.openings) {
    EXPECT_GT(o.centroid.y(), 1.1);
    EXPECT_LT(o.centroid.y(), 1.9);
    EXPECT_GT(o.centroid.z(), 1.1);
    EXPECT_LT(o.centroid.z(), 1.9);
  }
}

TEST_F(Samplers, EverySamplerReturnsOnlyValidStates) {
  auto* state = problem_->si()->allocState();
  for (const std::string& name : planner::knownSamplers()) {
    SCOPED_TRACE(name);
    problem_->seeds()->reset(99);
    problem_->useSampler(name);
    auto sampler = problem_->si()->allocValidStateSampler();
    int returned = 0, nearWall = 0;
    for (int i = 0; i < 60; ++i) {
      if (!sampler->sample(state)) continue;
      ++returned;
      const Vec3 p = problem_->position(state);
      const Eigen::Quaterniond q = problem_->orientation(state);
      EXPECT_TRUE(problem_->si()->isValid(state));
      EXPECT_TRUE(exactlyFree(scenario_, p, q)) << p.transpose();
      nearWall += std::abs(p.x() - 3.0) < 1.0;
    }
    EXPECT_GT(returned, 30);
    if (name == "acd") EXPECT_GT(nearWall, returned / 2) << "acd samples gather at the opening";
  }
  problem_->si()->freeState(state);
}

TEST_F(Samplers, AcdCandidatesGatherAroundTheOpenings) {
  problem_->seeds()->reset(5);
  planner::AcdSamplerSettings settings;
  settings.uniformFraction = 0.0, settings.orientationTries = 1, settings.alignedFraction = 0.0;
  planner::AcdValidStateSampler sampler(problem_->si().get(), *problem_, 0.1, settings, 1234);
  auto* state = problem_->si()->allocState();
  double meanDistance = 0;
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    sampler.candidate(state);
    const Vec3 p = problem_->position(state);
    double best = 1e9;
    for (const planner::Opening& o : pre_.openings) {
      // In the plane of the opening the point lies on the opening's triangles.
      const Vec3 along = p - o.centroid;
      const Vec3 inPlane = along - along.dot(o.normal) * o.normal;
      EXPECT_LE(inPlane.cwiseAbs().maxCoeff(), 0.4 + 1e-9);
      best = std::min(best, std::abs(along.dot(o.normal)));
    }
    meanDistance += best / n;
  }
  problem_->si()->freeState(state);
  // Half-normal with sigma 0.1: mean 0.08 (less, with two openings to choose the nearer of).
  EXPECT_LT(meanDistance, 0.1);
}

/// A point robot and a tiny hole: cheap checks, a passage uniform sampling misses.
const char* kPinhole = R"(
name: pinhole
workspace: {min: [0, 0, 0], max: [4, 2, 2]}
obstacles:
  - box: {min: [1.8, 0.0, 0.0], max: [2.2, 0.95, 2.0]}
  - box: {min: [1.8, 1.05, 0.0], max: [2.2, 2.0, 2.0]}
  - box: {min: [1.8, 0.95, 0.0], max: [2.2, 1.05, 0.95]}
  - box: {min: [1.8, 0.95, 1.05], max: [2.2, 1.05, 2.0]}
robot: {type: point}
start: {position: [0.3, 0.3, 0.3]}
goal: {position: [3.7, 1.7, 1.7]}
samples: 200
prm: {neighbors: 10, resolution: 0.002}
acd: {tau: 0.05}
seed: 3
)";

TEST(SeededRun, AcdConnectsAndUniformDoesNot) {
  const planner::Scenario s = planner::parseScenario(kPinhole, "pinhole.yaml", ".");
  const planner::Preprocessing pre = planner::preprocess(s);
  ASSERT_FALSE(pre.openings.empty());
  planner::PlanningProblem problem(s, pre.freeSpace, pre.openings);
  for (int trial = 0; trial < 5; ++trial) {
    const planner::Trial acd = planner::runTrial(problem, "acd", 200, trial);
    const planner::Trial uniform = planner::runTrial(problem, "uniform", 200, trial);
    EXPECT_TRUE(acd.outcome.connected) << "trial " << trial;
    EXPECT_FALSE(uniform.outcome.connected) << "trial " << trial;
    EXPECT_EQ(acd.outcome.milestones, 200);
    EXPECT_EQ(uniform.outcome.milestones, 200);
    if (acd.outcome.connected) {
      // A path through a 0.1-wide hole is at least the straight distance, and goes through the hole.
      EXPECT_GE(acd.outcome.pathLength, (s.goal.position - s.start.position).norm() - 1e-9);
      ASSERT_TRUE(acd.outcome.path);
      bool throughHole = false;
      const auto& states = acd.outcome.path->getStates();
      for (std::size_t i = 0; i + 1 < states.size(); ++i) {
        const Vec3 a = problem.position(states[i]), b = problem.position(states[i + 1]);
        if ((a.x() - 2.0) * (b.x() - 2.0) <= 0 && a.x() != b.x()) {
          const Vec3 x = a + (2.0 - a.x()) / (b.x() - a.x()) * (b - a);
          throughHole = std::abs(x.y() - 1.0) < 0.05 && std::abs(x.z() - 1.0) < 0.05;
        }
      }
      EXPECT_TRUE(throughHole);
    }
  }
}

TEST(SeededRun, SameSeedSameRoadmap) {
  const planner::Scenario s = planner::parseScenario(kPinhole, "pinhole.yaml", ".");
  const planner::Preprocessing pre = planner::preprocess(s);
  planner::PlanningProblem problem(s, pre.freeSpace, pre.openings);
  for (const std::string name : {"acd", "uniform", "bridge_test"}) {
    const planner::Trial a = planner::runTrial(problem, name, 100, 4);
    planner::runTrial(problem, name, 100, 5);  // another trial in between changes nothing
    const planner::Trial b = planner::runTrial(problem, name, 100, 4);
    EXPECT_EQ(a.outcome.edges, b.outcome.edges) << name;
    EXPECT_EQ(a.outcome.samplerFailures, b.outcome.samplerFailures) << name;
    EXPECT_EQ(a.checks, b.checks) << name;
    EXPECT_EQ(a.outcome.connected, b.outcome.connected) << name;
    EXPECT_DOUBLE_EQ(a.outcome.pathLength, b.outcome.pathLength) << name;
  }
}

TEST(Statistics, WilsonInterval) {
  double lo = 0, hi = 0;
  planner::wilson(0, 10, lo, hi);
  EXPECT_DOUBLE_EQ(lo, 0.0);
  EXPECT_NEAR(hi, 0.2775, 1e-4);
  planner::wilson(95, 100, lo, hi);
  EXPECT_NEAR(lo, 0.8883, 1e-4);
  EXPECT_NEAR(hi, 0.9785, 1e-4);
  planner::wilson(100, 100, lo, hi);
  EXPECT_NEAR(lo, 0.9630, 1e-4);
  EXPECT_DOUBLE_EQ(hi, 1.0);
}

}  // namespace
