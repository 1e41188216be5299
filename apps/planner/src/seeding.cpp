#include "seeding.hpp"

#include <acd/algo/random.hpp>

#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>
#include <ompl/base/spaces/SO2StateSpace.h>
#include <ompl/base/spaces/SO3StateSpace.h>

#include <string>

namespace planner {

std::uint32_t SeedSource::next() {
  const std::uint64_t z = acd::mix64(base_ ^ acd::mix64(++counter_));
  return static_cast<std::uint32_t>(z >> 32) | 1u;  // OMPL ignores a zero seed
}

namespace {

/// One of OMPL's state samplers with its RNG reseeded at construction.
template <class Base>
class Seeded : public Base {
 public:
  Seeded(const ompl::base::StateSpace* space, std::uint32_t seed) : Base(space) { this->rng_.setLocalSeed(seed); }
};

template <class Sampler>
void install(ompl::base::StateSpace* space, const std::shared_ptr<SeedSource>& seeds) {
  space->setStateSamplerAllocator([seeds](const ompl::base::StateSpace* s) -> ompl::base::StateSamplerPtr {
    return std::make_shared<Seeded<Sampler>>(s, seeds->next());
  });
}

}  // namespace

void installSeededSamplers(const ompl::base::StateSpacePtr& space, const std::shared_ptr<SeedSource>& seeds) {
  namespace ob = ompl::base;
  if (auto* rv = dynamic_cast<ob::RealVectorStateSpace*>(space.get())) {
    install<ob::RealVectorStateSampler>(rv, seeds);
  } else if (auto* se3 = dynamic_cast<ob::SE3StateSpace*>(space.get())) {
    install<ob::RealVectorStateSampler>(se3->getSubspace(0).get(), seeds);
    install<ob::SO3StateSampler>(se3->getSubspace(1).get(), seeds);
  } else if (auto* se2 = dynamic_cast<ob::SE2StateSpace*>(space.get())) {
    install<ob::RealVectorStateSampler>(se2->getSubspace(0).get(), seeds);
    install<ob::SO2StateSampler>(se2->getSubspace(1).get(), seeds);
  }
}

std::uint64_t trialSeed(unsigned seed, const std::string& sampler, int samples, int trial) {
  std::uint64_t h = acd::mix64(seed);
  for (char c : sampler) h = acd::mix64(h ^ static_cast<unsigned char>(c));
  h = acd::mix64(h ^ static_cast<std::uint64_t>(samples));
  return acd::mix64(h ^ static_cast<std::uint64_t>(trial));
}

}  // namespace planner
