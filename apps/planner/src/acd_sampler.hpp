// The ACD sampler: robot reference points on and around the openings between the ACD
// components of the free space (Lien & Amato 2007, Section 7, "Motion planning", Figure 3), and
// poses that thread a convex part of the robot or of the obstacles through a gap of the other.
#pragma once

#include "aligned_poses.hpp"
#include "openings.hpp"

#include <ompl/base/ValidStateSampler.h>
#include <ompl/base/StateSampler.h>
#include <ompl/util/RandomNumbers.h>

#include <functional>
#include <vector>

namespace planner {

class PlanningProblem;

/// Each attempt draws a candidate: with probability `uniformFraction` a plain uniform state;
/// otherwise, where the problem has threading poses (a part of the robot that fits a gap between
/// the obstacles' ACD components, or an obstacle's part that fits a gap of the robot's;
/// threading_poses.hpp), with probability `threadFraction` one of those; otherwise an opening chosen with probability proportional to 1 / max(area, pi spread^2)
/// (narrow openings first), and there, for a robot that turns, with probability
/// `alignedFraction` a pose aligned to the opening (OpeningAlignment::sample, tilt `tilt`),
/// else a point uniform on the opening's triangles, moved along its normal by a normal deviate
/// of std. deviation `spread`, where up to `orientationTries` uniformly random orientations are
/// tried. A candidate whose reference point is not free is dropped at once. The first valid
/// state within getNrAttempts() candidates is returned.
class AcdValidStateSampler : public ompl::base::ValidStateSampler {
 public:
  AcdValidStateSampler(const ompl::base::SpaceInformation* si, const PlanningProblem& problem, double spread,
                       const AcdSamplerSettings& settings, std::uint32_t seed);

  bool sample(ompl::base::State* state) override;
  bool sampleNear(ompl::base::State* state, const ompl::base::State* near, double distance) override;

  /// One candidate (not checked for validity): exposed for tests. Returns true for an
  /// aligned pose (whose orientation is not to be replaced by random ones).
  bool candidate(ompl::base::State* state);

 private:
  int chooseOpening();
  acd::Vec3 pointNearOpening(int which);

  const PlanningProblem& problem_;
  ompl::base::StateSamplerPtr sampler_;
  ompl::RNG rng_;
  double spread_;
  double uniformFraction_;
  double alignedFraction_;
  double threadFraction_;
  double tilt_;
  unsigned orientationTries_;
  const OpeningAlignment* alignment_;                // null: the robot does not turn (a point or a sphere)
  bool bodyIsReference_;                             // the body point is the reference point: bounds do not depend on the turn
  std::vector<double> cumulativeWeight_;             // per opening
  std::vector<std::vector<double>> cumulativeArea_;  // per opening, per triangle
};

}  // namespace planner
