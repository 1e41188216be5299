// Is the robot at a pose inside the free space? FCL for surface contact with the obstacles'
// own triangles (soups included), plus exact point location so that a robot wholly inside an
// obstacle, or an obstacle wholly inside the robot, is caught too (FCL sees surfaces only).
#pragma once

#include "scenario.hpp"

#include <acd/inside.hpp>
#include <acd/mesh.hpp>

#include <Eigen/Geometry>

#include <memory>
#include <vector>

namespace planner {

class CollisionWorld {
 public:
  /// `freeSpace`: closed, outward mesh (workspace minus obstacles); the robot must not touch
  /// its boundary. `robot`: as parsed.
  CollisionWorld(const acd::TriMesh& freeSpace, const Robot& robot);
  /// The same, but the robot must not touch `obstacles` (their triangles as given, closed or
  /// not) nor the walls of `workspace`; `freeSpace` (made from the obstacles' solids, which
  /// contain the triangles) serves point location only.
  CollisionWorld(const acd::TriMesh& freeSpace, const acd::TriMesh& obstacles, const acd::Box3& workspace,
                 const Robot& robot);
  ~CollisionWorld();
  CollisionWorld(const CollisionWorld&) = delete;
  CollisionWorld& operator=(const CollisionWorld&) = delete;

  /// The robot at (position, orientation) lies in the free space's interior, touching nothing:
  /// (1) its reference point is inside the free space, (2) FCL finds no contact between its
  /// triangles and the obstacles' (or the free space's boundary), (3) no piece of the
  /// obstacles (or inner shell of the free space) has its probe vertex inside the robot.
  /// Since the robot is connected and contains its reference point, these three together
  /// mean the robot is inside. Not thread-safe (FCL objects are reused); one per thread.
  bool valid(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const;

  /// (1) alone: the reference point is inside the free space.
  bool pointFree(const acd::Vec3& p) const;

  long checks() const { return checks_; }

 private:
  struct Fcl;
  void setUpFcl(const acd::TriMesh& environment);
  const Robot& robot_;
  acd::InsideTest freeInside_;
  std::unique_ptr<acd::InsideTest> robotInside_;
  std::vector<acd::Vec3> islandProbes_;  // one vertex per obstacle piece (or inner shell of the free space)
  double reach_ = 0.0;                   // the robot's bounding radius: probes farther away are skipped
  std::unique_ptr<Fcl> fcl_;
  mutable long checks_ = 0;
};

}  // namespace planner
