// CGAL's convex_hull_3 (quickhull with exact predicates) into a polygon soup, mapped back to input indices.
#include <acd/hull.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
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
    // Unique points only: CGAL 5.5's quickhull can erase a list element twice on duplicates (CGAL issue 6543).
    if (index.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, i).second) pts.emplace_back(p.x(), p.y(), p.z());
  }
  if (pts.size() < 4) {
    out.degenerate = true;
    return out;
  }
  // Into a Surface_mesh: CGAL 5.5's polygon-soup output of convex_hull_3 is unreliable
  // (different, wrong face counts from run to run on the same points).
  CGAL::Surface_mesh<K::Point_3> sm;
  CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
  if (sm.number_of_faces() < 4) {
    out.degenerate = true;
    return out;
  }
  std::vector<int> id(sm.number_of_vertices() + sm.number_of_removed_vertices(), -1);
  for (auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    id[v.idx()] = static_cast<int>(out.mesh.vertices.size());
    out.mesh.vertices.emplace_back(p.x(), p.y(), p.z());
    out.source.push_back(index.at({p.x(), p.y(), p.z()}));
  }
  for (auto f : sm.faces()) {
    Face tri{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (k < 3) tri[k] = id[v.idx()];
      ++k;
    }
    if (k != 3) {  // convex_hull_3 triangulates; anything else is a bug we must not hide
      out = ConvexHull{};
      out.degenerate = true;
      return out;
    }
    out.mesh.faces.push_back(tri);
  }
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
