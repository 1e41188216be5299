// closestPointOnTriangle (libacd/src/hull/closest_point.cpp) against its definition: the answer
// lies on the triangle (non-negative barycentric coordinates, in its plane) and no point of a
// dense barycentric sampling of the triangle is nearer; plus the seven Voronoi regions by hand.
#include <acd/algo/closest_point.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <algorithm>
#include <cmath>
#include <random>

using acd::Vec3;
using acd::closestPointOnTriangle;

namespace {

/// Barycentric coordinates of q in triangle abc (q assumed in its plane), by areas.
Vec3 barycentric(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double area = n.squaredNorm();
  const double u = (c - b).cross(q - b).dot(n) / area;
  const double v = (a - c).cross(q - c).dot(n) / area;
  return Vec3(u, v, 1.0 - u - v);
}

/// Nearest of (k+1)(k+2)/2 points spread over the triangle: an upper bound of the true distance.
double sampledDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int k) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= k; ++i)
    for (int j = 0; i + j <= k; ++j) {
      const double u = double(i) / k, v = double(j) / k;
      best = std::min(best, (p - (a + u * (b - a) + v * (c - a))).norm());
    }
  return best;
}

}  // namespace

TEST(ClosestPoint, TheSevenRegionsOfATriangle) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  // Inside the face: the foot of the perpendicular.
  EXPECT_TRUE(closestPointOnTriangle(Vec3(0.5, 0.5, 3), a, b, c).isApprox(Vec3(0.5, 0.5, 0)));
  // Beyond each corner: the corner.
  EXPECT_EQ(closestPointOnTriangle(Vec3(-1, -1, 1), a, b, c), a);
  EXPECT_EQ(closestPointOnTriangle(Vec3(3, -1, -1), a, b, c), b);
  EXPECT_EQ(closestPointOnTriangle(Vec3(-1, 3, 0), a, b, c), c);
  // Beyond each edge: the foot on that edge.
  EXPECT_TRUE(closestPointOnTriangle(Vec3(1, -2, 1), a, b, c).isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(closestPointOnTriangle(Vec3(-2, 1, -1), a, b, c).isApprox(Vec3(0, 1, 0)));
  EXPECT_TRUE(closestPointOnTriangle(Vec3(2, 2, 0.5), a, b, c).isApprox(Vec3(1, 1, 0)));
}

TEST(ClosestPoint, OnTheTriangleAndNoSampledPointIsNearer) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int t = 0; t < 200; ++t) {
    const Vec3 a = acdtest::drawPoint([&] { return u(rng); });
    const Vec3 b = acdtest::drawPoint([&] { return u(rng); });
    const Vec3 c = acdtest::drawPoint([&] { return u(rng); });
    if ((b - a).cross(c - a).norm() < 1e-2) continue;  // nearly flat: the oracle's areas are unreliable
    const Vec3 p = 2 * acdtest::drawPoint([&] { return u(rng); });
    const Vec3 q = closestPointOnTriangle(p, a, b, c);
    const double scale = std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()});
    const Vec3 n = (b - a).cross(c - a).normalized();
    EXPECT_NEAR(n.dot(q - a), 0.0, 1e-12 * scale) << "not in the plane";
    const Vec3 w = barycentric(q, a, b, c);
    EXPECT_GE(w.minCoeff(), -1e-9) << "outside the triangle: " << w.transpose();
    const double d = (p - q).norm();
    EXPECT_LE(d, sampledDistance(p, a, b, c, 60) + 1e-12) << "a sampled point is nearer";
    // and not much farther than the best sample (the samples are at most scale/60 apart)
    EXPECT_GE(d, sampledDistance(p, a, b, c, 60) - scale / 60.0);
  }
}

TEST(ClosestPoint, DegenerateTriangleGivesItsNearestCorner) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(2, 0, 0);  // collinear
  EXPECT_EQ(closestPointOnTriangle(Vec3(2.5, 1, 0), a, b, c), c);
  EXPECT_EQ(closestPointOnTriangle(Vec3(-0.5, 1, 0), a, b, c), a);
  const Vec3 same(1, 1, 1);
  EXPECT_EQ(closestPointOnTriangle(Vec3(4, 5, 6), same, same, same), same);
}
