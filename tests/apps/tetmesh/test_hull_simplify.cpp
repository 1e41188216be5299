// Simplified hull regions: vertex budget met, every component still inside its region, regions
// of different components never overlap, the two sides of a cut share one plane.
#include "hull_simplify.hpp"

#include <acd/decompose.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/random.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace tetmesh;
using acd::Vec3;

namespace {

/// Whether p is inside the convex mesh (within eps of every face plane).
bool insideConvex(const acd::TriMesh& convex, const Vec3& p, double eps) {
  for (int f = 0; f < static_cast<int>(convex.faces.size()); ++f) {
    const Vec3 n = acd::faceNormal(convex, f);
    if (!(n.norm() > 0)) continue;
    if (n.normalized().dot(p - convex.vertices[convex.faces[f][0]]) > eps) return false;
  }
  return true;
}

SimplifiedHulls simplify(const std::vector<acd::TriMesh>& hulls, int k) {
  HullSimplifyOptions o;
  o.maxVertices = k;
  return simplifyHulls(hulls, o);
}

}  // namespace

TEST(HullSimplify, SphereHullGetsDownToKAndStillContainsIt) {
  const acd::TriMesh sphere = acd::shapes::icosphere(Vec3(0.3, -1, 2), 1.5, 2);  // 162 vertices
  const acd::TriMesh hull = acd::hullMesh(sphere.vertices);
  double volume8 = 0, volume40 = 0;
  for (int k : {8, 12, 40}) {
    const SimplifiedHulls s = simplify({hull}, k);
    ASSERT_EQ(s.regions.size(), 1u);
    const acd::TriMesh& r = s.regions[0];
    EXPECT_TRUE(s.reached[0]) << k;
    EXPECT_LE(static_cast<int>(r.vertices.size()), k);
    EXPECT_TRUE(acd::isClosedOriented(r));
    EXPECT_LE(maxOutsideDistance(r, sphere.vertices), 1e-9) << k;
    EXPECT_GE(acd::signedVolume(r), acd::signedVolume(hull));
    EXPECT_LE(maxOutsideDistance(r, r.vertices), 1e-9);  // convex
    (k == 8 ? volume8 : volume40) = k == 12 ? 0 : acd::signedVolume(r);
  }
  // More vertices, tighter; and not absurdly loose with 40 (the sphere's own hull is 4.1 % below
  // the ball, a cube around it 91 % above).
  EXPECT_LT(volume40, volume8);
  EXPECT_LT(volume40, 1.35 * acd::signedVolume(hull));
}

TEST(HullSimplify, TwoHalvesOfABarShareTheCutPlaneAndDoNotOverlap) {
  // A bar cut at x = 1 into two boxes: their regions may grow anywhere but across x = 1.
  const acd::TriMesh left = acd::hullMesh(acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)).vertices);
  const acd::TriMesh right = acd::hullMesh(acd::shapes::box(Vec3(1, 0.2, 0.1), Vec3(2.5, 0.9, 1.3)).vertices);
  const SimplifiedHulls s = simplify({left, right}, 8);
  ASSERT_EQ(s.regions.size(), 2u);
  EXPECT_EQ(s.separatingPlanes, 1);
  EXPECT_EQ(s.overlappingHulls, 0);
  for (const Vec3& p : s.regions[0].vertices) EXPECT_LE(p.x(), 1.0 + 1e-12);
  for (const Vec3& p : s.regions[1].vertices) EXPECT_GE(p.x(), 1.0 - 1e-12);
  EXPECT_LE(maxOutsideDistance(s.regions[0], left.vertices), 1e-12);
  EXPECT_LE(maxOutsideDistance(s.regions[1], right.vertices), 1e-12);
  // Boxes are within the budget: they are their own regions.
  EXPECT_NEAR(acd::signedVolume(s.regions[0]), 1.0, 1e-12);
  EXPECT_NEAR(acd::signedVolume(s.regions[1]), 1.5 * 0.7 * 1.2, 1e-12);
  // With a budget of 6 they are not, and grow (by a margin at least) but stay on their side.
  const SimplifiedHulls six = simplify({left, right}, 6);
  EXPECT_GT(acd::signedVolume(six.regions[0]), 1.0);
  for (const Vec3& p : six.regions[0].vertices) EXPECT_LE(p.x(), 1.0 + 1e-12);
  for (const Vec3& p : six.regions[1].vertices) EXPECT_GE(p.x(), 1.0 - 1e-12);
}

TEST(HullSimplify, DecomposedTorusRegionsContainTheirPiecesAndNeverOverlap) {
  const acd::TriMesh torus = acd::shapes::torus(2.0, 0.6, 32, 12);
  acd::DecomposeOptions d;  // as tetmesh decomposes (hull_mesher.cpp)
  d.tau = 0.1;
  d.merge = false;
  d.mergeScope = acd::MergeScope::Component;
  d.invariant = false;
  const acd::Decomposition dec = acd::decompose(torus, d);
  ASSERT_TRUE(dec.status.ok()) << dec.status.message;
  ASSERT_GE(dec.components.size(), 4u);
  std::vector<acd::TriMesh> hulls;
  for (const acd::Component& c : dec.components) hulls.push_back(c.hull);
  const SimplifiedHulls s = simplify(hulls, 12);
  ASSERT_EQ(s.regions.size(), hulls.size());
  EXPECT_EQ(s.overlappingHulls, 0);
  EXPECT_GE(s.separatedPairs, static_cast<int>(hulls.size()));  // at least the ring of cuts
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    EXPECT_TRUE(s.reached[i]) << i;
    EXPECT_LE(s.regions[i].vertices.size(), 12u);
    EXPECT_TRUE(acd::isClosedOriented(s.regions[i]));
    EXPECT_LE(maxOutsideDistance(s.regions[i], dec.components[i].mesh.vertices), 1e-9) << i;
  }
  // No point of space lies inside two regions (beyond rounding): random points in the box.
  const double eps = -1e-9;  // strictly inside
  int doubly = 0, covered = 0;
  for (std::uint64_t k = 0; k < 20000; ++k) {
    const Vec3 p(-3 + 6 * acd::unitInterval(acd::mix64(3 * k)), -3 + 6 * acd::unitInterval(acd::mix64(3 * k + 1)),
                 -1 + 2 * acd::unitInterval(acd::mix64(3 * k + 2)));
    int in = 0;
    for (const acd::TriMesh& r : s.regions) in += insideConvex(r, p, eps) ? 1 : 0;
    doubly += in > 1 ? 1 : 0;
    covered += in > 0 ? 1 : 0;
  }
  EXPECT_EQ(doubly, 0);
  EXPECT_GT(covered, 1000);  // the test sees the regions at all
}

TEST(HullSimplify, MaxOutsideDistanceMeasuresDistance) {
  const acd::TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_NEAR(maxOutsideDistance(box, {Vec3(0.5, 0.5, 1.25)}), 0.25, 1e-12);
  EXPECT_EQ(maxOutsideDistance(box, {Vec3(0.5, 0.5, 0.5)}), 0.0);
}
