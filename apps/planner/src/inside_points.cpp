#include "inside_points.hpp"

#include <acd/algo/inside.hpp>

#include <algorithm>
#include <limits>
#include <numeric>

namespace planner {

namespace {

/// Distance along the ray (origin, direction) to the nearest triangle hit beyond `minT`;
/// infinity when none (Moller-Trumbore).
double firstHit(const acd::TriMesh& m, const acd::Vec3& origin, const acd::Vec3& direction, double minT) {
  double best = std::numeric_limits<double>::infinity();
  for (const acd::Face& f : m.faces) {
    const acd::Vec3& a = m.vertices[f[0]];
    const acd::Vec3 e1 = m.vertices[f[1]] - a, e2 = m.vertices[f[2]] - a;
    const acd::Vec3 p = direction.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-300) continue;
    const acd::Vec3 s = origin - a;
    const double u = s.dot(p) / det;
    if (u < 0 || u > 1) continue;
    const acd::Vec3 q = s.cross(e1);
    const double v = direction.dot(q) / det;
    if (v < 0 || u + v > 1) continue;
    const double t = e2.dot(q) / det;
    if (t > minT) best = std::min(best, t);
  }
  return best;
}

bool deepPoint(const acd::TriMesh& piece, const acd::InsideTest& inside, acd::Vec3& out) {
  std::vector<int> order(piece.faces.size());
  std::iota(order.begin(), order.end(), 0);
  // Largest faces first (ties by index: the result does not depend on anything else).
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return acd::faceNormal(piece, a).squaredNorm() > acd::faceNormal(piece, b).squaredNorm();
  });
  order.resize(std::min<std::size_t>(order.size(), 64));
  const double eps = 1e-9 * acd::boundingBox(piece).size().norm();
  double bestChord = 0.0;
  for (int f : order) {
    const acd::Vec3 n = acd::faceNormal(piece, f);
    if (n.norm() <= 0) continue;
    const acd::Face& tri = piece.faces[f];
    const acd::Vec3 c = (piece.vertices[tri[0]] + piece.vertices[tri[1]] + piece.vertices[tri[2]]) / 3.0;
    const acd::Vec3 d = -n.normalized();
    const double t = firstHit(piece, c, d, eps);
    if (!std::isfinite(t) || t <= bestChord) continue;
    const acd::Vec3 mid = c + 0.5 * t * d;
    if (!inside.inside(mid)) continue;
    bestChord = t;
    out = mid;
  }
  return bestChord > 0;
}

}  // namespace

std::vector<acd::Vec3> insidePoints(const std::vector<acd::TriMesh>& pieces, const acd::Vec3& preferred) {
  std::vector<acd::Vec3> points;
  for (const acd::TriMesh& piece : pieces) {
    if (piece.faces.empty()) continue;
    const acd::InsideTest inside(piece);
    acd::Vec3 p;
    if (inside.inside(preferred))
      points.push_back(preferred);
    else if (deepPoint(piece, inside, p))
      points.push_back(p);
  }
  return points;
}

}  // namespace planner
