// cutByPlane on hand-made cases: generic, through vertices and edges, coplanar with faces, missing.
#include <acd/algo/cut.hpp>
#include <acd/mesh.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

using namespace acd;

namespace {

double totalVolume(const std::vector<TriMesh>& pieces) {
  double v = 0;
  for (const auto& m : pieces) v += signedVolume(m);
  return v;
}

/// Every piece is closed and outward, lies on its side of the plane, and the volumes add up.
void expectValidCut(const TriMesh& mesh, const Plane& plane, const CutResult& r, double relTol = 1e-9) {
  ASSERT_TRUE(r.ok) << r.error;
  const double n = plane.normal.norm();
  for (const auto* side : {&r.below, &r.above})
    for (const auto& piece : *side) {
      EXPECT_TRUE(isClosedOriented(piece));
      EXPECT_GT(signedVolume(piece), 0.0);
      for (const Face& f : piece.faces)
        for (int v : f) {
          const double d = plane.signedDistance(piece.vertices[v]);
          if (side == &r.below)
            EXPECT_LE(d, 1e-9 * std::max(1.0, std::abs(plane.offset / n)));
          else
            EXPECT_GE(d, -1e-9 * std::max(1.0, std::abs(plane.offset / n)));
        }
    }
  const double v = signedVolume(mesh);
  EXPECT_NEAR(totalVolume(r.below) + totalVolume(r.above), v, relTol * std::abs(v));
}

TriMesh tetrahedron() {
  TriMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

}  // namespace

TEST(Cut, TetrahedronFixtureIsClosed) {
  const TriMesh t = tetrahedron();
  EXPECT_TRUE(isClosedOriented(t));
  EXPECT_NEAR(signedVolume(t), 1.0 / 6.0, 1e-15);
}

TEST(Cut, BoxThroughItsMiddle) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  for (int axis = 0; axis < 3; ++axis) {
    SCOPED_TRACE(axis);
    const Plane plane{Vec3::Unit(axis), 0.5};
    const CutResult r = cutByPlane(box, plane);
    expectValidCut(box, plane, r);
    ASSERT_EQ(r.below.size(), 1u);
    ASSERT_EQ(r.above.size(), 1u);
    EXPECT_NEAR(signedVolume(r.below[0]), 0.5, 1e-12);
    EXPECT_NEAR(signedVolume(r.above[0]), 0.5, 1e-12);
    const Box3 b = boundingBox(r.below[0]), a = boundingBox(r.above[0]);
    EXPECT_NEAR(b.hi[axis], 0.5, 1e-15);
    EXPECT_NEAR(a.lo[axis], 0.5, 1e-15);
  }
}

TEST(Cut, BoxObliquePlaneNormalNeedNotBeUnit) {
  const TriMesh box = shapes::box(Vec3(-1, -2, -3), Vec3(2, 1, 0.5));
  const Plane plane{Vec3(3.0, -1.5, 6.0), 0.7};
  const CutResult r = cutByPlane(box, plane);
  expectValidCut(box, plane, r);
  EXPECT_EQ(r.below.size(), 1u);
  EXPECT_EQ(r.above.size(), 1u);
}

TEST(Cut, TetrahedronPlaneThroughOneVertex) {
  const TriMesh t = tetrahedron();
  // n = (1, -1, 0.2), offset 0.2: through the apex (0,0,1) only; origin and (0,1,0) below, (1,0,0) above.
  const Plane plane{Vec3(1, -1, 0.2), 0.2};
  const CutResult r = cutByPlane(t, plane);
  expectValidCut(t, plane, r, 1e-12);
  ASSERT_EQ(r.below.size(), 1u);
  ASSERT_EQ(r.above.size(), 1u);
  // The apex is shared by both pieces and was not moved.
  for (const auto* side : {&r.below, &r.above}) {
    bool apex = false;
    for (const Vec3& v : (*side)[0].vertices) apex |= v == Vec3(0, 0, 1);
    EXPECT_TRUE(apex);
  }
  // Above: the tetrahedron apex, (1,0,0) and the two section points on edges 0-1 and 1-2.
  // Edge 0-1 is cut at x = 0.2, edge 1-2 at (0.6, 0.4, 0): the piece is the tetrahedron
  // (1,0,0),(0.2,0,0),(0.6,0.4,0),(0,0,1) of volume |det| / 6.
  const Vec3 a(1, 0, 0), b(0.2, 0, 0), c(0.6, 0.4, 0), d(0, 0, 1);
  const double expected = std::abs((b - a).cross(c - a).dot(d - a)) / 6.0;
  EXPECT_NEAR(signedVolume(r.above[0]), expected, 1e-15);
  EXPECT_NEAR(signedVolume(r.below[0]), 1.0 / 6.0 - expected, 1e-15);
}

TEST(Cut, TetrahedronPlaneTouchingOnlyAVertex) {
  const TriMesh t = tetrahedron();
  const Plane plane{Vec3(0, 0, 1), 1.0};  // z = 1 touches the apex only
  const CutResult r = cutByPlane(t, plane);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.above.size(), 0u);
  ASSERT_EQ(r.below.size(), 1u);
  EXPECT_NEAR(signedVolume(r.below[0]), 1.0 / 6.0, 1e-15);
}

TEST(Cut, BoxPlaneThroughOneCorner) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  // (1, 2, -2.5).x = 0 contains the corner (0,0,0) and no other corner.
  const Plane plane{Vec3(1, 2, -2.5), 0.0};
  const CutResult r = cutByPlane(box, plane);
  expectValidCut(box, plane, r, 1e-12);
  EXPECT_EQ(r.below.size(), 1u);
  EXPECT_EQ(r.above.size(), 1u);
}

TEST(Cut, BoxPlaneThroughThreeCornersCutsOffACornerTetrahedron) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const Plane plane{Vec3(1, 1, 1), 1.0};
  const CutResult r = cutByPlane(box, plane);
  expectValidCut(box, plane, r, 1e-12);
  ASSERT_EQ(r.below.size(), 1u);
  ASSERT_EQ(r.above.size(), 1u);
  EXPECT_NEAR(signedVolume(r.below[0]), 1.0 / 6.0, 1e-14);
  EXPECT_NEAR(signedVolume(r.above[0]), 5.0 / 6.0, 1e-14);
  // The corner tetrahedron: the three corners on the plane were kept, not moved.
  const TriMesh corner = compact(r.below[0]);
  for (const Vec3& c : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)})
    EXPECT_NE(std::find(corner.vertices.begin(), corner.vertices.end(), c), corner.vertices.end()) << c.transpose();
}

TEST(Cut, BoxDiagonalPlaneThroughTwoOppositeEdgesGivesTwoPrisms) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const Plane plane{Vec3(1, -1, 0), 0.0};  // x = y: contains the edges x=y=0 and x=y=1
  const CutResult r = cutByPlane(box, plane);
  expectValidCut(box, plane, r, 1e-12);
  ASSERT_EQ(r.below.size(), 1u);
  ASSERT_EQ(r.above.size(), 1u);
  for (const auto* side : {&r.below, &r.above}) {
    const TriMesh piece = compact((*side)[0]);
    EXPECT_NEAR(signedVolume(piece), 0.5, 1e-14);
    // A triangular prism: 6 corners, all original box corners (no new points were made).
    EXPECT_EQ(piece.vertices.size(), 6u);
    for (const Vec3& v : piece.vertices)
      for (int k = 0; k < 3; ++k) EXPECT_TRUE(v[k] == 0.0 || v[k] == 1.0) << v.transpose();
  }
}

TEST(Cut, PlaneCoplanarWithTopFaceLeavesOnePiece) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  // Planes containing the top face (z = 1), the bottom face (-z = 0) and a side face (x = 0), with the
  // side the solid lies on.
  const std::vector<std::pair<Plane, bool>> cases = {
      {Plane{Vec3(0, 0, 1), 1.0}, true}, {Plane{Vec3(0, 0, -1), 0.0}, true}, {Plane{Vec3(1, 0, 0), 0.0}, false}};
  for (const auto& [plane, below] : cases) {
    SCOPED_TRACE(plane.normal.transpose());
    const CutResult r = cutByPlane(box, plane);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(r.below.size(), below ? 1u : 0u);
    ASSERT_EQ(r.above.size(), below ? 0u : 1u);
    const TriMesh& piece = below ? r.below[0] : r.above[0];
    EXPECT_TRUE(isClosedOriented(piece));
    EXPECT_EQ(piece.faces.size(), box.faces.size());
    EXPECT_NEAR(signedVolume(piece), 1.0, 1e-15);
  }
}

TEST(Cut, PlaneMissingTheMesh) {
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 2);
  const CutResult r1 = cutByPlane(sphere, Plane{Vec3(0, 1, 0), 5.0});
  ASSERT_TRUE(r1.ok) << r1.error;
  ASSERT_EQ(r1.below.size(), 1u);
  EXPECT_TRUE(r1.above.empty());
  EXPECT_EQ(r1.below[0].faces.size(), sphere.faces.size());
  const CutResult r2 = cutByPlane(sphere, Plane{Vec3(0, 1, 0), -5.0});
  ASSERT_TRUE(r2.ok) << r2.error;
  EXPECT_TRUE(r2.below.empty());
  ASSERT_EQ(r2.above.size(), 1u);
  EXPECT_NEAR(signedVolume(r2.above[0]), signedVolume(sphere), 1e-15);
}

TEST(Cut, InvalidPlaneFailsCleanly) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_FALSE(cutByPlane(box, Plane{Vec3(0, 0, 0), 0.5}).ok);
  EXPECT_FALSE(cutByPlane(box, Plane{Vec3(0, 0, 1), std::nan("")}).ok);
}

TEST(Cut, LShapeAlongItsInnerFacePlane) {
  const TriMesh l = shapes::lShape();  // [0,2]x[0,1]x[0,1] plus [0,1]x[1,2]x[0,1]
  const Plane plane{Vec3(0, 1, 0), 1.0};
  const CutResult r = cutByPlane(l, plane);
  expectValidCut(l, plane, r, 1e-12);
  ASSERT_EQ(r.below.size(), 1u);
  ASSERT_EQ(r.above.size(), 1u);
  EXPECT_NEAR(signedVolume(r.below[0]), 2.0, 1e-14);
  EXPECT_NEAR(signedVolume(r.above[0]), 1.0, 1e-14);
  const Box3 b = boundingBox(compact(r.below[0])), a = boundingBox(compact(r.above[0]));
  EXPECT_EQ(b.lo, Vec3(0, 0, 0));
  EXPECT_EQ(b.hi, Vec3(2, 1, 1));
  EXPECT_EQ(a.lo, Vec3(0, 1, 0));
  EXPECT_EQ(a.hi, Vec3(1, 2, 1));
}

TEST(Cut, TorusByItsEquatorialPlane) {
  const TriMesh torus = shapes::torus(2.0, 0.5, 48, 24);
  const Plane plane{Vec3(0, 0, 1), 0.0};
  const CutResult r = cutByPlane(torus, plane);
  expectValidCut(torus, plane, r);
  ASSERT_EQ(r.below.size(), 1u);
  ASSERT_EQ(r.above.size(), 1u);
  const double v = signedVolume(torus);
  EXPECT_NEAR(signedVolume(r.below[0]), 0.5 * v, 1e-9 * v);
  EXPECT_NEAR(signedVolume(r.above[0]), 0.5 * v, 1e-9 * v);
}

TEST(Cut, TorusByAPlaneThroughItsAxisGivesTwoHalfTori) {
  const TriMesh torus = shapes::torus(2.0, 0.5, 48, 24);
  const Plane plane{Vec3(1, 0, 0), 0.0};
  const CutResult r = cutByPlane(torus, plane);
  expectValidCut(torus, plane, r);
  ASSERT_EQ(r.below.size(), 1u);
  ASSERT_EQ(r.above.size(), 1u);
  const double v = signedVolume(torus);
  for (const auto* side : {&r.below, &r.above}) {
    const TriMesh& half = (*side)[0];
    EXPECT_NEAR(signedVolume(half), 0.5 * v, 1e-9 * v);
    // A half torus is a bent cylinder: two caps (discs) at x = 0, y in +-[1.5, 2.5]; genus 0.
    const TriMesh c = compact(half);
    std::size_t edges = c.faces.size() * 3 / 2;
    EXPECT_EQ(static_cast<long>(c.vertices.size()) - static_cast<long>(edges) + static_cast<long>(c.faces.size()), 2);
    const Box3 box = boundingBox(c);
    EXPECT_NEAR(box.lo.y(), -2.5, 1e-12);
    EXPECT_NEAR(box.hi.y(), 2.5, 1e-12);
  }
  // x = 1 crosses the tube twice (y > 0 and y < 0): the arc x > 1 is one piece, the rest another.
  const Plane off{Vec3(1, 0, 0), 1.0};
  const CutResult r2 = cutByPlane(torus, off);
  expectValidCut(torus, off, r2);
  EXPECT_EQ(r2.below.size(), 1u);
  EXPECT_EQ(r2.above.size(), 1u);
  // y = 2.2 crosses the tube once, near u = 90 degrees: a cap above, the rest below.
  const Plane tangentish{Vec3(0, 1, 0), 2.2};
  const CutResult r3 = cutByPlane(torus, tangentish);
  expectValidCut(torus, tangentish, r3);
  EXPECT_EQ(r3.below.size(), 1u);
  EXPECT_EQ(r3.above.size(), 1u);
}

TEST(Cut, HalfTorusCutIntoThreePieces) {
  // The half torus x >= 0 (a C) cut by x = 1: the outer arc x >= 1 is one piece, and
  // 0 <= x <= 1 leaves two stubs (y > 0 and y < 0) on the other side.
  const TriMesh torus = shapes::torus(2.0, 0.5, 48, 24);
  const CutResult half = cutByPlane(torus, Plane{Vec3(-1, 0, 0), 0.0});  // "below" of -x = 0 is x >= 0
  ASSERT_TRUE(half.ok) << half.error;
  ASSERT_EQ(half.below.size(), 1u);
  const TriMesh c = half.below[0];
  const Plane plane{Vec3(-1, 0, 0), -1.0};  // -x <= -1  <=>  x >= 1
  const CutResult r = cutByPlane(c, plane);
  expectValidCut(c, plane, r);
  EXPECT_EQ(r.below.size(), 1u);  // the outer arc x >= 1 is one connected piece
  EXPECT_EQ(r.above.size(), 2u);  // 0 <= x <= 1: two stubs, y > 0 and y < 0
}

TEST(Cut, IcosphereByManyRandomPlanes) {
  const TriMesh sphere = shapes::icosphere(Vec3(0.3, -0.2, 0.1), 1.3, 3);
  const double v = signedVolume(sphere);
  std::mt19937_64 rng(20070101);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uni(-1.2, 1.2);
  int split = 0;
  for (int i = 0; i < 200; ++i) {
    SCOPED_TRACE(i);
    const Vec3 n = acdtest::drawPoint([&] { return gauss(rng); });
    const Vec3 p = Vec3(0.3, -0.2, 0.1) + acdtest::drawPoint([&] { return uni(rng); });
    const Plane plane = Plane::through(p, n);
    const CutResult r = cutByPlane(sphere, plane);
    expectValidCut(sphere, plane, r);
    EXPECT_LE(r.below.size(), 1u);
    EXPECT_LE(r.above.size(), 1u);
    split += !r.below.empty() && !r.above.empty();
  }
  EXPECT_GT(split, 100);  // most planes cross the sphere
}

TEST(Cut, IcospherePlanesThroughItsVertices) {
  // Planes through mesh vertices (snapped, never moved) in random directions.
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 2);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(sphere.vertices.size()) - 1);
  for (int i = 0; i < 60; ++i) {
    SCOPED_TRACE(i);
    const Vec3& at = sphere.vertices[pick(rng)];
    const Plane plane = Plane::through(at, acdtest::drawPoint([&] { return gauss(rng); }));
    const CutResult r = cutByPlane(sphere, plane);
    expectValidCut(sphere, plane, r);
  }
  // Planes through the centre along coordinate axes pass through many vertices at once.
  for (int axis = 0; axis < 3; ++axis) {
    const Plane plane{Vec3::Unit(axis), 0.0};
    const CutResult r = cutByPlane(sphere, plane);
    expectValidCut(sphere, plane, r);
    ASSERT_EQ(r.below.size(), 1u);
    ASSERT_EQ(r.above.size(), 1u);
    EXPECT_NEAR(signedVolume(r.below[0]), signedVolume(r.above[0]), 1e-12);
  }
}

TEST(Cut, PiecesContainExactlyTheirHalfOfSampledPoints) {
  // Geometry, not just bookkeeping: a point of the U on one side of the plane lies inside exactly one piece of that side.
  const TriMesh u = shapes::uShape();
  const Plane plane{Vec3(0.3, 1, 0.1), 1.7};
  const CutResult r = cutByPlane(u, plane);
  expectValidCut(u, plane, r, 1e-12);
  EXPECT_EQ(r.below.size(), 1u);
  EXPECT_EQ(r.above.size(), 2u);  // the two arms
  const acdtest::MeshIndex model(u);
  std::vector<acdtest::MeshIndex> below, above;
  for (const auto& m : r.below) below.emplace_back(m);
  for (const auto& m : r.above) above.emplace_back(m);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> x(-0.1, 3.1), z(-0.1, 1.1);
  int inside = 0;
  for (int i = 0; i < 4000; ++i) {
    const double px = x(rng), py = x(rng), pz = z(rng);  // drawn in this order
    const Vec3 p(px, py, pz);
    const bool in = model.inside(p);
    inside += in;
    int nb = 0, na = 0;
    for (const auto& b : below) nb += b.inside(p);
    for (const auto& a : above) na += a.inside(p);
    const double d = plane.signedDistance(p);
    if (std::abs(d) < 1e-9) continue;
    EXPECT_EQ(nb, in && d < 0 ? 1 : 0) << p.transpose();
    EXPECT_EQ(na, in && d > 0 ? 1 : 0) << p.transpose();
  }
  EXPECT_GT(inside, 1000);
}

// A comb: a bar [0,6]x[0,1]x[0,1] with prongs [0,1]x[1,2]x[0,1] and [5,6]x[1,2]x[0,1]; y = 1.5
// crosses both prongs, and each tip is 1/16 of the comb (under cutNear's 10 %).
TEST(Cut, NearOneRegionCutsOnlyThatProng) {
  const TriMesh comb = shapes::voxels({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {5, 0, 0}, {0, 1, 0}, {5, 1, 0}});
  const Plane plane{Vec3(0, 1, 0), 1.5};
  const CutResult all = cutByPlane(comb, plane);
  expectValidCut(comb, plane, all, 1e-12);
  EXPECT_EQ(all.below.size() + all.above.size(), 3u);  // the bar, and each prong's tip

  const Vec3 near(0.5, 1.5, 0.2);  // on the first prong's section
  const CutResult r = cutByPlane(comb, plane, 1e-10, &near);
  ASSERT_TRUE(r.ok) << r.error;
  ASSERT_EQ(r.below.size(), 1u);
  ASSERT_EQ(r.above.size(), 1u);
  EXPECT_TRUE(isClosedOriented(r.below[0]));
  EXPECT_TRUE(isClosedOriented(r.above[0]));
  // Above: the first prong's tip alone. Below: the bar with the second prong whole.
  EXPECT_NEAR(signedVolume(r.above[0]), 0.5, 1e-14);
  EXPECT_NEAR(signedVolume(r.below[0]), 7.5, 1e-14);
  const Box3 a = boundingBox(compact(r.above[0])), b = boundingBox(compact(r.below[0]));
  EXPECT_EQ(a.lo, Vec3(0, 1.5, 0));
  EXPECT_EQ(a.hi, Vec3(1, 2, 1));
  EXPECT_EQ(b.lo, Vec3(0, 0, 0));
  EXPECT_EQ(b.hi, Vec3(6, 2, 1));

  const Vec3 other(5.6, 1.5, 0.9);  // the second prong's
  const CutResult s = cutByPlane(comb, plane, 1e-10, &other);
  ASSERT_TRUE(s.ok) << s.error;
  ASSERT_EQ(s.above.size(), 1u);
  EXPECT_EQ(boundingBox(compact(s.above[0])).lo, Vec3(5, 1.5, 0));
}

// Two towers [0,1]x[1,5] and [2,3]x[1,5] on a bar [0,3]x[0,1]: y = 3 leaves 2/11 of the model
// on each side of each tower's section, so the other tower is cut too, as without `near`.
TEST(Cut, NearAlsoCutsARegionWithLargePiecesOnBothSides) {
  std::vector<std::array<int, 3>> cells{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  for (int y = 1; y < 5; ++y) cells.push_back({0, y, 0}), cells.push_back({2, y, 0});
  const TriMesh towers = shapes::voxels(cells);
  const Plane plane{Vec3(0, 1, 0), 3.0};
  const Vec3 near(0.5, 3.0, 0.5);
  const CutResult r = cutByPlane(towers, plane, 1e-10, &near);
  expectValidCut(towers, plane, r, 1e-12);
  ASSERT_EQ(r.below.size(), 1u);
  ASSERT_EQ(r.above.size(), 2u);
  for (const TriMesh& top : r.above) EXPECT_NEAR(signedVolume(top), 2.0, 1e-14);
}

// Cutting one of the two sections of a torus through its axis would leave a piece meeting itself
// across that section: the cut goes through both, as without `near`.
TEST(Cut, NearARegionOfAHandleCutsEveryRegion) {
  const TriMesh torus = shapes::torus(2.0, 0.5, 48, 24);
  const Plane plane{Vec3(1, 0, 0), 0.0};
  const Vec3 near(0, 2, 0);
  const CutResult r = cutByPlane(torus, plane, 1e-10, &near);
  expectValidCut(torus, plane, r);
  ASSERT_EQ(r.below.size(), 1u);
  ASSERT_EQ(r.above.size(), 1u);
  const double v = signedVolume(torus);
  EXPECT_NEAR(signedVolume(r.below[0]), 0.5 * v, 1e-9 * v);
}
