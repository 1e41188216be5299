// T-junctions closed by splitting boundary edges (acd/algo/t_junctions.hpp).
#include <acd/algo/t_junctions.hpp>

#include <algorithm>
#include <utility>

namespace acd {

namespace {

/// The boundary vertices sorted by x, for the edges to find the ones near them.
struct BoundaryVertices {
  std::vector<std::pair<double, int>> byX;

  BoundaryVertices(const std::vector<Vec3>& vertices, const std::vector<int>& ids) {
    for (int v : ids) byX.emplace_back(vertices[v].x(), v);
    std::sort(byX.begin(), byX.end());
  }
};

/// Per face side (3 * face + k, the side from corner k to k + 1) used by no other face.
std::vector<char> boundarySides(const std::vector<Face>& faces) {
  const SideEdges edges = numberEdges(faces);
  std::vector<int> uses(edges.edges, 0);
  for (int e : edges.edgeOfSide)
    if (e >= 0) ++uses[e];
  std::vector<char> side(3 * faces.size(), 0);
  for (std::size_t s = 0; s < side.size(); ++s) {
    const int e = edges.edgeOfSide[s];
    side[s] = e < 0 || uses[e] == 1;  // a side from a vertex to itself is used by no other face
  }
  return side;
}

/// The vertices strictly inside segment a-b (within `tol` of it, farther than `tol` from its
/// ends), in order from a to b.
std::vector<int> verticesOn(const std::vector<Vec3>& vertices, const BoundaryVertices& near, int a, int b, double tol) {
  const Vec3 &pa = vertices[a], &pb = vertices[b];
  const Vec3 d = pb - pa;
  const double length2 = d.squaredNorm();
  std::vector<std::pair<double, int>> found;
  if (!(length2 > 4 * tol * tol)) return {};
  const double lo = std::min(pa.x(), pb.x()) - tol, hi = std::max(pa.x(), pb.x()) + tol;
  auto it = std::lower_bound(near.byX.begin(), near.byX.end(), std::make_pair(lo, -1));
  for (; it != near.byX.end() && it->first <= hi; ++it) {
    const int v = it->second;
    if (v == a || v == b) continue;
    const Vec3& p = vertices[v];
    const double t = (p - pa).dot(d) / length2;
    if ((p - pa).squaredNorm() <= tol * tol || (p - pb).squaredNorm() <= tol * tol || t <= 0.0 || t >= 1.0) continue;
    if ((pa + t * d - p).squaredNorm() <= tol * tol) found.emplace_back(t, v);
  }
  std::sort(found.begin(), found.end());  // by t, then by index for points at one t
  std::vector<int> out;
  for (const auto& [t, v] : found) out.push_back(v);
  return out;
}

}  // namespace

TJunctionSplit splitTJunctions(const std::vector<Vec3>& vertices, const std::vector<Face>& faces, double tolerance) {
  TJunctionSplit out;
  out.faces = faces;
  std::vector<char> splitAt(vertices.size(), 0);
  // A face with cracks on two sides is split on one per round; its fan's outer triangles carry
  // the other sides into the next round. Three rounds cover a triangle's three sides.
  for (int round = 0; round < 3; ++round) {
    const std::vector<char> boundary = boundarySides(out.faces);
    std::vector<int> ids;
    for (std::size_t i = 0; i < out.faces.size(); ++i)
      for (int k = 0; k < 3; ++k)
        if (boundary[3 * i + k]) ids.push_back(out.faces[i][k]), ids.push_back(out.faces[i][(k + 1) % 3]);
    if (ids.empty()) break;
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    const BoundaryVertices near(vertices, ids);
    std::vector<Face> next;
    next.reserve(out.faces.size());
    bool changed = false;
    for (std::size_t i = 0; i < out.faces.size(); ++i) {
      const Face f = out.faces[i];
      std::vector<int> on;
      int k = 0;
      for (; k < 3 && on.empty(); ++k)
        if (boundary[3 * i + k]) {
          on = verticesOn(vertices, near, f[k], f[(k + 1) % 3], tolerance);
          // A flat face's own third corner may lie on that side: a fan to it would repeat it
          // (a triangle with a corner twice hangs CGAL's orient_polygon_soup).
          on.erase(std::remove(on.begin(), on.end(), f[(k + 2) % 3]), on.end());
        }
      if (on.empty()) {
        next.push_back(f);
        continue;
      }
      --k;  // the side split: from corner k to k + 1, the fan from corner k + 2
      const int a = f[k], b = f[(k + 1) % 3], c = f[(k + 2) % 3];
      int from = a;
      for (int v : on) {
        next.push_back({from, v, c});
        from = v;
        splitAt[v] = 1;
      }
      next.push_back({from, b, c});
      ++out.splitEdges;
      changed = true;
    }
    out.faces = std::move(next);
    if (!changed) break;
  }
  out.splitVertices = static_cast<int>(std::count(splitAt.begin(), splitAt.end(), 1));
  return out;
}

}  // namespace acd
