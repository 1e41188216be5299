#include "problem.hpp"

#include "acd_sampler.hpp"

#include <ompl/base/DiscreteMotionValidator.h>
#include <ompl/base/samplers/BridgeTestValidStateSampler.h>
#include <ompl/base/samplers/GaussianValidStateSampler.h>
#include <ompl/base/samplers/MaximizeClearanceValidStateSampler.h>
#include <ompl/base/samplers/ObstacleBasedValidStateSampler.h>
#include <ompl/base/samplers/UniformValidStateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include <cstdio>

namespace planner {

namespace ob = ompl::base;

namespace {

class WorldValidityChecker : public ob::StateValidityChecker {
 public:
  WorldValidityChecker(const ob::SpaceInformationPtr& si, const PlanningProblem& problem)
      : StateValidityChecker(si), problem_(problem) {
    specs_.clearanceComputationType = ob::StateValidityCheckerSpecs::EXACT;  // for the maximum-clearance sampler
  }
  bool isValid(const ob::State* state) const override {
    if (!si_->satisfiesBounds(state)) return false;
    return problem_.world().valid(problem_.position(state), problem_.orientation(state));
  }
  double clearance(const ob::State* state) const override {
    return problem_.world().clearance(problem_.position(state), problem_.orientation(state));
  }

 private:
  const PlanningProblem& problem_;
};

}  // namespace

PlanningProblem::PlanningProblem(const Scenario& scenario, const acd::TriMesh& freeSpace, std::vector<Opening> openings,
                                 std::vector<NamedSolid> solids)
    : scenario_(scenario), openings_(std::move(openings)), seeds_(std::make_shared<SeedSource>()) {
  if (scenario.freeSpaceGiven || scenario.obstacles.empty())
    world_ = std::make_unique<CollisionWorld>(freeSpace, scenario.robot, scenario.validity);
  else
    world_ = std::make_unique<CollisionWorld>(freeSpace, scenario.obstacles, std::move(solids), scenario.workspace,
                                              scenario.robot, scenario.validity);
  // The reference point's bounds (OMPL.app's volume); the workspace when none are given.
  const bool hasBounds = ((scenario.bounds.hi - scenario.bounds.lo).array() > 0).all();
  const acd::Box3& ws = hasBounds ? scenario.bounds : scenario.workspace;
  const Robot& robot = scenario.robot;
  if (robot.planar) {
    auto se2 = std::make_shared<ob::SE2StateSpace>();
    ob::RealVectorBounds bounds(2);
    for (int i = 0; i < 2; ++i) bounds.setLow(i, ws.lo[i]), bounds.setHigh(i, ws.hi[i]);
    se2->setBounds(bounds);
    space_ = se2;
    planeZ_ = scenario.start.position.z();
  } else if (robot.kind == RobotKind::Point || robot.kind == RobotKind::Sphere) {
    auto r3 = std::make_shared<ob::RealVectorStateSpace>(3);
    ob::RealVectorBounds bounds(3);
    for (int i = 0; i < 3; ++i) bounds.setLow(i, ws.lo[i]), bounds.setHigh(i, ws.hi[i]);
    r3->setBounds(bounds);
    space_ = r3;
  } else {
    auto se3 = std::make_shared<ob::SE3StateSpace>();
    ob::RealVectorBounds bounds(3);
    for (int i = 0; i < 3; ++i) bounds.setLow(i, ws.lo[i]), bounds.setHigh(i, ws.hi[i]);
    se3->setBounds(bounds);
    space_ = se3;
  }
  installSeededSamplers(space_, seeds_);
  si_ = std::make_shared<ob::SpaceInformation>(space_);
  si_->setStateValidityChecker(std::make_shared<WorldValidityChecker>(si_, *this));
  si_->setStateValidityCheckingResolution(scenario.prm.resolution);
  si_->setup();
  // Default spread: half the robot's reach from its reference point, so that most samples put
  // the robot across the opening; a point robot has no reach, so half the largest opening's radius.
  double reach = robot.boundingRadius();
  if (reach <= 0)
    for (const Opening& o : openings_) reach = std::max(reach, o.radius);
  spread_ = scenario.acd.spread > 0 ? scenario.acd.spread : std::max(0.5 * reach, 1e-6 * scenario.workspace.size().norm());

  if ((robot.kind == RobotKind::Box || robot.kind == RobotKind::Mesh) && !openings_.empty())
    alignment_ = std::make_unique<OpeningAlignment>(robot, openings_, robot.planar);

  start_ = si_->allocState();
  goal_ = si_->allocState();
  setPose(start_, scenario.start.position, scenario.start.orientation);
  setPose(goal_, scenario.goal.position, scenario.goal.orientation);
  refuseInvalid("start", scenario.start);
  refuseInvalid("goal", scenario.goal);
}

void PlanningProblem::useThreading(const BodyParts& robot, const BodyParts& obstacles) {
  threading_ = std::make_unique<ThreadingPoses>(robot, obstacles);
  if (threading_->threadings().empty()) threading_.reset();
}

void PlanningProblem::refuseInvalid(const std::string& which, const Pose& pose) const {
  ob::State* state = which == "start" ? start_ : goal_;
  if (si_->isValid(state)) return;
  std::string why;
  if (!si_->satisfiesBounds(state)) {
    const acd::Box3& b = ((scenario_.bounds.hi - scenario_.bounds.lo).array() > 0).all() ? scenario_.bounds : scenario_.workspace;
    char buf[256];
    std::snprintf(buf, sizeof buf, "its reference point (%.6g, %.6g, %.6g) is outside the volume [%.6g, %.6g] x [%.6g, %.6g] x [%.6g, %.6g]",
                  pose.position.x(), pose.position.y(), pose.position.z(), b.lo.x(), b.hi.x(), b.lo.y(), b.hi.y(),
                  b.lo.z(), b.hi.z());
    why = buf;
  } else {
    why = world_->whyInvalid(position(state), orientation(state));
    if (why.empty()) why = "not valid";
  }
  throw ScenarioError(scenario_.path + ": the " + which + " pose is not valid: " + why);
}

PlanningProblem::~PlanningProblem() {
  if (si_) {
    if (start_) si_->freeState(start_);
    if (goal_) si_->freeState(goal_);
  }
}

void PlanningProblem::setPose(ob::State* state, const acd::Vec3& p, const Eigen::Quaterniond& q) const {
  if (auto* se3 = dynamic_cast<ob::SE3StateSpace*>(space_.get())) {
    (void)se3;
    auto* s = state->as<ob::SE3StateSpace::StateType>();
    s->setXYZ(p.x(), p.y(), p.z());
    s->rotation().w = q.w(), s->rotation().x = q.x(), s->rotation().y = q.y(), s->rotation().z = q.z();
  } else if (dynamic_cast<ob::SE2StateSpace*>(space_.get())) {
    auto* s = state->as<ob::SE2StateSpace::StateType>();
    s->setX(p.x()), s->setY(p.y());
    const acd::Vec3 x = q * acd::Vec3::UnitX();
    s->setYaw(std::atan2(x.y(), x.x()));
  } else {
    auto* s = state->as<ob::RealVectorStateSpace::StateType>();
    for (int i = 0; i < 3; ++i) s->values[i] = p[i];
  }
}

void PlanningProblem::setPosition(ob::State* state, const acd::Vec3& p) const {
  if (dynamic_cast<ob::SE3StateSpace*>(space_.get())) {
    state->as<ob::SE3StateSpace::StateType>()->setXYZ(p.x(), p.y(), p.z());
  } else if (dynamic_cast<ob::SE2StateSpace*>(space_.get())) {
    auto* s = state->as<ob::SE2StateSpace::StateType>();
    s->setX(p.x()), s->setY(p.y());
  } else {
    auto* s = state->as<ob::RealVectorStateSpace::StateType>();
    for (int i = 0; i < 3; ++i) s->values[i] = p[i];
  }
}

acd::Vec3 PlanningProblem::bodyPoint(const ob::State* state) const {
  return position(state) + orientation(state) * scenario_.robot.insidePoints.front();
}

void PlanningProblem::placeBody(ob::State* state, const acd::Vec3& p) const {
  setPosition(state, p - orientation(state) * scenario_.robot.insidePoints.front());
}

acd::Vec3 PlanningProblem::position(const ob::State* state) const {
  if (dynamic_cast<ob::SE3StateSpace*>(space_.get())) {
    const auto* s = state->as<ob::SE3StateSpace::StateType>();
    return {s->getX(), s->getY(), s->getZ()};
  }
  if (dynamic_cast<ob::SE2StateSpace*>(space_.get())) {
    const auto* s = state->as<ob::SE2StateSpace::StateType>();
    return {s->getX(), s->getY(), planeZ_};
  }
  const auto* s = state->as<ob::RealVectorStateSpace::StateType>();
  return {s->values[0], s->values[1], s->values[2]};
}

Eigen::Quaterniond PlanningProblem::orientation(const ob::State* state) const {
  if (dynamic_cast<ob::SE3StateSpace*>(space_.get())) {
    const auto& r = state->as<ob::SE3StateSpace::StateType>()->rotation();
    return Eigen::Quaterniond(r.w, r.x, r.y, r.z);
  }
  if (dynamic_cast<ob::SE2StateSpace*>(space_.get()))
    return Eigen::Quaterniond(Eigen::AngleAxisd(state->as<ob::SE2StateSpace::StateType>()->getYaw(), acd::Vec3::UnitZ()));
  return Eigen::Quaterniond::Identity();
}

void PlanningProblem::useSampler(const std::string& name) {
  const PlanningProblem* self = this;
  const std::shared_ptr<SeedSource> seeds = seeds_;
  if (name == "uniform") {
    si_->setValidStateSamplerAllocator([](const ob::SpaceInformation* si) -> ob::ValidStateSamplerPtr {
      return std::make_shared<ob::UniformValidStateSampler>(si);
    });
  } else if (name == "gaussian") {
    si_->setValidStateSamplerAllocator([](const ob::SpaceInformation* si) -> ob::ValidStateSamplerPtr {
      return std::make_shared<ob::GaussianValidStateSampler>(si);
    });
  } else if (name == "obstacle_based") {
    si_->setValidStateSamplerAllocator([](const ob::SpaceInformation* si) -> ob::ValidStateSamplerPtr {
      return std::make_shared<ob::ObstacleBasedValidStateSampler>(si);
    });
  } else if (name == "bridge_test") {
    si_->setValidStateSamplerAllocator([](const ob::SpaceInformation* si) -> ob::ValidStateSamplerPtr {
      return std::make_shared<ob::BridgeTestValidStateSampler>(si);
    });
  } else if (name == "max_clearance") {
    si_->setValidStateSamplerAllocator([](const ob::SpaceInformation* si) -> ob::ValidStateSamplerPtr {
      return std::make_shared<ob::MaximizeClearanceValidStateSampler>(si);
    });
  } else if (name == "acd") {
    const double spread = spread_;
    const AcdSamplerSettings settings = scenario_.acd;
    si_->setValidStateSamplerAllocator([self, seeds, spread, settings](const ob::SpaceInformation* si) -> ob::ValidStateSamplerPtr {
      return std::make_shared<AcdValidStateSampler>(si, *self, spread, settings, seeds->next());
    });
  } else {
    throw ScenarioError("unknown sampler '" + name + "'");
  }
  si_->setup();  // a new allocator marks the space information as not set up
}

}  // namespace planner
