// Experiment output: the summary table, JSON, an OMPL benchmark log (the format
// ompl_benchmark_statistics.py reads) and the best path.
#pragma once

#include "experiment.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace planner {

void printTable(std::ostream& out, const std::vector<SamplerRuns>& runs);

void printPreprocessing(std::ostream& out, const Preprocessing& pre, double spread);

/// JSON: scenario, preprocessing, one entry per sampler (summary), optional sweep.
std::string resultsJson(const Scenario& scenario, const Preprocessing& pre, double spread,
                        const std::vector<SamplerRuns>& runs, const std::vector<SamplerSummary>& sweep);

/// OMPL benchmark log: one "planner" per sampler (geometric_PRM_<sampler>), one run per trial.
/// Returns false when the file cannot be written.
bool writeBenchmarkLog(const std::string& path, const PlanningProblem& problem, const std::vector<SamplerRuns>& runs,
                       double totalSeconds);

/// The shortest solution over all trials, one state per line (OMPL's printAsMatrix: x y z
/// qx qy qz qw for SE(3), x y yaw for SE(2), x y z for R^3), interpolated at the motion
/// checking resolution. Returns the sampler it came from, empty when no trial connected.
std::string writeBestPath(const std::string& path, const std::vector<SamplerRuns>& runs);

/// Success rates per sampler and sample count, as CSV (sampler,samples,trials,successes,rate,ci_low,ci_high,mean_seconds).
bool writeSweepCsv(const std::string& path, const std::vector<SamplerSummary>& sweep);

}  // namespace planner
