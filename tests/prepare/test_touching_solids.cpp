// splitTouchingSolids (libacd/src/prepare/touching_solids.cpp): two boxes welded along an edge (as
// exports weld an assembly's parts) come apart into the two boxes, each closed and oriented, with
// the volumes of the boxes; a mesh without such edges is left exactly as it is.
#include <gtest/gtest.h>

#include <acd/algo/shapes.hpp>
#include <acd/algo/touching_solids.hpp>

#include "helpers.hpp"

#include <algorithm>
#include <random>
#include <string>
#include <vector>

using namespace acd;
using acd::shapes::box;

namespace {

/// The meshes in one, with vertices at the same position welded (the lowest index kept).
TriMesh welded(const std::vector<TriMesh>& parts) {
  TriMesh all = concatenate(parts);
  std::vector<int> to(all.vertices.size());
  for (std::size_t v = 0; v < all.vertices.size(); ++v) {
    to[v] = static_cast<int>(v);
    for (std::size_t w = 0; w < v; ++w)
      if (all.vertices[w] == all.vertices[v]) {
        to[v] = static_cast<int>(w);
        break;
      }
  }
  for (Face& f : all.faces)
    for (int& v : f) v = to[v];
  return compact(all);
}

}  // namespace

TEST(SplitTouchingSolids, BoxesWeldedAlongAnEdgeComeApart) {
  // A vertical edge x = y = 1 of four faces; each box keeps its own copy of the edge.
  for (bool secondFirst : {false, true}) {
    const TriMesh a = box(Vec3(0, 0, 0), Vec3(1, 1, 1)), b = box(Vec3(1, 1, 0), Vec3(2, 2, 1));
    const TriMesh input = secondFirst ? welded({b, a}) : welded({a, b});
    ASSERT_EQ(splitEdgeConnected(input).size(), 1u);
    const TouchingSolidsSplit split = splitTouchingSolids(input);
    EXPECT_EQ(split.splitEdges, 1);
    EXPECT_EQ(split.copiedVertices, 2);
    EXPECT_EQ(split.mesh.faces.size(), input.faces.size());
    const std::vector<TriMesh> parts = splitEdgeConnected(split.mesh);
    ASSERT_EQ(parts.size(), 2u);
    for (const TriMesh& p : parts) {
      EXPECT_TRUE(isClosedOriented(p));
      EXPECT_NEAR(signedVolume(p), 1.0, 1e-12);
      EXPECT_EQ(p.vertices.size(), 8u);
    }
  }
}

TEST(SplitTouchingSolids, ManifoldMeshUnchanged) {
  const TriMesh m = shapes::torus(1.0, 0.3, 24, 12);
  const TouchingSolidsSplit split = splitTouchingSolids(m);
  EXPECT_EQ(split.splitEdges, 0);
  EXPECT_EQ(split.copiedVertices, 0);
  EXPECT_EQ(split.mesh.faces, m.faces);
  EXPECT_EQ(split.mesh.vertices.size(), m.vertices.size());
}

TEST(SplitTouchingSolids, FacesLyingOnEachOtherPairTheSameInEveryPose) {
  // A block on the left half of a slab, welded at its two bottom-left corners: around the edge
  // x = 0, z = 1 the slab's top and the block's bottom lie on each other (and both left sides on
  // one plane). Rounding in a turned pose puts those faces a hair apart either way; the pairing
  // must follow the rule for faces on each other, not the rounding.
  const TriMesh slab = box(Vec3(0, 0, 0), Vec3(2, 1, 1)), block = box(Vec3(0, 0, 1), Vec3(1, 1, 2));
  const TriMesh input = welded({slab, block});
  std::mt19937_64 rng(3);
  for (int pose = 0; pose < 20; ++pose) {
    SCOPED_TRACE("pose " + std::to_string(pose));
    const Eigen::Matrix3d r = acdtest::randomRotation(rng);
    const TouchingSolidsSplit split = splitTouchingSolids(acdtest::moved(input, r, Vec3(0.3, -7.1, 2.2)));
    EXPECT_EQ(split.copiedVertices, 2);
    std::vector<double> volumes;
    for (const TriMesh& p : splitEdgeConnected(split.mesh)) {
      EXPECT_TRUE(isClosedOriented(p));
      volumes.push_back(signedVolume(p));
    }
    std::sort(volumes.begin(), volumes.end());
    ASSERT_EQ(volumes.size(), 2u);
    EXPECT_NEAR(volumes[0], 1.0, 1e-9);
    EXPECT_NEAR(volumes[1], 2.0, 1e-9);
  }
}
