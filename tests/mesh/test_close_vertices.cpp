// closeVertexRoots (libacd/src/mesh/close_vertices.cpp) against an all-pairs oracle: chains of
// close vertices form one group, represented by its lowest index, whatever the grid cells.
#include <gtest/gtest.h>

#include <acd/algo/close_vertices.hpp>
#include <acd/algo/union_find.hpp>
#include <random>

using namespace acd;

TEST(CloseVertexRoots, MatchesAllPairsOnClusteredPoints) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0), jitter(-2e-3, 2e-3);
  std::vector<Vec3> points;
  for (int c = 0; c < 200; ++c) {
    const Vec3 centre(u(rng), u(rng), u(rng));
    const int copies = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < copies; ++k) points.push_back(centre + Vec3(jitter(rng), jitter(rng), jitter(rng)));
  }
  points.push_back(points.front());  // an exact copy
  Box3 box;
  box.lo = box.hi = points.front();
  for (const Vec3& p : points) box.lo = box.lo.cwiseMin(p), box.hi = box.hi.cwiseMax(p);
  for (double tolerance : {0.0, 1e-3, 3e-3, 2e-2}) {
    const int n = static_cast<int>(points.size());
    UnionFind oracle(n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < i; ++j)
        if (tolerance > 0.0 && (points[i] - points[j]).norm() <= tolerance) oracle.joinKeepingSmallest(i, j);
    const std::vector<int> roots = closeVertexRoots(points, box, tolerance);
    ASSERT_EQ(static_cast<int>(roots.size()), n);
    for (int i = 0; i < n; ++i) ASSERT_EQ(roots[i], oracle.find(i)) << "tolerance " << tolerance << " vertex " << i;
  }
}

// Vertices exactly the tolerance apart on a lattice whose lines fall on cell walls: every
// neighbour is found across the walls (the grid looks across a wall only when a vertex is near it).
TEST(CloseVertexRoots, JoinsALatticeAtExactlyTheTolerance) {
  std::vector<Vec3> points;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 4; ++k) points.emplace_back(0.25 * i, 0.25 * j, 0.25 * k);
  Box3 box;
  box.lo = Vec3::Zero();
  box.hi = Vec3(1.25, 1.0, 0.75);
  for (int v : closeVertexRoots(points, box, 0.25)) EXPECT_EQ(v, 0);
  // Just below the spacing nothing joins.
  const std::vector<int> apart = closeVertexRoots(points, box, 0.2499);
  for (int v = 0; v < static_cast<int>(points.size()); ++v) EXPECT_EQ(apart[v], v);
}
