// Degree-2 contraction (D2): hand-made graphs and invariants on random graphs.
#include "ged.hpp"
#include "graph.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace skeleton;

namespace {

std::vector<int> sortedDegrees(const Graph& g) {
  std::vector<int> d = degrees(g);
  std::sort(d.begin(), d.end());
  return d;
}

/// Same graph up to isomorphism (exact distance 0).
void expectIsomorphic(const Graph& a, const Graph& b) {
  const GedResult r = exactGed(a, b);
  ASSERT_TRUE(r.exact);
  EXPECT_EQ(r.distance, 0);
}

}  // namespace

TEST(Contract, PathBecomesOneEdge) {
  const Graph g = contractDegreeTwo(makeGraph(6, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}}));
  EXPECT_EQ(g.nodeCount(), 2);
  EXPECT_EQ(g.edgeCount(), 1);
}

TEST(Contract, StarAndIsolatedNodesStay) {
  const Graph star = makeGraph(5, {{0, 1}, {0, 2}, {0, 3}, {0, 4}});
  expectIsomorphic(contractDegreeTwo(star), star);
  const Graph lonely = makeGraph(3, {});
  EXPECT_EQ(contractDegreeTwo(lonely).nodeCount(), 3);
}

TEST(Contract, LongArmsOfAYBecomeAStar) {
  // Centre 0 with three arms of three nodes each.
  const Graph y = makeGraph(10, {{0, 1}, {1, 2}, {2, 3}, {0, 4}, {4, 5}, {5, 6}, {0, 7}, {7, 8}, {8, 9}});
  const Graph c = contractDegreeTwo(y);
  expectIsomorphic(c, makeGraph(4, {{0, 1}, {0, 2}, {0, 3}}));
}

TEST(Contract, CycleWithoutBranchNodeBecomesATriangle) {
  const Graph c6 = makeGraph(6, {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}});
  expectIsomorphic(contractDegreeTwo(c6), makeGraph(3, {{0, 1}, {1, 2}, {2, 0}}));
  const Graph triangle = makeGraph(3, {{0, 1}, {1, 2}, {2, 0}});
  expectIsomorphic(contractDegreeTwo(triangle), triangle);
}

TEST(Contract, ParallelChainsKeepOneNodeEach) {
  // Theta graph: branch nodes 0 and 1 joined by three chains of two inner nodes each.
  const Graph theta = makeGraph(8, {{0, 2}, {2, 3}, {3, 1}, {0, 4}, {4, 5}, {5, 1}, {0, 6}, {6, 7}, {7, 1}});
  const Graph c = contractDegreeTwo(theta);
  // One chain becomes the edge 0-1, the other two keep one node each: K4 minus an edge.
  EXPECT_EQ(c.nodeCount(), 4);
  EXPECT_EQ(c.edgeCount(), 5);
  EXPECT_EQ(sortedDegrees(c), (std::vector<int>{2, 2, 3, 3}));
}

TEST(Contract, LoopThroughOneBranchNodeKeepsTwoNodes) {
  // Node 0 has a tail 0-1 and a loop 0-2-3-4-5-0.
  const Graph g = makeGraph(6, {{0, 1}, {0, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}});
  expectIsomorphic(contractDegreeTwo(g), makeGraph(4, {{0, 1}, {0, 2}, {2, 3}, {3, 0}}));
}

TEST(Contract, SkeletonCutNodesDisappear) {
  // Component nodes 0..3 joined through cut nodes 4..6 (each of degree 2): a path 0-1-2 and 1-3.
  const Graph skel = makeGraph(7, {{0, 4}, {4, 1}, {1, 5}, {5, 2}, {1, 6}, {6, 3}});
  expectIsomorphic(contractDegreeTwo(skel), makeGraph(4, {{0, 1}, {1, 2}, {1, 3}}));
}

TEST(Contract, InvariantsOnRandomGraphs) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = std::uniform_int_distribution<int>(1, 14)(rng);
    std::bernoulli_distribution coin(std::uniform_real_distribution<double>(0.05, 0.4)(rng));
    Graph g = makeGraph(n, {});
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        if (coin(rng)) g.addEdge(a, b);
    const Graph c = contractDegreeTwo(g);
    // Each removal takes one node and one edge: the cycle rank and the components stay.
    EXPECT_EQ(c.edgeCount() - c.nodeCount(), g.edgeCount() - g.nodeCount());
    EXPECT_EQ(connectedComponents(c), connectedComponents(g));
    // Degrees other than 2 are untouched.
    std::vector<int> before = degrees(g), after = degrees(c);
    before.erase(std::remove(before.begin(), before.end(), 2), before.end());
    after.erase(std::remove(after.begin(), after.end(), 2), after.end());
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    EXPECT_EQ(before, after);
    // Nothing more can go: every degree-2 node left has adjacent neighbours.
    const std::vector<char> adj = adjacency(c);
    std::vector<std::vector<int>> nbr(c.nodeCount());
    for (const auto& [a, b] : c.edges) nbr[a].push_back(b), nbr[b].push_back(a);
    for (int v = 0; v < c.nodeCount(); ++v)
      if (nbr[v].size() == 2) EXPECT_TRUE(adj[nbr[v][0] * c.nodeCount() + nbr[v][1]]);
    // Contracting twice changes nothing.
    EXPECT_EQ(contractDegreeTwo(c).nodeCount(), c.nodeCount());
  }
}

TEST(Contract, ChainsRebuildTheInput) {
  std::mt19937 rng(8);
  for (int trial = 0; trial < 100; ++trial) {
    // Sparse graphs have long chains.
    const int n = std::uniform_int_distribution<int>(2, 30)(rng);
    Graph g = makeGraph(n, {});
    for (int v = 1; v < n; ++v) g.addEdge(v, std::uniform_int_distribution<int>(0, v - 1)(rng));  // a tree
    for (int k = 0; k < 3; ++k) {
      const int a = std::uniform_int_distribution<int>(0, n - 1)(rng);
      const int b = std::uniform_int_distribution<int>(0, n - 1)(rng);  // drawn after a
      g.addEdge(a, b);
    }
    const Contraction c = contractWithChains(g);
    ASSERT_EQ(c.kept.size(), static_cast<std::size_t>(c.graph.nodeCount()));
    ASSERT_EQ(c.chains.size(), c.graph.edges.size());
    const std::vector<char> adj = adjacency(g);
    std::vector<int> seen(n, 0);
    for (int k : c.kept) ++seen[k];
    for (std::size_t e = 0; e < c.graph.edges.size(); ++e) {
      std::vector<int> walk{c.kept[c.graph.edges[e].first]};
      walk.insert(walk.end(), c.chains[e].begin(), c.chains[e].end());
      walk.push_back(c.kept[c.graph.edges[e].second]);
      for (std::size_t i = 0; i + 1 < walk.size(); ++i) EXPECT_TRUE(adj[walk[i] * n + walk[i + 1]]);
      for (int v : c.chains[e]) ++seen[v];
    }
    for (int v = 0; v < n; ++v) EXPECT_EQ(seen[v], 1) << "node " << v << " trial " << trial;
  }
}
