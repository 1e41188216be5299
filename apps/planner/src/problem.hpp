// One planning problem in OMPL terms: the state space of the robot (R^3 for a point or a
// sphere, SE(3) for a rigid body, SE(2) for a planar one), the validity checker on top of
// CollisionWorld, discrete motion checking, and the samplers by name.
#pragma once

#include "aligned_poses.hpp"
#include "collision_world.hpp"
#include "openings.hpp"
#include "scenario.hpp"
#include "seeding.hpp"
#include "threading_poses.hpp"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/ValidStateSampler.h>

#include <memory>
#include <string>
#include <vector>

namespace planner {

class PlanningProblem {
 public:
  /// `solids`: what the free space was cut from, named (for the messages only).
  /// \throw ScenarioError when the start or the goal is not valid, saying why (CollisionWorld::whyInvalid).
  PlanningProblem(const Scenario& scenario, const acd::TriMesh& freeSpace, std::vector<Opening> openings,
                  std::vector<NamedSolid> solids = {});

  const ompl::base::SpaceInformationPtr& si() const { return si_; }
  const std::shared_ptr<SeedSource>& seeds() const { return seeds_; }
  const CollisionWorld& world() const { return *world_; }
  const std::vector<Opening>& openings() const { return openings_; }
  const Scenario& scenario() const { return scenario_; }

  /// Pose <-> state, whatever the space.
  void setPose(ompl::base::State* state, const acd::Vec3& position, const Eigen::Quaterniond& orientation) const;
  void setPosition(ompl::base::State* state, const acd::Vec3& position) const;
  acd::Vec3 position(const ompl::base::State* state) const;
  /// The robot's body point (its first inside point, Robot::insidePoints) in the world, and
  /// the position that puts it at p with the state's orientation kept.
  acd::Vec3 bodyPoint(const ompl::base::State* state) const;
  void placeBody(ompl::base::State* state, const acd::Vec3& p) const;
  Eigen::Quaterniond orientation(const ompl::base::State* state) const;

  ompl::base::State* startState() const { return start_; }
  ompl::base::State* goalState() const { return goal_; }

  /// Installs the named valid-state sampler ("uniform", "acd", "gaussian", "obstacle_based",
  /// "bridge_test") on the space information; samplers allocated later use it.
  void useSampler(const std::string& name);

  /// Poses aligned to the openings; null for a robot that does not turn (a point or a sphere).
  const OpeningAlignment* alignment() const { return alignment_.get(); }

  /// Poses that thread a part of the robot through a gap of the obstacles or the reverse;
  /// null when there are none (useThreading not called, or no part fits a gap).
  const ThreadingPoses* threading() const { return threading_.get(); }
  void useThreading(const BodyParts& robot, const BodyParts& obstacles);

  /// Std. deviation of the ACD sampler across the openings (length units), as resolved.
  double acdSpread() const { return spread_; }

  ~PlanningProblem();

 private:
  void refuseInvalid(const std::string& which, const Pose& pose) const;
  const Scenario& scenario_;
  std::vector<Opening> openings_;
  std::unique_ptr<CollisionWorld> world_;
  std::unique_ptr<OpeningAlignment> alignment_;
  std::unique_ptr<ThreadingPoses> threading_;
  ompl::base::StateSpacePtr space_;
  ompl::base::SpaceInformationPtr si_;
  std::shared_ptr<SeedSource> seeds_;
  ompl::base::State* start_ = nullptr;
  ompl::base::State* goal_ = nullptr;
  double planeZ_ = 0.0;   // SE(2): the height the robot moves at
  double spread_ = 0.0;
};

}  // namespace planner
