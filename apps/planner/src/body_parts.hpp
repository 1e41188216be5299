// The convex parts of a body (the robot, the obstacles) and the gaps between them. A passage
// of the robot's configuration space that the free space's openings do not show — a bar that
// must pass through a gap in a link, a link that must slide along a bar threaded through it —
// is a part of one body lying in a gap of the other; threading_poses.hpp samples those.
#pragma once

#include <acd/mesh.hpp>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace planner {

/// A convex part: its hull's box along the hull's principal axes.
struct BodyPart {
  acd::Vec3 centre = acd::Vec3::Zero();        // the box's centre
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns: principal axes, longest extent first
  acd::Vec3 halfExtent = acd::Vec3::Zero();    // along each axis
  double radius = 0.0;                         // farthest hull corner from the centre
};

/// Two parts of one body with empty space between them: the segment between their closest
/// points is the gap (parts that touch or overlap have none).
struct PartGap {
  int a = 0, b = 0;                           // parts, a < b
  acd::Vec3 middle = acd::Vec3::Zero();       // half way between the closest points, across from the parts' centres
  acd::Vec3 direction = acd::Vec3::UnitX();   // unit, from a's closest point to b's
  acd::Vec3 through = acd::Vec3::Zero();      // unit, across `direction` and the parts' length: the way
                                              // through the gap; zero when the parts lie end to end
                                              // (a gap in a bar is open on every side)
  double width = 0.0;                         // the distance between the parts
};

struct BodyParts {
  std::vector<BodyPart> parts;
  std::vector<PartGap> gaps;   // sorted by width, then parts
};

/// The ACD components (solid ACD at `tau`, single-threaded) of a body, and the gaps between any
/// two of them no wider than `widestGap` whose middle lies outside the body. `soup`: the body's
/// triangles as given, decomposed as the acd command decomposes them with --no-union
/// (acd::decomposeRepaired: repairs, a wrap only where nothing else closes the surface; shells
/// that touch or overlap have no gap between them, so they need not be united);
/// when that fails, each of `solids` (the body made closed for the free space, whose wrap may
/// close gaps) on its own.
BodyParts bodyParts(const acd::TriMesh& soup, const std::vector<acd::TriMesh>& solids, double tau, double widestGap);

}  // namespace planner
