// planner: PRM with a fixed number of samples per sampler (uniform, acd, OMPL's Gaussian,
// obstacle-based and bridge-test) over seeded trials, on a scenario file (docs/PLANNER.md).
#include "experiment.hpp"
#include "report.hpp"
#include "scenario.hpp"

#include <acd/io.hpp>

#include <CLI/CLI.hpp>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace {

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"PRM with samples biased toward the openings between the ACD components of the free space"};
  std::string scenarioPath, samplerList, outputDir;
  int samples = 0, trials = 0, sweepTrials = 0;
  long long seed = 0;
  bool sweep = false, quiet = false;
  app.add_option("scenario", scenarioPath, "Scenario file (YAML, see docs/PLANNER.md)")->required();
  app.add_option("-n,--samples", samples, "Sampled milestones per roadmap (overrides the scenario)");
  app.add_option("-t,--trials", trials, "Seeded trials per sampler (overrides the scenario)");
  app.add_option("-s,--samplers", samplerList, "Comma-separated: uniform,acd,gaussian,obstacle_based,bridge_test");
  app.add_option("--seed", seed, "Scenario seed (overrides the scenario)");
  app.add_option("-o,--output", outputDir, "Output folder (default: the scenario's 'output', else out/planner/<name>)");
  app.add_flag("--sweep", sweep, "Also run every sample count of the scenario's 'sweep' (success-rate plot data)");
  app.add_option("--sweep-trials", sweepTrials, "Trials per point of the sweep (overrides the scenario)");
  app.add_flag("-q,--quiet", quiet, "No progress and no preprocessing report");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 1;  // --help is not an error
  }

  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  planner::Scenario scenario;
  planner::Preprocessing pre;
  std::unique_ptr<planner::PlanningProblem> problem;
  try {
    scenario = planner::loadScenario(scenarioPath);
    if (samples < 0 || trials < 0 || sweepTrials < 0) throw planner::ScenarioError("--samples, --trials and --sweep-trials must be positive");
    if (samples > 0) scenario.samples = samples;
    if (trials > 0) scenario.trials = trials;
    if (sweepTrials > 0) scenario.sweepTrials = sweepTrials;
    if (seed != 0) {
      if (seed < 0 || seed > 0xFFFFFFFFll) throw planner::ScenarioError("--seed must be in 1..4294967295");
      scenario.seed = static_cast<unsigned>(seed);
    }
    if (!samplerList.empty()) {
      scenario.samplers.clear();
      for (const std::string& name : splitList(samplerList)) {
        const auto& known = planner::knownSamplers();
        if (std::find(known.begin(), known.end(), name) == known.end())
          throw planner::ScenarioError("--samplers: unknown sampler '" + name + "'");
        scenario.samplers.push_back(name);
      }
    }
    // Every random stream of a trial has its own local seed (seeding.hpp); the global seed
    // covers anything else OMPL draws, and must be set before OMPL's first generator exists.
    ompl::RNG::setSeed(scenario.seed);
    if (!outputDir.empty()) scenario.outputDir = outputDir;
    if (scenario.outputDir.empty()) scenario.outputDir = "out/planner/" + scenario.name;
    pre = planner::preprocess(scenario);
    problem = std::make_unique<planner::PlanningProblem>(scenario, pre.freeSpace, pre.openings);
  } catch (const planner::ScenarioError& e) {
    std::cerr << "planner: " << e.what() << "\n";
    return 2;
  }
  // Before the long part: a run whose results cannot be written is not started.
  std::error_code ec;
  std::filesystem::create_directories(scenario.outputDir, ec);
  if (ec || !std::filesystem::is_directory(scenario.outputDir)) {
    std::cerr << "planner: cannot create the output folder " << scenario.outputDir << (ec ? ": " + ec.message() : "") << "\n";
    return 3;
  }
  if (pre.openings.empty() && std::find(scenario.samplers.begin(), scenario.samplers.end(), "acd") != scenario.samplers.end())
    std::cerr << "planner: warning: the ACD of the free space has no openings (one component at tau " << scenario.acd.tau
              << "); the acd sampler falls back to uniform samples\n";
  if (!quiet && !scenario.robot.solidSummary.empty())
    std::cout << "robot " << scenario.robot.meshPath << ": " << scenario.robot.solidSummary << "\n";
  if (!quiet) planner::printPreprocessing(std::cout, pre, problem->acdSpread());

  const bool tty = !quiet && ::isatty(STDERR_FILENO);
  auto progress = [&](const std::string& name, int done, int total) {
    if (tty) std::cerr << "\r" << name << " " << done << "/" << total << "   " << (done == total ? "\n" : "") << std::flush;
  };
  const auto t0 = std::chrono::steady_clock::now();
  const auto runs = planner::runExperiment(*problem, scenario.samplers, scenario.samples, scenario.trials, progress);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::vector<planner::SamplerSummary> sweepResults;
  if (sweep) {
    for (int n : scenario.sweep) {
      auto point = planner::runExperiment(*problem, scenario.samplers, n, scenario.sweepTrials,
                                          [&](const std::string& name, int done, int total) {
                                            progress(name + " n=" + std::to_string(n), done, total);
                                          });
      for (const auto& r : point) sweepResults.push_back(r.summary);
    }
  }

  std::cout << "scenario " << scenario.name << ": " << scenario.samples << " samples, " << scenario.trials
            << " trials per sampler, seed " << scenario.seed << "\n";
  planner::printTable(std::cout, runs);

  const std::filesystem::path dir(scenario.outputDir);
  std::ofstream(dir / "results.json") << planner::resultsJson(scenario, pre, problem->acdSpread(), runs, sweepResults) << "\n";
  if (!planner::writeBenchmarkLog((dir / "benchmark.log").string(), *problem, runs, seconds))
    std::cerr << "planner: cannot write " << (dir / "benchmark.log").string() << "\n";
  const std::string bestFrom = planner::writeBestPath((dir / "best_path.txt").string(), runs);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < pre.components.size(); ++i) names.push_back("component_" + std::to_string(i));
  acd::writeObjObjects((dir / "free_space_acd.obj").string(), pre.components, names);
  if (!sweepResults.empty()) planner::writeSweepCsv((dir / "sweep.csv").string(), sweepResults);
  std::cout << "wrote " << (dir / "results.json").string() << ", " << (dir / "benchmark.log").string()
            << (bestFrom.empty() ? "" : ", " + (dir / "best_path.txt").string() + " (from " + bestFrom + ")")
            << (sweepResults.empty() ? "" : ", " + (dir / "sweep.csv").string()) << "\n";
  return 0;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const planner::ScenarioError& e) {
    std::cerr << "planner: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    // OMPL, FCL or the standard library refusing something we did not foresee: a bug to report.
    std::cerr << "planner: internal error: " << e.what() << "\n";
    return 4;
  }
}
