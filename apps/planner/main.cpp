// planner: PRM with a fixed number of samples per sampler (uniform, acd, OMPL's Gaussian,
// obstacle-based and bridge-test) over seeded trials, on a scenario file (docs/PLANNER.md).
#include "experiment.hpp"
#include "n90_search.hpp"
#include "ompl_app_problem.hpp"
#include "ompl_planners.hpp"
#include "report.hpp"
#include "search_report.hpp"
#include "scenario.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/io.hpp>
#include <appcli/console.hpp>
#include <appcli/exit_codes.hpp>

#include <CLI/CLI.hpp>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace {

// The programs' shared exit codes (apps/cli, docs/ERRORS.md) and "planner: ..." messages.
using appcli::kBadInput;
using appcli::kInternal;
using appcli::kOk;
using appcli::kOutputFailed;
const appcli::Console kConsole("planner");

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

/// The command line: the scenario file and what overrides or adds to it.
struct Args {
  std::string scenarioPath, samplerList, outputDir;
  int samples = 0, trials = 0, sweepTrials = 0;
  long long seed = 0;
  bool sweep = false, quiet = false, n90 = false, race = false, noFixed = false;
  int n90Start = 50, n90Max = 8000, n90Trials = 20, raceRuns = -1;  // -1: the scenario's (OMPL.app's run_count)
  double timeLimit = -1;                                                 // -1: the scenario's (time_limit)
  std::string plannerList;
};

void addOptions(CLI::App& app, Args& a) {
  app.add_option("scenario", a.scenarioPath, "Scenario file (YAML) or OMPL.app problem file (.cfg); see docs/PLANNER.md")->required();
  app.add_option("-n,--samples", a.samples, "Sampled milestones per roadmap (overrides the scenario)");
  app.add_option("-t,--trials", a.trials, "Seeded trials per sampler (overrides the scenario)");
  app.add_option("-s,--samplers", a.samplerList, "Comma-separated: uniform,acd,gaussian,obstacle_based,bridge_test");
  app.add_option("--seed", a.seed, "Scenario seed (overrides the scenario)");
  app.add_option("-o,--output", a.outputDir, "Output folder (default: the scenario's 'output', else out/planner/<name>)");
  app.add_flag("--sweep", a.sweep, "Also run every sample count of the scenario's 'sweep' (success-rate plot data)");
  app.add_option("--sweep-trials", a.sweepTrials, "Trials per point of the sweep (overrides the scenario)");
  app.add_flag("--n90", a.n90, "Also search, per sampler, the milestones needed for 90 % success (n90.csv)");
  app.add_option("--n90-start", a.n90Start, "First N of the search (doubled from there; default 50)");
  app.add_option("--n90-max", a.n90Max, "Largest N the search tries (default 8000)");
  app.add_option("--n90-trials", a.n90Trials, "Trials per N of the search (default 20)");
  app.add_flag("--race", a.race,
               "Also race PRM with each sampler (acd included) against OMPL's planners and those the .cfg lists "
               "(race.csv, race_runs.csv, ompl_benchmark.log)");
  app.add_option("--time-limit", a.timeLimit, "Seconds per run of --race (default: the .cfg's time_limit, else 30)");
  app.add_option("--runs", a.raceRuns, "Runs per planner of --race (default: the .cfg's run_count, else 20)");
  app.add_option("--planners", a.plannerList, "Comma-separated subset of the race's planners (PRM_acd,RRTConnect,...)");
  app.add_flag("--no-fixed", a.noFixed, "Skip the fixed-N table (with --n90 or --race)");
  app.add_flag("-q,--quiet", a.quiet, "No progress and no preprocessing report");
}

/// The scenario file with the command line's overrides; throws ScenarioError for a bad file or option.
planner::Scenario scenarioFor(const Args& a) {
  planner::Scenario scenario = planner::isOmplAppProblem(a.scenarioPath) ? planner::loadOmplAppProblem(a.scenarioPath)
                                                                         : planner::loadScenario(a.scenarioPath);
  if (a.samples < 0 || a.trials < 0 || a.sweepTrials < 0)
    throw planner::ScenarioError("--samples, --trials and --sweep-trials must be positive");
  if (a.n90Start <= 0 || a.n90Max < a.n90Start || a.n90Trials <= 0)
    throw planner::ScenarioError("--n90-start and --n90-trials must be positive, --n90-max at least --n90-start");
  if (a.timeLimit <= 0 && a.timeLimit != -1) throw planner::ScenarioError("--time-limit must be positive");
  if (a.raceRuns <= 0 && a.raceRuns != -1) throw planner::ScenarioError("--runs must be positive");
  if (a.timeLimit > 0) scenario.race.timeLimit = a.timeLimit;
  if (a.raceRuns > 0) scenario.race.runs = a.raceRuns;
  if (a.noFixed && !a.n90 && !a.race) throw planner::ScenarioError("--no-fixed needs --n90 or --race");
  if (a.samples > 0) scenario.samples = a.samples;
  if (a.trials > 0) scenario.trials = a.trials;
  if (a.sweepTrials > 0) scenario.sweepTrials = a.sweepTrials;
  if (a.seed != 0) {
    if (a.seed < 0 || a.seed > 0xFFFFFFFFll) throw planner::ScenarioError("--seed must be in 1..4294967295");
    scenario.seed = static_cast<unsigned>(a.seed);
  }
  if (!a.samplerList.empty()) {
    scenario.samplers.clear();
    for (const std::string& name : splitList(a.samplerList)) {
      const auto& known = planner::knownSamplers();
      if (std::find(known.begin(), known.end(), name) == known.end())
        throw planner::ScenarioError("--samplers: unknown sampler '" + name + "'");
      scenario.samplers.push_back(name);
    }
  }
  if (!a.outputDir.empty()) scenario.outputDir = a.outputDir;
  if (scenario.outputDir.empty()) scenario.outputDir = "out/planner/" + scenario.name;
  return scenario;
}

}  // namespace

int run(int argc, char** argv) {
  CLI::App app{"PRM with samples biased toward the openings between the ACD components of the free space"};
  Args args;
  addOptions(app, args);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return appcli::usageExit(app.exit(e));  // --help is not an error
  }
  const bool sweep = args.sweep, quiet = args.quiet, n90 = args.n90, race = args.race, noFixed = args.noFixed;
  const int n90Start = args.n90Start, n90Max = args.n90Max, n90Trials = args.n90Trials;

  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  planner::Scenario scenario;
  planner::Preprocessing pre;
  std::unique_ptr<planner::PlanningProblem> problem;
  try {
    scenario = scenarioFor(args);
    // Every random stream of a trial has its own local seed (seeding.hpp); the global seed
    // covers anything else OMPL draws, and must be set before OMPL's first generator exists.
    ompl::RNG::setSeed(scenario.seed);
    pre = planner::preprocess(scenario);
    problem = std::make_unique<planner::PlanningProblem>(scenario, pre.freeSpace, pre.openings, pre.solids);
    problem->useThreading(pre.robotParts, pre.obstacleParts);
  } catch (const planner::ScenarioError& e) {
    return kConsole.fail(kBadInput, e.what());
  }
  // Before the long part: a run whose results cannot be written is not started.
  std::error_code ec;
  std::filesystem::create_directories(scenario.outputDir, ec);
  if (ec || !std::filesystem::is_directory(scenario.outputDir))
    return kConsole.fail(kOutputFailed,
                         "cannot create the output folder " + scenario.outputDir + (ec ? ": " + ec.message() : ""));
  if (pre.openings.empty() && std::find(scenario.samplers.begin(), scenario.samplers.end(), "acd") != scenario.samplers.end())
    std::cerr << "planner: warning: the ACD of the free space has no openings (one component at tau " << scenario.acd.tau
              << "); the acd sampler "
              << (problem->threading() ? "draws threading poses and uniform samples only" : "falls back to uniform samples")
              << "\n";
  if (!quiet && !scenario.robot.solidSummary.empty())
    std::cout << "robot " << scenario.robot.meshPath << ": " << scenario.robot.solidSummary << "\n";
  if (!quiet) planner::printPreprocessing(std::cout, pre, problem->acdSpread());

  const bool tty = !quiet && ::isatty(STDERR_FILENO);
  auto progress = [&](const std::string& name, int done, int total) {
    if (tty) std::cerr << "\r" << name << " " << done << "/" << total << "   " << (done == total ? "\n" : "") << std::flush;
  };
  const auto t0 = acd::Clock::now();
  const auto runs = noFixed ? std::vector<planner::SamplerRuns>{}
                            : planner::runExperiment(*problem, scenario.samplers, scenario.samples, scenario.trials, progress);
  const double seconds = acd::secondsSince(t0);
  const std::filesystem::path dir(scenario.outputDir);

  if (n90) {
    std::vector<planner::N90Search> searches;
    std::vector<planner::SamplerSummary> points;
    for (const std::string& name : scenario.samplers) {
      searches.push_back(planner::searchN90(*problem, name, n90Start, n90Max, n90Trials, pre.totalSeconds(),
                                            [&](const std::string& what) { progress("n90 " + what, 0, n90Trials); }));
      points.insert(points.end(), searches.back().points.begin(), searches.back().points.end());
    }
    planner::printN90Table(std::cout, searches, n90Max);
    planner::writeN90Csv((dir / "n90.csv").string(), searches, n90Trials);
    planner::writeSweepCsv((dir / "n90_points.csv").string(), points);
  }
  if (race) {
    const double timeLimit = scenario.race.timeLimit;
    std::vector<std::string> skipped;
    const std::vector<std::string> all = planner::racePlannerNames(scenario.race.planners, &skipped);
    for (const std::string& name : skipped)
      std::cerr << "planner: the problem file's planner '" << name << "' is not raced (not a plain OMPL geometric planner)\n";
    const std::vector<std::string> only = splitList(args.plannerList);
    for (const std::string& name : only)
      if (std::find(all.begin(), all.end(), name) == all.end())
        return kConsole.fail(appcli::kBadParameter, "--planners: unknown planner '" + name + "'");
    if (tty) std::cerr << "racing " << (only.empty() ? all.size() : only.size()) << " planners (" << scenario.race.runs
                       << " runs of up to " << timeLimit << " s each)\n";
    const auto times = planner::raceOmplPlanners(*problem, pre, timeLimit, scenario.race.runs,
                                                 (dir / "ompl_benchmark.log").string(), only);
    planner::printRaceTable(std::cout, times, timeLimit);
    planner::writeRaceCsv((dir / "race.csv").string(), times);
    planner::writeRaceRunsCsv((dir / "race_runs.csv").string(), times);
  }

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

  if (!noFixed) {
    std::cout << "scenario " << scenario.name << ": " << scenario.samples << " samples, " << scenario.trials
              << " trials per sampler, seed " << scenario.seed << "\n";
    planner::printTable(std::cout, runs);
  }

  std::ofstream(dir / "results.json") << planner::resultsJson(scenario, pre, problem->acdSpread(), runs, sweepResults) << "\n";
  if (!noFixed && !planner::writeBenchmarkLog((dir / "benchmark.log").string(), *problem, runs, seconds))
    std::cerr << "planner: cannot write " << (dir / "benchmark.log").string() << "\n";
  const std::string bestFrom = planner::writeBestPath((dir / "best_path.txt").string(), runs);
  std::vector<std::string> names;
  for (std::size_t i = 0; i < pre.components.size(); ++i) names.push_back("component_" + std::to_string(i));
  acd::writeObjObjects((dir / "free_space_acd.obj").string(), pre.components, names);
  if (!sweepResults.empty()) planner::writeSweepCsv((dir / "sweep.csv").string(), sweepResults);
  std::cout << "wrote " << (dir / "results.json").string() << (noFixed ? "" : ", " + (dir / "benchmark.log").string())
            << (bestFrom.empty() ? "" : ", " + (dir / "best_path.txt").string() + " (from " + bestFrom + ")")
            << (sweepResults.empty() ? "" : ", " + (dir / "sweep.csv").string())
            << (n90 ? ", " + (dir / "n90.csv").string() + ", " + (dir / "n90_points.csv").string() : "")
            << (race ? ", " + (dir / "race.csv").string() + ", " + (dir / "race_runs.csv").string() + ", " +
                           (dir / "ompl_benchmark.log").string()
                     : "")
            << "\n";
  return kOk;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const planner::ScenarioError& e) {
    return kConsole.fail(kBadInput, e.what());
  } catch (const std::exception& e) {
    // OMPL, FCL or the standard library refusing something we did not foresee: a bug to report.
    return kConsole.fail(kInternal, std::string("internal error: ") + e.what());
  }
}
