// The ACD sampler: robot reference points on and around the openings between the ACD
// components of the free space (Lien & Amato 2007, Section 7, "Motion planning", Figure 3).
#pragma once

#include "openings.hpp"

#include <ompl/base/ValidStateSampler.h>
#include <ompl/base/StateSampler.h>
#include <ompl/util/RandomNumbers.h>

#include <functional>
#include <vector>

namespace planner {

class PlanningProblem;

/// Each attempt draws a position: with probability `uniformFraction` a plain uniform state;
/// otherwise an opening chosen with probability proportional to 1 / max(area, pi spread^2)
/// (narrow openings first), a point uniform on its shared triangles, moved along the opening's normal by a
/// normal deviate of std. deviation `spread`. A position whose reference point is not free
/// is dropped at once; otherwise up to `orientationTries` uniformly random orientations are
/// tried there. The first valid state within getNrAttempts() positions is returned.
class AcdValidStateSampler : public ompl::base::ValidStateSampler {
 public:
  AcdValidStateSampler(const ompl::base::SpaceInformation* si, const PlanningProblem& problem, double spread,
                       double uniformFraction, unsigned orientationTries, std::uint32_t seed);

  bool sample(ompl::base::State* state) override;
  bool sampleNear(ompl::base::State* state, const ompl::base::State* near, double distance) override;

  /// One candidate (not checked for validity): exposed for tests.
  void candidate(ompl::base::State* state);

 private:
  acd::Vec3 pointNearOpening();

  const PlanningProblem& problem_;
  ompl::base::StateSamplerPtr sampler_;
  ompl::RNG rng_;
  double spread_;
  double uniformFraction_;
  unsigned orientationTries_;
  std::vector<double> cumulativeWeight_;             // per opening
  std::vector<std::vector<double>> cumulativeArea_;  // per opening, per triangle
};

}  // namespace planner
