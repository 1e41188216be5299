#include "fixed_prm.hpp"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/datastructures/NearestNeighborsLinear.h>

namespace planner {

KavrakiPRM::KavrakiPRM(const ompl::base::SpaceInformationPtr& si) : PRM(si) {
  // Runs inside addMilestone, under the graph's lock, as PRM's own solution check does.
  setConnectionFilter([this](const Vertex& a, const Vertex& b) { return !sameComponent(a, b); });
}

FixedSamplePRM::FixedSamplePRM(const ompl::base::SpaceInformationPtr& si, unsigned neighbors) : KavrakiPRM(si) {
  setNearestNeighbors<ompl::NearestNeighborsLinear>();
  setMaxNearestNeighbors(neighbors);
}

RoadmapOutcome FixedSamplePRM::grow(const ompl::base::State* start, const ompl::base::State* goal, int samples,
                                    long maxFailures) {
  RoadmapOutcome out;
  // PRM's setup needs a problem definition for its path-length objective (edge weights).
  auto pdef = std::make_shared<ompl::base::ProblemDefinition>(si_);
  pdef->setStartAndGoalStates(start, goal);
  setProblemDefinition(pdef);
  setup();
  // PRM::setup() sets the distance only on a structure it made itself.
  nn_->setDistanceFunction([this](const Vertex a, const Vertex b) { return distanceFunction(a, b); });
  sampler_ = si_->allocValidStateSampler();
  const Vertex s = addMilestone(si_->cloneState(start));
  const Vertex g = addMilestone(si_->cloneState(goal));
  ompl::base::State* work = si_->allocState();
  long failuresInRow = 0;
  while (out.milestones < samples) {
    if (sampler_->sample(work)) {
      addMilestone(si_->cloneState(work));
      ++out.milestones;
      failuresInRow = 0;
    } else {
      ++out.samplerFailures;
      if (++failuresInRow >= maxFailures) {
        out.exhausted = true;
        break;
      }
    }
  }
  si_->freeState(work);
  out.edges = static_cast<int>(boost::num_edges(g_));
  out.connected = sameComponent(s, g);
  if (out.connected) {
    auto path = std::dynamic_pointer_cast<ompl::geometric::PathGeometric>(constructSolution(s, g));
    if (path) {
      out.path = path;
      out.pathLength = path->length();
    }
  }
  return out;
}

}  // namespace planner
