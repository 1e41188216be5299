// The race, as the field runs it (OMPL's benchmark machinery, ompl::tools::Benchmark): PRM with
// each sampler (OMPL's uniform, Gaussian, obstacle-based, bridge-test and maximum-clearance
// samplers, and the acd sampler, whose time includes the ACD preprocessing), OMPL's planners
// RRTConnect, KPIECE1, BKPIECE1, EST and SBL, and every planner the problem file lists. Each
// run stops at the first exact solution or at the time limit.
#pragma once

#include "experiment.hpp"

#include <string>
#include <vector>

namespace planner {

struct PlannerTimes {
  std::string planner;                // "PRM_acd", "RRTConnect", "kpiece_cfg1"...
  int runs = 0;
  int solved = 0;
  std::vector<double> seconds;        // per run: time to the first solution; the limit when unsolved
  std::vector<char> solvedRuns;
  double addedSeconds = 0.0;          // PRM_acd: the ACD preprocessing, added to every run's time
  /// Time by which 90 % of the runs had a solution; < 0 when fewer than 90 % solved in the limit.
  double seconds90() const;
  double medianSeconds() const;       // over all runs, unsolved ones at the limit
};

/// The standard set (above) plus `listed` (OMPL.app's [planner] entries; ones this build does
/// not know are skipped and named in `skipped`), in a fixed order.
std::vector<std::string> racePlannerNames(const std::vector<PlannerEntry>& listed, std::vector<std::string>* skipped = nullptr);

/// Runs each planner `runs` times with `timeLimit` seconds per run, seeded from the scenario's
/// seed, the planner's name and the run. Writes OMPL's benchmark log to `logPath` (empty: not
/// written; readable by OMPL's ompl_benchmark_statistics.py), PRM_acd's times with the
/// preprocessing included there too. `only`: a subset of racePlannerNames (empty: all).
std::vector<PlannerTimes> raceOmplPlanners(PlanningProblem& problem, const Preprocessing& pre, double timeLimit, int runs,
                                           const std::string& logPath, const std::vector<std::string>& only = {});

}  // namespace planner
