#include "acd_skeleton.hpp"

#include <Eigen/Geometry>
#include <acd/algo/closest_point.hpp>
#include <acd/algo/union_find.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace skeleton {

namespace {

/// Triangles of a component with their unit normals, for the test "does this point lie on its
/// surface, on a face turned against `normal`".
class SurfaceOf {
 public:
  SurfaceOf(const acd::TriMesh& m, double tolerance) : tolerance_(tolerance) {
    for (const acd::Face& f : m.faces) {
      const Vec3 &p = m.vertices[f[0]], &q = m.vertices[f[1]], &r = m.vertices[f[2]];
      const Vec3 n = (q - p).cross(r - p);
      if (n.norm() > 0) triangles_.push_back({p, q, r, n.normalized()});
    }
  }

  /// Whether any face of this surface is coplanar with, and turned against, a face of normal n
  /// through the point.
  bool faces(const Vec3& point, const Vec3& n) const {
    return std::any_of(triangles_.begin(), triangles_.end(),
                       [&](const Triangle& t) { return planeAgainst(t, point, n); });
  }

  /// Whether the point lies on a face turned against n (within the tolerance).
  bool holds(const Vec3& point, const Vec3& n) const {
    return std::any_of(triangles_.begin(), triangles_.end(), [&](const Triangle& t) {
      return planeAgainst(t, point, n) &&
             (acd::closestPointOnTriangle(point, t.p, t.q, t.r) - point).norm() <= tolerance_;
    });
  }

 private:
  static constexpr double kOpposite = 0.9999;  // cos of 0.8 degrees
  struct Triangle {
    Vec3 p, q, r, n;
  };
  bool planeAgainst(const Triangle& t, const Vec3& point, const Vec3& n) const {
    return t.n.dot(n) < -kOpposite && std::abs(t.n.dot(point - t.p)) <= tolerance_;
  }
  std::vector<Triangle> triangles_;
  double tolerance_;
};

/// Area of triangle pqr that lies on `other` (faces turned against n), and its moment: whole when
/// its corners and centroid do, else split in four, down to kDepth levels. `whole` gets the area
/// counted without splitting.
void contactOf(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& n, const SurfaceOf& other, int depth,
               double& area, Vec3& moment, double& whole) {
  constexpr int kDepth = 4;
  const Vec3 c = (p + q + r) / 3.0;
  const bool inC = other.holds(c, n), inP = other.holds(p, n), inQ = other.holds(q, n), inR = other.holds(r, n);
  const double a = 0.5 * (q - p).cross(r - p).norm();
  if ((inC && inP && inQ && inR) || (depth == kDepth && inC)) {
    area += a;
    moment += a * c;
    if (depth == 0) whole += a;
    return;
  }
  if (depth == kDepth || !(inC || inP || inQ || inR)) return;
  const Vec3 pq = 0.5 * (p + q), qr = 0.5 * (q + r), rp = 0.5 * (r + p);
  contactOf(p, pq, rp, n, other, depth + 1, area, moment, whole);
  contactOf(pq, q, qr, n, other, depth + 1, area, moment, whole);
  contactOf(rp, qr, r, n, other, depth + 1, area, moment, whole);
  contactOf(pq, qr, rp, n, other, depth + 1, area, moment, whole);
}

/// The patches where mesh m touches `other`, measured on m's triangles (normals out of m), and the
/// share of their area that lay on `other` triangle by whole triangle.
struct Side {
  std::vector<Cut> patches;
  double area = 0.0, whole = 0.0;
};

Side contactSide(const acd::TriMesh& m, const SurfaceOf& other) {
  Side side;
  std::vector<int> touching;
  std::vector<double> area;
  std::vector<Vec3> moment, normal;
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) {
    const Vec3 &p = m.vertices[m.faces[f][0]], &q = m.vertices[m.faces[f][1]], &r = m.vertices[m.faces[f][2]];
    const Vec3 twice = (q - p).cross(r - p);
    if (!(twice.norm() > 0)) continue;
    const Vec3 unit = twice.normalized();
    if (!other.faces((p + q + r) / 3.0, unit)) continue;
    double s = 0.0;
    Vec3 c = Vec3::Zero();
    contactOf(p, q, r, unit, other, 0, s, c, side.whole);
    if (!(s > 0)) continue;
    touching.push_back(f);
    area.push_back(s);
    moment.push_back(c);
    normal.push_back(s * unit);
    side.area += s;
  }
  acd::UnionFind sets(static_cast<int>(touching.size()));
  std::map<int, int> firstUser;  // corner -> first touching triangle using it
  for (int t = 0; t < static_cast<int>(touching.size()); ++t)
    for (int v : m.faces[touching[t]]) {
      auto [it, inserted] = firstUser.emplace(v, t);
      if (!inserted) sets.join(sets.find(t), sets.find(it->second));
    }
  std::map<int, Cut> patches;
  for (int t = 0; t < static_cast<int>(touching.size()); ++t) {
    Cut& cut = patches[sets.find(t)];
    cut.centre += moment[t];
    cut.area += area[t];
    cut.normal += normal[t];
    ++cut.triangles;
  }
  for (auto& [root, cut] : patches) {
    cut.centre /= cut.area;
    if (cut.normal.norm() > 0) cut.normal.normalize();
    side.patches.push_back(cut);
  }
  return side;
}

}  // namespace

std::vector<Cut> findCuts(const std::vector<acd::TriMesh>& components) {
  const int n = static_cast<int>(components.size());
  std::vector<acd::Box3> boxes(n);
  Eigen::AlignedBox3d all;
  for (int i = 0; i < n; ++i) {
    boxes[i] = acd::boundingBox(components[i]);
    if (!components[i].vertices.empty()) all.extend(boxes[i].lo), all.extend(boxes[i].hi);
  }
  const double tolerance = all.isEmpty() ? 0.0 : kCutTolerance * all.diagonal().norm();
  std::vector<SurfaceOf> surfaces;
  for (const acd::TriMesh& m : components) surfaces.emplace_back(m, tolerance);

  std::vector<Cut> cuts;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      const acd::Box3 &x = boxes[a], &y = boxes[b];
      if (components[a].faces.empty() || components[b].faces.empty() ||
          ((x.lo.array() - tolerance) > y.hi.array()).any() || ((y.lo.array() - tolerance) > x.hi.array()).any())
        continue;
      // Measured on the side whose triangles lie wholly on the other (the side a later cut split):
      // exact there, where the other side's larger triangles would need splitting. Both sides are
      // asked: a small face on a large one is seen only from the small side.
      const Side onA = contactSide(components[a], surfaces[b]);
      const Side onB = contactSide(components[b], surfaces[a]);
      if (onA.patches.empty() && onB.patches.empty()) continue;
      const bool useB = onA.patches.empty() || (!onB.patches.empty() && onB.whole * onA.area > onA.whole * onB.area);
      std::vector<Cut> local = useB ? onB.patches : onA.patches;
      for (Cut& cut : local) {
        cut.a = a;
        cut.b = b;
        if (useB) cut.normal = -cut.normal;  // out of a
      }
      std::stable_sort(local.begin(), local.end(), [](const Cut& u, const Cut& v) { return u.area > v.area; });
      cuts.insert(cuts.end(), local.begin(), local.end());
    }
  return cuts;
}

Vec3 solidCentroid(const acd::TriMesh& mesh) {
  // Signed tetrahedra against a point near the mesh (its vertex mean) keep rounding small.
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : mesh.vertices) mean += v;
  if (!mesh.vertices.empty()) mean /= static_cast<double>(mesh.vertices.size());
  double volume = 0.0;
  Vec3 moment = Vec3::Zero();
  for (const acd::Face& f : mesh.faces) {
    const Vec3 a = mesh.vertices[f[0]] - mean, b = mesh.vertices[f[1]] - mean, c = mesh.vertices[f[2]] - mean;
    const double v = a.dot(b.cross(c)) / 6.0;
    volume += v;
    moment += v * (a + b + c) / 4.0;
  }
  if (!(std::abs(volume) > 0.0)) return mean;
  return mean + moment / volume;
}

Graph skeletonFromComponents(const std::vector<acd::TriMesh>& components) {
  Graph g;
  for (int i = 0; i < static_cast<int>(components.size()); ++i)
    g.addNode(solidCentroid(components[i]), NodeKind::Component, i);
  for (const Cut& cut : findCuts(components)) {
    const int node = g.addNode(cut.centre, NodeKind::Cut);
    g.addEdge(cut.a, node);
    g.addEdge(cut.b, node);
  }
  return g;
}

}  // namespace skeleton
