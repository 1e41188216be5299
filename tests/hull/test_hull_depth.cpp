// How deep a surface lies below its hull, on shapes whose answer is known in closed form.
#include <acd/algo/hull_depth.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace {

using acd::TriMesh;
using acd::Vec3;

TEST(HullDepth, ConvexMeshHasNone) {
  const TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  EXPECT_LT(acd::deepestBelowHull(box, acd::hullMesh(box.vertices)).distance, 1e-12);
}

// A 3x3x2 block of unit cells without its top middle cell: the pocket's floor lies 1 below the
// hull's top and 1 inside its sides; every other vertex is on the hull.
TEST(HullDepth, PocketFloorIsOneDeep) {
  std::vector<std::array<int, 3>> cells;
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 3; ++x)
        if (!(z == 1 && x == 1 && y == 1)) cells.push_back({x, y, z});
  const TriMesh block = acd::shapes::voxels(cells);
  const TriMesh hull = acd::hullMesh(block.vertices);
  const acd::HullDepth d = acd::deepestBelowHull(block, hull);
  EXPECT_NEAR(d.distance, 1.0, 1e-12);
  ASSERT_GE(d.vertex, 0);
  const Vec3& deepest = block.vertices[d.vertex];
  EXPECT_NEAR(deepest.z(), 1.0, 1e-12);
  EXPECT_TRUE(deepest.x() > 0.5 && deepest.x() < 2.5 && deepest.y() > 0.5 && deepest.y() < 2.5);
  ASSERT_GE(d.hullFace, 0);
  // The face reported is one of those at distance 1: its plane is 1 from the floor vertex.
  const Vec3 n = acd::faceNormal(hull, d.hullFace).normalized();
  EXPECT_NEAR(std::abs(n.dot(hull.vertices[hull.faces[d.hullFace][0]] - deepest)), 1.0, 1e-12);

  // Scaled by 3 and moved, the depth scales with it.
  TriMesh moved = block;
  for (Vec3& v : moved.vertices) v = 3.0 * v + Vec3(5, -2, 7);
  EXPECT_NEAR(acd::deepestBelowHull(moved, acd::hullMesh(moved.vertices)).distance, 3.0, 1e-9);
}

}  // namespace
