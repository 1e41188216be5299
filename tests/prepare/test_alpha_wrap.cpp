// The watertight wrap (libacd/src/prepare/alpha_wrap.cpp, acd/algo/alpha_wrap.hpp): its parameters
// follow tau, it is closed and lies outside the input at the offset (distances measured with the
// tests' own geometry), and the library's Hausdorff estimate agrees with a brute-force one.
#include <acd/algo/alpha_wrap.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <random>

#include "helpers.hpp"

using namespace acd;
using acdtest::MeshIndex;

TEST(Wrap, ParametersFollowTau) {
  for (double tau : {0.02, 0.05, 0.2}) {
    const WrapParameters p = wrapParametersFor(tau);
    EXPECT_GT(p.offset, 0.0);
    EXPECT_LT(p.offset, tau);  // room is left in the tau budget
    EXPECT_GE(p.alpha, p.offset);
  }
}

TEST(Wrap, IsClosedOutsideTheInputAtTheOffset) {
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  const Wrap w = alphaWrap(sphere, 0.1, 0.01);
  ASSERT_TRUE(w.status.ok()) << w.status.message;
  EXPECT_TRUE(isClosedOriented(w.mesh));
  EXPECT_GT(signedVolume(w.mesh), signedVolume(sphere));
  EXPECT_EQ(countSelfIntersections(w.mesh), 0);
  // Independent distances: every wrap vertex at about the offset from the sphere's surface.
  const MeshIndex index(sphere);
  double lo = 1e9, hi = 0;
  for (const Vec3& p : w.mesh.vertices) {
    const double d = index.distance(p);
    lo = std::min(lo, d), hi = std::max(hi, d);
    EXPECT_FALSE(index.inside(p));
  }
  EXPECT_GT(lo, 0.005);
  EXPECT_LT(hi, 0.02);
  // The library's Hausdorff estimate agrees with a brute-force one in both directions.
  const double h = hausdorffDistance(w.mesh, sphere);
  const MeshIndex wrapIndex(w.mesh);
  std::mt19937_64 rng(3);
  double brute = hi;
  for (const Vec3& p : acdtest::sampleSurface(sphere, 4000, rng)) brute = std::max(brute, wrapIndex.distance(p));
  EXPECT_NEAR(h, brute, 0.002);
}


// distanceOutside counts only the part of the first surface outside the solid: a box reaching out
// of the unit box by one unit along each axis reaches sqrt(3) out (its far corner, a sampled
// vertex, to the unit box's corner), and a box inside the unit box reaches nothing.
TEST(SurfaceDistance, OutsideCountsOnlyWhatLiesOutsideTheSolid) {
  const TriMesh unit = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const TriMesh reaching = shapes::box(Vec3(0.5, 0.5, 0.5), Vec3(2, 2, 2));
  EXPECT_NEAR(distanceOutside(reaching, unit), std::sqrt(3.0), 1e-12);
  EXPECT_EQ(distanceOutside(shapes::box(Vec3(0.2, 0.2, 0.2), Vec3(0.8, 0.8, 0.8)), unit), 0.0);
  // The two-sided measure sees the inner box's distance to the unit box's surface instead.
  EXPECT_NEAR(surfaceDistance(shapes::box(Vec3(0.2, 0.2, 0.2), Vec3(0.8, 0.8, 0.8)), unit).aToB, 0.2, 1e-9);
}

TEST(Wrap, ASoupOfFlatFacesIsRefusedWithAMessage) {
  // Every corner on one line: CGAL's oracle drops such triangles, and with none left its tree is
  // empty (the wrap then read the box of nothing: undefined behaviour under the sanitizers).
  TriMesh flat;
  flat.vertices = {Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2), Vec3(3, 3, 3)};
  flat.faces = {{0, 1, 2}, {1, 2, 3}, {0, 3, 2}};
  const Wrap w = alphaWrap(flat, 0.1, 0.01);
  EXPECT_FALSE(w.status.ok());
  EXPECT_NE(w.status.message.find("area"), std::string::npos) << w.status.message;
  EXPECT_TRUE(w.mesh.faces.empty());
}
