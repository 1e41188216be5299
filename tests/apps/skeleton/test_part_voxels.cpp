// Loops of a solid of labelled pieces on a voxel grid, against shapes whose topology is known by
// construction: a ball, a ring, two rings, a ring cut in quarters (every contact a free disc a loop
// passes through), a ring in halves (the loop lies between the two alone), a block cut like a pie
// (three pieces along one line: no loop), a handle inside one part; and the same counts after a
// rigid motion.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <acd/algo/cut.hpp>
#include <acd/algo/shapes.hpp>

#include "graph.hpp"
#include "part_voxels.hpp"

using namespace skeleton;

namespace {

std::vector<acd::TriMesh> cut(const acd::TriMesh& m, const Vec3& point, const Vec3& normal) {
  const acd::CutResult r = acd::cutByPlane(m, acd::Plane::through(point, normal));
  EXPECT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.below.size(), 1u);
  EXPECT_EQ(r.above.size(), 1u);
  if (!r.ok || r.below.empty() || r.above.empty()) return {};
  return {r.below[0], r.above[0]};
}

/// A ring (major radius 2, minor 0.5) cut by two planes through its axis into four quarters.
std::vector<acd::TriMesh> ringQuarters() {
  const acd::TriMesh ring = acd::shapes::torus(2.0, 0.5, 64, 16);
  std::vector<acd::TriMesh> quarters;
  for (const acd::TriMesh& half : cut(ring, Vec3::Zero(), Vec3(1, 0.01, 0)))
    for (const acd::TriMesh& q : cut(half, Vec3::Zero(), Vec3(0.01, 1, 0))) quarters.push_back(q);
  return quarters;
}

acd::TriMesh moved(acd::TriMesh m) {
  const Eigen::Matrix3d turn =
      (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(-1.1, Vec3::UnitX())).toRotationMatrix();
  for (Vec3& v : m.vertices) v = turn * v + Vec3(3.5, -2, 10);
  return m;
}

}  // namespace

TEST(PartVoxels, CountsTheHandlesOfKnownSolids) {
  EXPECT_EQ(PartVoxels({acd::shapes::icosphere(Vec3::Zero(), 1.0, 3)}, {0}, 64).loops(), 0);
  EXPECT_EQ(PartVoxels({acd::shapes::box(Vec3::Zero(), Vec3(3, 1, 0.5))}, {0}, 64).loops(), 0);
  EXPECT_EQ(PartVoxels({acd::shapes::torus(2.0, 0.5, 64, 16)}, {0}, 64).loops(), 1);
  // Two rings side by side, as two pieces of one part and as two parts.
  acd::TriMesh second = acd::shapes::torus(2.0, 0.5, 64, 16);
  for (Vec3& v : second.vertices) v.x() += 6.0;
  const std::vector<acd::TriMesh> rings{acd::shapes::torus(2.0, 0.5, 64, 16), second};
  EXPECT_EQ(PartVoxels(rings, {0, 0}, 64).loops(), 2);
  const PartVoxels two(rings, {0, 1}, 64);
  EXPECT_EQ(two.loops(), 2);
  EXPECT_EQ(two.loops(0), 1);
  EXPECT_EQ(two.loops(1), 1);
  // A hollow ball (a cavity) has no loop.
  acd::TriMesh hollow = acd::shapes::icosphere(Vec3::Zero(), 1.0, 3);
  acd::TriMesh inner = acd::shapes::icosphere(Vec3::Zero(), 0.5, 3);
  for (acd::Face& f : inner.faces) std::swap(f[1], f[2]);
  const int offset = static_cast<int>(hollow.vertices.size());
  hollow.vertices.insert(hollow.vertices.end(), inner.vertices.begin(), inner.vertices.end());
  for (acd::Face f : inner.faces) hollow.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  EXPECT_EQ(PartVoxels({hollow}, {0}, 64).loops(), 0);
}

TEST(PartVoxels, ALoopPassesThroughEveryQuarterOfARing) {
  const std::vector<acd::TriMesh> quarters = ringQuarters();
  ASSERT_EQ(quarters.size(), 4u);
  const PartVoxels grid(quarters, {0, 1, 2, 3}, 64);
  EXPECT_EQ(grid.loops(), 1);
  for (int p = 0; p < 4; ++p) EXPECT_EQ(grid.loops(p), 0) << p;
  // Quarters 0-1 and 2-3 share a cut across the ring (below/above the second plane), as do 0-2
  // and 1-3 (the first plane): four free discs round one loop.
  for (auto [a, b] : {std::pair{0, 1}, {2, 3}, {0, 2}, {1, 3}}) EXPECT_EQ(grid.loopsThrough(a, b, true), 1) << a << b;
  EXPECT_EQ(grid.loopsThrough(0, 3, true), 0);  // not neighbours
}

TEST(PartVoxels, ALoopBetweenTwoHalvesPassesThroughNoOtherPart) {
  const std::vector<acd::TriMesh> quarters = ringQuarters();
  ASSERT_EQ(quarters.size(), 4u);
  // Halves {0, 1} and {2, 3}: they meet at two separate discs; the loop goes through both.
  const PartVoxels grid(quarters, {0, 0, 1, 1}, 64);
  EXPECT_EQ(grid.loops(), 1);
  EXPECT_EQ(grid.loopsThrough(0, 1, false), 0);
  // The whole ring one part: its handle is inside it.
  const PartVoxels whole(quarters, {0, 0, 0, 0}, 64);
  EXPECT_EQ(whole.loops(0), 1);
}

TEST(PartVoxels, ThreeSlicesOfAPieMakeNoLoop) {
  // A block cut at x = 1.3, its right piece at y = 0.7: three pieces meeting along one line, whose
  // adjacency graph is a triangle; the caps are not conforming (the left piece's cap is whole).
  std::vector<acd::TriMesh> pieces = cut(acd::shapes::box(Vec3::Zero(), Vec3(3, 2, 1)), Vec3(1.3, 0, 0), Vec3::UnitX());
  ASSERT_EQ(pieces.size(), 2u);
  const std::vector<acd::TriMesh> right = cut(pieces[1], Vec3(0, 0.7, 0), Vec3::UnitY());
  ASSERT_EQ(right.size(), 2u);
  pieces = {pieces[0], right[0], right[1]};
  for (const std::vector<acd::TriMesh>& solid :
       {pieces, std::vector<acd::TriMesh>{moved(pieces[0]), moved(pieces[1]), moved(pieces[2])}}) {
    const PartVoxels grid(solid, {0, 1, 2}, 64);
    EXPECT_EQ(grid.loops(), 0);
    for (auto [a, b] : {std::pair{0, 1}, {0, 2}, {1, 2}}) EXPECT_EQ(grid.loopsThrough(a, b, true), 0) << a << b;
  }
}

TEST(PartVoxels, ARigidMotionGivesTheSameCounts) {
  std::vector<acd::TriMesh> quarters = ringQuarters();
  ASSERT_EQ(quarters.size(), 4u);
  const PartVoxels here(quarters, {0, 1, 2, 3}, 64);
  for (acd::TriMesh& q : quarters) q = moved(q);
  const PartVoxels there(quarters, {0, 1, 2, 3}, 64);
  EXPECT_EQ(there.loops(), here.loops());
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) EXPECT_EQ(there.loopsThrough(a, b, true), here.loopsThrough(a, b, true)) << a << b;
}
