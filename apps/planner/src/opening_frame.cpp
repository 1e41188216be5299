#include "opening_frame.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace planner {

namespace {

using Point2 = std::array<double, 2>;

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

/// Andrew's monotone chain: the hull counter-clockwise, no collinear points.
std::vector<Point2> convexHull(std::vector<Point2> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Point2> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

OpeningFrame openingFrame(const Opening& opening) {
  OpeningFrame f;
  f.normal = opening.normal.normalized();
  // A basis of the plane: the coordinate axis least aligned with the normal, made orthogonal.
  int least = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(f.normal[i]) < std::abs(f.normal[least])) least = i;
  const acd::Vec3 e1 = (acd::Vec3::Unit(least) - f.normal[least] * f.normal).normalized();
  const acd::Vec3 e2 = f.normal.cross(e1);
  std::vector<Point2> points;
  for (const acd::Vec3& p : opening.triangles.vertices) {
    const acd::Vec3 d = p - opening.centroid;
    points.push_back({d.dot(e1), d.dot(e2)});
  }
  const std::vector<Point2> hull = convexHull(points);
  // Rotating calipers: the smallest rectangle has a side along a hull edge.
  double bestArea = INFINITY;
  Point2 bestDir{1, 0}, bestMid{0, 0};
  double bestHalf[2] = {0, 0};
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point2& a = hull[i];
    const Point2& b = hull[(i + 1) % hull.size()];
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (len <= 0) continue;
    const Point2 d{(b[0] - a[0]) / len, (b[1] - a[1]) / len};
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (const Point2& q : hull) {
      const double s = q[0] * d[0] + q[1] * d[1], t = -q[0] * d[1] + q[1] * d[0];
      lo[0] = std::min(lo[0], s), hi[0] = std::max(hi[0], s);
      lo[1] = std::min(lo[1], t), hi[1] = std::max(hi[1], t);
    }
    const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
    if (area < bestArea * (1 - 1e-12)) {
      bestArea = area;
      bestDir = d;
      bestHalf[0] = 0.5 * (hi[0] - lo[0]), bestHalf[1] = 0.5 * (hi[1] - lo[1]);
      const double s = 0.5 * (lo[0] + hi[0]), t = 0.5 * (lo[1] + hi[1]);
      bestMid = {s * d[0] - t * d[1], s * d[1] + t * d[0]};
    }
  }
  acd::Vec3 side = bestDir[0] * e1 + bestDir[1] * e2;
  acd::Vec3 across = f.normal.cross(side);
  if (bestHalf[1] > bestHalf[0]) std::swap(side, across), std::swap(bestHalf[0], bestHalf[1]);
  f.longSide = side.normalized();
  f.shortSide = f.normal.cross(f.longSide);
  f.halfLong = bestHalf[0];
  f.halfShort = bestHalf[1];
  f.center = opening.centroid + bestMid[0] * e1 + bestMid[1] * e2;
  return f;
}

}  // namespace planner
