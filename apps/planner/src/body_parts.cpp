#include "body_parts.hpp"

#include "aligned_poses.hpp"
#include "fcl_bvh.hpp"
#include "smallest_rectangle.hpp"

#include <acd/algo/hull.hpp>
#include <acd/algo/shell_inside.hpp>
#include <acd/decompose.hpp>
#include <acd/robust.hpp>

#include <fcl/narrowphase/distance.h>
#include <fcl/geometry/bvh/BVH_model.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <tuple>

namespace planner {

namespace {

/// A gap has a way through when a part's length makes more than 30 degrees with the gap's
/// direction (two bars side by side); parts end to end (less) leave the gap open on every side.
constexpr double kThroughSine = 0.5;

BodyPart partOf(const acd::TriMesh& hull) {
  BodyPart p;
  // The long axis by the second moment; across it, the smallest rectangle around the section.
  const Eigen::Matrix3d principal = robotPrincipalAxes(hull, false);
  const acd::Vec3 e0 = principal.col(0), e1 = principal.col(1), e2 = principal.col(2);
  // (A bar's square section has no principal axes of its own: its box is found here.)
  std::vector<Point2> section;
  for (const acd::Vec3& v : hull.vertices) section.push_back({e1.dot(v), e2.dot(v)});
  const Point2 side = smallestRectangle(section).side;
  std::array<acd::Vec3, 3> axes{e0, side[0] * e1 + side[1] * e2, -side[1] * e1 + side[0] * e2};
  std::array<double, 3> lo, hi;
  for (int i = 0; i < 3; ++i) lo[i] = INFINITY, hi[i] = -INFINITY;
  for (const acd::Vec3& v : hull.vertices)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], axes[i].dot(v)), hi[i] = std::max(hi[i], axes[i].dot(v));
  std::array<int, 3> order{0, 1, 2};  // longest extent first
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return hi[i] - lo[i] > (hi[j] - lo[j]) * (1 + 1e-9); });
  acd::Vec3 centre = acd::Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    p.axes.col(i) = axes[order[i]];
    p.halfExtent[i] = 0.5 * (hi[order[i]] - lo[order[i]]);
    centre += 0.5 * (lo[order[i]] + hi[order[i]]) * axes[order[i]];
  }
  p.axes.col(2) = p.axes.col(0).cross(p.axes.col(1));  // right-handed
  p.centre = centre;
  for (const acd::Vec3& v : hull.vertices) p.radius = std::max(p.radius, (v - p.centre).norm());
  return p;
}

}  // namespace

BodyParts bodyParts(const acd::TriMesh& soup, const std::vector<acd::TriMesh>& closedSolids, double tau,
                    double widestGap) {
  BodyParts body;
  acd::DecomposeOptions options;
  options.tau = tau;
  options.threads = 1;  // timed as part of the planner's preprocessing
  // Shells apart: where they touch or overlap they have no gap between them anyway, and their
  // union (an exact corefinement) would cost more than the rest of the preprocessing.
  options.uniteShells = false;
  std::vector<acd::TriMesh> hulls;
  auto take = [&](const acd::Decomposition& d) {
    for (const acd::Component& c : d.components) {
      acd::TriMesh hull = c.hull.empty() ? acd::hullMesh(c.mesh.vertices) : c.hull;
      if (hull.faces.empty()) continue;
      body.parts.push_back(partOf(hull));
      hulls.push_back(std::move(hull));
    }
  };
  // The soup as the acd command takes it, shells apart (repairs, a wrap only where nothing else
  // closes the surface); the closed solids when that fails.
  const acd::Decomposition whole = acd::decomposeRepaired(soup, options);
  if (whole.status.ok()) {
    take(whole);
  } else {
    for (const acd::TriMesh& solid : closedSolids) {
      const acd::Decomposition d = acd::decompose(solid, options);
      if (d.status.ok()) take(d);  // a solid that cannot be decomposed gives no parts
    }
  }
  // The hulls' surfaces, in world coordinates (identity transforms: FCL's nearest points need no
  // change of frame). Hulls of ACD components do not nest, so the surfaces' distance is the parts'.
  std::vector<std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>>> bvh;
  for (const acd::TriMesh& h : hulls) bvh.push_back(bvhOf(h));
  const fcl::Transform3d identity = fcl::Transform3d::Identity();
  const acd::ShellsInside inside(soup);
  for (int a = 0; a < static_cast<int>(hulls.size()); ++a)
    for (int b = a + 1; b < static_cast<int>(hulls.size()); ++b) {
      const BodyPart &pa = body.parts[a], &pb = body.parts[b];
      if ((pa.centre - pb.centre).norm() - pa.radius - pb.radius > widestGap) continue;
      fcl::DistanceRequestd request(true);  // nearest points
      fcl::DistanceResultd result;
      fcl::distance(bvh[a].get(), identity, bvh[b].get(), identity, request, result);
      if (!(result.min_distance > 0) || result.min_distance > widestGap) continue;
      const acd::Vec3 p = result.nearest_points[0], q = result.nearest_points[1];
      if (!((q - p).norm() > 0) || inside.inside(0.5 * (p + q))) continue;  // parts of one solid cut apart
      PartGap g;
      g.a = a, g.b = b;
      g.direction = (q - p).normalized();
      // Parallel faces have many closest points; the gap's middle is taken across from the
      // middle of the parts' centres (the centre of a ring's hole, not one of its corners).
      const acd::Vec3 centres = 0.5 * (pa.centre + pb.centre);
      g.middle = centres + (0.5 * (p + q) - centres).dot(g.direction) * g.direction;
      for (const BodyPart* part : {&pa, &pb}) {
        const acd::Vec3 t = g.direction.cross(part->axes.col(0));
        if (g.through.isZero() && t.norm() > kThroughSine) g.through = t.normalized();
      }
      g.width = result.min_distance;
      body.gaps.push_back(g);
    }
  std::sort(body.gaps.begin(), body.gaps.end(),
            [](const PartGap& x, const PartGap& y) { return std::tie(x.width, x.a, x.b) < std::tie(y.width, y.a, y.b); });
  return body;
}

}  // namespace planner
