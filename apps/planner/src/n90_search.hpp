// How many milestones does a sampler need? The smallest N (on a doubling-then-bisecting search)
// at which the fixed-sample PRM connects start and goal in at least 90 % of the seeded trials.
#pragma once

#include "experiment.hpp"

#include <functional>
#include <string>
#include <vector>

namespace planner {

struct N90Search {
  std::string sampler;
  int n90 = -1;                        // -1: not reached at maxN
  double rate = 0.0;                   // success rate at n90
  double trialSeconds90 = 0.0;         // 90th percentile of roadmap time at n90 (failed trials count as endless)
  double preprocessingSeconds = 0.0;   // the ACD preprocessing, charged to the acd sampler only
  double seconds90() const { return preprocessingSeconds + trialSeconds90; }
  std::vector<SamplerSummary> points;  // every N evaluated, in order
};

/// Doubles N from `startN` until the success rate reaches 90 % (the last step clamped to `maxN`), then
/// bisects between the last N below and the first at or above until they are within 10 %.
/// Success is not strictly monotone in N; the result is the N the search settles on.
N90Search searchN90(PlanningProblem& problem, const std::string& sampler, int startN, int maxN, int trials,
                    double preprocessingSeconds, const std::function<void(const std::string&)>& progress = {});

}  // namespace planner
