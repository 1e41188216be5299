// convexHull: hull vertices traced back to the input, canonical facets, exact predicates. The
// reference is CGAL's convex_hull_3 with its stock traits, which shares neither the predicates
// nor the interior-point elimination of libacd's hull.
#include <acd/algo/hull.hpp>
#include <acd/algo/shapes.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>

using namespace acd;
using acdtest::randomPoints;

namespace {


void expectConvexHullOf(const ConvexHull& hull, const std::vector<Vec3>& points) {
  ASSERT_FALSE(hull.degenerate);
  ASSERT_FALSE(hull.mesh.empty());
  EXPECT_TRUE(isClosedOriented(hull.mesh));
  EXPECT_GT(signedVolume(hull.mesh), 0.0);
  ASSERT_EQ(hull.source.size(), hull.mesh.vertices.size());
  for (std::size_t i = 0; i < hull.source.size(); ++i) {
    ASSERT_GE(hull.source[i], 0);
    ASSERT_LT(hull.source[i], static_cast<int>(points.size()));
    EXPECT_EQ(hull.mesh.vertices[i], points[hull.source[i]]) << "hull vertex " << i;
  }
  for (int f = 0; f < static_cast<int>(hull.mesh.faces.size()); ++f) {
    const Vec3 n = faceNormal(hull.mesh, f).normalized();
    const double d = n.dot(hull.mesh.vertices[hull.mesh.faces[f][0]]);
    double worst = -1e300;
    for (const Vec3& p : points) worst = std::max(worst, n.dot(p) - d);
    EXPECT_LE(worst, 1e-9) << "facet " << f;
  }
}

/// Indices (first occurrence) of the vertices of CGAL's stock hull of `points`.
std::set<int> stockHullVertices(const std::vector<Vec3>& points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::map<std::array<double, 3>, int> first;
  std::vector<K::Point_3> pts;
  for (int i = 0; i < static_cast<int>(points.size()); ++i)
    if (first.emplace(std::array<double, 3>{points[i].x(), points[i].y(), points[i].z()}, i).second)
      pts.emplace_back(points[i].x(), points[i].y(), points[i].z());
  CGAL::Surface_mesh<K::Point_3> sm;
  CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
  std::set<int> out;
  for (auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    out.insert(first.at({p.x(), p.y(), p.z()}));
  }
  return out;
}

/// A sphere of random centre and radius cut by a random oblique plane (offset from the centre by
/// up to `spread`): the vertices below the plane and the points where edges cross it, as a cut
/// piece's vertices are (coplanar only up to rounding).
struct CutSphere {
  TriMesh sphere;
  Vec3 normal;
  double offset;
  std::vector<Vec3> points;
};

CutSphere cutSphere(std::mt19937_64& rng, int level, double spread) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  CutSphere c;
  const Vec3 centre = acdtest::drawPoint([&] { return u(rng); });
  c.sphere = shapes::icosphere(centre, 1.0 + 0.5 * u(rng), level);
  c.normal = acdtest::drawPoint([&] { return u(rng); }).normalized();
  c.offset = c.normal.dot(boundingBox(c.sphere).center()) + spread * u(rng);
  for (const Vec3& v : c.sphere.vertices)
    if (c.normal.dot(v) <= c.offset) c.points.push_back(v);
  for (const Face& f : c.sphere.faces)
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = c.sphere.vertices[f[k]], &b = c.sphere.vertices[f[(k + 1) % 3]];
      const double da = c.normal.dot(a) - c.offset, db = c.normal.dot(b) - c.offset;
      if (da < 0 && db > 0) c.points.push_back(a + da / (da - db) * (b - a));
    }
  return c;
}

/// A cut sphere's points plus `inside` points inside it and below the plane.
std::vector<Vec3> cutSpherePoints(std::uint64_t seed, int level, int inside) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  CutSphere c = cutSphere(rng, level, 0.3);
  const Vec3 centre = boundingBox(c.sphere).center();
  const double r = 0.5 * boundingBox(c.sphere).size().x();
  for (int i = 0; i < inside; ++i) {
    const Vec3 p = centre + 0.9 * r * acdtest::drawPoint([&] { return u(rng); }) / std::sqrt(3.0);
    if (c.normal.dot(p) < c.offset) c.points.push_back(p);
  }
  return c.points;
}

}  // namespace

// ------------------------------------------------------------------ hull

TEST(Hull, RandomPointsInACube) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    const auto points = randomPoints(500, seed);
    expectConvexHullOf(convexHull(points), points);
  }
}

TEST(Hull, PointsOnASphereAreAllHullVertices) {
  const TriMesh sphere = shapes::icosphere(Vec3(1, 2, 3), 2.0, 2);
  const ConvexHull hull = convexHull(sphere.vertices);
  expectConvexHullOf(hull, sphere.vertices);
  EXPECT_EQ(hull.mesh.vertices.size(), sphere.vertices.size());
  std::set<int> sources(hull.source.begin(), hull.source.end());
  EXPECT_EQ(sources.size(), sphere.vertices.size());
}

TEST(Hull, InteriorPointsAreNotHullVertices) {
  std::vector<Vec3> points = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)).vertices;
  const auto inner = randomPoints(100, 9);
  for (const Vec3& p : inner) points.push_back(Vec3(0.5, 0.5, 0.5) + 0.4 * p);
  const ConvexHull hull = convexHull(points);
  expectConvexHullOf(hull, points);
  EXPECT_EQ(hull.mesh.vertices.size(), 8u);
  for (int s : hull.source) EXPECT_LT(s, 8);
  EXPECT_NEAR(signedVolume(hull.mesh), 1.0, 1e-14);
}

TEST(Hull, DuplicatePointsMapToTheFirstOccurrence) {
  std::vector<Vec3> points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                              Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0.1, 0.1, 0.1)};
  const ConvexHull hull = convexHull(points);
  expectConvexHullOf(hull, points);
  EXPECT_EQ(hull.mesh.vertices.size(), 4u);
  std::set<int> sources(hull.source.begin(), hull.source.end());
  EXPECT_EQ(sources, std::set<int>({0, 1, 2, 3}));
  // A repeat before its first occurrence's index in sorted order, and -0 against +0: the first
  // occurrence in input order still wins.
  const std::vector<Vec3> signedZeros = {Vec3(1, 1, 1), Vec3(-0.0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0),
                                         Vec3(0, 0, 1), Vec3(0, -0.0, 0), Vec3(1, 1, 1)};
  const ConvexHull z = convexHull(signedZeros);
  EXPECT_EQ(std::set<int>(z.source.begin(), z.source.end()), std::set<int>({0, 1, 2, 3, 4}));
}

TEST(Hull, GridPointsWithCollinearAndCoplanarPointsGiveNoDegenerateFacets) {
  // Points on a 5x4x3 grid: many coplanar points per hull face and collinear points on its edges.
  std::vector<Vec3> points;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) points.emplace_back(0.5 * i, 0.25 * j + 0.1, 0.3 * k);
  const ConvexHull hull = convexHull(points);
  expectConvexHullOf(hull, points);
  EXPECT_NEAR(signedVolume(hull.mesh), 2.0 * 0.75 * 0.6, 1e-12);
  for (int f = 0; f < static_cast<int>(hull.mesh.faces.size()); ++f)
    EXPECT_GT(0.5 * faceNormal(hull.mesh, f).norm(), 1e-6) << "zero-area hull facet " << f;
}

// Points on a plane section, computed in floating point, are coplanar only up to rounding. The
// exact hull once triangulated its planar facets with triangles on (nearly) collinear corners,
// areas ~1e-18 whose normals were noise (points up to ~2e-3 outside their planes), and
// measureConcavity took bridge planes from them. convexHull now clips the fattest ear first and
// skips exactly collinear corners; this test, disabled until then, checks it on 60 oblique cuts.
TEST(Hull, PointsOfACutSectionGiveFacetPlanesThatBoundThePoints) {
  // Spheres cut obliquely: each section's points are coplanar up to rounding.
  std::mt19937_64 rng(7);
  for (int level : {2, 3, 4})
    for (int trial = 0; trial < 20; ++trial) {
      SCOPED_TRACE("level " + std::to_string(level) + " trial " + std::to_string(trial));
      const std::vector<Vec3> points = cutSphere(rng, level, 0.5).points;
      const ConvexHull hull = convexHull(points);
      expectConvexHullOf(hull, points);
      int slivers = 0;
      for (int f = 0; f < static_cast<int>(hull.mesh.faces.size()); ++f) slivers += faceNormal(hull.mesh, f).norm() < 1e-14;
      EXPECT_EQ(slivers, 0) << "hull facets with area below 5e-15";
    }
}

TEST(Hull, DegenerateInputs) {
  EXPECT_TRUE(convexHull({}).degenerate);
  EXPECT_TRUE(convexHull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}).degenerate);
  std::vector<Vec3> planar;
  for (const Vec3& p : randomPoints(50, 4)) planar.emplace_back(p.x(), p.y(), 0.25);
  const ConvexHull h = convexHull(planar);
  EXPECT_TRUE(h.degenerate);
  EXPECT_TRUE(h.mesh.empty());
  // A coordinate that is no number: no hull, rather than one built on it.
  EXPECT_TRUE(convexHull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1),
                          Vec3(std::nan(""), 0, 0)}).degenerate);
}

// Large inputs go through the interior-point elimination and all through the hull's own
// predicates: the vertex set must be exactly CGAL's, on cut sections (coplanar up to rounding),
// grids (exactly coplanar and collinear points) and random clouds.
TEST(Hull, SameVerticesAsCgalsStockHullOnLargeAndDegenerateInputs) {
  std::vector<std::pair<std::string, std::vector<Vec3>>> cases;
  for (std::uint64_t seed : {1u, 2u, 3u, 4u}) {
    cases.push_back({"cut sphere level 4, seed " + std::to_string(seed), cutSpherePoints(seed, 4, 2000)});
    cases.push_back({"cut sphere level 5, seed " + std::to_string(seed), cutSpherePoints(seed, 5, 500)});
    cases.push_back({"cloud, seed " + std::to_string(seed), randomPoints(5000, seed + 10)});
  }
  std::vector<Vec3> grid;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 10; ++j)
      for (int k = 0; k < 8; ++k) grid.emplace_back(0.1 * i, 0.3 * j - 1.0, 0.7 * k);
  cases.push_back({"grid", grid});
  for (const auto& [name, points] : cases) {
    SCOPED_TRACE(name);
    ASSERT_GE(points.size(), 256u);  // large enough for the elimination
    const ConvexHull hull = convexHull(points);
    expectConvexHullOf(hull, points);
    EXPECT_EQ(std::set<int>(hull.source.begin(), hull.source.end()), stockHullVertices(points));
  }
}

TEST(Hull, PointsOnASphereAroundManyInsideAreExactlyTheHullVertices) {
  // 3000 random directions at radius 2 and 30000 points of radius <= 1.9: by construction every
  // sphere point is extreme (neighbours are far apart next to rounding) and no inner point is.
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  std::vector<Vec3> points;
  for (int i = 0; i < 3000; ++i) points.push_back(2.0 * acdtest::drawPoint([&] { return g(rng); }).normalized());
  for (const Vec3& p : randomPoints(30000, 6, true)) points.push_back(1.9 * p);
  const ConvexHull hull = convexHull(points);
  expectConvexHullOf(hull, points);
  std::set<int> expected;
  for (int i = 0; i < 3000; ++i) expected.insert(i);
  EXPECT_EQ(std::set<int>(hull.source.begin(), hull.source.end()), expected);
  // Volume below the ball's (4/3 pi 8) and above the 0.95-scaled ball's.
  const double ball = 4.0 / 3.0 * std::acos(-1.0) * 8.0;
  EXPECT_LT(signedVolume(hull.mesh), ball);
  EXPECT_GT(signedVolume(hull.mesh), 0.95 * 0.95 * 0.95 * ball);
}
