// OMPL's own planners on the same problem and time budget, through OMPL's benchmark machinery:
// PRM with its default (uniform) sampler, RRTConnect and KPIECE1, and for comparison PRM with
// the acd sampler (whose times include the ACD preprocessing). Each run stops at the first
// solution or at the time limit.
#pragma once

#include "experiment.hpp"

#include <string>
#include <vector>

namespace planner {

struct PlannerTimes {
  std::string planner;                // "PRM", "RRTConnect", "KPIECE1", "PRM_acd"
  int runs = 0;
  int solved = 0;
  std::vector<double> seconds;        // per run: time to the first solution; the limit when unsolved
  std::vector<char> solvedRuns;
  double addedSeconds = 0.0;          // PRM_acd: the ACD preprocessing, added to every run's time
  /// Time by which 90 % of the runs had a solution; < 0 when fewer than 90 % solved in the limit.
  double seconds90() const;
  double medianSeconds() const;       // over all runs, unsolved ones at the limit
};

/// Runs each planner `runs` times with `timeLimit` seconds per run (OMPL's Benchmark), seeded
/// from the scenario's seed, the planner's name and the run. Writes OMPL's benchmark log to
/// `logPath` (empty: not written).
std::vector<PlannerTimes> raceOmplPlanners(PlanningProblem& problem, const Preprocessing& pre, double timeLimit, int runs,
                                           const std::string& logPath);

}  // namespace planner
