// Is the robot at a pose valid? FCL for contact between the robot's triangles and the
// obstacles' own triangles (soups included), and with Validity::FreeSpace exact point location
// too, so that a robot wholly inside an obstacle, or an obstacle wholly inside the robot, is
// caught (FCL sees surfaces only). Says why a pose is not valid (whyInvalid).
#pragma once

#include "scenario.hpp"

#include <acd/algo/inside.hpp>
#include <acd/mesh.hpp>

#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace planner {

/// A closed solid the free space was cut from, named for messages.
struct NamedSolid {
  std::string name;   // "obstacles[1] (wall.dae) piece 0"
  std::string how;    // "closed as given", "repaired", "alpha-wrapped, 0.005 beyond its triangles"
  acd::TriMesh mesh;
};

class CollisionWorld {
 public:
  /// `freeSpace`: closed, outward mesh (workspace minus obstacles); the robot must not touch
  /// its boundary. `robot`: as parsed.
  CollisionWorld(const acd::TriMesh& freeSpace, const Robot& robot, Validity validity = Validity::FreeSpace);
  /// The same, but the robot must not touch the obstacles' triangles as given (closed or not)
  /// nor the walls of `workspace`; `freeSpace` (made from `solids`, which contain the
  /// triangles) serves point location only.
  CollisionWorld(const acd::TriMesh& freeSpace, const std::vector<Obstacle>& obstacles, std::vector<NamedSolid> solids,
                 const acd::Box3& workspace, const Robot& robot, Validity validity);
  ~CollisionWorld();
  CollisionWorld(const CollisionWorld&) = delete;
  CollisionWorld& operator=(const CollisionWorld&) = delete;

  /// The robot at (position, orientation) touches no obstacle triangle (FCL) and, with
  /// Validity::FreeSpace (and always for a point robot), (1) its inside points lie in the
  /// free space and (3) no obstacle piece (or inner shell of the free space) has its probe
  /// vertex inside it. Each piece of the robot is connected and contains an inside point, so
  /// (1)-(3) mean it lies in the free space. Not thread-safe (FCL objects are reused).
  bool valid(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const;

  /// Empty when valid(); else one line saying which test failed and where.
  std::string whyInvalid(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const;

  /// Distance between the robot and the obstacles' triangles (FCL); for a point robot, to the
  /// free space's boundary. Not thread-safe.
  double clearance(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const;

  /// The point p (a robot's body point, world frame) is inside the free space.
  bool pointFree(const acd::Vec3& p) const;

  long checks() const { return checks_; }

 private:
  struct Fcl;
  struct Contact {
    bool found = false;
    int robotTriangle = -1, environmentTriangle = -1;
    acd::Vec3 at = acd::Vec3::Zero();
  };
  void setUpFcl(const acd::TriMesh& environment);
  Contact contact(const acd::Vec3& position, const Eigen::Quaterniond& orientation, bool where) const;
  int islandInside(const acd::Vec3& position, const Eigen::Quaterniond& orientation) const;
  std::string environmentName(int triangle) const;
  const Robot& robot_;
  bool usesFreeSpace_;
  acd::InsideTest freeInside_;
  std::unique_ptr<acd::InsideTest> robotInside_;
  std::vector<acd::Vec3> islandProbes_;  // one vertex per obstacle piece (or inner shell of the free space)
  double reach_ = 0.0;                   // the robot's bounding radius: probes farther away are skipped
  std::vector<std::string> names_;       // environment part names, starting at firstTriangle_
  std::vector<int> firstTriangle_;
  std::vector<NamedSolid> solids_;
  acd::Box3 workspace_;
  std::unique_ptr<Fcl> fcl_;
  mutable long checks_ = 0;
};

}  // namespace planner
