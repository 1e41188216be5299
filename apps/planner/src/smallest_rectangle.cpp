#include "smallest_rectangle.hpp"

#include <algorithm>
#include <cmath>

namespace planner {

namespace {

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

Rectangle2 smallestRectangle(const std::vector<Point2>& points) {
  const std::vector<Point2> hull = convexHull(points);
  // Rotating calipers: the smallest rectangle has a side along a hull edge.
  Rectangle2 best;
  double bestArea = INFINITY;
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
      best.side = d;
      best.half[0] = 0.5 * (hi[0] - lo[0]), best.half[1] = 0.5 * (hi[1] - lo[1]);
      const double s = 0.5 * (lo[0] + hi[0]), t = 0.5 * (lo[1] + hi[1]);
      best.middle = {s * d[0] - t * d[1], s * d[1] + t * d[0]};
    }
  }
  return best;
}

}  // namespace planner
