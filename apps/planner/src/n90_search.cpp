#include "n90_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace planner {

namespace {

constexpr double kTarget = 0.9;

/// The 90th percentile of the trials' roadmap times, a failed trial counting as endless.
double percentile90(const SamplerRuns& runs) {
  std::vector<double> t;
  for (const Trial& trial : runs.trials)
    t.push_back(trial.outcome.connected ? trial.seconds : std::numeric_limits<double>::infinity());
  std::sort(t.begin(), t.end());
  const std::size_t k = static_cast<std::size_t>(std::ceil(kTarget * t.size())) - 1;
  return t.empty() ? 0.0 : t[std::min(k, t.size() - 1)];
}

}  // namespace

N90Search searchN90(PlanningProblem& problem, const std::string& sampler, int startN, int maxN, int trials,
                    double preprocessingSeconds, const std::function<void(const std::string&)>& progress) {
  N90Search out;
  out.sampler = sampler;
  out.preprocessingSeconds = sampler == "acd" ? preprocessingSeconds : 0.0;
  auto evaluate = [&](int n) {
    if (progress) progress(sampler + " n=" + std::to_string(n));
    SamplerRuns runs = std::move(runExperiment(problem, {sampler}, n, trials).front());
    out.points.push_back(runs.summary);
    return runs;
  };
  int below = 0, above = -1;
  SamplerRuns best;
  // Doubling, the last step clamped to maxN so that maxN itself is always tried.
  for (int n = std::max(1, std::min(startN, maxN));; n = std::min(2 * n, maxN)) {
    SamplerRuns runs = evaluate(n);
    if (runs.summary.rate >= kTarget) {
      above = n;
      best = std::move(runs);
      break;
    }
    below = n;
    if (n == maxN) break;
  }
  if (above < 0) return out;
  while (above - below > std::max(1, above / 10)) {
    const int mid = below + (above - below) / 2;
    SamplerRuns runs = evaluate(mid);
    if (runs.summary.rate >= kTarget) {
      above = mid;
      best = std::move(runs);
    } else {
      below = mid;
    }
  }
  out.n90 = above;
  out.rate = best.summary.rate;
  out.trialSeconds90 = percentile90(best);
  return out;
}

}  // namespace planner
