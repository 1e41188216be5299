// SurfaceGraph and PathFinder (libacd/src/mesh/surface_graph.cpp): adjacency read back from the
// faces themselves, and shortest paths and floods against a plain Dijkstra written here, on a
// triangulated grid (open) and a torus (closed).
#include <acd/algo/surface_graph.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <set>

using namespace acd;

namespace {

/// An n x n grid of unit squares in the plane z = 0, each split along a diagonal.
TriMesh grid(int n) {
  TriMesh m;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) m.vertices.emplace_back(x, y, 0);
  auto id = [n](int x, int y) { return y * (n + 1) + x; };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      m.faces.push_back({id(x, y), id(x + 1, y), id(x + 1, y + 1)});
      m.faces.push_back({id(x, y), id(x + 1, y + 1), id(x, y + 1)});
    }
  return m;
}

/// Edge lengths by vertex pair, from the faces.
std::map<std::pair<int, int>, double> edges(const TriMesh& m) {
  std::map<std::pair<int, int>, double> out;
  for (const Face& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      const double len = (m.vertices[a] - m.vertices[b]).norm();
      out[{a, b}] = len, out[{b, a}] = len;
    }
  return out;
}

/// Distances from `source` along the edges (the oracle).
std::vector<double> dijkstra(const TriMesh& m, int source, const std::vector<char>* allowed = nullptr) {
  std::vector<std::vector<std::pair<int, double>>> adj(m.vertices.size());
  for (const auto& [e, len] : edges(m)) adj[e.first].push_back({e.second, len});
  std::vector<double> d(m.vertices.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
  d[source] = 0, q.push({0, source});
  while (!q.empty()) {
    const auto [dv, v] = q.top();
    q.pop();
    if (dv > d[v]) continue;
    for (const auto& [w, len] : adj[v]) {
      if (allowed && !(*allowed)[w]) continue;
      if (dv + len < d[w]) d[w] = dv + len, q.push({d[w], w});
    }
  }
  return d;
}

double pathLength(const TriMesh& m, const std::vector<int>& path) {
  const auto e = edges(m);
  double sum = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const auto it = e.find({path[i - 1], path[i]});
    if (it == e.end()) return -1;  // not an edge
    sum += it->second;
  }
  return sum;
}

}  // namespace

TEST(SurfaceGraph, AdjacencyIsTheFacesOwn) {
  for (const TriMesh& m : {grid(4), shapes::torus(2.0, 0.5, 10, 6)}) {
    const SurfaceGraph g(m);
    EXPECT_EQ(g.vertexCount(), static_cast<int>(m.vertices.size()));
    EXPECT_EQ(g.faceCount(), static_cast<int>(m.faces.size()));
    const auto e = edges(m);
    std::set<std::pair<int, int>> seen;
    for (int v = 0; v < g.vertexCount(); ++v)
      for (int s = g.begin(v); s < g.end(v); ++s) {
        const int w = g.neighbour(s);
        ASSERT_TRUE(e.count({v, w})) << v << " -> " << w << " is no edge";
        if (s > g.begin(v)) EXPECT_LT(g.neighbour(s - 1), w) << "neighbours of " << v << " sorted, once each";
        EXPECT_DOUBLE_EQ(g.length(s), e.at({v, w}));
        seen.insert({v, w});
      }
    EXPECT_EQ(seen.size(), e.size());  // every edge, both ways
    for (int f = 0; f < g.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = m.faces[f][k], b = m.faces[f][(k + 1) % 3];
        EXPECT_EQ(g.faceLeftOf(a, b), f);
        const int across = g.faceAcross(f, k);
        if (across < 0) {
          EXPECT_EQ(g.faceLeftOf(b, a), -1);  // a boundary edge
          continue;
        }
        EXPECT_EQ(g.faceLeftOf(b, a), across);
      }
  }
  // A directed edge two faces repeat (a non-manifold input): the later face is left of it.
  TriMesh twice;
  twice.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0)};
  twice.faces = {{0, 1, 2}, {0, 1, 3}};
  const SurfaceGraph repeated(twice);
  EXPECT_EQ(repeated.faceLeftOf(0, 1), 1);
  EXPECT_EQ(repeated.end(0) - repeated.begin(0), 3);  // 1, 2 and 3, each once
  // The grid's border edges have no face across, the torus's none without.
  const TriMesh open = grid(3);
  const SurfaceGraph g(open);
  int border = 0;
  for (int f = 0; f < g.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) border += g.faceAcross(f, k) < 0;
  EXPECT_EQ(border, 4 * 3);
}

TEST(PathFinder, ShortestPathsAndFloodsMatchDijkstra) {
  for (const TriMesh& m : {grid(6), shapes::torus(2.0, 0.5, 12, 8)}) {
    const SurfaceGraph g(m);
    PathFinder finder(g);
    const int n = static_cast<int>(m.vertices.size());
    const std::vector<double> fromZero = dijkstra(m, 0);
    for (int t = 1; t < n; t += 5) {
      const std::vector<int> path = finder.path(0, t);
      ASSERT_FALSE(path.empty());
      EXPECT_EQ(path.front(), 0);
      EXPECT_EQ(path.back(), t);
      EXPECT_NEAR(pathLength(m, path), fromZero[t], 1e-12) << "to " << t;
      // With explicit Euclidean weights (Dijkstra instead of A*), the same length.
      const std::vector<int> weighted =
          finder.path(0, t, [&](int a, int b, int) { return (m.vertices[a] - m.vertices[b]).norm(); });
      EXPECT_NEAR(pathLength(m, weighted), fromZero[t], 1e-12) << "to " << t;
    }
    std::vector<double> distance;
    std::vector<int> parent;
    finder.flood({0, n / 2}, [&](int a, int b, int) { return (m.vertices[a] - m.vertices[b]).norm(); }, nullptr,
                 distance, parent);
    const std::vector<double> fromHalf = dijkstra(m, n / 2);
    for (int v = 0; v < n; ++v) EXPECT_NEAR(distance[v], std::min(fromZero[v], fromHalf[v]), 1e-12) << v;
  }
}

// A wall of forbidden vertices: the path goes around it, or there is none.
TEST(PathFinder, AllowedMaskAndUnreachableTargets) {
  const int n = 6;
  const TriMesh m = grid(n);
  const SurfaceGraph g(m);
  PathFinder finder(g);
  auto id = [n](int x, int y) { return y * (n + 1) + x; };
  std::vector<char> allowed(m.vertices.size(), 1);
  for (int y = 0; y < n; ++y) allowed[id(3, y)] = 0;  // a wall at x = 3 with a gap at the top
  const std::vector<int> around = finder.path(id(0, 0), id(6, 0), {}, &allowed);
  ASSERT_FALSE(around.empty());
  for (int v : around) EXPECT_TRUE(allowed[v]) << v;
  EXPECT_NEAR(pathLength(m, around), dijkstra(m, id(0, 0), &allowed)[id(6, 0)], 1e-12);
  EXPECT_GT(pathLength(m, around), 6.0 + 1e-9);  // longer than the straight way
  allowed[id(3, n)] = 0;  // close the gap
  EXPECT_TRUE(finder.path(id(0, 0), id(6, 0), {}, &allowed).empty());
}

// search(): the flood in the finder's own buffers. Interleaved with path() (which shares them),
// masked, and stopped at targets, its distances and paths must be Dijkstra's written here.
TEST(PathFinder, SearchesInTheFindersBuffersMatchDijkstra) {
  const int n = 6;
  const TriMesh m = grid(n);
  const SurfaceGraph g(m);
  PathFinder finder(g);
  auto id = [n](int x, int y) { return y * (n + 1) + x; };
  std::vector<char> allowed(m.vertices.size(), 1);
  for (int y = 0; y < n; ++y) allowed[id(3, y)] = 0;  // a wall with a gap at the top
  const EdgeWeight euclid = [&](int a, int b, int) { return (m.vertices[a] - m.vertices[b]).norm(); };
  for (int source : {id(0, 0), id(5, 2), id(1, 6)}) {
    finder.path(id(6, 6), id(0, 1));  // leaves marks in the shared buffers
    const std::vector<double> expected = dijkstra(m, source, &allowed);
    // Stopped once two far targets are settled: theirs are final.
    const std::vector<int> targets{id(6, 0), id(0, 6)};
    finder.search({source}, euclid, &allowed, &targets);
    for (int t : targets) {
      EXPECT_NEAR(finder.distance(t), expected[t], 1e-12) << source << " to " << t;
      const std::vector<int> path = finder.pathTo(t);
      ASSERT_FALSE(path.empty());
      EXPECT_EQ(path.front(), source);
      EXPECT_EQ(path.back(), t);
      EXPECT_NEAR(pathLength(m, path), expected[t], 1e-12);
      for (int v : path) EXPECT_TRUE(allowed[v]) << v;
    }
    // Unstopped: every vertex, the wall's unreachable.
    finder.search({source}, euclid, &allowed);
    for (int v = 0; v < static_cast<int>(m.vertices.size()); ++v) {
      if (!allowed[v]) {
        EXPECT_EQ(finder.distance(v), std::numeric_limits<double>::infinity()) << v;
        EXPECT_EQ(finder.pathTo(v), std::vector<int>{v});
        continue;
      }
      EXPECT_NEAR(finder.distance(v), expected[v], 1e-12) << source << " to " << v;
    }
  }
}
