#include "report.hpp"

#include <nlohmann/json.hpp>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace planner {

void printTable(std::ostream& out, const std::vector<SamplerRuns>& runs) {
  char line[256];
  std::snprintf(line, sizeof line, "%-15s %7s %6s %8s %17s %11s %10s %8s %8s\n", "sampler", "samples", "trials", "success",
                "95% CI (Wilson)", "time [ms]", "milestones", "edges", "length");
  out << line;
  for (const SamplerRuns& r : runs) {
    const SamplerSummary& s = r.summary;
    char ci[64];
    std::snprintf(ci, sizeof ci, "[%5.1f, %5.1f] %%", 100 * s.ciLow, 100 * s.ciHigh);
    char length[32];
    if (s.successes > 0)
      std::snprintf(length, sizeof length, "%8.2f", s.meanPathLength);
    else
      std::snprintf(length, sizeof length, "%8s", "-");
    std::snprintf(line, sizeof line, "%-15s %7d %6d %6.1f %% %17s %11.1f %10.1f %8.1f %s%s\n", s.sampler.c_str(), s.samples,
                  s.trials, 100 * s.rate, ci, 1000 * s.meanSeconds, s.meanMilestones, s.meanEdges, length,
                  s.exhaustedTrials > 0 ? "  (sampler gave up early in some trials)" : "");
    out << line;
  }
}

void printPreprocessing(std::ostream& out, const Preprocessing& pre, double spread) {
  for (const std::string& line : pre.obstacleSolids) out << "obstacle " << line << "\n";
  if (pre.wrapped)
    out << "wrap: alpha " << pre.wrap.alpha << ", offset " << pre.wrap.offset << " (robot thickness "
        << pre.robotThickness << "; the wrap narrows passages by twice the offset)\n";
  if (pre.cavities > 0)
    out << "free space: " << pre.cavities << " floating obstacle(s) (cavities); decomposed as " << pre.freeSpacePieces
        << " pieces cut through them\n";
  out << "free space: " << pre.freeSpace.faces.size() << " triangles (" << pre.freeSpaceMethod << ", "
      << std::fixed << std::setprecision(3) << pre.solidSeconds + pre.freeSpaceSeconds << " s); ACD: " << pre.components.size()
      << " components (" << pre.decomposeSeconds << " s); openings: " << pre.openings.size() << " ("
      << pre.openingsSeconds << " s); ACD preprocessing total " << pre.totalSeconds() << " s; spread " << spread << "\n";
  for (const Opening& o : pre.openings)
    out << "  opening " << o.a << "-" << o.b << ": centre (" << o.centroid.x() << ", " << o.centroid.y() << ", "
        << o.centroid.z() << "), normal (" << o.normal.x() << ", " << o.normal.y() << ", " << o.normal.z()
        << "), area " << o.area << ", radius " << o.radius << "\n";
  if (!pre.robotParts.parts.empty() || !pre.obstacleParts.parts.empty()) {
    out << "parts for the threading poses (" << pre.partsSeconds << " s): robot " << pre.robotParts.parts.size()
        << " parts, " << pre.robotParts.gaps.size() << " gaps; obstacles " << pre.obstacleParts.parts.size() << " parts, "
        << pre.obstacleParts.gaps.size() << " gaps\n";
    for (const auto* body : {&pre.robotParts, &pre.obstacleParts})
      for (const PartGap& g : body->gaps)
        out << "  gap in the " << (body == &pre.robotParts ? "robot" : "obstacles") << " between parts " << g.a << " and "
            << g.b << ": width " << g.width << ", middle (" << g.middle.x() << ", " << g.middle.y() << ", "
            << g.middle.z() << "), direction (" << g.direction.x() << ", " << g.direction.y() << ", "
            << g.direction.z() << ")\n";
  }
  out.unsetf(std::ios::floatfield);
  out << std::setprecision(6);
}

namespace {
nlohmann::json gapsJson(const BodyParts& body) {
  nlohmann::json gaps = nlohmann::json::array();
  for (const PartGap& g : body.gaps)
    gaps.push_back({{"parts", {g.a, g.b}},
                    {"width", g.width},
                    {"middle", {g.middle.x(), g.middle.y(), g.middle.z()}},
                    {"direction", {g.direction.x(), g.direction.y(), g.direction.z()}},
                    {"through", {g.through.x(), g.through.y(), g.through.z()}}});
  return gaps;
}

nlohmann::json summaryJson(const SamplerSummary& s) {
  return {{"sampler", s.sampler},        {"samples", s.samples},
          {"trials", s.trials},          {"successes", s.successes},
          {"success_rate", s.rate},      {"ci95", {s.ciLow, s.ciHigh}},
          {"mean_seconds", s.meanSeconds}, {"mean_milestones", s.meanMilestones},
          {"mean_edges", s.meanEdges},   {"mean_path_length", s.meanPathLength},
          {"mean_validity_checks", s.meanChecks}, {"exhausted_trials", s.exhaustedTrials}};
}
}  // namespace

std::string resultsJson(const Scenario& scenario, const Preprocessing& pre, double spread,
                        const std::vector<SamplerRuns>& runs, const std::vector<SamplerSummary>& sweep) {
  nlohmann::json j;
  j["scenario"] = {{"name", scenario.name}, {"file", scenario.path}, {"seed", scenario.seed},
                   {"samples", scenario.samples}, {"trials", scenario.trials}, {"tau", scenario.acd.tau},
                   {"spread", spread}, {"uniform_fraction", scenario.acd.uniformFraction},
                   {"aligned_fraction", scenario.acd.alignedFraction}, {"tilt", scenario.acd.tilt},
                   {"neighbors", scenario.prm.neighbors}, {"resolution", scenario.prm.resolution}};
  nlohmann::json openings = nlohmann::json::array();
  for (const Opening& o : pre.openings)
    openings.push_back({{"components", {o.a, o.b}},
                        {"centroid", {o.centroid.x(), o.centroid.y(), o.centroid.z()}},
                        {"normal", {o.normal.x(), o.normal.y(), o.normal.z()}},
                        {"area", o.area},
                        {"radius", o.radius}});
  j["preprocessing"] = {{"obstacle_solids", pre.obstacleSolids},
                        {"wrap", pre.wrapped ? nlohmann::json{{"alpha", pre.wrap.alpha}, {"offset", pre.wrap.offset},
                                                              {"robot_thickness", pre.robotThickness}}
                                             : nlohmann::json()},
                        {"free_space_triangles", pre.freeSpace.faces.size()},
                        {"free_space_method", pre.freeSpaceMethod},
                        {"cavities", pre.cavities},
                        {"free_space_pieces", pre.freeSpacePieces},
                        {"components", pre.components.size()},
                        {"openings", openings},
                        {"threading", {{"robot_parts", pre.robotParts.parts.size()},
                                       {"robot_gaps", gapsJson(pre.robotParts)},
                                       {"obstacle_parts", pre.obstacleParts.parts.size()},
                                       {"obstacle_gaps", gapsJson(pre.obstacleParts)}}},
                        {"seconds", {{"solids", pre.solidSeconds}, {"free_space", pre.freeSpaceSeconds},
                                     {"decompose", pre.decomposeSeconds},
                                     {"openings", pre.openingsSeconds}, {"parts", pre.partsSeconds},
                                     {"total", pre.totalSeconds()}}}};
  j["samplers"] = nlohmann::json::array();
  for (const SamplerRuns& r : runs) j["samplers"].push_back(summaryJson(r.summary));
  if (!sweep.empty()) {
    j["sweep"] = nlohmann::json::array();
    for (const SamplerSummary& s : sweep) j["sweep"].push_back(summaryJson(s));
  }
  return j.dump(2);
}

namespace {
/// OMPL's Benchmark, filled with our own runs instead of running solve().
class RecordedBenchmark : public ompl::tools::Benchmark {
 public:
  using Benchmark::Benchmark;
  CompleteExperiment& data() { return exp_; }
};
}  // namespace

bool writeBenchmarkLog(const std::string& path, const PlanningProblem& problem, const std::vector<SamplerRuns>& runs,
                       double totalSeconds) {
  ompl::geometric::SimpleSetup setup(problem.si());
  RecordedBenchmark bench(setup, problem.scenario().name);
  auto& exp = bench.data();
  exp.maxTime = std::numeric_limits<double>::infinity();
  exp.maxMem = 0;
  exp.runCount = runs.empty() ? 0 : static_cast<unsigned>(runs.front().trials.size());
  exp.startTime = ompl::time::now();
  exp.totalDuration = totalSeconds;
  exp.seed = problem.scenario().seed;
  exp.host = "localhost";
  exp.setupInfo = "PRM with exactly N sampled milestones per run; samplers compared at the same N";
  exp.parameters["samples INTEGER"] = std::to_string(problem.scenario().samples);
  exp.parameters["neighbors INTEGER"] = std::to_string(problem.scenario().prm.neighbors);
  for (const SamplerRuns& r : runs) {
    ompl::tools::Benchmark::PlannerExperiment pe;
    pe.name = "geometric_PRM_" + r.summary.sampler;
    pe.common["samples INTEGER"] = std::to_string(r.summary.samples);
    for (const Trial& t : r.trials) {
      ompl::tools::Benchmark::RunProperties run;
      run["solved BOOLEAN"] = t.outcome.connected ? "1" : "0";
      run["time REAL"] = std::to_string(t.seconds);
      run["graph states INTEGER"] = std::to_string(t.outcome.milestones + 2);
      run["graph motions INTEGER"] = std::to_string(t.outcome.edges);
      run["valid state checks INTEGER"] = std::to_string(t.checks);
      run["sampler failures INTEGER"] = std::to_string(t.outcome.samplerFailures);
      if (t.outcome.connected) run["solution length REAL"] = std::to_string(t.outcome.pathLength);
      pe.runs.push_back(std::move(run));
    }
    exp.planners.push_back(std::move(pe));
  }
  return bench.saveResultsToFile(path.c_str());
}

std::string writeBestPath(const std::string& path, const std::vector<SamplerRuns>& runs) {
  const Trial* best = nullptr;
  std::string from;
  for (const SamplerRuns& r : runs)
    for (const Trial& t : r.trials)
      if (t.outcome.connected && t.outcome.path && (!best || t.outcome.pathLength < best->outcome.pathLength))
        best = &t, from = r.summary.sampler;
  if (!best) return "";
  ompl::geometric::PathGeometric p(*best->outcome.path);
  p.interpolate();
  std::ofstream out(path);
  p.printAsMatrix(out);
  return out ? from : "";
}

bool writeSweepCsv(const std::string& path, const std::vector<SamplerSummary>& sweep) {
  std::ofstream out(path);
  out << "sampler,samples,trials,successes,rate,ci_low,ci_high,mean_seconds\n";
  for (const SamplerSummary& s : sweep)
    out << s.sampler << ',' << s.samples << ',' << s.trials << ',' << s.successes << ',' << s.rate << ',' << s.ciLow
        << ',' << s.ciHigh << ',' << s.meanSeconds << '\n';
  return static_cast<bool>(out);
}

}  // namespace planner
