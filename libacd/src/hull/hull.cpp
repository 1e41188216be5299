// The convex hull of a point set in canonical form: quickhull (quickhull.cpp), then facets as polygons of their corners, triangulated alike whatever the input order.
#include <acd/algo/hull.hpp>

#include <acd/algo/quickhull.hpp>
#include <acd/algo/union_find.hpp>

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <cmath>
#include <unordered_map>

namespace acd {

namespace {
// Akl-Toussaint elimination: the points extreme in 26 directions span a polytope inside the hull,
// and a point strictly inside it cannot be a hull vertex. The test is a floating-point orientation
// with a margin above its worst rounding error, so a point is dropped only when it is certainly
// inside; points on or near a face stay. The hull is the same; quickhull sees a fraction of the
// points (most of a piece's surface lies inside its hull).
void dropInteriorPoints(std::vector<Vec3>& pts, std::vector<int>& orig) {
  if (pts.size() < 256) return;
  std::vector<std::size_t> extreme;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        std::size_t best = 0;
        double bestValue = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < pts.size(); ++i) {
          const double v = dx * pts[i].x() + dy * pts[i].y() + dz * pts[i].z();
          if (v > bestValue) bestValue = v, best = i;  // ties: the first point
        }
        extreme.push_back(best);
      }
  std::sort(extreme.begin(), extreme.end());
  extreme.erase(std::unique(extreme.begin(), extreme.end()), extreme.end());
  if (extreme.size() < 4) return;
  std::vector<Vec3> corners;
  for (std::size_t i : extreme) corners.push_back(pts[i]);
  const QuickHull inner = quickHull(corners);
  if (inner.degenerate || inner.failed) return;
  double lo[3] = {pts[0].x(), pts[0].y(), pts[0].z()}, hi[3] = {lo[0], lo[1], lo[2]};
  for (const auto& p : pts)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  // |error| of (b-a)x(c-a).(p-a) is below ~16 eps |b-a||c-a||p-a| <= 16 eps (2 size)^3: 1e-12 size^3 is far above it.
  const double margin = 1e-12 * size * size * size;
  struct Facet {
    double a[3], n[3];
  };
  std::vector<Facet> facets;
  for (const auto& f : inner.faces) {
    const Vec3& a = corners[f[0]];
    const Vec3 n = (corners[f[1]] - a).cross(corners[f[2]] - a);
    facets.push_back({{a.x(), a.y(), a.z()}, {n.x(), n.y(), n.z()}});
  }
  // Outward normals, checked: the corners' centroid must be inside every facet.
  double centre[3] = {0, 0, 0};
  for (const auto& c : corners)
    for (int k = 0; k < 3; ++k) centre[k] += c[k] / static_cast<double>(corners.size());
  for (const Facet& f : facets)
    if ((centre[0] - f.a[0]) * f.n[0] + (centre[1] - f.a[1]) * f.n[1] + (centre[2] - f.a[2]) * f.n[2] >= 0) return;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& p = pts[i];
    bool inside = true;
    for (const Facet& f : facets) {
      const double s = (p.x() - f.a[0]) * f.n[0] + (p.y() - f.a[1]) * f.n[1] + (p.z() - f.a[2]) * f.n[2];
      if (s > -margin) {  // outward normals: negative is inside
        inside = false;
        break;
      }
    }
    if (!inside) orig[kept] = orig[i], pts[kept++] = p;
  }
  pts.resize(kept);
  orig.resize(kept);
}

}  // namespace

ConvexHull convexHull(const std::vector<Vec3>& points) {
  ConvexHull out;
  std::vector<Vec3> pts;
  std::vector<int> orig;  // pts -> index in points: the first of each position, in input order
  for (const Vec3& p : points)
    if (!p.allFinite()) {  // no hull, and no order to sort by
      out.degenerate = true;
      return out;
    }
  const std::vector<int> first = firstAtSamePosition(points);
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    if (first[i] == i) pts.push_back(points[i]), orig.push_back(i);
  if (pts.size() < 4) {
    out.degenerate = true;
    return out;
  }
  dropInteriorPoints(pts, orig);
  const QuickHull qh = quickHull(pts);
  if (qh.degenerate || qh.failed || qh.faces.size() < 4) {
    out.degenerate = true;
    return out;
  }
  // Canonical output, whatever order quickhull added the points in: the hull's facets (triangles
  // joined across exactly coplanar edges) as polygons of their corners only (a point on an edge
  // or inside a facet is no corner), vertices sorted by input index, each facet triangulated by
  // clipping ears, faces sorted.
  const int nf = static_cast<int>(qh.faces.size());
  UnionFind facet(nf);
  for (int f = 0; f < nf; ++f) {
    const auto& v = qh.faces[f];
    const TriangleSide side(pts[v[0]], pts[v[1]], pts[v[2]]);
    for (int k = 0; k < 3; ++k) {
      const int g = qh.across[f][k];
      if (g < f) continue;
      const auto& w = qh.faces[g];
      const int far = w[0] != v[k] && w[0] != v[(k + 1) % 3] ? w[0] : w[1] != v[k] && w[1] != v[(k + 1) % 3] ? w[1] : w[2];
      if (side.sign(pts[far]) == 0) facet.joinKeepingSmallest(f, g);
    }
  }
  std::vector<int> members(nf, 0);
  for (int f = 0; f < nf; ++f) ++members[facet.find(f)];
  std::vector<std::array<int, 3>> triangles;  // pts indices
  std::vector<std::array<int, 3>> boundary;    // facet, corner, next corner: edges of facets of several triangles
  for (int f = 0; f < nf; ++f) {
    const int g = facet.find(f);
    if (members[g] == 1) {
      triangles.push_back(qh.faces[f]);  // a facet of one triangle: its own triangulation
      continue;
    }
    for (int k = 0; k < 3; ++k)
      if (facet.find(qh.across[f][k]) != g) boundary.push_back({g, qh.faces[f][k], qh.faces[f][(k + 1) % 3]});
  }
  std::sort(boundary.begin(), boundary.end());
  for (std::size_t begin = 0, end = 0; begin < boundary.size(); begin = end) {
    while (end < boundary.size() && boundary[end][0] == boundary[begin][0]) ++end;
    // The facet's outline, from its corner of smallest input index; edges are sorted by corner.
    auto nextOf = [&](int v) {
      const auto it = std::lower_bound(boundary.begin() + begin, boundary.begin() + end, std::array<int, 3>{boundary[begin][0], v, -1});
      return it != boundary.begin() + end && (*it)[1] == v ? (*it)[2] : -1;
    };
    int first = boundary[begin][1];
    for (std::size_t e = begin; e < end; ++e)
      if (orig[boundary[e][1]] < orig[first]) first = boundary[e][1];
    std::vector<int> loop{first};
    for (int v = nextOf(first); v >= 0 && v != first && loop.size() <= end - begin; v = nextOf(v)) loop.push_back(v);
    std::vector<int> ring;  // the loop's corners: points on the facet's edges are dropped
    for (std::size_t i = 0; i < loop.size(); ++i)
      if (!collinear(pts[loop[(i + loop.size() - 1) % loop.size()]], pts[loop[i]], pts[loop[(i + 1) % loop.size()]]))
        ring.push_back(loop[i]);
    // Ear clipping: on a convex polygon every corner is an ear. Clip the fattest ear first
    // (largest area, ties to the earlier corner) so that no sliver triangles with meaningless
    // normals are made.
    while (ring.size() > 3) {
      std::size_t ear = ring.size();
      double fattest = -1.0;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const int a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
        if (collinear(pts[a], pts[b], pts[c])) continue;
        const double area = (pts[b] - pts[a]).cross(pts[c] - pts[a]).norm();
        if (area > fattest) fattest = area, ear = i;
      }
      if (ear == ring.size()) break;  // only collinear points left: nothing with area to add
      const std::size_t prev = (ear + ring.size() - 1) % ring.size(), nextI = (ear + 1) % ring.size();
      triangles.push_back({ring[prev], ring[ear], ring[nextI]});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(ear));
    }
    if (ring.size() == 3 && !collinear(pts[ring[0]], pts[ring[1]], pts[ring[2]]))
      triangles.push_back({ring[0], ring[1], ring[2]});
  }
  std::vector<int> sorted;  // input indices of the corners
  for (const auto& t : triangles)
    for (int v : t) sorted.push_back(orig[v]);
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  std::unordered_map<int, int> hullIndex;
  for (int i = 0; i < static_cast<int>(sorted.size()); ++i) {
    hullIndex[sorted[i]] = i;
    out.mesh.vertices.push_back(points[sorted[i]]);
    out.source.push_back(sorted[i]);
  }
  for (const auto& t : triangles) out.mesh.faces.push_back({hullIndex.at(orig[t[0]]), hullIndex.at(orig[t[1]]), hullIndex.at(orig[t[2]])});
  for (Face& f : out.mesh.faces) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(out.mesh.faces.begin(), out.mesh.faces.end());
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
