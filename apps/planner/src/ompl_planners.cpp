#include "ompl_planners.hpp"

#include "fixed_prm.hpp"

#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/fmt/FMT.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/kpiece/LBKPIECE1.h>
#include <ompl/geometric/planners/pdst/PDST.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/prm/SPARS.h>
#include <ompl/geometric/planners/prm/SPARStwo.h>
#include <ompl/geometric/planners/rrt/LBTRRT.h>
#include <ompl/geometric/planners/rrt/LazyRRT.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/rrt/TRRT.h>
#include <ompl/geometric/planners/sbl/SBL.h>
#include <ompl/geometric/planners/stride/STRIDE.h>
#include <ompl/tools/benchmark/Benchmark.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

namespace planner {

namespace og = ompl::geometric;
namespace ob = ompl::base;

namespace {

using Allocator = std::function<ob::PlannerPtr(const ob::SpaceInformationPtr&)>;

template <class P>
Allocator make() {
  return [](const ob::SpaceInformationPtr& si) -> ob::PlannerPtr { return std::make_shared<P>(si); };
}

/// OMPL.app's [planner] keys and the OMPL planners they make (its benchmark's table). aps
/// (anytime path shortening) and the Syclop planners need more than a problem file gives.
const std::map<std::string, std::pair<std::string, Allocator>>& plannersByKey() {
  static const std::map<std::string, std::pair<std::string, Allocator>> table{
      {"rrtconnect", {"RRTConnect", make<og::RRTConnect>()}}, {"lazyrrt", {"LazyRRT", make<og::LazyRRT>()}},
      {"lazyprm", {"LazyPRM", make<og::LazyPRM>()}},          {"kpiece", {"KPIECE1", make<og::KPIECE1>()}},
      {"bkpiece", {"BKPIECE1", make<og::BKPIECE1>()}},        {"lbkpiece", {"LBKPIECE1", make<og::LBKPIECE1>()}},
      {"est", {"EST", make<og::EST>()}},                      {"sbl", {"SBL", make<og::SBL>()}},
      {"prm", {"PRM", make<og::PRM>()}},                      {"rrt", {"RRT", make<og::RRT>()}},
      {"stride", {"STRIDE", make<og::STRIDE>()}},             {"pdst", {"PDST", make<og::PDST>()}},
      {"rrtstar", {"RRTstar", make<og::RRTstar>()}},          {"prmstar", {"PRMstar", make<og::PRMstar>()}},
      {"lazyprmstar", {"LazyPRMstar", make<og::LazyPRMstar>()}}, {"spars", {"SPARS", make<og::SPARS>()}},
      {"spars2", {"SPARStwo", make<og::SPARStwo>()}},         {"lbtrrt", {"LBTRRT", make<og::LBTRRT>()}},
      {"trrt", {"TRRT", make<og::TRRT>()}},                   {"fmt", {"FMT", make<og::FMT>()}}};
  return table;
}

/// The standard set: PRM per sampler ("PRM" is OMPL's own, uniform), then OMPL's planners.
const std::vector<std::pair<std::string, std::string>>& standardSet() {  // (race name, sampler or key)
  static const std::vector<std::pair<std::string, std::string>> set{
      {"PRM_acd", "acd"},           {"PRM", "uniform"},     {"PRM_gaussian", "gaussian"},
      {"PRM_obstacle_based", "obstacle_based"}, {"PRM_bridge_test", "bridge_test"},
      {"PRM_max_clearance", "max_clearance"},   {"RRTConnect", "rrtconnect"}, {"KPIECE1", "kpiece"},
      {"BKPIECE1", "bkpiece"},      {"EST", "est"},          {"SBL", "sbl"}};
  return set;
}

struct RacePlanner {
  std::string name;
  std::string sampler;          // PRM's valid-state sampler; "uniform" for the others
  std::string key;              // plannersByKey; empty: PRM
  std::vector<std::pair<std::string, std::string>> params;
};

std::vector<RacePlanner> racePlanners(const std::vector<PlannerEntry>& listed, std::vector<std::string>* skipped) {
  std::vector<RacePlanner> out;
  for (const auto& [name, what] : standardSet()) {
    if (name.rfind("PRM", 0) == 0)
      out.push_back({name, what, "", {}});
    else
      out.push_back({name, "uniform", what, {}});
  }
  int k = 0;
  for (const PlannerEntry& e : listed) {
    ++k;
    const auto it = plannersByKey().find(e.name);
    if (it == plannersByKey().end()) {
      if (skipped) skipped->push_back(e.name);
      continue;
    }
    // A listed planner without parameters that the standard set already runs is that run.
    const bool standard = std::any_of(standardSet().begin(), standardSet().end(), [&](const auto& s) {
      return s.second == e.name || (e.name == "prm" && s.first == "PRM");
    });
    if (standard && e.params.empty()) continue;
    out.push_back({it->second.first + "_cfg" + std::to_string(k), "uniform", e.name, e.params});
  }
  return out;
}

}  // namespace

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

std::vector<std::string> racePlannerNames(const std::vector<PlannerEntry>& listed, std::vector<std::string>* skipped) {
  std::vector<std::string> names;
  for (const RacePlanner& p : racePlanners(listed, skipped)) names.push_back(p.name);
  return names;
}

std::vector<PlannerTimes> raceOmplPlanners(PlanningProblem& problem, const Preprocessing& pre, double timeLimit, int runs,
                                           const std::string& logPath, const std::vector<std::string>& only) {
  og::SimpleSetup setup(problem.si());
  setup.getProblemDefinition()->setStartAndGoalStates(problem.startState(), problem.goalState());
  ompl::tools::Benchmark benchmark(setup, problem.scenario().name);
  const auto& si = problem.si();
  const bool withAcd = !pre.components.empty();
  std::map<std::string, std::string> samplerOf;
  for (const RacePlanner& rp : racePlanners(problem.scenario().race.planners, nullptr)) {
    if (!only.empty() && std::find(only.begin(), only.end(), rp.name) == only.end()) continue;
    if (rp.sampler == "acd" && !withAcd) continue;
    ob::PlannerPtr p = rp.key.empty() ? std::make_shared<KavrakiPRM>(si) : plannersByKey().at(rp.key).second(si);
    for (const auto& [param, value] : rp.params) p->params().setParam(param, value);
    p->setName(rp.name);
    samplerOf[rp.name] = rp.sampler;
    benchmark.addPlanner(p);
  }
  // Before each run: the planner's sampler, and the run's own seeds (seeding.hpp).
  std::map<std::string, int> runIndex;
  benchmark.setPreRunEvent([&](const ob::PlannerPtr& planner) {
    const std::string& name = planner->getName();
    problem.seeds()->reset(trialSeed(problem.scenario().seed, name, 0, runIndex[name]++));
    problem.useSampler(samplerOf[name]);
  });
  // The acd sampler's preprocessing (free space, its ACD, the openings) is part of its time.
  const double added = pre.totalSeconds();
  // A run solved only after the limit, preprocessing included, did not solve within it.
  benchmark.setPostRunEvent([&](const ob::PlannerPtr& planner, ompl::tools::Benchmark::RunProperties& run) {
    if (samplerOf[planner->getName()] != "acd") return;
    const auto time = run.find("time REAL");
    if (time == run.end()) return;
    const double total = std::stod(time->second) + added;
    time->second = std::to_string(total);
    if (total > timeLimit) run["solved BOOLEAN"] = "0";
  });
  ompl::tools::Benchmark::Request request(timeLimit, 4096.0, static_cast<unsigned>(runs), 0.05, false, false, false);
  benchmark.benchmark(request);
  if (!logPath.empty()) benchmark.saveResultsToFile(logPath.c_str());
  problem.useSampler("uniform");

  std::vector<PlannerTimes> out;
  for (const auto& experiment : benchmark.getRecordedExperimentData().planners) {
    PlannerTimes t;
    t.planner = experiment.name.rfind("geometric_", 0) == 0 ? experiment.name.substr(10) : experiment.name;
    t.addedSeconds = samplerOf[t.planner] == "acd" ? added : 0.0;
    for (const auto& run : experiment.runs) {
      const auto solved = run.find("solved BOOLEAN");
      const auto time = run.find("time REAL");
      const auto approximate = run.find("approximate solution BOOLEAN");  // KPIECE1 returns its nearest miss
      const bool ok = solved != run.end() && solved->second == "1" && (approximate == run.end() || approximate->second != "1");
      const double seconds = time != run.end() ? std::stod(time->second) : timeLimit;  // includes `added`
      t.solvedRuns.push_back(ok);
      t.seconds.push_back(ok ? seconds : timeLimit);
      t.solved += ok;
      ++t.runs;
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace planner
