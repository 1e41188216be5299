// Extension 2 of Section 4.1: concave hull vertices and the projection of bridge edges on open surfaces.
#include <acd/algo/open_surface.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace acd {

std::vector<Vec3> vertexNormals(const TriMesh& mesh) {
  // Weighted by the corner angle, not the area: at a hull vertex one huge facet (a flat cap over an
  // opening) must not outvote the thin facets that carry the other half of its normal cone.
  std::vector<Vec3> n(mesh.vertices.size(), Vec3::Zero());
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    const Vec3 c = faceNormal(mesh, f);
    if (!(c.norm() > 0)) continue;
    const Vec3 unit = c.normalized();
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.vertices[mesh.faces[f][k]];
      const Vec3 a = mesh.vertices[mesh.faces[f][(k + 1) % 3]] - p, b = mesh.vertices[mesh.faces[f][(k + 2) % 3]] - p;
      n[mesh.faces[f][k]] += std::atan2(a.cross(b).norm(), a.dot(b)) * unit;
    }
  }
  for (Vec3& x : n)
    if (x.norm() > 0) x.normalize();
  return n;
}

std::vector<char> boundaryVertices(const SurfaceGraph& graph) {
  const TriMesh& mesh = graph.mesh();
  std::vector<char> on(mesh.vertices.size(), 0);
  for (int f = 0; f < graph.faceCount(); ++f)
    for (int k = 0; k < 3; ++k)
      if (graph.faceAcross(f, k) < 0) on[mesh.faces[f][k]] = on[mesh.faces[f][(k + 1) % 3]] = 1;
  return on;
}

std::vector<char> concaveHullVertices(const TriMesh& mesh, const ConvexHull& hull) {
  std::vector<char> concave(hull.mesh.vertices.size(), 0);
  if (hull.degenerate) return concave;
  const std::vector<Vec3> surface = vertexNormals(mesh);
  const std::vector<Vec3> onHull = vertexNormals(hull.mesh);
  for (std::size_t h = 0; h < concave.size(); ++h) concave[h] = onHull[h].dot(surface[hull.source[h]]) < 0.0;
  return concave;
}

bool orientTowardHull(TriMesh& mesh) {
  if (mesh.faces.empty() || isClosedOriented(mesh)) return false;
  const ConvexHull hull = convexHull(mesh.vertices);
  if (hull.degenerate) return false;
  const std::vector<char> concave = concaveHullVertices(mesh, hull);
  const auto count = std::count(concave.begin(), concave.end(), 1);
  if (2 * count <= static_cast<long>(concave.size())) return false;
  for (Face& f : mesh.faces) std::swap(f[1], f[2]);
  return true;
}

OpenSurfaceProjection::OpenSurfaceProjection(const TriMesh& mesh, const SurfaceGraph& graph, const ConvexHull& hull)
    : mesh_(mesh), graph_(graph), hull_(hull) {
  const std::vector<char> boundary = boundaryVertices(graph);
  open_ = std::find(boundary.begin(), boundary.end(), 1) != boundary.end();
  if (!open_ || hull.degenerate) return;
  concave_ = concaveHullVertices(mesh, hull);
  // Distances to the opening, once: every mixed edge walks from its convex end down this field.
  std::vector<int> sources;
  for (int v = 0; v < static_cast<int>(boundary.size()); ++v)
    if (boundary[v]) sources.push_back(v);
  PathFinder(graph).flood(sources, {}, nullptr, toOpening_, towardOpening_);
}

int OpenSurfaceProjection::concaveVertices() const {
  return static_cast<int>(std::count(concave_.begin(), concave_.end(), 1));
}

std::vector<int> OpenSurfaceProjection::project(PathFinder& finder, int u, int v) const {
  const int a = hull_.source[u], b = hull_.source[v];
  if (!open_ || concave_.empty() || (!concave_[u] && !concave_[v])) return finder.path(a, b);
  if (concave_[u] && concave_[v]) return {};
  // One end convex: from it down to the opening. The path keeps the edge's direction (u's side first).
  const int convexEnd = concave_[u] ? b : a;
  std::vector<int> path;
  if (!(toOpening_[convexEnd] < std::numeric_limits<double>::infinity())) return path;
  for (int x = convexEnd; x != -1; x = towardOpening_[x]) path.push_back(x);
  if (concave_[u]) std::reverse(path.begin(), path.end());  // opening ... v
  if (path.size() < 2) return {};
  return path;
}

int OpenSurfaceProjection::nearestBridge(const TriMesh& mesh, const std::vector<int>& faces,
                                         const std::vector<Bridge>& bridges) {
  int best = 0;
  double bestDepth = std::numeric_limits<double>::infinity();
  for (int b = 0; b < static_cast<int>(bridges.size()); ++b) {
    double depth = 0.0;
    for (int f : faces)
      for (int v : mesh.faces[f]) depth = std::max(depth, bridges[b].offset - bridges[b].normal.dot(mesh.vertices[v]));
    if (depth < bestDepth) bestDepth = depth, best = b;
  }
  return best;
}

}  // namespace acd
