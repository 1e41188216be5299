#include "collision_world.hpp"

#include <acd/shapes.hpp>

#include <fcl/fcl.h>

namespace planner {

struct CollisionWorld::Fcl {
  std::shared_ptr<fcl::CollisionGeometryd> environment;
  std::shared_ptr<fcl::CollisionGeometryd> robot;
  std::unique_ptr<fcl::CollisionObjectd> envObject, robotObject;
};

namespace {

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> bvhOf(const acd::TriMesh& m) {
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Vector3d> points(m.vertices.begin(), m.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(m.faces.size());
  for (const acd::Face& f : m.faces) triangles.emplace_back(f[0], f[1], f[2]);
  model->beginModel();
  model->addSubModel(points, triangles);
  model->endModel();
  return model;
}

}  // namespace

CollisionWorld::CollisionWorld(const acd::TriMesh& freeSpace, const Robot& robot)
    : robot_(robot), freeInside_(freeSpace), fcl_(std::make_unique<Fcl>()) {
  // Shells with negative volume bound cavities of the free space: obstacles floating in it.
  for (const acd::TriMesh& shell : acd::splitEdgeConnected(freeSpace))
    if (acd::signedVolume(shell) < 0) islandProbes_.push_back(shell.vertices.front());
  setUpFcl(freeSpace);
}

CollisionWorld::CollisionWorld(const acd::TriMesh& freeSpace, const acd::TriMesh& obstacles, const acd::Box3& workspace,
                               const Robot& robot)
    : robot_(robot), freeInside_(freeSpace), fcl_(std::make_unique<Fcl>()) {
  islandProbes_ = pieceProbes(obstacles);
  setUpFcl(acd::concatenate({obstacles, acd::shapes::box(workspace.lo, workspace.hi)}));
}

void CollisionWorld::setUpFcl(const acd::TriMesh& environment) {
  const Robot& robot = robot_;
  reach_ = robot.boundingRadius();
  if (robot.kind == RobotKind::Point) return;
  fcl_->environment = bvhOf(environment);
  switch (robot.kind) {
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

bool CollisionWorld::pointFree(const acd::Vec3& p) const { return freeInside_.inside(p); }

bool CollisionWorld::valid(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const {
  ++checks_;
  if (!freeInside_.inside(position)) return false;
  if (robot_.kind == RobotKind::Point) return true;
  // An island wholly inside the robot touches no surface: test one of its vertices.
  for (const acd::Vec3& q : islandProbes_) {
    if ((q - position).squaredNorm() > reach_ * reach_) continue;  // out of the robot's reach
    const acd::Vec3 local = orientation.conjugate() * (q - position);
    switch (robot_.kind) {
      case RobotKind::Sphere:
        if (local.norm() <= robot_.radius) return false;
        break;
      case RobotKind::Box:
        if ((local.cwiseAbs().array() <= 0.5 * robot_.size.array()).all()) return false;
        break;
      default:
        if (robotInside_->inside(local)) return false;
        break;
    }
  }
  fcl_->robotObject->setTransform(orientation.toRotationMatrix(), position);
  fcl_->robotObject->computeAABB();
  fcl::CollisionRequestd request;
  fcl::CollisionResultd result;
  fcl::collide(fcl_->robotObject.get(), fcl_->envObject.get(), request, result);
  return !result.isCollision();
}

}  // namespace planner
