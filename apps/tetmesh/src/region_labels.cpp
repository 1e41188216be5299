// Point labels of the hull regions; see region_labels.hpp.
#include "region_labels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tetmesh {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// A face's plane supports its region when no corner lies farther beyond it than this share of
/// the region's box diagonal (rounding of a true face plane is some 1e-16 of it).
constexpr double kPlaneSlack = 1e-9;

}  // namespace

RegionLabels::RegionLabels(const std::vector<acd::TriMesh>& regions, const std::vector<double>& closedGaps) {
  lower_ = Vec3::Constant(kInf);
  upper_ = Vec3::Constant(-kInf);
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const acd::TriMesh& mesh = regions[i];
    Region r;
    r.gap = i < closedGaps.size() ? std::max(0.0, closedGaps[i]) : 0.0;
    gap_ = std::max(gap_, r.gap);
    r.lower = Vec3::Constant(kInf);
    r.upper = Vec3::Constant(-kInf);
    for (const Vec3& v : mesh.vertices) r.lower = r.lower.cwiseMin(v), r.upper = r.upper.cwiseMax(v);
    const double slack = kPlaneSlack * (r.upper - r.lower).norm();
    for (const acd::Face& f : mesh.faces) {
      const Vec3& a = mesh.vertices[f[0]];
      const Vec3 n = (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a);
      const double length = n.norm();
      if (!(length > 0)) continue;  // a flat face bounds nothing its neighbours do not
      const Plane plane{n / length, n.dot(a) / length};
      // A face of nearly collinear corners (a CAD edge's points on the hull) has a normal of
      // rounding noise: its plane may cut the region in half (fandisk at tau 0.2 lost two of
      // its four regions whole). A face plane of a convex region has every corner behind it.
      bool supporting = true;
      for (const Vec3& v : mesh.vertices) supporting = supporting && plane.distance(v) <= slack;
      if (supporting) r.planes.push_back(plane);
    }
    if (r.planes.size() < 4) r.planes.clear();  // empty or degenerate: never a label
    r.width = r.planes.empty() ? 0.0 : kInf;
    for (const Plane& plane : r.planes) {
      double least = kInf;
      for (const Vec3& v : mesh.vertices) least = std::min(least, plane.normal.dot(v));
      r.width = std::min(r.width, plane.offset - least);
    }
    r.lower.array() -= r.gap;
    r.upper.array() += r.gap;
    if (!r.planes.empty()) lower_ = lower_.cwiseMin(r.lower), upper_ = upper_.cwiseMax(r.upper);
    regions_.push_back(std::move(r));
  }
  if (lower_.x() > upper_.x()) lower_ = upper_ = Vec3::Zero();
}

double RegionLabels::excess(const Region& r, const Vec3& p, double stopAbove, const Plane** beyond) const {
  double worst = -kInf;
  for (const Plane& plane : r.planes) {
    const double d = plane.distance(p);
    if (d > worst) {
      worst = d;
      *beyond = &plane;
      if (worst > stopAbove) break;
    }
  }
  return worst;
}

int RegionLabels::operator()(const Vec3& p) const {
  // Deepest region (smallest excess) first; while no region holds p, the two nearest within the
  // gap, with the planes p lies beyond.
  int best = 0, second = 0;  // labels
  double bestExcess = kInf, secondExcess = kInf;
  const Plane *bestPlane = nullptr, *secondPlane = nullptr;
  for (std::size_t i = 0; i < regions_.size(); ++i) {
    const Region& r = regions_[i];
    if (r.planes.empty() || (p.array() < r.lower.array()).any() || (p.array() > r.upper.array()).any()) continue;
    // A region can only matter if it beats the runner-up (outside) or the best (inside).
    const double stopAbove = bestExcess <= 0 ? bestExcess : std::min(gap_, secondExcess);
    const Plane* plane = nullptr;
    const double e = excess(r, p, stopAbove, &plane);
    if (e > stopAbove) continue;  // (possibly only a bound: excess stopped early)
    const int label = static_cast<int>(i) + 1;
    if (e < bestExcess) {
      second = best, secondExcess = bestExcess, secondPlane = bestPlane;
      best = label, bestExcess = e, bestPlane = plane;
    } else if (e < secondExcess) {
      second = label, secondExcess = e, secondPlane = plane;
    }
  }
  if (best == 0) return 0;
  if (bestExcess <= 0) return best;
  // In a gap: filled when the two nearest regions face each other across p, narrower than both allow.
  const double gap = second != 0 ? std::min(regions_[best - 1].gap, regions_[second - 1].gap) : 0.0;
  if (second != 0 && secondExcess <= gap && bestPlane->normal.dot(secondPlane->normal) < 0) return best;
  return 0;
}

}  // namespace tetmesh
