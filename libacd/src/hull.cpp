// CGAL's convex_hull_3 (quickhull with exact predicates) into a polygon soup, mapped back to input indices.
#include <acd/hull.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_3.h>

#include <array>
#include <cmath>
#include <unordered_map>

namespace acd {

namespace {
struct PointHash {
  std::size_t operator()(const std::array<double, 3>& p) const {
    std::size_t h = 1469598103934665603ull;
    for (double d : p) h = (h ^ std::hash<double>()(d)) * 1099511628211ull;
    return h;
  }
};
}  // namespace

ConvexHull convexHull(const std::vector<Vec3>& points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  ConvexHull out;
  std::vector<K::Point_3> pts;
  pts.reserve(points.size());
  std::unordered_map<std::array<double, 3>, int, PointHash> index;
  index.reserve(points.size() * 2);
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const Vec3& p = points[i];
    pts.emplace_back(p.x(), p.y(), p.z());
    index.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, i);  // first occurrence wins
  }
  if (pts.size() < 4) {
    out.degenerate = true;
    return out;
  }
  std::vector<K::Point_3> hullPoints;
  std::vector<std::array<std::size_t, 3>> hullFaces;
  CGAL::convex_hull_3(pts.begin(), pts.end(), hullPoints, hullFaces);
  if (hullFaces.size() < 4) {
    out.degenerate = true;
    return out;
  }
  out.mesh.vertices.reserve(hullPoints.size());
  out.source.reserve(hullPoints.size());
  for (const auto& p : hullPoints) {
    out.mesh.vertices.emplace_back(p.x(), p.y(), p.z());
    out.source.push_back(index.at({p.x(), p.y(), p.z()}));
  }
  for (const auto& f : hullFaces)
    out.mesh.faces.push_back({static_cast<int>(f[0]), static_cast<int>(f[1]), static_cast<int>(f[2])});
  const double volume = signedVolume(out.mesh);
  const double extent = boundingBox(out.mesh).size().maxCoeff();
  if (std::abs(volume) <= 1e-14 * extent * extent * extent) {  // coplanar input: a flat, two-sided "hull"
    out = ConvexHull{};
    out.degenerate = true;
    return out;
  }
  if (volume < 0)
    for (Face& f : out.mesh.faces) std::swap(f[1], f[2]);
  return out;
}

}  // namespace acd
