#include <acd/algo/knots.hpp>

#include <algorithm>

namespace acd {

namespace {
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}
}  // namespace

std::vector<int> douglasPeucker(const std::vector<Vec2>& polyline, double tolerance) {
  const int n = static_cast<int>(polyline.size());
  if (n <= 2) {
    std::vector<int> all(n);
    for (int i = 0; i < n; ++i) all[i] = i;
    return all;
  }
  std::vector<char> keep(n, 0);
  keep[0] = keep[n - 1] = 1;
  std::vector<std::pair<int, int>> stack{{0, n - 1}};  // explicit stack: long boundaries must not overflow
  while (!stack.empty()) {
    const auto [lo, hi] = stack.back();
    stack.pop_back();
    int far = -1;
    double farDist = tolerance;
    for (int i = lo + 1; i < hi; ++i) {
      const double d = distanceToSegment(polyline[i], polyline[lo], polyline[hi]);
      if (d > farDist) farDist = d, far = i;
    }
    if (far < 0) continue;
    keep[far] = 1;
    stack.emplace_back(lo, far);
    stack.emplace_back(far, hi);
  }
  std::vector<int> kept;
  for (int i = 0; i < n; ++i)
    if (keep[i]) kept.push_back(i);
  return kept;
}

std::vector<int> findKnots(const std::vector<Vec2>& profile, double delta) {
  const std::vector<int> kept = douglasPeucker(profile, delta);
  std::vector<int> knots;
  for (std::size_t k = 1; k + 1 < kept.size(); ++k) {
    const Vec2 in = profile[kept[k]] - profile[kept[k - 1]];
    const Vec2 out = profile[kept[k + 1]] - profile[kept[k]];
    const double turn = in.x() * out.y() - in.y() * out.x();  // < 0: turns clockwise, a peak
    if (turn < 0 && profile[kept[k]].y() > delta) knots.push_back(kept[k]);
  }
  return knots;
}

}  // namespace acd
