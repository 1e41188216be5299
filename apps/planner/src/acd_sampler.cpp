#include "acd_sampler.hpp"

#include "problem.hpp"

#include <algorithm>
#include <cmath>

namespace planner {

AcdValidStateSampler::AcdValidStateSampler(const ompl::base::SpaceInformation* si, const PlanningProblem& problem,
                                           double spread, const AcdSamplerSettings& settings, std::uint32_t seed)
    : ValidStateSampler(si),
      problem_(problem),
      sampler_(si->allocStateSampler()),
      rng_(seed),
      spread_(spread),
      uniformFraction_(settings.uniformFraction),
      alignedFraction_(settings.alignedFraction),
      threadFraction_(settings.threadFraction),
      tilt_(settings.tilt),
      orientationTries_(static_cast<unsigned>(std::max(1, settings.orientationTries))),
      alignment_(problem.alignment()),
      bodyIsReference_(problem.scenario().robot.insidePoints.front().isZero()) {
  name_ = "acd";
  // Narrow openings first: weight 1 / area, with areas below pi spread^2 counted as that much,
  // so that slivers left by the decomposition do not take every sample.
  double totalWeight = 0.0;
  for (const Opening& o : problem.openings()) {
    totalWeight += 1.0 / std::max(o.area, M_PI * spread * spread);
    cumulativeWeight_.push_back(totalWeight);
  }
  for (const Opening& o : problem.openings()) {
    std::vector<double> cumulative;
    double total = 0.0;
    for (int f = 0; f < static_cast<int>(o.triangles.faces.size()); ++f) {
      total += 0.5 * acd::faceNormal(o.triangles, f).norm();
      cumulative.push_back(total);
    }
    cumulativeArea_.push_back(std::move(cumulative));
  }
}

int AcdValidStateSampler::chooseOpening() {
  const double w = rng_.uniformReal(0.0, cumulativeWeight_.back());
  return static_cast<int>(std::min<std::size_t>(
      std::lower_bound(cumulativeWeight_.begin(), cumulativeWeight_.end(), w) - cumulativeWeight_.begin(),
      cumulativeWeight_.size() - 1));
}

acd::Vec3 AcdValidStateSampler::pointNearOpening(int which) {
  const Opening& o = problem_.openings()[which];
  const std::vector<double>& cumulative = cumulativeArea_[which];
  const double r = rng_.uniformReal(0.0, cumulative.back());
  const int f = static_cast<int>(std::min<std::size_t>(
      std::lower_bound(cumulative.begin(), cumulative.end(), r) - cumulative.begin(), cumulative.size() - 1));
  double s = rng_.uniform01(), t = rng_.uniform01();
  if (s + t > 1) s = 1 - s, t = 1 - t;
  const acd::Face& tri = o.triangles.faces[f];
  const acd::Vec3& a = o.triangles.vertices[tri[0]];
  const acd::Vec3& b = o.triangles.vertices[tri[1]];
  const acd::Vec3& c = o.triangles.vertices[tri[2]];
  return a + s * (b - a) + t * (c - a) + rng_.gaussian(0.0, spread_) * o.normal;
}

bool AcdValidStateSampler::candidate(ompl::base::State* state) {
  sampler_->sampleUniform(state);  // uniform orientation (and position, kept for the uniform share)
  const ThreadingPoses* threading = problem_.threading();
  if ((problem_.openings().empty() && !threading) || rng_.uniform01() < uniformFraction_) return false;
  if (threading && (problem_.openings().empty() || rng_.uniform01() < threadFraction_)) {
    const Pose pose = threading->sample(rng_, tilt_);
    problem_.setPose(state, pose.position, pose.orientation);
    return true;
  }
  const int which = chooseOpening();
  if (alignment_ && rng_.uniform01() < alignedFraction_) {
    const Pose pose = alignment_->sample(which, rng_, tilt_, spread_);
    problem_.setPose(state, pose.position, pose.orientation);
    return true;
  }
  problem_.placeBody(state, pointNearOpening(which));
  return false;
}

bool AcdValidStateSampler::sample(ompl::base::State* state) {
  ompl::base::State* turned = si_->allocState();
  bool found = false;
  for (unsigned attempt = 0; attempt < attempts_ && !found; ++attempt) {
    const bool aligned = candidate(state);
    // Where the robot's body point is blocked no orientation helps: next position.
    const acd::Vec3 body = problem_.bodyPoint(state);
    if (!problem_.world().pointFree(body)) continue;
    // Out of bounds: turning helps only when the reference point is not the body point.
    if (!si_->satisfiesBounds(state) && (aligned || bodyIsReference_)) continue;
    if (si_->isValid(state)) {
      found = true;
      break;
    }
    if (aligned) continue;  // its orientation is the point of it: a new candidate, not random turns
    // Keep the position and turn the robot: in a passage few orientations fit, and without
    // this the valid states would gather where every orientation fits, away from the passage.
    for (unsigned turn = 1; turn < orientationTries_ && !found; ++turn) {
      sampler_->sampleUniform(turned);
      problem_.placeBody(turned, body);
      if (si_->isValid(turned)) {
        si_->copyState(state, turned);
        found = true;
      }
    }
  }
  si_->freeState(turned);
  return found;
}

bool AcdValidStateSampler::sampleNear(ompl::base::State* state, const ompl::base::State* near, double distance) {
  for (unsigned attempt = 0; attempt < attempts_; ++attempt) {
    sampler_->sampleUniformNear(state, near, distance);
    if (si_->isValid(state)) return true;
  }
  return false;
}

}  // namespace planner
