// Graph edit distance: hand-made graphs with known distances, properties of the exact and
// bipartite methods on random graphs.
#include "ged.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace skeleton;

namespace {

Graph path(int n) {
  std::vector<std::pair<int, int>> e;
  for (int i = 0; i + 1 < n; ++i) e.push_back({i, i + 1});
  return makeGraph(n, e);
}

Graph star(int leaves) {
  std::vector<std::pair<int, int>> e;
  for (int i = 1; i <= leaves; ++i) e.push_back({0, i});
  return makeGraph(leaves + 1, e);
}

Graph cycle(int n) {
  Graph g = path(n);
  g.addEdge(n - 1, 0);
  return g;
}

Graph randomGraph(std::mt19937& rng, int maxNodes, double p) {
  const int n = std::uniform_int_distribution<int>(0, maxNodes)(rng);
  std::bernoulli_distribution coin(p);
  Graph g = makeGraph(n, {});
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if (coin(rng)) g.addEdge(a, b);
  return g;
}

/// A relabelled copy: the distance to the original must be 0.
Graph shuffled(const Graph& g, std::mt19937& rng) {
  std::vector<int> perm(g.nodeCount());
  for (int i = 0; i < g.nodeCount(); ++i) perm[i] = i;
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<std::pair<int, int>> e;
  for (const auto& [a, b] : g.edges) e.push_back({perm[a], perm[b]});
  return makeGraph(g.nodeCount(), e);
}

void expectExact(const Graph& a, const Graph& b, int expected) {
  const GedResult r = exactGed(a, b);
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.distance, expected);
  EXPECT_EQ(r.lowerBound, expected);
  EXPECT_EQ(editPathCost(a, b, r.mapping), r.distance);  // the reported map realises the distance
  EXPECT_EQ(exactGed(b, a).distance, expected);          // symmetric cost model
}

}  // namespace

TEST(Ged, IdenticalGraphsAreAtZero) {
  expectExact(path(5), path(5), 0);
  expectExact(star(4), star(4), 0);
  expectExact(cycle(7), cycle(7), 0);
  expectExact(Graph{}, Graph{}, 0);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Graph g = randomGraph(rng, 10, 0.35);
    expectExact(g, shuffled(g, rng), 0);
  }
}

TEST(Ged, PathAgainstStar) {
  // Same node and edge counts but different degree sequences: one edge moves (delete + insert).
  expectExact(path(4), star(3), 2);
  // P5 vs K1,4: three of the path's edges can be kept at most (a star has no two disjoint
  // edges, so only the two edges at a degree-2 node fit): 2 deletions + 2 insertions.
  expectExact(path(5), star(4), 4);
}

TEST(Ged, TriangleAgainstPath) {
  expectExact(cycle(3), path(3), 1);  // delete one edge
  expectExact(cycle(3), path(4), 3);  // delete an edge, insert a node and its edge
  expectExact(cycle(4), path(4), 1);
}

TEST(Ged, EmptyGraphCostsEverything) {
  const Graph g = makeGraph(6, {{0, 1}, {1, 2}, {2, 0}, {3, 4}});
  expectExact(Graph{}, g, 6 + 4);
  const GedResult approx = bipartiteGed(g, Graph{});
  EXPECT_EQ(approx.distance, 10);
}

TEST(Ged, EditPathCostCountsEveryOperation) {
  const Graph a = path(3), b = cycle(3);
  EXPECT_EQ(editPathCost(a, b, {0, 1, 2}), 1);     // insert edge 0-2
  EXPECT_EQ(editPathCost(a, b, {-1, -1, -1}), 11);  // 3 nodes + 2 edges deleted, 3 + 3 inserted
  // a1 deleted with its 2 edges; b1 inserted with its 2 edges; a0-a2 is no edge, so b0-b2 is inserted.
  EXPECT_EQ(editPathCost(a, b, {2, -1, 0}), 1 + 2 + 1 + 2 + 1);
}

TEST(Ged, BipartiteBracketsTheExactDistance) {
  std::mt19937 rng(2024);
  int strictlyAbove = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Graph a = randomGraph(rng, 8, 0.3), b = randomGraph(rng, 8, 0.3);
    const GedResult exact = exactGed(a, b);
    const GedResult approx = bipartiteGed(a, b);
    ASSERT_TRUE(exact.exact);
    EXPECT_GE(approx.distance, exact.distance) << "trial " << trial;
    EXPECT_LE(approx.lowerBound, exact.distance) << "trial " << trial;
    EXPECT_EQ(editPathCost(a, b, approx.mapping), approx.distance);
    EXPECT_GE(approx.assignmentCost, exact.distance);  // the plain Riesen-Bunke path is an edit path too
    strictlyAbove += approx.assignmentCost > exact.distance;
  }
  // The plain assignment is often above the distance on these graphs, so the bound is tested
  // on values that differ (local search usually closes the gap on graphs this small).
  EXPECT_GT(strictlyAbove, 30);
}

TEST(Ged, TriangleInequalityOnRandomGraphs) {
  std::mt19937 rng(99);
  for (int trial = 0; trial < 60; ++trial) {
    const Graph a = randomGraph(rng, 6, 0.4), b = randomGraph(rng, 6, 0.4), c = randomGraph(rng, 6, 0.4);
    const int ab = exactGed(a, b).distance, bc = exactGed(b, c).distance, ac = exactGed(a, c).distance;
    EXPECT_LE(ac, ab + bc);
  }
}

TEST(Ged, ExactUpToTwelveNodesWithinBudget) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 6; ++trial) {
    Graph a = makeGraph(12, {}), b = makeGraph(12, {});
    std::bernoulli_distribution coin(0.25);
    for (int i = 0; i < 12; ++i)
      for (int j = i + 1; j < 12; ++j) {
        if (coin(rng)) a.addEdge(i, j);
        if (coin(rng)) b.addEdge(i, j);
      }
    const GedResult r = graphEditDistance(a, b);
    EXPECT_EQ(r.method, "exact");
    EXPECT_TRUE(r.exact) << "expansions " << r.expansions;
    EXPECT_LE(r.distance, bipartiteGed(a, b).distance);
    EXPECT_EQ(editPathCost(a, b, r.mapping), r.distance);
  }
}

TEST(Ged, LargeGraphsUseTheBipartiteMethod) {
  const GedResult r = graphEditDistance(path(50), star(49));
  EXPECT_EQ(r.method, "bipartite");
  EXPECT_EQ(r.exact, r.lowerBound == r.distance);
  // Same counts: at least 2 (degree sequences differ); a path keeps at most 2 star edges.
  EXPECT_GE(r.lowerBound, 2);
  EXPECT_GE(r.distance, 2 * (49 - 2));
}

TEST(Ged, MidSizedGraphsUseTheBinaryProgram) {
  // A path keeps at most 2 of a star's edges and every node can be matched: 2 * (29 - 2).
  const GedResult r = graphEditDistance(path(30), star(29));
  EXPECT_EQ(r.method, "mip");
  EXPECT_EQ(r.exact, r.lowerBound == r.distance);
  EXPECT_GE(r.lowerBound, 2);
  EXPECT_EQ(r.distance, 2 * (29 - 2));
}

TEST(Ged, BudgetExhaustedIsReportedNotHidden) {
  std::mt19937 rng(5);
  Graph a = makeGraph(11, {}), b = makeGraph(11, {});
  std::bernoulli_distribution coin(0.5);
  for (int i = 0; i < 11; ++i)
    for (int j = i + 1; j < 11; ++j) {
      if (coin(rng)) a.addEdge(i, j);
      if (coin(rng)) b.addEdge(i, j);
    }
  const GedResult r = exactGed(a, b, 3);
  if (!r.exact) {
    EXPECT_LE(r.lowerBound, r.distance);
    EXPECT_EQ(editPathCost(a, b, r.mapping), r.distance);
  } else {
    EXPECT_EQ(r.lowerBound, r.distance);  // solved at the root already
  }
  const GedResult full = exactGed(a, b);
  ASSERT_TRUE(full.exact);
  EXPECT_LE(r.lowerBound, full.distance);
  EXPECT_GE(r.distance, full.distance);
}

TEST(Ged, BipartiteIsTightOnSkeletonLikeGraphs) {
  // Long paths: the distance is the length difference (nodes plus edges).
  GedResult r = bipartiteGed(path(40), path(37));
  EXPECT_EQ(r.distance, 6);
  EXPECT_EQ(r.lowerBound, 6);
  // Spiders (a centre with arms) with arms of 9, 12, 20 against 9, 14, 17. An edit path of
  // cost 4: the first 14 nodes of arm 20 onto arm 14, arm 12 onto the start of arm 17, the last
  // 6 nodes of arm 20 onto the last 5 of arm 17 (one node and its edge deleted), one edge
  // deleted and one inserted where the pieces join. Fewer than 2 is impossible (42 vs 41 nodes,
  // 41 vs 40 edges).
  auto spider = [](std::vector<int> arms) {
    Graph g = makeGraph(1, {});
    for (int len : arms) {
      int prev = 0;
      for (int i = 0; i < len; ++i) {
        const int v = g.addNode(Vec3::Zero());
        g.addEdge(prev, v);
        prev = v;
      }
    }
    return g;
  };
  r = bipartiteGed(spider({9, 12, 20}), spider({9, 14, 17}));
  EXPECT_LE(r.distance, 4);
  EXPECT_GE(r.distance, 2);
  EXPECT_LE(r.lowerBound, r.distance);
  EXPECT_GT(r.assignmentCost, r.distance);  // the plain assignment alone is far off here
}

TEST(Ged, BipartiteIsSymmetric) {
  std::mt19937 rng(31);
  for (int trial = 0; trial < 30; ++trial) {
    const Graph a = randomGraph(rng, 30, 0.1), b = randomGraph(rng, 30, 0.1);
    const GedResult ab = bipartiteGed(a, b), ba = bipartiteGed(b, a);
    EXPECT_EQ(ab.distance, ba.distance);
    EXPECT_EQ(ab.lowerBound, ba.lowerBound);
    EXPECT_EQ(editPathCost(a, b, ab.mapping), ab.distance);
    EXPECT_EQ(editPathCost(b, a, ba.mapping), ba.distance);
  }
}

// A graph against itself, in the same node order: the bipartite method must prove 0, as the
// skeleton's rigid-motion control needs (ACD skeletons of an invariant decomposition come out in
// the same order). Sparse random graphs of skeleton size (98 nodes, as armadillo's) are where the
// assignment alone got lost among look-alike nodes: 98-232 edits for the graph against itself.
TEST(Ged, SameGraphInTheSameOrderIsProvenZeroAtSkeletonSize) {
  std::mt19937 rng(11);
  for (int t = 0; t < 5; ++t) {
    SCOPED_TRACE(t);
    std::bernoulli_distribution coin(0.03 + 0.005 * t);
    Graph g = makeGraph(98, {});
    for (int a = 0; a < 98; ++a)
      for (int b = a + 1; b < 98; ++b)
        if (coin(rng)) g.addEdge(a, b);
    const GedResult r = bipartiteGed(g, g);
    EXPECT_EQ(r.distance, 0);
    EXPECT_TRUE(r.exact);
    EXPECT_EQ(editPathCost(g, g, r.mapping), 0);
  }
}
