// InsideTest (libacd/src/hull/inside.cpp) against independent oracles: the analytic box and torus,
// and the generalised winding number (sum of the triangles' solid angles, Van Oosterom &
// Strackee) on non-convex shapes, for random points and for points on the vertices' x and y
// coordinates, where the +z ray of the library passes through edges and vertices.
#include <acd/algo/inside.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <cmath>
#include <random>

using namespace acd;

namespace {

/// Whether q lies within 1e-9 of a face (in its plane and inside its edges, slightly widened).
bool onSurface(const TriMesh& m, const Vec3& q) {
  for (const Face& f : m.faces) {
    const Vec3 &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    const Vec3 n = (b - a).cross(c - a);
    if (std::abs(n.normalized().dot(q - a)) > 1e-9) continue;
    const double u = (c - b).cross(q - b).dot(n), v = (a - c).cross(q - c).dot(n), w = (b - a).cross(q - a).dot(n);
    const double slack = 1e-9 * n.squaredNorm();
    if (u >= -slack && v >= -slack && w >= -slack) return true;
  }
  return false;
}

/// Points on the surface are skipped: only they may get either answer (documented).
void expectAgreesWithWinding(const TriMesh& m, const std::vector<Vec3>& points) {
  const InsideTest test(m);
  int inside = 0, checked = 0;
  for (const Vec3& q : points) {
    if (onSurface(m, q)) continue;
    const double w = acdtest::windingSummed(m, q);
    EXPECT_NEAR(w, std::round(w), 1e-6) << q.transpose();
    ++checked;
    const bool expected = std::lround(w) == 1;
    inside += expected;
    EXPECT_EQ(test.inside(q), expected) << q.transpose() << " winding " << w;
  }
  EXPECT_GT(checked, static_cast<int>(points.size()) / 2);
  EXPECT_GT(inside, 0);
}

std::vector<Vec3> randomPoints(const TriMesh& m, int count, unsigned seed) {
  Box3 box{m.vertices[0], m.vertices[0]};
  for (const Vec3& v : m.vertices) box.lo = box.lo.cwiseMin(v), box.hi = box.hi.cwiseMax(v);
  const Vec3 pad = 0.1 * box.size();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> out;
  for (int i = 0; i < count; ++i)
    out.push_back(box.lo - pad + (box.size() + 2 * pad).cwiseProduct(acdtest::drawPoint([&] { return u(rng); })));
  return out;
}

}  // namespace

TEST(InsideTest, BoxIsItsInequalities) {
  const TriMesh box = shapes::box(Vec3(-1, -2, -3), Vec3(1, 2, 3));
  const InsideTest test(box);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-4, 4);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 q = acdtest::drawPoint([&] { return u(rng); });
    const bool expected = std::abs(q.x()) < 1 && std::abs(q.y()) < 2 && std::abs(q.z()) < 3;
    EXPECT_EQ(test.inside(q), expected) << q.transpose();
  }
}

// The torus's own inequality, away from its polygonal surface: every facet lies within the two
// chords' sagittas (around the tube and around the axis) of the smooth torus.
TEST(InsideTest, TorusIsItsInequalityAwayFromTheFacets) {
  const double R = 2.0, r = 0.5;
  const int segments = 48, sides = 24;
  const TriMesh torus = shapes::torus(R, r, segments, sides);
  const double sagitta = r * (1 - std::cos(M_PI / sides)) + (R + r) * (1 - std::cos(M_PI / segments)) + 1e-9;
  const double inner = r - sagitta;
  const InsideTest test(torus);
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(-3, 3);
  int checked = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 q = acdtest::drawPoint([&] { return u(rng); }).cwiseProduct(Vec3(1, 1, 1.0 / 3));
    const double tube = std::hypot(std::hypot(q.x(), q.y()) - R, q.z());
    if (tube > inner && tube < r + sagitta) continue;  // within the sagittas: the facets decide
    ++checked;
    EXPECT_EQ(test.inside(q), tube <= inner) << q.transpose();
  }
  EXPECT_GT(checked, 3000);
}

TEST(InsideTest, NonConvexShapesAgreeWithTheWindingNumber) {
  for (const TriMesh& m : {shapes::lShape(), shapes::uShape(), shapes::torus(2.0, 0.5, 16, 8)})
    expectAgreesWithWinding(m, randomPoints(m, 1500, 3));
}

// Queries on the vertices' x and y coordinates: the +z ray then meets edges and vertices
// exactly, which the symbolic perturbation must count once.
TEST(InsideTest, RaysThroughEdgesAndVerticesCountOnce) {
  const TriMesh u = shapes::uShape();
  std::vector<Vec3> points;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> t(0.0, 1.0);
  Box3 box{u.vertices[0], u.vertices[0]};
  for (const Vec3& v : u.vertices) box.lo = box.lo.cwiseMin(v), box.hi = box.hi.cwiseMax(v);
  for (const Vec3& a : u.vertices)
    for (const Vec3& b : u.vertices) {
      const double z = box.lo.z() - 0.5 + (box.size().z() + 1.0) * t(rng);
      points.emplace_back(a.x(), b.y(), z);                                      // on vertex lines
      points.emplace_back(0.5 * (a.x() + b.x()), 0.5 * (a.y() + b.y()), z);      // on edge midlines
    }
  expectAgreesWithWinding(u, points);
}

// A cavity: a box with a smaller, inward-facing box inside it is inside only between the two.
TEST(InsideTest, CavityIsOutside) {
  TriMesh outer = shapes::box(Vec3(0, 0, 0), Vec3(4, 4, 4));
  TriMesh inner = shapes::box(Vec3(1, 1, 1), Vec3(3, 3, 3));
  for (Face& f : inner.faces) std::swap(f[1], f[2]);
  const int base = static_cast<int>(outer.vertices.size());
  outer.vertices.insert(outer.vertices.end(), inner.vertices.begin(), inner.vertices.end());
  for (const Face& f : inner.faces) outer.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  const InsideTest test(outer);
  EXPECT_TRUE(test.inside(Vec3(0.5, 0.5, 0.5)));
  EXPECT_TRUE(test.inside(Vec3(2, 2, 3.5)));
  EXPECT_FALSE(test.inside(Vec3(2, 2, 2)));
  EXPECT_FALSE(test.inside(Vec3(2, 2, 5)));
  expectAgreesWithWinding(outer, randomPoints(outer, 1000, 5));
}
