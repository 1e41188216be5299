#include "experiment.hpp"

#include "free_space.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace planner {

namespace {
double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

Preprocessing preprocess(const Scenario& scenario) {
  Preprocessing pre;
  auto t0 = std::chrono::steady_clock::now();
  if (scenario.freeSpaceGiven) {
    pre.freeSpace = scenario.freeSpace;
    pre.freeSpaceMethod = "given";
  } else {
    FreeSpace fs = buildFreeSpace(scenario.workspace, scenario.obstacles, scenario.obstacleNames);
    if (!fs.ok) throw ScenarioError(scenario.path + ": cannot build the free space: " + fs.error);
    pre.freeSpace = std::move(fs.mesh);
    pre.freeSpaceMethod = fs.method;
  }
  pre.freeSpaceSeconds = secondsSince(t0);
  const bool acdWanted =
      std::find(scenario.samplers.begin(), scenario.samplers.end(), "acd") != scenario.samplers.end();
  if (!acdWanted) return pre;
  // libacd decomposes every closed shell as a solid of its own; the shell around an obstacle
  // floating in the workspace would become that obstacle, not a hole in the free space.
  int cavities = 0;
  for (const acd::TriMesh& shell : acd::splitEdgeConnected(pre.freeSpace)) cavities += acd::signedVolume(shell) < 0;
  if (cavities > 0)
    throw ScenarioError(scenario.path + ": " + std::to_string(cavities) +
                        " obstacle(s) float inside the workspace (the free space has a cavity), which the solid ACD "
                        "cannot decompose as one free space; let every obstacle touch the workspace boundary or an "
                        "obstacle that does, or drop the acd sampler");

  t0 = std::chrono::steady_clock::now();
  acd::DecomposeOptions options;
  options.tau = scenario.acd.tau;
  options.threads = 1;  // the trials are timed; keep the preprocessing single-threaded too
  const acd::Decomposition d = acd::decompose(pre.freeSpace, options);
  if (!d.status.ok()) throw ScenarioError(scenario.path + ": the free space cannot be decomposed: " + d.status.message);
  for (const acd::Component& c : d.components) pre.components.push_back(c.mesh);
  pre.decomposeSeconds = secondsSince(t0);

  t0 = std::chrono::steady_clock::now();
  pre.openings = extractOpenings(pre.freeSpace, pre.components);
  pre.openingsSeconds = secondsSince(t0);
  return pre;
}

Trial runTrial(PlanningProblem& problem, const std::string& sampler, int samples, int trial) {
  Trial t;
  problem.seeds()->reset(trialSeed(problem.scenario().seed, sampler, samples, trial));
  problem.useSampler(sampler);
  const long checks0 = problem.world().checks();
  const auto t0 = std::chrono::steady_clock::now();
  FixedSamplePRM prm(problem.si(), static_cast<unsigned>(problem.scenario().prm.neighbors));
  t.outcome = prm.grow(problem.startState(), problem.goalState(), samples);
  t.seconds = secondsSince(t0);
  t.checks = problem.world().checks() - checks0;
  return t;
}

void wilson(int successes, int trials, double& low, double& high) {
  if (trials <= 0) {
    low = 0, high = 1;
    return;
  }
  const double z = 1.959963984540054, n = trials, p = successes / n;
  const double denom = 1 + z * z / n;
  const double centre = (p + z * z / (2 * n)) / denom;
  const double half = z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denom;
  low = std::max(0.0, centre - half);
  high = std::min(1.0, centre + half);
}

std::vector<SamplerRuns> runExperiment(PlanningProblem& problem, const std::vector<std::string>& samplers, int samples,
                                       int trials, const std::function<void(const std::string&, int, int)>& progress) {
  std::vector<SamplerRuns> all;
  for (const std::string& name : samplers) {
    SamplerRuns runs;
    SamplerSummary& s = runs.summary;
    s.sampler = name;
    s.samples = samples;
    s.trials = trials;
    double lengthSum = 0;
    for (int i = 0; i < trials; ++i) {
      Trial t = runTrial(problem, name, samples, i);
      s.successes += t.outcome.connected ? 1 : 0;
      s.meanSeconds += t.seconds;
      s.meanMilestones += t.outcome.milestones;
      s.meanEdges += t.outcome.edges;
      s.meanChecks += static_cast<double>(t.checks);
      s.exhaustedTrials += t.outcome.exhausted ? 1 : 0;
      if (t.outcome.connected) lengthSum += t.outcome.pathLength;
      runs.trials.push_back(std::move(t));
      if (progress) progress(name, i + 1, trials);
    }
    s.rate = static_cast<double>(s.successes) / trials;
    wilson(s.successes, trials, s.ciLow, s.ciHigh);
    s.meanSeconds /= trials;
    s.meanMilestones /= trials;
    s.meanEdges /= trials;
    s.meanChecks /= trials;
    s.meanPathLength = s.successes > 0 ? lengthSum / s.successes : 0.0;
    all.push_back(std::move(runs));
  }
  return all;
}

}  // namespace planner
