#include "experiment.hpp"

#include <acd/algo/stopwatch.hpp>

#include "free_space.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace planner {

Preprocessing preprocess(const Scenario& scenario) {
  Preprocessing pre;
  auto t0 = acd::Clock::now();
  if (scenario.freeSpaceGiven) {
    pre.freeSpace = scenario.freeSpace;
    pre.freeSpaceMethod = "given";
  } else {
    pre.wrap = resolvedWrap(scenario);
    pre.robotThickness = scenario.robot.thickness();
    std::vector<acd::TriMesh> solids;
    std::vector<std::string> names;
    for (const Obstacle& o : scenario.obstacles) {
      if (o.box) {
        solids.push_back(o.triangles);
        names.push_back(o.name);
        pre.solids.push_back({o.name, "a box", o.triangles});
        continue;
      }
      const SolidObstacle solid = solidify(o.triangles, pre.wrap);
      if (!solid.ok) throw ScenarioError(scenario.path + ": " + o.name + ": " + solid.error);
      pre.obstacleSolids.push_back(o.name + ": " + solid.summary());
      pre.wrapped = pre.wrapped || solid.wrappedPieces > 0;
      for (std::size_t i = 0; i < solid.pieces.size(); ++i) {
        solids.push_back(solid.pieces[i]);
        names.push_back(o.name + " piece " + std::to_string(i));
        const bool wrap = solid.wrappedPieces > 0 && i + 1 == solid.pieces.size();
        char how[160];
        std::snprintf(how, sizeof how, "the alpha wrap of %d open pieces, %g beyond their triangles (alpha %g)",
                      solid.wrappedPieces, solid.wrap.offset, solid.wrap.alpha);
        pre.solids.push_back({names.back(), wrap ? std::string(how) : "closed or repaired exactly", solid.pieces[i]});
      }
    }
    pre.solidSeconds = acd::secondsSince(t0);
    t0 = acd::Clock::now();
    FreeSpace fs = buildFreeSpace(scenario.workspace, solids, names);
    if (!fs.ok) throw ScenarioError(scenario.path + ": cannot build the free space: " + fs.error);
    pre.freeSpace = std::move(fs.mesh);
    pre.freeSpaceMethod = fs.method;
  }
  for (const acd::TriMesh& shell : acd::splitEdgeConnected(pre.freeSpace)) pre.cavities += acd::signedVolume(shell) < 0;
  pre.freeSpaceSeconds = acd::secondsSince(t0);
  const bool acdWanted =
      std::find(scenario.samplers.begin(), scenario.samplers.end(), "acd") != scenario.samplers.end();
  if (!acdWanted) return pre;

  t0 = acd::Clock::now();
  // libacd decomposes every closed shell as a solid of its own: a cavity's shell would become
  // the obstacle, not a hole. Pieces cut through the cavities have none (free_space.hpp).
  std::string error;
  const std::vector<acd::TriMesh> pieces =
      pre.cavities > 0 ? cavityFreePieces(pre.freeSpace, error) : std::vector<acd::TriMesh>{pre.freeSpace};
  if (pieces.empty()) throw ScenarioError(scenario.path + ": " + error);
  pre.freeSpacePieces = static_cast<int>(pieces.size());
  acd::DecomposeOptions options;
  // Openings are the regions two components share: each component one solid, concave by at most
  // tau (a merge held to the model may give one hull to touching pieces that do not glue). The
  // free space stays in the scene's coordinates bit for bit.
  options.mergeScope = acd::MergeScope::Component;
  options.invariant = false;
  options.tau = scenario.acd.tau;
  options.threads = 1;  // the trials are timed; keep the preprocessing single-threaded too
  for (const acd::TriMesh& piece : pieces) {
    const acd::Decomposition d = acd::decompose(piece, options);
    if (!d.status.ok()) throw ScenarioError(scenario.path + ": the free space cannot be decomposed: " + d.status.message);
    for (const acd::Component& c : d.components) pre.components.push_back(c.mesh);
  }
  pre.decomposeSeconds = acd::secondsSince(t0);

  t0 = acd::Clock::now();
  pre.openings = extractOpenings(pre.freeSpace, pre.components);
  pre.openingsSeconds = acd::secondsSince(t0);

  const Robot& robot = scenario.robot;
  if ((robot.kind == RobotKind::Box || robot.kind == RobotKind::Mesh) && !robot.planar) {
    t0 = acd::Clock::now();
    // A gap wider than the robot is no passage for it.
    const double widest = 2.0 * robot.boundingRadius();
    pre.robotParts = bodyParts(robot.mesh, {robot.closedMesh()}, scenario.acd.tau, widest);
    std::vector<acd::TriMesh> triangles, solids;
    for (const Obstacle& o : scenario.obstacles) triangles.push_back(o.triangles);
    for (const NamedSolid& s : pre.solids) solids.push_back(s.mesh);
    pre.obstacleParts = bodyParts(acd::concatenate(triangles), solids, scenario.acd.tau, widest);
    pre.partsSeconds = acd::secondsSince(t0);
  }
  return pre;
}

Trial runTrial(PlanningProblem& problem, const std::string& sampler, int samples, int trial) {
  Trial t;
  problem.seeds()->reset(trialSeed(problem.scenario().seed, sampler, samples, trial));
  problem.useSampler(sampler);
  const long checks0 = problem.world().checks();
  const auto t0 = acd::Clock::now();
  FixedSamplePRM prm(problem.si(), static_cast<unsigned>(problem.scenario().prm.neighbors));
  t.outcome = prm.grow(problem.startState(), problem.goalState(), samples);
  t.seconds = acd::secondsSince(t0);
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
