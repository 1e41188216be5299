// CGAL's convex_hull_3 (quickhull with exact predicates) into a polygon soup, mapped back to input indices.
#include <acd/hull.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
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
  CGAL::get_default_random() = CGAL::Random(0);  // per-thread state: keep the result thread-independent
  CGAL::Surface_mesh<K::Point_3> sm;
  CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
  if (sm.number_of_faces() < 4) {
    out.degenerate = true;
    return out;
  }
  // Canonical output, whatever CGAL's internal order (which follows heap addresses, so it changes
  // with threads): vertices sorted by input index, each planar facet re-triangulated by clipping
  // ears from its lowest-index corner, faces sorted.
  using SM = CGAL::Surface_mesh<K::Point_3>;
  std::vector<int> src(sm.number_of_vertices() + sm.number_of_removed_vertices(), -1);
  std::vector<int> sorted;
  for (auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    src[v.idx()] = index.at({p.x(), p.y(), p.z()});
    sorted.push_back(src[v.idx()]);
  }
  std::sort(sorted.begin(), sorted.end());
  std::unordered_map<int, int> hullIndex;
  for (int i = 0; i < static_cast<int>(sorted.size()); ++i) {
    hullIndex[sorted[i]] = i;
    out.mesh.vertices.push_back(points[sorted[i]]);
    out.source.push_back(sorted[i]);
  }
  // Facets: faces joined across exactly coplanar edges.
  const int nf = static_cast<int>(sm.number_of_faces() + sm.number_of_removed_faces());
  std::vector<int> group(nf);
  std::iota(group.begin(), group.end(), 0);
  auto root = [&](int f) {
    while (group[f] != f) f = group[f] = group[group[f]];
    return f;
  };
  for (auto h : sm.halfedges()) {
    const auto o = sm.opposite(h);
    if (sm.is_border(h) || sm.is_border(o)) continue;
    const auto& p = sm.point(sm.source(h));
    const auto& q = sm.point(sm.target(h));
    const auto& r = sm.point(sm.target(sm.next(h)));
    const auto& t = sm.point(sm.target(sm.next(o)));
    if (CGAL::coplanar(p, q, r, t)) group[root(static_cast<int>(sm.face(h)))] = root(static_cast<int>(sm.face(o)));
  }
  std::unordered_map<int, std::unordered_map<int, int>> ringNext;  // facet -> (source -> next source)
  for (auto h : sm.halfedges()) {
    const auto o = sm.opposite(h);
    if (sm.is_border(h)) continue;
    const int g = root(static_cast<int>(sm.face(h)));
    if (!sm.is_border(o) && root(static_cast<int>(sm.face(o))) == g) continue;
    ringNext[g][src[sm.source(h).idx()]] = src[sm.target(h).idx()];
  }
  for (auto& [g, next] : ringNext) {
    int first = std::numeric_limits<int>::max();
    for (const auto& [a, b] : next) first = std::min(first, a);
    std::vector<int> ring{first};
    for (int v = next.at(first); v != first && ring.size() <= next.size(); v = next.at(v)) ring.push_back(v);
    auto pt = [&](int v) { return K::Point_3(points[v].x(), points[v].y(), points[v].z()); };
    // Ear clipping: on a convex polygon every corner that is not collinear with its neighbours is an
    // ear. Clip the fattest ear first (largest area, ties to the earlier corner) so that no sliver
    // triangles with meaningless normals are made.
    while (ring.size() > 3) {
      std::size_t ear = ring.size();
      double fattest = -1.0;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const int a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
        if (CGAL::collinear(pt(a), pt(b), pt(c))) continue;
        const double area = (points[b] - points[a]).cross(points[c] - points[a]).norm();
        if (area > fattest) fattest = area, ear = i;
      }
      if (ear == ring.size()) break;  // only collinear points left: nothing with area to add
      const std::size_t prev = (ear + ring.size() - 1) % ring.size(), nextI = (ear + 1) % ring.size();
      out.mesh.faces.push_back({hullIndex.at(ring[prev]), hullIndex.at(ring[ear]), hullIndex.at(ring[nextI])});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(ear));
    }
    if (ring.size() == 3 && !CGAL::collinear(pt(ring[0]), pt(ring[1]), pt(ring[2])))
      out.mesh.faces.push_back({hullIndex.at(ring[0]), hullIndex.at(ring[1]), hullIndex.at(ring[2])});
  }
  for (Face& f : out.mesh.faces) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(out.mesh.faces.begin(), out.mesh.faces.end());
  (void)sizeof(SM);
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
