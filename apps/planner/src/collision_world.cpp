#include "collision_world.hpp"

#include "fcl_bvh.hpp"

#include <acd/algo/shapes.hpp>

#include <fcl/fcl.h>

#include <algorithm>
#include <cstdio>

namespace planner {

struct CollisionWorld::Fcl {
  std::shared_ptr<fcl::CollisionGeometryd> environment;
  std::shared_ptr<fcl::CollisionGeometryd> robot;
  std::unique_ptr<fcl::CollisionObjectd> envObject, robotObject;
};

namespace {

std::string point(const acd::Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return buf;
}

}  // namespace

CollisionWorld::CollisionWorld(const acd::TriMesh& freeSpace, const Robot& robot, Validity validity)
    : robot_(robot),
      usesFreeSpace_(validity == Validity::FreeSpace || robot.kind == RobotKind::Point),
      freeInside_(freeSpace),
      fcl_(std::make_unique<Fcl>()) {
  // Shells with negative volume bound cavities of the free space: obstacles floating in it.
  for (const acd::TriMesh& shell : acd::splitEdgeConnected(freeSpace))
    if (acd::signedVolume(shell) < 0) islandProbes_.push_back(shell.vertices.front());
  workspace_ = acd::boundingBox(freeSpace);
  names_ = {"the free space's boundary"};
  firstTriangle_ = {0};
  setUpFcl(freeSpace);
}

CollisionWorld::CollisionWorld(const acd::TriMesh& freeSpace, const std::vector<Obstacle>& obstacles,
                               std::vector<NamedSolid> solids, const acd::Box3& workspace, const Robot& robot,
                               Validity validity)
    : robot_(robot),
      usesFreeSpace_(validity == Validity::FreeSpace || robot.kind == RobotKind::Point),
      freeInside_(freeSpace),
      solids_(std::move(solids)),
      fcl_(std::make_unique<Fcl>()) {
  std::vector<acd::TriMesh> parts;
  int faces = 0;
  for (const Obstacle& o : obstacles) {
    parts.push_back(o.triangles);
    names_.push_back(o.name);
    firstTriangle_.push_back(faces);
    faces += static_cast<int>(o.triangles.faces.size());
  }
  islandProbes_ = pieceProbes(acd::concatenate(parts));
  workspace_ = workspace;
  parts.push_back(acd::shapes::box(workspace.lo, workspace.hi));
  names_.push_back("the workspace's walls");
  firstTriangle_.push_back(faces);
  setUpFcl(acd::concatenate(parts));
}

void CollisionWorld::setUpFcl(const acd::TriMesh& environment) {
  const Robot& robot = robot_;
  reach_ = robot.boundingRadius();
  fcl_->environment = bvhOf(environment);
  switch (robot.kind) {
    case RobotKind::Point: fcl_->robot = std::make_shared<fcl::Sphered>(0.0); break;
    case RobotKind::Sphere: fcl_->robot = std::make_shared<fcl::Sphered>(robot.radius); break;
    case RobotKind::Box: fcl_->robot = std::make_shared<fcl::Boxd>(robot.size); break;
    default: fcl_->robot = bvhOf(robot.mesh); break;
  }
  if (robot.kind == RobotKind::Mesh) robotInside_ = std::make_unique<acd::InsideTest>(robot.closedMesh());
  fcl_->envObject = std::make_unique<fcl::CollisionObjectd>(fcl_->environment, fcl::Transform3d::Identity());
  fcl_->robotObject = std::make_unique<fcl::CollisionObjectd>(fcl_->robot, fcl::Transform3d::Identity());
  fcl_->envObject->computeAABB();
}

CollisionWorld::~CollisionWorld() = default;

bool CollisionWorld::pointFree(const acd::Vec3& p) const { return !usesFreeSpace_ || freeInside_.inside(p); }

int CollisionWorld::islandInside(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const {
  for (std::size_t i = 0; i < islandProbes_.size(); ++i) {
    const acd::Vec3& q = islandProbes_[i];
    if ((q - position).squaredNorm() > reach_ * reach_) continue;  // out of the robot's reach
    const acd::Vec3 local = orientation.conjugate() * (q - position);
    bool in = false;
    switch (robot_.kind) {
      case RobotKind::Sphere: in = local.norm() <= robot_.radius; break;
      case RobotKind::Box: in = (local.cwiseAbs().array() <= 0.5 * robot_.size.array()).all(); break;
      default: in = robotInside_->inside(local); break;
    }
    if (in) return static_cast<int>(i);
  }
  return -1;
}

CollisionWorld::Contact CollisionWorld::contact(const acd::Vec3& position, const Eigen::Quaterniond& orientation,
                                                bool where) const {
  fcl_->robotObject->setTransform(orientation.toRotationMatrix(), position);
  fcl_->robotObject->computeAABB();
  fcl::CollisionRequestd request(1, where);
  fcl::CollisionResultd result;
  fcl::collide(fcl_->robotObject.get(), fcl_->envObject.get(), request, result);
  Contact c;
  c.found = result.isCollision();
  if (c.found && where && result.numContacts() > 0) {
    const fcl::Contactd& k = result.getContact(0);
    const bool robotFirst = k.o1 == fcl_->robot.get();
    c.robotTriangle = robotFirst ? static_cast<int>(k.b1) : static_cast<int>(k.b2);
    c.environmentTriangle = robotFirst ? static_cast<int>(k.b2) : static_cast<int>(k.b1);
    c.at = k.pos;
  }
  return c;
}

bool CollisionWorld::valid(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const {
  ++checks_;
  if (usesFreeSpace_)
    for (const acd::Vec3& a : robot_.insidePoints)
      if (!freeInside_.inside(position + orientation * a)) return false;
  if (robot_.kind == RobotKind::Point) return true;
  if (usesFreeSpace_ && islandInside(position, orientation) >= 0) return false;
  return !contact(position, orientation, false).found;
}

double CollisionWorld::clearance(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const {
  fcl_->robotObject->setTransform(orientation.toRotationMatrix(), position);
  fcl_->robotObject->computeAABB();
  fcl::DistanceRequestd request;
  fcl::DistanceResultd result;
  fcl::distance(fcl_->robotObject.get(), fcl_->envObject.get(), request, result);
  return std::max(0.0, result.min_distance);
}

std::string CollisionWorld::environmentName(int triangle) const {
  const auto it = std::upper_bound(firstTriangle_.begin(), firstTriangle_.end(), triangle);
  const std::size_t i = it == firstTriangle_.begin() ? 0 : static_cast<std::size_t>(it - firstTriangle_.begin()) - 1;
  return names_[i] + ", its triangle " + std::to_string(triangle - firstTriangle_[i]);
}

std::string CollisionWorld::whyInvalid(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const {
  if (robot_.kind != RobotKind::Point) {
    const Contact c = contact(position, orientation, true);
    if (c.found) {
      std::string s = "the robot touches " + (c.environmentTriangle >= 0 ? environmentName(c.environmentTriangle)
                                                                            : std::string("the environment"));
      if (robot_.kind == RobotKind::Mesh && c.robotTriangle >= 0) s += " (robot triangle " + std::to_string(c.robotTriangle) + ")";
      return s + " at " + point(c.at);
    }
  }
  if (!usesFreeSpace_) return "";
  for (const acd::Vec3& a : robot_.insidePoints) {
    const acd::Vec3 p = position + orientation * a;
    if (freeInside_.inside(p)) continue;
    std::string s = "the robot lies outside the free space: its inside point " + point(p) + " is ";
    for (const NamedSolid& solid : solids_)
      if (acd::InsideTest(solid.mesh).inside(p)) return s + "inside " + solid.name + " (" + solid.how + ")";
    if (((p - workspace_.lo).array() >= 0).all() && ((workspace_.hi - p).array() >= 0).all())
      return s + "inside an obstacle's solid";
    return s + "outside the workspace";
  }
  const int island = robot_.kind == RobotKind::Point ? -1 : islandInside(position, orientation);
  if (island >= 0)
    return "an obstacle piece lies wholly inside the robot (its vertex " + point(islandProbes_[island]) + ")";
  return "";
}

}  // namespace planner
