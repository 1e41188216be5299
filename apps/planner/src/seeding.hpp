// Deterministic trials under OMPL: every random stream of a trial is seeded from the trial's
// seed and a counter, so a trial's outcome depends on (scenario seed, sampler, trial index)
// only, not on which trials ran before it. OMPL's global RNG::setSeed works once per process;
// instead the state samplers of the space are allocated here with local seeds.
#pragma once

#include <ompl/base/StateSpace.h>

#include <cstdint>
#include <memory>

namespace planner {

/// Hands out the seeds of one trial: (trial seed, counter) mixed. Reset before each trial.
class SeedSource {
 public:
  void reset(std::uint64_t trialSeed) {
    base_ = trialSeed;
    counter_ = 0;
  }
  std::uint32_t next();

 private:
  std::uint64_t base_ = 1;
  std::uint64_t counter_ = 0;
};

/// Makes every state sampler of `space` (and of its components, for SE(2) and SE(3)) draw
/// its RNG seed from `seeds`.
void installSeededSamplers(const ompl::base::StateSpacePtr& space, const std::shared_ptr<SeedSource>& seeds);

/// Seed of trial `trial` of sampler `sampler` at `samples` milestones under scenario seed `seed`.
std::uint64_t trialSeed(unsigned seed, const std::string& sampler, int samples, int trial);

}  // namespace planner
