#include <acd/algo/concavity.hpp>
#include <acd/algo/features.hpp>
#include <acd/algo/knot_graph.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace acd;

TEST(NonCrossingMatching, PrefersTwoNestedPairsOverCheaperCrossingOnes) {
  // Both lists in loop order: (0,0) and (1,1) would cross, (0,1) and (1,0) nest.
  const auto pairs = nonCrossingMatching({{1.0, 10.0}, {10.0, 1.0}});
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0], std::make_pair(0, 1));
  EXPECT_EQ(pairs[1], std::make_pair(1, 0));
}

TEST(NonCrossingMatching, MinimisesWeightAmongMaximumMatchings) {
  const double inf = std::numeric_limits<double>::infinity();
  // One row, three columns: a single pair, the cheapest.
  auto pairs = nonCrossingMatching({{5.0, 2.0, 7.0}});
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], std::make_pair(0, 1));
  // Forbidden pairs are never used; with everything forbidden there is no pair.
  EXPECT_TRUE(nonCrossingMatching({{inf, inf}, {inf, inf}}).empty());
  pairs = nonCrossingMatching({{inf, 3.0}, {inf, inf}});
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], std::make_pair(0, 1));
  // Every pair of the result is non-crossing: rows ascend while columns descend.
  pairs = nonCrossingMatching({{1, 2, 3, 4}, {2, 1, 2, 3}, {3, 2, 1, 2}});
  ASSERT_EQ(pairs.size(), 3u);
  for (std::size_t k = 1; k < pairs.size(); ++k) {
    EXPECT_LT(pairs[k - 1].first, pairs[k].first);
    EXPECT_GT(pairs[k - 1].second, pairs[k].second);
  }
}

TEST(KnotGraph, DumbbellCycleRingsTheBarWhereItMeetsABall) {
  const TriMesh raw = shapes::dumbbell();
  const TriMesh m = applyNormalization(raw, minimumSphereNormalization(raw));
  SurfaceGraph graph(m);
  ConcavityOptions co;
  co.epsilon = 0.025;
  const ConcavityMap map = measureConcavity(m, graph, co);
  ASSERT_GT(map.concavity, 0.1);
  const KnotGraph kg = buildKnotGraph(m, graph, map, 0.0025);
  ASSERT_FALSE(kg.nodes.empty());
  ASSERT_FALSE(kg.edges.empty());
  for (const auto& e : kg.edges) {
    ASSERT_GE(e.path.size(), 1u);
    EXPECT_EQ(e.path.front(), kg.nodes[e.a].vertex);
    EXPECT_EQ(e.path.back(), kg.nodes[e.b].vertex);
    EXPECT_GE(e.weight, 0.0);
  }
  const GlobalCut cycle = knotGraphCycle(m, map, kg);
  ASSERT_TRUE(cycle.closed);
  ASSERT_GE(cycle.vertices.size(), 8u);
  EXPECT_EQ(cycle.vertices.front(), cycle.vertices.back());  // a cycle
  // The ring lies at the notch's height (the bar meets the ball there), all the way round the bar.
  const double z = m.vertices[map.notch].z();
  double angleCovered = 0.0;
  for (std::size_t i = 0; i < cycle.vertices.size(); ++i) {
    const Vec3& p = m.vertices[cycle.vertices[i]];
    EXPECT_NEAR(p.z(), z, 0.05) << "cycle vertex " << i;
    if (i > 0) {
      const Vec3& q = m.vertices[cycle.vertices[i - 1]];
      angleCovered += std::abs(std::remainder(std::atan2(p.y(), p.x()) - std::atan2(q.y(), q.x()), 2 * std::acos(-1.0)));
    }
  }
  EXPECT_GT(angleCovered, 6.0);  // goes once around (2 pi)
}
