// Progressive-hull simplification; see hull_simplify.hpp.
#include "hull_simplify.hpp"

#include <acd/hull.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace tetmesh {

namespace {

using acd::Face;
using acd::TriMesh;
using acd::Vec3;

struct FacePlane {
  Vec3 n;        // unit, outward
  double d;      // n . x = d
  double area;
};

struct Collapse {
  int a = -1, b = -1;
  Vec3 p = Vec3::Zero();
  double cost = std::numeric_limits<double>::infinity();
};

/// Best replacement point for edge ab: a corner of the region outside all star planes that
/// minimises the added volume sum(area * (n . p - d)).
Collapse bestCollapse(int a, int b, const std::vector<FacePlane>& planes, const std::vector<int>& star,
                      const TriMesh& mesh, double reach) {
  Collapse best;
  best.a = a, best.b = b;
  // Distinct planes of the star (a hull face split in triangles gives the same plane several times).
  std::vector<int> uniq;
  for (int f : star) {
    bool dup = false;
    for (int g : uniq)
      if (planes[g].n.dot(planes[f].n) > 1.0 - 1e-12 && std::abs(planes[g].d - planes[f].d) < 1e-12 * reach) {
        dup = true;
        break;
      }
    if (!dup) uniq.push_back(f);
  }
  Vec3 w = Vec3::Zero();
  double w0 = 0.0;
  for (int f : star) w += planes[f].area * planes[f].n, w0 += planes[f].area * planes[f].d;
  const Vec3 mid = 0.5 * (mesh.vertices[a] + mesh.vertices[b]);
  const int m = static_cast<int>(uniq.size());
  for (int i = 0; i < m; ++i)
    for (int j = i + 1; j < m; ++j)
      for (int k = j + 1; k < m; ++k) {
        Eigen::Matrix3d A;
        A.row(0) = planes[uniq[i]].n.transpose();
        A.row(1) = planes[uniq[j]].n.transpose();
        A.row(2) = planes[uniq[k]].n.transpose();
        if (std::abs(A.determinant()) < 1e-9) continue;
        const Vec3 p = A.partialPivLu().solve(Vec3(planes[uniq[i]].d, planes[uniq[j]].d, planes[uniq[k]].d));
        if (!p.allFinite() || (p - mid).norm() > reach) continue;
        bool feasible = true;
        for (int f : uniq)
          if (planes[f].n.dot(p) < planes[f].d - 1e-12 * reach) {
            feasible = false;
            break;
          }
        if (!feasible) continue;
        const double cost = w.dot(p) - w0;
        if (cost < best.cost) best.cost = cost, best.p = p;
      }
  return best;
}

}  // namespace

double maxOutsideDistance(const TriMesh& convex, const std::vector<Vec3>& points) {
  // Sliver faces (nearly coplanar corners) have no reliable normal in floating point; their
  // wide neighbours bound the same region to within their size, so they are skipped.
  const double size = acd::boundingBox(convex).size().norm();
  const double minArea2 = 1e-12 * size * size;
  double worst = 0.0;
  for (int f = 0; f < static_cast<int>(convex.faces.size()); ++f) {
    const Vec3 nrm = acd::faceNormal(convex, f);
    const double len = nrm.norm();
    if (!(len > minArea2)) continue;
    const Vec3 u = nrm / len;
    const double d = u.dot(convex.vertices[convex.faces[f][0]]);
    for (const Vec3& p : points) worst = std::max(worst, u.dot(p) - d);
  }
  return worst;
}

SimplifiedHull simplifyHull(const TriMesh& hull, int maxVertices) {
  SimplifiedHull out;
  out.mesh = hull;
  maxVertices = std::max(maxVertices, 4);
  const acd::Box3 box = acd::boundingBox(hull);
  const double reach = 4.0 * box.size().norm();  // how far a new corner may go
  const double eps = 1e-10 * reach;
  while (static_cast<int>(out.mesh.vertices.size()) > maxVertices) {
    const TriMesh& cur = out.mesh;
    const int nv = static_cast<int>(cur.vertices.size());
    std::vector<FacePlane> planes(cur.faces.size());
    std::vector<std::vector<int>> facesOf(nv);
    std::vector<std::set<int>> neighbours(nv);
    for (int f = 0; f < static_cast<int>(cur.faces.size()); ++f) {
      const Vec3 nrm = acd::faceNormal(cur, f);
      const double len = nrm.norm();
      planes[f] = {len > 0 ? Vec3(nrm / len) : Vec3::Zero(), len > 0 ? nrm.dot(cur.vertices[cur.faces[f][0]]) / len : 0.0,
                   0.5 * len};
      for (int k = 0; k < 3; ++k) {
        facesOf[cur.faces[f][k]].push_back(f);
        neighbours[cur.faces[f][k]].insert(cur.faces[f][(k + 1) % 3]);
      }
    }
    std::vector<Collapse> candidates;
    for (int a = 0; a < nv; ++a)
      for (int b : neighbours[a]) {
        if (b < a) continue;
        std::vector<int> star = facesOf[a];
        for (int f : facesOf[b])
          if (std::find(star.begin(), star.end(), f) == star.end()) star.push_back(f);
        Collapse c = bestCollapse(a, b, planes, star, cur, reach);
        if (std::isfinite(c.cost)) candidates.push_back(c);
      }
    std::sort(candidates.begin(), candidates.end(), [](const Collapse& x, const Collapse& y) {
      return x.cost != y.cost ? x.cost < y.cost : std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
    });
    // Collapse a batch of edges whose neighbourhoods do not touch, then check containment;
    // if the batch fails, fall back to the single cheapest collapse that passes.
    const int excess = nv - maxVertices;
    const int batchLimit = std::max(1, std::min(excess, nv / 10));
    auto attempt = [&](const std::vector<const Collapse*>& batch, TriMesh& result) {
      std::vector<bool> drop(nv, false);
      std::vector<Vec3> pts;
      for (const Collapse* c : batch) drop[c->a] = drop[c->b] = true, pts.push_back(c->p);
      for (int v = 0; v < nv; ++v)
        if (!drop[v]) pts.push_back(cur.vertices[v]);
      const acd::ConvexHull h = acd::convexHull(pts);
      if (h.degenerate || static_cast<int>(h.mesh.vertices.size()) >= nv) return false;
      if (maxOutsideDistance(h.mesh, cur.vertices) > eps) return false;
      result = h.mesh;
      return true;
    };
    std::vector<const Collapse*> batch;
    std::vector<bool> used(nv, false);
    for (const Collapse& c : candidates) {
      if (static_cast<int>(batch.size()) >= batchLimit) break;
      bool clash = used[c.a] || used[c.b];
      for (int v : neighbours[c.a]) clash = clash || used[v];
      for (int v : neighbours[c.b]) clash = clash || used[v];
      if (clash) continue;
      batch.push_back(&c);
      used[c.a] = used[c.b] = true;
      for (int v : neighbours[c.a]) used[v] = true;
      for (int v : neighbours[c.b]) used[v] = true;
    }
    TriMesh next;
    bool done = batch.size() > 1 && attempt(batch, next);
    if (done) {
      out.collapses += static_cast<int>(batch.size());
    } else {
      const std::size_t tries = std::min<std::size_t>(candidates.size(), 32);
      for (std::size_t t = 0; t < tries && !done; ++t)
        if (attempt({&candidates[t]}, next)) {
          done = true;
          ++out.collapses;
        }
    }
    if (!done) break;
    out.mesh = std::move(next);
  }
  out.reached = static_cast<int>(out.mesh.vertices.size()) <= maxVertices;
  return out;
}

}  // namespace tetmesh
