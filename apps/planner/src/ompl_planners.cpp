#include "ompl_planners.hpp"

#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace planner {

namespace og = ompl::geometric;

double PlannerTimes::seconds90() const {
  std::vector<double> t;
  for (std::size_t i = 0; i < seconds.size(); ++i)
    t.push_back(solvedRuns[i] ? seconds[i] : std::numeric_limits<double>::infinity());
  if (t.empty()) return -1.0;
  std::sort(t.begin(), t.end());
  const double v = t[std::min(t.size() - 1, static_cast<std::size_t>(std::ceil(0.9 * t.size())) - 1)];
  return std::isfinite(v) ? v : -1.0;
}

double PlannerTimes::medianSeconds() const {
  if (seconds.empty()) return 0.0;
  std::vector<double> t = seconds;
  std::sort(t.begin(), t.end());
  return t.size() % 2 ? t[t.size() / 2] : 0.5 * (t[t.size() / 2 - 1] + t[t.size() / 2]);
}

std::vector<PlannerTimes> raceOmplPlanners(PlanningProblem& problem, const Preprocessing& pre, double timeLimit, int runs,
                                           const std::string& logPath) {
  og::SimpleSetup setup(problem.si());
  setup.getProblemDefinition()->setStartAndGoalStates(problem.startState(), problem.goalState());
  ompl::tools::Benchmark benchmark(setup, problem.scenario().name);
  const auto& si = problem.si();
  auto named = [](ompl::base::PlannerPtr p, const std::string& name) {
    p->setName(name);
    return p;
  };
  benchmark.addPlanner(named(std::make_shared<og::PRM>(si), "PRM"));
  benchmark.addPlanner(named(std::make_shared<og::RRTConnect>(si), "RRTConnect"));
  benchmark.addPlanner(named(std::make_shared<og::KPIECE1>(si), "KPIECE1"));
  const bool withAcd = !pre.components.empty();
  if (withAcd) benchmark.addPlanner(named(std::make_shared<og::PRM>(si), "PRM_acd"));
  // Before each run: the planner's sampler, and the run's own seeds (seeding.hpp).
  std::map<std::string, int> runIndex;
  benchmark.setPreRunEvent([&](const ompl::base::PlannerPtr& planner) {
    const std::string& name = planner->getName();
    problem.seeds()->reset(trialSeed(problem.scenario().seed, name, 0, runIndex[name]++));
    problem.useSampler(name == "PRM_acd" ? "acd" : "uniform");
  });
  ompl::tools::Benchmark::Request request(timeLimit, 4096.0, static_cast<unsigned>(runs), 0.05, false, false, false);
  benchmark.benchmark(request);
  if (!logPath.empty()) benchmark.saveResultsToFile(logPath.c_str());
  problem.useSampler("uniform");

  std::vector<PlannerTimes> out;
  for (const auto& experiment : benchmark.getRecordedExperimentData().planners) {
    PlannerTimes t;
    t.planner = experiment.name.rfind("geometric_", 0) == 0 ? experiment.name.substr(10) : experiment.name;
    t.addedSeconds = t.planner == "PRM_acd" ? pre.totalSeconds() : 0.0;
    for (const auto& run : experiment.runs) {
      const auto solved = run.find("solved BOOLEAN");
      const auto time = run.find("time REAL");
      const auto approximate = run.find("approximate solution BOOLEAN");  // KPIECE1 returns its nearest miss
      const bool ok = solved != run.end() && solved->second == "1" && (approximate == run.end() || approximate->second != "1");
      const double seconds = time != run.end() ? std::stod(time->second) : timeLimit;
      t.solvedRuns.push_back(ok);
      t.seconds.push_back((ok ? seconds : timeLimit) + t.addedSeconds);
      t.solved += ok;
      ++t.runs;
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace planner
