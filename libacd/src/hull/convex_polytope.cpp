// See convex_polytope.hpp.
#include <acd/algo/convex_polytope.hpp>

#include <acd/algo/hull.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace acd {

namespace {

/// Drops points closer than eps to the one before them (and the last if close to the first).
void dropRepeats(std::vector<Vec3>& pts, double eps) {
  std::vector<Vec3> out;
  for (const Vec3& p : pts)
    if (out.empty() || (p - out.back()).norm() > eps) out.push_back(p);
  while (out.size() > 1 && (out.back() - out.front()).norm() <= eps) out.pop_back();
  pts = std::move(out);
}

/// Twice the area of a planar polygon, as a vector along its normal.
Vec3 areaVector(const std::vector<Vec3>& pts) {
  Vec3 a = Vec3::Zero();
  for (std::size_t k = 0; k < pts.size(); ++k) a += pts[k].cross(pts[(k + 1) % pts.size()]);
  return a;
}

}  // namespace

ConvexPolytope ConvexPolytope::box(const Vec3& lo, const Vec3& hi, double eps) {
  auto v = [&](int i, int j, int k) { return Vec3(i ? hi.x() : lo.x(), j ? hi.y() : lo.y(), k ? hi.z() : lo.z()); };
  ConvexPolytope p;
  p.eps_ = eps;
  p.faces_ = {{{v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)}, -Vec3::UnitX()},
              {{v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)}, Vec3::UnitX()},
              {{v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1)}, -Vec3::UnitY()},
              {{v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0)}, Vec3::UnitY()},
              {{v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0)}, -Vec3::UnitZ()},
              {{v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)}, Vec3::UnitZ()}};
  return p;
}

bool ConvexPolytope::cutBy(const HalfSpace& h) const {
  for (const Face& f : faces_)
    for (const Vec3& p : f.corners)
      if (h.distance(p) > eps_) return true;
  return false;
}

ConvexPolytope ConvexPolytope::clipped(const HalfSpace& h) const {
  ConvexPolytope out;
  out.eps_ = eps_;
  std::vector<Vec3> cap;
  bool capExists = false;  // a face already lies on the plane, facing the same way
  for (const Face& f : faces_) {
    const std::size_t m = f.corners.size();
    std::vector<Vec3> kept;
    for (std::size_t k = 0; k < m; ++k) {
      const Vec3& a = f.corners[k];
      const Vec3& b = f.corners[(k + 1) % m];
      const double da = h.distance(a), db = h.distance(b);
      if (da <= eps_) kept.push_back(a);
      if (std::abs(da) <= eps_) cap.push_back(a);
      if ((da < -eps_ && db > eps_) || (da > eps_ && db < -eps_)) {
        const Vec3 x = a + (da / (da - db)) * (b - a);
        kept.push_back(x);
        cap.push_back(x);
      }
    }
    dropRepeats(kept, eps_);
    if (kept.size() < 3 || !(areaVector(kept).norm() > eps_ * eps_)) continue;
    if (f.normal.dot(h.normal) > 1.0 - 1e-12) {
      bool onPlane = true;
      for (const Vec3& p : kept) onPlane = onPlane && std::abs(h.distance(p)) <= eps_;
      capExists = capExists || onPlane;
    }
    out.faces_.push_back({std::move(kept), f.normal});
  }
  if (capExists || cap.size() < 3) return out;
  // The new face: the points on the plane, in counter-clockwise order about the normal.
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : cap) centre += p;
  centre /= static_cast<double>(cap.size());
  const Vec3 u = (std::abs(h.normal.x()) < 0.9 ? h.normal.cross(Vec3::UnitX()) : h.normal.cross(Vec3::UnitY())).normalized();
  const Vec3 v = h.normal.cross(u);
  std::sort(cap.begin(), cap.end(), [&](const Vec3& a, const Vec3& b) {
    return std::atan2((a - centre).dot(v), (a - centre).dot(u)) < std::atan2((b - centre).dot(v), (b - centre).dot(u));
  });
  dropRepeats(cap, eps_);
  if (cap.size() >= 3 && areaVector(cap).norm() > eps_ * eps_) out.faces_.push_back({std::move(cap), h.normal});
  return out;
}

double ConvexPolytope::volume() const {
  if (empty()) return 0.0;
  const Vec3 r = faces_.front().corners.front();
  double six = 0.0;
  for (const Face& f : faces_)
    for (std::size_t k = 1; k + 1 < f.corners.size(); ++k)
      six += (f.corners[0] - r).dot((f.corners[k] - r).cross(f.corners[k + 1] - r));
  return six / 6.0;
}

std::vector<Vec3> ConvexPolytope::corners() const {
  std::vector<Vec3> out;
  for (const Face& f : faces_)
    for (const Vec3& p : f.corners) {
      bool seen = false;
      for (const Vec3& q : out)
        if ((p - q).norm() <= eps_) {
          seen = true;
          break;
        }
      if (!seen) out.push_back(p);
    }
  return out;
}

double ConvexPolytope::shortestEdge() const {
  double s = std::numeric_limits<double>::infinity();
  for (const Face& f : faces_)
    for (std::size_t k = 0; k < f.corners.size(); ++k)
      s = std::min(s, (f.corners[(k + 1) % f.corners.size()] - f.corners[k]).norm());
  return s;
}

TriMesh ConvexPolytope::mesh() const {
  if (empty()) return {};
  const ConvexHull h = convexHull(corners());
  return h.degenerate ? TriMesh{} : h.mesh;
}

std::vector<Vec3> uniqueFacetNormals(const TriMesh& mesh) {
  std::vector<Vec3> out;
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    const Vec3 n = faceNormal(mesh, f);
    const double len = n.norm();
    if (!(len > 0)) continue;
    const Vec3 u = n / len;
    bool seen = false;
    for (const Vec3& o : out)
      if (o.dot(u) > 1.0 - 1e-12) {
        seen = true;
        break;
      }
    if (!seen) out.push_back(u);
  }
  return out;
}

double maxAlong(const std::vector<Vec3>& pts, const Vec3& n) {
  double m = -std::numeric_limits<double>::infinity();
  for (const Vec3& p : pts) m = std::max(m, n.dot(p));
  return m;
}

double minAlong(const std::vector<Vec3>& pts, const Vec3& n) {
  double m = std::numeric_limits<double>::infinity();
  for (const Vec3& p : pts) m = std::min(m, n.dot(p));
  return m;
}

double maxOutsideDistance(const TriMesh& convex, const std::vector<Vec3>& points) {
  const double size = boundingBox(convex).size().norm();
  const double minArea2 = 1e-12 * size * size;
  double worst = 0.0;
  for (int f = 0; f < static_cast<int>(convex.faces.size()); ++f) {
    const Vec3 nrm = faceNormal(convex, f);
    const double len = nrm.norm();
    if (!(len > minArea2)) continue;
    const Vec3 u = nrm / len;
    const double d = u.dot(convex.vertices[convex.faces[f][0]]);
    for (const Vec3& p : points) worst = std::max(worst, u.dot(p) - d);
  }
  return worst;
}

}  // namespace acd
