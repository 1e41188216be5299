// PRM grown with exactly N sampled milestones. OMPL's PRM::solve() also adds states from
// expandRoadmap() that bypass the valid-state sampler, and stops on time; the paper's
// experiment counts samples, so the roadmap is grown here one sampled milestone at a time.
#pragma once

#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/prm/PRM.h>

#include <memory>

namespace planner {

struct RoadmapOutcome {
  bool connected = false;        // start and goal in one roadmap component
  int milestones = 0;            // sampled milestones added (start and goal not counted)
  int edges = 0;
  long samplerFailures = 0;      // sample() calls that found no valid state within their attempts
  bool exhausted = false;        // gave up before N milestones (see maxFailures)
  double pathLength = 0.0;       // shortest roadmap path, when connected
  std::shared_ptr<ompl::geometric::PathGeometric> path;
};

/// PRM as Kavraki et al. (1996) grow it: no motion check between milestones already in one
/// component. Which milestones end up connected is the same as with every connection (OMPL's
/// PRM checks every neighbour, to shorten paths later); the first solution comes sooner. The
/// race's PRM for every sampler (ompl_planners.hpp).
class KavrakiPRM : public ompl::geometric::PRM {
 public:
  explicit KavrakiPRM(const ompl::base::SpaceInformationPtr& si);
};

class FixedSamplePRM : public KavrakiPRM {
 public:
  /// `neighbors`: k of the k-nearest connection strategy. Nearest neighbours by linear scan
  /// (exact and deterministic at these sizes). Pairs already in one component are not
  /// connected again (Kavraki et al. 1996): connectivity is unchanged, the roadmap is sparser.
  FixedSamplePRM(const ompl::base::SpaceInformationPtr& si, unsigned neighbors);

  /// Adds start and goal, then N milestones from the space information's valid-state
  /// sampler, each connected to its k nearest milestones by checked straight motions. Stops
  /// early after `maxFailures` failed sample() calls in a row.
  RoadmapOutcome grow(const ompl::base::State* start, const ompl::base::State* goal, int samples,
                      long maxFailures = 1000);
};

}  // namespace planner
