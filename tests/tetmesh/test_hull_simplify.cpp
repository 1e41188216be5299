// Simplified hulls: vertex budget met, component still inside.
#include "hull_simplify.hpp"

#include <acd/hull.hpp>
#include <acd/shapes.hpp>

#include <gtest/gtest.h>

using namespace tetmesh;
using acd::Vec3;

TEST(HullSimplify, SphereHullGetsDownToKAndStillContainsIt) {
  const acd::TriMesh sphere = acd::shapes::icosphere(Vec3(0.3, -1, 2), 1.5, 2);  // 162 vertices
  const acd::TriMesh hull = acd::hullMesh(sphere.vertices);
  for (int k : {8, 12, 40}) {
    const SimplifiedHull s = simplifyHull(hull, k);
    EXPECT_TRUE(s.reached) << k;
    EXPECT_LE(static_cast<int>(s.mesh.vertices.size()), k);
    EXPECT_TRUE(acd::isClosedOriented(s.mesh));
    EXPECT_LE(maxOutsideDistance(s.mesh, sphere.vertices), 1e-9) << k;
    EXPECT_GE(acd::signedVolume(s.mesh), acd::signedVolume(hull));
    // It is a hull: convex (every vertex inside every face plane).
    EXPECT_LE(maxOutsideDistance(s.mesh, s.mesh.vertices), 1e-9);
  }
  // More vertices, tighter: the 40-vertex hull is smaller than the 8-vertex one.
  EXPECT_LT(acd::signedVolume(simplifyHull(hull, 40).mesh), acd::signedVolume(simplifyHull(hull, 8).mesh));
}

TEST(HullSimplify, TorusHullStaysAroundEveryVertex) {
  const acd::TriMesh torus = acd::shapes::torus(2.0, 0.5, 48, 16);
  const acd::TriMesh hull = acd::hullMesh(torus.vertices);
  const SimplifiedHull s = simplifyHull(hull, 24);
  EXPECT_TRUE(s.reached);
  EXPECT_LE(s.mesh.vertices.size(), 24u);
  EXPECT_LE(maxOutsideDistance(s.mesh, torus.vertices), 1e-9);
  // Not absurdly loose: within 40 % of the exact hull's volume.
  EXPECT_LT(acd::signedVolume(s.mesh), 1.4 * acd::signedVolume(hull));
}

TEST(HullSimplify, SmallHullIsLeftAlone) {
  const acd::TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const SimplifiedHull s = simplifyHull(acd::hullMesh(box.vertices), 8);
  EXPECT_TRUE(s.reached);
  EXPECT_EQ(s.collapses, 0);
  EXPECT_NEAR(acd::signedVolume(s.mesh), 6.0, 1e-12);
}

TEST(HullSimplify, MaxOutsideDistanceMeasuresDistance) {
  const acd::TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_NEAR(maxOutsideDistance(box, {Vec3(0.5, 0.5, 1.25)}), 0.25, 1e-12);
  EXPECT_EQ(maxOutsideDistance(box, {Vec3(0.5, 0.5, 0.5)}), 0.0);
}
