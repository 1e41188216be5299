#include "graph.hpp"

#include <acd/algo/union_find.hpp>
#include <algorithm>
#include <numeric>
#include <set>

namespace skeleton {

const char* toString(NodeKind kind) {
  switch (kind) {
    case NodeKind::Component: return "component";
    case NodeKind::Cut: return "cut";
    case NodeKind::Curve: return "curve";
  }
  return "curve";
}

int Graph::addNode(const Vec3& position, NodeKind kind, int source) {
  nodes.push_back({position, kind, source});
  return nodeCount() - 1;
}

bool Graph::addEdge(int a, int b) {
  if (a == b) return false;
  const std::pair<int, int> e = std::minmax(a, b);
  if (std::find(edges.begin(), edges.end(), e) != edges.end()) return false;
  edges.push_back(e);
  return true;
}

Graph makeGraph(int nodes, const std::vector<std::pair<int, int>>& edges) {
  Graph g;
  for (int i = 0; i < nodes; ++i) g.addNode(Vec3::Zero());
  for (const auto& [a, b] : edges) g.addEdge(a, b);
  return g;
}

std::vector<int> degrees(const Graph& g) {
  std::vector<int> d(g.nodes.size(), 0);
  for (const auto& [a, b] : g.edges) ++d[a], ++d[b];
  return d;
}

std::vector<char> adjacency(const Graph& g) {
  const std::size_t n = g.nodes.size();
  std::vector<char> m(n * n, 0);
  for (const auto& [a, b] : g.edges) m[a * n + b] = m[b * n + a] = 1;
  return m;
}

int connectedComponents(const Graph& g) {
  acd::UnionFind sets(static_cast<int>(g.nodes.size()));
  int count = g.nodeCount();
  for (const auto& [a, b] : g.edges) {
    const int ra = sets.find(a), rb = sets.find(b);
    if (ra != rb) sets.join(ra, rb), --count;
  }
  return count;
}

Graph contractDegreeTwo(const Graph& g) { return contractWithChains(g).graph; }

Contraction contractWithChains(const Graph& g) {
  const int n = g.nodeCount();
  std::vector<std::set<int>> adj(n);
  for (const auto& [a, b] : g.edges) adj[a].insert(b), adj[b].insert(a);
  std::vector<char> removed(n, 0);
  // Repeat until no node can go: removing a node replaces two edges by one, which can make
  // a node skipped earlier (its neighbours were adjacent) removable.
  bool changed = true;
  while (changed) {
    changed = false;
    for (int v = 0; v < n; ++v) {
      if (removed[v] || adj[v].size() != 2) continue;
      const int a = *adj[v].begin(), b = *adj[v].rbegin();
      if (adj[a].count(b)) continue;
      adj[a].erase(v), adj[b].erase(v);
      adj[a].insert(b), adj[b].insert(a);
      adj[v].clear();
      removed[v] = 1;
      changed = true;
    }
  }
  Contraction c;
  Graph& out = c.graph;
  std::vector<int> index(n, -1);
  for (int v = 0; v < n; ++v)
    if (!removed[v]) {
      index[v] = out.addNode(g.nodes[v].position, g.nodes[v].kind, g.nodes[v].source);
      c.kept.push_back(v);
    }
  for (int v = 0; v < n; ++v)
    for (int w : adj[v])
      if (v < w) out.addEdge(index[v], index[w]);
  std::sort(out.edges.begin(), out.edges.end());
  // Chains: from each kept node, walk the input through removed nodes to the next kept one.
  std::vector<std::vector<int>> nbr(n);
  for (const auto& [a, b] : g.edges) nbr[a].push_back(b), nbr[b].push_back(a);
  c.chains.assign(out.edges.size(), {});
  for (int p : c.kept)
    for (int t : nbr[p]) {
      std::vector<int> chain;
      int prev = p, cur = t;
      while (removed[cur]) {
        chain.push_back(cur);
        const int next = nbr[cur][0] == prev ? nbr[cur][1] : nbr[cur][0];
        prev = cur;
        cur = next;
      }
      const int a = index[p], b = index[cur];
      if (a >= b) continue;  // each chain once, walked from its lower end
      const auto it = std::lower_bound(out.edges.begin(), out.edges.end(), std::make_pair(a, b));
      if (it != out.edges.end() && *it == std::make_pair(a, b)) c.chains[it - out.edges.begin()] = chain;
    }
  return c;
}

}  // namespace skeleton
