// quickHull: a closed surface of triangles with consistent neighbours that bounds every point,
// checked with CGAL's orientation predicate (not the hull's own side test); and convexHull's
// canonical output on top of it, which must not depend on the order of the input points.
#include <acd/algo/quickhull.hpp>
#include <acd/algo/hull.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <random>
#include <set>
#include <string>

using namespace acd;
using acdtest::randomPoints;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
K::Point_3 cgal(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

/// Every triangle's neighbour across each edge holds the edge reversed and names it back; no point
/// lies strictly outside a triangle; every triangle has area.
void expectHullOf(const QuickHull& qh, const std::vector<Vec3>& points) {
  ASSERT_FALSE(qh.degenerate);
  ASSERT_FALSE(qh.failed);
  ASSERT_EQ(qh.faces.size(), qh.across.size());
  ASSERT_GE(qh.faces.size(), 4u);
  EXPECT_EQ(qh.faces.size() % 2, 0u);  // a closed surface of triangles (Euler)
  for (std::size_t f = 0; f < qh.faces.size(); ++f) {
    const auto& v = qh.faces[f];
    EXPECT_FALSE(CGAL::collinear(cgal(points[v[0]]), cgal(points[v[1]]), cgal(points[v[2]]))) << "flat triangle " << f;
    for (int k = 0; k < 3; ++k) {
      const int g = qh.across[f][k];
      ASSERT_GE(g, 0);
      ASSERT_LT(g, static_cast<int>(qh.faces.size()));
      const auto& w = qh.faces[g];
      int back = -1;
      for (int j = 0; j < 3; ++j)
        if (w[j] == v[(k + 1) % 3] && w[(j + 1) % 3] == v[k]) back = j;
      ASSERT_GE(back, 0) << "face " << f << " edge " << k << ": the neighbour lacks the reversed edge";
      EXPECT_EQ(qh.across[g][back], static_cast<int>(f));
    }
    // CGAL's orientation is positive when the fourth point is on the side the triangle's normal
    // (counter-clockwise seen from there) points to: outside.
    for (const Vec3& p : points)
      ASSERT_NE(CGAL::orientation(cgal(points[v[0]]), cgal(points[v[1]]), cgal(points[v[2]]), cgal(p)), CGAL::POSITIVE)
          << "a point outside face " << f;
  }
}

std::vector<Vec3> grid(int nx, int ny, int nz) {
  std::vector<Vec3> points;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) points.emplace_back(0.1 * i, 0.3 * j - 1.0, 0.7 * k);
  return points;
}

}  // namespace

TEST(QuickHull, RandomCloudsAndGridsAreBoundedByConsistentTriangles) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expectHullOf(quickHull(randomPoints(400, seed)), randomPoints(400, seed));
  }
  const std::vector<Vec3> g = grid(6, 5, 4);  // points on every face, edge and inside
  expectHullOf(quickHull(g), g);
}

TEST(QuickHull, PointsOnAPlaneOrALineAreDegenerate) {
  std::vector<Vec3> planar, line;
  for (int i = 0; i < 20; ++i) planar.emplace_back(0.1 * i, 0.37 * (i % 7), 2.0), line.emplace_back(i, 2.0 * i, -i);
  EXPECT_TRUE(quickHull(planar).degenerate);
  EXPECT_TRUE(quickHull(line).degenerate);
  EXPECT_TRUE(quickHull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}).degenerate);
}

TEST(QuickHull, ATetrahedronIsFourTriangles) {
  const std::vector<Vec3> t{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.1, 0.1, 0.1)};
  const QuickHull qh = quickHull(t);
  expectHullOf(qh, t);
  EXPECT_EQ(qh.faces.size(), 4u);
}

TEST(QuickHull, CoordinatesBeyondTheIntegersOfADoubleAreNoDegeneracy) {
  // At 1e17 a double's spacing is 16: adding 1 to a coordinate changes nothing, which must not
  // make three corners of a tetrahedron look collinear.
  const Vec3 a(1e17, 1e17, 1e17);
  const std::vector<Vec3> t{a, a + Vec3(1e16, 0, 0), a + Vec3(0, 1e16, 0), a + Vec3(0, 0, 1e16)};
  const QuickHull qh = quickHull(t);
  expectHullOf(qh, t);
  EXPECT_EQ(qh.faces.size(), 4u);
}

TEST(TriangleSide, SignsBelowTheDoubleRoundingAreExact) {
  // A point 2^-60 above the plane z = 0.5 of a large triangle: the double evaluation cannot
  // tell it from the plane, the exact one can.
  const TriangleSide side(Vec3(0, 0, 0.5), Vec3(1, 0, 0.5), Vec3(0, 1, 0.5));
  EXPECT_EQ(side.sign(Vec3(0.3, 0.3, 0.5)), 0);
  EXPECT_EQ(side.sign(Vec3(0.3, 0.3, std::nextafter(0.5, 1.0))), 1);
  EXPECT_EQ(side.sign(Vec3(0.3, 0.3, std::nextafter(0.5, 0.0))), -1);
  // Products that underflow: a point one subnormal ulp above the plane z = 0, and a triangle of
  // 1e-170 sides (its normal's components underflow to zero in doubles).
  const TriangleSide floor(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
  EXPECT_EQ(floor.sign(Vec3(0.5, 0.5, std::numeric_limits<double>::denorm_min())), 1);
  EXPECT_EQ(floor.sign(Vec3(0.5, 0.5, -std::numeric_limits<double>::denorm_min())), -1);
  EXPECT_EQ(floor.sign(Vec3(0.5, 0.5, 0.0)), 0);
  const TriangleSide tiny(Vec3(0, 0, 0), Vec3(1e-170, 0, 0), Vec3(0, 1e-170, 0));
  EXPECT_EQ(tiny.sign(Vec3(0.3, 0.3, 1.0)), 1);
  EXPECT_EQ(tiny.sign(Vec3(0.3, 0.3, -1.0)), -1);
  // A tilted plane through points that are not on a grid: the sign agrees with CGAL's.
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 p(0.1, 0.2, 0.3), q(0.9, -0.3, 0.35), r(-0.4, 0.8, 0.31);
  const TriangleSide tilted(p, q, r);
  for (int i = 0; i < 2000; ++i) {
    // Points on the line from p towards q, off by a few ulps: nearly in the plane.
    const double t = u(rng);
    Vec3 s = p + t * (q - p);
    s.z() = std::nextafter(s.z(), i % 3 == 0 ? 1.0 : i % 3 == 1 ? -1.0 : s.z());
    const CGAL::Orientation o = CGAL::orientation(cgal(p), cgal(q), cgal(r), cgal(s));
    EXPECT_EQ(tilted.sign(s), o == CGAL::POSITIVE ? 1 : o == CGAL::NEGATIVE ? -1 : 0) << "point " << i;
  }
}

TEST(Hull, TheResultDoesNotDependOnTheOrderOfThePoints) {
  // A grid has points on the hull's edges and inside its facets: whichever order quickhull meets
  // them in, the hull is its 8 corners. (A rectangle's triangulation starts at its corner of
  // smallest input index, so it follows the order; a cloud's facets are triangles.)
  std::vector<std::pair<std::string, std::vector<Vec3>>> cases{{"grid", grid(7, 5, 4)},
                                                               {"cloud", randomPoints(3000, 11)}};
  for (auto& [name, points] : cases) {
    SCOPED_TRACE(name);
    const ConvexHull reference = convexHull(points);
    ASSERT_FALSE(reference.degenerate);
    if (name == "grid") EXPECT_EQ(reference.mesh.vertices.size(), 8u);
    std::mt19937_64 rng(3);
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<int> order(points.size());
      for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
      std::shuffle(order.begin(), order.end(), rng);
      std::vector<Vec3> shuffled;
      for (int i : order) shuffled.push_back(points[i]);
      const ConvexHull hull = convexHull(shuffled);
      // The same corners; faces compared as sets of positions.
      std::set<std::array<double, 9>> a, b;
      for (const auto* h : {&reference, &hull})
        for (const Face& f : h->mesh.faces) {
          std::array<Vec3, 3> c{h->mesh.vertices[f[0]], h->mesh.vertices[f[1]], h->mesh.vertices[f[2]]};
          // rotate to the lexicographically smallest corner, keeping orientation
          int lo = 0;
          for (int k = 1; k < 3; ++k)
            if (std::lexicographical_compare(c[k].data(), c[k].data() + 3, c[lo].data(), c[lo].data() + 3)) lo = k;
          std::array<double, 9> key;
          for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d) key[3 * k + d] = c[(lo + k) % 3][d];
          (h == &reference ? a : b).insert(key);
        }
      EXPECT_EQ(hull.mesh.vertices.size(), reference.mesh.vertices.size()) << "trial " << trial;
      if (name == "cloud") EXPECT_EQ(a, b) << "trial " << trial;  // no coplanar facets: one triangulation
    }
  }
}

// Many small degenerate clouds: points of a small integer lattice (coplanar and collinear
// everywhere), the same lattice turned by a rotation that is not exact (coplanar only up to
// rounding), and lattice points nudged by one ulp. Every hull bounds its points (CGAL's
// orientation) and has exactly the corners of CGAL's stock hull.
TEST(QuickHull, DegenerateLatticesAgreeWithCgalsStockHull) {
  using K2 = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::mt19937_64 rng(21);
  std::uniform_int_distribution<int> cell(0, 3);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  int checked = 0;
  for (int trial = 0; trial < 150; ++trial) {
    std::set<std::array<int, 3>> cells;
    const int n = 6 + trial % 40;
    while (static_cast<int>(cells.size()) < n) cells.insert({cell(rng), cell(rng), cell(rng)});
    std::vector<Vec3> points;
    for (const auto& c : cells) {
      Vec3 p(c[0], c[1], c[2]);
      if (trial % 3 == 1) p = turn * p;
      if (trial % 3 == 2) p.x() = std::nextafter(p.x(), rng() % 2 ? 10.0 : -10.0);
      points.push_back(p);
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    const ConvexHull hull = convexHull(points);
    std::vector<K2::Point_3> pts;
    for (const Vec3& p : points) pts.push_back(cgal(p));
    // Three points not on a line, if any: no volume means every point is in their plane.
    int third = -1;
    for (int i = 2; i < static_cast<int>(pts.size()) && third < 0; ++i)
      if (!CGAL::collinear(pts[0], pts[1], pts[i])) third = i;
    auto inPlane = [&](const std::vector<K2::Point_3>& set) {
      if (set.size() < 4) return true;
      int c = -1;
      for (int i = 2; i < static_cast<int>(set.size()) && c < 0; ++i)
        if (!CGAL::collinear(set[0], set[1], set[i])) c = i;
      if (c < 0) return true;
      for (const auto& q : set)
        if (!CGAL::coplanar(set[0], set[1], set[c], q)) return false;
      return true;
    };
    ASSERT_EQ(hull.degenerate, third < 0 || inPlane(pts));
    if (hull.degenerate) continue;
    ++checked;
    // Every point inside or on every face.
    for (const Face& f : hull.mesh.faces)
      for (const auto& q : pts)
        ASSERT_NE(CGAL::orientation(cgal(hull.mesh.vertices[f[0]]), cgal(hull.mesh.vertices[f[1]]), cgal(hull.mesh.vertices[f[2]]), q),
                  CGAL::POSITIVE);
    // The corners: CGAL's stock hull's vertices that are corners of its facets.
    CGAL::Surface_mesh<K2::Point_3> sm;
    CGAL::convex_hull_3(pts.begin(), pts.end(), sm);
    std::set<std::array<double, 3>> stock, ours;
    for (auto v : sm.vertices()) {
      // A corner is not inside the hull of the other points.
      std::vector<K2::Point_3> others;
      for (const auto& q : pts)
        if (q != sm.point(v)) others.push_back(q);
      bool outside = inPlane(others);  // the rest is flat and v is off it (the whole is not flat)
      CGAL::Surface_mesh<K2::Point_3> rest;
      if (!outside) CGAL::convex_hull_3(others.begin(), others.end(), rest);
      for (auto f : rest.faces()) {
        auto h = rest.halfedge(f);
        if (CGAL::orientation(rest.point(rest.source(h)), rest.point(rest.target(h)), rest.point(rest.target(rest.next(h))),
                              sm.point(v)) == CGAL::POSITIVE)
          outside = true;
      }
      const auto& p = sm.point(v);
      if (outside) stock.insert({p.x(), p.y(), p.z()});
    }
    for (const Vec3& v : hull.mesh.vertices) ours.insert({v.x(), v.y(), v.z()});
    EXPECT_EQ(ours, stock);
  }
  EXPECT_GT(checked, 100);
}

namespace {

// collinear() decides in doubles where a component of the normal stands clear of its rounding and
// exactly otherwise: it must agree with CGAL's exact predicate on points that are collinear only
// in exact arithmetic, one unit in the last place off it, tiny, huge, and far from the origin.
TEST(Collinear, AgreesWithCgalsExactPredicate) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int collinearSeen = 0, tested = 0;
  for (double scale : {1e-200, 1e-9, 1.0, 1e9, 1e200})
    for (double shift : {0.0, 1e6})
      for (int n = 0; n < 400; ++n) {
        const Vec3 a = Vec3(unit(random), unit(random), unit(random)) * scale + Vec3::Constant(shift * scale);
        const Vec3 d = Vec3(unit(random), unit(random), unit(random)) * scale;
        // b and c on the line through a along d where the doubles allow it exactly (steps of a
        // power of two along an axis-aligned d), or near it, then perhaps one ulp off.
        Vec3 step = d;
        if (n % 3 == 0) step = Vec3(d.x(), 0.0, 0.0);
        if (n % 3 == 1) step = Vec3(d.x(), d.x(), 0.0);
        Vec3 b = a + 0.5 * step, c = a + 2.0 * step;
        if (n % 4 == 1) c.y() = std::nextafter(c.y(), std::numeric_limits<double>::infinity());
        if (n % 4 == 2) b.z() = std::nextafter(b.z(), -std::numeric_limits<double>::infinity());
        const bool exact = CGAL::collinear(cgal(a), cgal(b), cgal(c));
        EXPECT_EQ(collinear(a, b, c), exact) << "scale " << scale << " shift " << shift << " case " << n;
        EXPECT_EQ(collinear(c, a, b), exact);
        collinearSeen += exact;
        ++tested;
      }
  EXPECT_GT(collinearSeen, tested / 10);  // the exact branch was taken, both ways
  EXPECT_LT(collinearSeen, tested);
  EXPECT_TRUE(collinear(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(5, 6, 7)));  // a repeated point
}

}  // namespace
