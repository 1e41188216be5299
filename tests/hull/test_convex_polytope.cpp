// ConvexPolytope and the support helpers (libacd/src/hull/convex_polytope.cpp) against analytic
// solids: a box, a box with a corner cut off (a tetrahedron of known volume), a slab, the
// octahedron |x| + |y| + |z| <= 1 cut down from a box by eight planes; and against the divergence
// theorem on the triangulated result.
#include <acd/algo/convex_polytope.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace acd;

namespace {

HalfSpace halfSpace(const Vec3& n, double c) {
  const double len = n.norm();
  return {n / len, c / len};
}

}  // namespace

TEST(ConvexPolytope, BoxHasItsVolumeCornersAndEdges) {
  const ConvexPolytope box = ConvexPolytope::box(Vec3(0, 0, 0), Vec3(1, 2, 3), 1e-12);
  EXPECT_FALSE(box.empty());
  EXPECT_NEAR(box.volume(), 6.0, 1e-12);
  EXPECT_EQ(box.corners().size(), 8u);
  EXPECT_NEAR(box.shortestEdge(), 1.0, 1e-12);
  const TriMesh m = box.mesh();
  EXPECT_TRUE(isClosedOriented(m));
  EXPECT_NEAR(signedVolume(m), 6.0, 1e-12);
}

// x + y + z <= 1/2 keeps the corner tetrahedron of the unit cube: volume (1/2)^3 / 6, 4 corners.
// The other side keeps the rest: volume 1 - 1/48, the cube's other 7 corners and 3 on the cut.
TEST(ConvexPolytope, CornerCutGivesTheTetrahedronAndTheRest) {
  const ConvexPolytope cube = ConvexPolytope::box(Vec3(0, 0, 0), Vec3(1, 1, 1), 1e-12);
  const HalfSpace below = halfSpace(Vec3(1, 1, 1), 0.5), above = halfSpace(Vec3(-1, -1, -1), -0.5);
  EXPECT_TRUE(cube.cutBy(below));
  EXPECT_TRUE(cube.cutBy(above));
  const ConvexPolytope tet = cube.clipped(below), rest = cube.clipped(above);
  EXPECT_NEAR(tet.volume(), 1.0 / 48.0, 1e-12);
  EXPECT_EQ(tet.corners().size(), 4u);
  EXPECT_NEAR(rest.volume(), 1.0 - 1.0 / 48.0, 1e-12);
  EXPECT_EQ(rest.corners().size(), 10u);
  EXPECT_NEAR(tet.shortestEdge(), 0.5, 1e-12);
  for (const ConvexPolytope* p : {&tet, &rest}) {
    const TriMesh m = p->mesh();
    EXPECT_TRUE(isClosedOriented(m));
    EXPECT_NEAR(signedVolume(m), p->volume(), 1e-12);
  }
}

// A plane that holds the whole box does not cut it; one that holds none of it leaves nothing.
TEST(ConvexPolytope, PlanesThatMissOrSwallowIt) {
  const ConvexPolytope cube = ConvexPolytope::box(Vec3(0, 0, 0), Vec3(1, 1, 1), 1e-9);
  const HalfSpace all = halfSpace(Vec3(0, 0, 1), 1.0), none = halfSpace(Vec3(0, 0, 1), -0.5);
  EXPECT_FALSE(cube.cutBy(all));
  EXPECT_NEAR(cube.clipped(all).volume(), 1.0, 1e-12);
  EXPECT_TRUE(cube.cutBy(none));
  const ConvexPolytope gone = cube.clipped(none);
  EXPECT_TRUE(gone.empty());
  EXPECT_TRUE(gone.mesh().faces.empty());
  // A plane within eps of a face counts as not cutting.
  EXPECT_FALSE(cube.cutBy(halfSpace(Vec3(0, 0, 1), 1.0 - 1e-10)));
}

// Eight planes |x| + |y| + |z| <= 1 cut the box [-1, 1]^3 down to the octahedron: volume 4/3,
// six corners, edges of length sqrt(2).
TEST(ConvexPolytope, OctahedronFromEightPlanes) {
  ConvexPolytope p = ConvexPolytope::box(Vec3(-1, -1, -1), Vec3(1, 1, 1), 1e-12);
  for (int sx : {-1, 1})
    for (int sy : {-1, 1})
      for (int sz : {-1, 1}) p = p.clipped(halfSpace(Vec3(sx, sy, sz), 1.0));
  EXPECT_NEAR(p.volume(), 4.0 / 3.0, 1e-12);
  EXPECT_EQ(p.corners().size(), 6u);
  EXPECT_NEAR(p.shortestEdge(), std::sqrt(2.0), 1e-12);
  const TriMesh m = p.mesh();
  EXPECT_TRUE(isClosedOriented(m));
  EXPECT_NEAR(signedVolume(m), 4.0 / 3.0, 1e-12);
  EXPECT_EQ(uniqueFacetNormals(m).size(), 8u);
}

TEST(ConvexPolytope, SupportAndOutsideDistance) {
  const std::vector<Vec3> pts{Vec3(0, 0, 0), Vec3(1, 2, 3), Vec3(-1, 5, 0)};
  EXPECT_DOUBLE_EQ(maxAlong(pts, Vec3(0, 1, 0)), 5.0);
  EXPECT_DOUBLE_EQ(minAlong(pts, Vec3(1, 0, 0)), -1.0);
  const TriMesh cube = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_EQ(uniqueFacetNormals(cube).size(), 6u);
  EXPECT_NEAR(maxOutsideDistance(cube, {Vec3(0.5, 0.5, 0.5)}), 0.0, 1e-15);
  EXPECT_NEAR(maxOutsideDistance(cube, {Vec3(0.5, 0.5, 0.5), Vec3(0.5, 1.25, 0.5), Vec3(1.5, 0.5, 0.5)}), 0.5, 1e-12);
}
