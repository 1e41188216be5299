#include <acd/algo/handles.hpp>

#include <acd/algo/union_find.hpp>

#include <algorithm>
#include <map>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace acd {
namespace {

/// Edge-connected face components of the mesh once `blocked` edges are removed.
int faceComponents(const TriMesh& mesh, const SurfaceGraph& graph,
                   const std::unordered_set<std::uint64_t>& blocked) {
  const int nf = static_cast<int>(mesh.faces.size());
  std::vector<char> seen(nf, 0);
  std::vector<int> stack;
  int components = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (seen[seed]) continue;
    ++components;
    seen[seed] = 1;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int g = graph.faceAcross(f, k);
        if (g < 0 || seen[g]) continue;
        if (blocked.count(edgeKey(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]))) continue;
        seen[g] = 1;
        stack.push_back(g);
      }
    }
  }
  return components;
}

/// Cut candidates of one shared pocket: closed curves where the faces nearest to one
/// loop meet the faces nearest to another.
void pocketCuts(const TriMesh& mesh, const SurfaceGraph& graph, const SharedPocket& pocket,
                std::vector<HandleCut>& out) {
  const int nv = static_cast<int>(mesh.vertices.size());
  const int nf = static_cast<int>(mesh.faces.size());
  std::vector<char> allowed(nv, 0), inPocket(nf, 0);
  for (int f : pocket.faces) {
    inPocket[f] = 1;
    for (int v : mesh.faces[f]) allowed[v] = 1;
  }
  std::vector<int> sourceLoop(nv, -1), sources;
  for (std::size_t i = 0; i < pocket.loops.size(); ++i)
    for (int v : pocket.loops[i])
      if (sourceLoop[v] < 0) sourceLoop[v] = static_cast<int>(i), sources.push_back(v);
  if (sources.empty()) return;

  std::vector<double> distance;
  std::vector<int> parent;
  PathFinder(graph).flood(sources, {}, &allowed, distance, parent);

  // Each vertex belongs to the loop its shortest path comes from.
  std::vector<int> vertexLoop(sourceLoop);
  std::vector<int> chain;
  for (int f : pocket.faces)
    for (int v0 : mesh.faces[f]) {
      int v = v0;
      chain.clear();
      while (vertexLoop[v] < 0 && parent[v] >= 0) chain.push_back(v), v = parent[v];
      for (int c : chain) vertexLoop[c] = vertexLoop[v];
    }
  // A face belongs to the loop of its vertex nearest to any loop.
  std::unordered_map<int, int> faceLoop;
  for (int f : pocket.faces) {
    int best = mesh.faces[f][0];
    for (int v : mesh.faces[f])
      if (distance[v] < distance[best]) best = v;
    faceLoop[f] = vertexLoop[best];
  }

  // Edges between faces of different loops, grouped into connected curves.
  struct CutEdge {
    int a, b, loopA, loopB;
  };
  std::vector<CutEdge> edges;
  for (int f : pocket.faces)
    for (int k = 0; k < 3; ++k) {
      const int g = graph.faceAcross(f, k);
      if (g < 0 || g < f || !inPocket[g]) continue;
      const int lf = faceLoop[f], lg = faceLoop[g];
      if (lf == lg || lf < 0 || lg < 0) continue;
      edges.push_back({mesh.faces[f][k], mesh.faces[f][(k + 1) % 3], std::min(lf, lg), std::max(lf, lg)});
    }
  if (edges.empty()) return;
  // The border of each loop's part is a candidate: with two loops it is the curve between them;
  // with three or more, where the parts' borders branch, each part's own border is still closed.
  for (std::size_t loop = 0; loop < pocket.loops.size(); ++loop) {
    std::vector<const CutEdge*> mine;
    for (const auto& e : edges)
      if (e.loopA == static_cast<int>(loop) || e.loopB == static_cast<int>(loop)) mine.push_back(&e);
    if (mine.empty()) continue;
    std::unordered_map<int, int> local;
    for (const CutEdge* e : mine) {
      local.emplace(e->a, static_cast<int>(local.size()));
      local.emplace(e->b, static_cast<int>(local.size()));
    }
    UnionFind sets(static_cast<int>(local.size()));
    for (const CutEdge* e : mine) sets.join(local[e->a], local[e->b]);
    std::map<int, std::vector<const CutEdge*>> curves;
    for (const CutEdge* e : mine) curves[sets.find(local[e->a])].push_back(e);

    for (const auto& [root, curve] : curves) {
      // Only a closed curve cuts a handle; an open arc would only split the pocket.
      std::unordered_map<int, int> degree;
      std::map<int, int> others;
      HandleCut cut;
      for (const CutEdge* e : curve) {
        ++degree[e->a], ++degree[e->b];
        ++others[e->loopA == static_cast<int>(loop) ? e->loopB : e->loopA];
        cut.edges.push_back(edgeKey(e->a, e->b));
        cut.length += (mesh.vertices[e->a] - mesh.vertices[e->b]).norm();
      }
      if (!std::all_of(degree.begin(), degree.end(), [](const auto& d) { return d.second % 2 == 0; })) continue;
      const auto major = std::max_element(others.begin(), others.end(),
                                          [](const auto& x, const auto& y) { return x.second < y.second; });
      const int bridgeA = pocket.loopBridge[loop], bridgeB = pocket.loopBridge[major->first];
      cut.capA = std::min(bridgeA, bridgeB);
      cut.capB = std::max(bridgeA, bridgeB);
      std::sort(cut.edges.begin(), cut.edges.end());
      out.push_back(std::move(cut));
    }
  }
}

/// Every pocket's candidate curves, shortest first.
std::vector<HandleCut> candidatesOf(const TriMesh& mesh, const SurfaceGraph& graph,
                                    const std::vector<SharedPocket>& pockets) {
  std::vector<HandleCut> candidates;
  for (const auto& pocket : pockets)
    if (pocket.loops.size() >= 2) pocketCuts(mesh, graph, pocket, candidates);
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const HandleCut& a, const HandleCut& b) { return a.length < b.length; });
  return candidates;
}

}  // namespace

std::vector<HandleCut> findHandleCuts(const TriMesh& mesh, const SurfaceGraph& graph,
                                      const std::vector<SharedPocket>& pockets,
                                      const std::vector<std::uint64_t>& existing) {
  std::vector<HandleCut> candidates = candidatesOf(mesh, graph, pockets);

  std::unordered_set<std::uint64_t> blocked(existing.begin(), existing.end());
  const int baseline = faceComponents(mesh, graph, blocked);
  std::vector<HandleCut> kept;
  for (auto& cut : candidates) {
    std::vector<std::uint64_t> added;
    for (std::uint64_t e : cut.edges)
      if (blocked.insert(e).second) added.push_back(e);
    if (added.empty()) continue;
    if (faceComponents(mesh, graph, blocked) > baseline) {
      for (std::uint64_t e : added) blocked.erase(e);  // would split the model: drop it
      continue;
    }
    kept.push_back(std::move(cut));
  }
  return kept;
}

std::vector<HandleCut> findPocketDivides(const TriMesh& mesh, const SurfaceGraph& graph,
                                         const std::vector<SharedPocket>& pockets,
                                         const std::vector<std::uint64_t>& existing) {
  std::vector<HandleCut> candidates = candidatesOf(mesh, graph, pockets);
  std::unordered_set<std::uint64_t> blocked(existing.begin(), existing.end());
  std::vector<HandleCut> kept;
  for (auto& cut : candidates) {
    if (cut.capA == cut.capB) continue;  // both sides belong to one bridge: nothing to divide
    bool fresh = false;
    for (std::uint64_t e : cut.edges) fresh |= blocked.insert(e).second;
    if (fresh) kept.push_back(std::move(cut));
  }
  return kept;
}

int distinctBridges(const SharedPocket& pocket) {
  std::vector<int> b = pocket.loopBridge;
  std::sort(b.begin(), b.end());
  return static_cast<int>(std::unique(b.begin(), b.end()) - b.begin());
}

std::vector<SharedPocket> findSharedPockets(const TriMesh& mesh, const SurfaceGraph& graph,
                                            const std::vector<int>& faceRegion,
                                            const std::unordered_map<std::uint64_t, int>& bridgeOnLeft) {
  const int nf = static_cast<int>(mesh.faces.size());
  int regions = 0;
  for (int r : faceRegion) regions = std::max(regions, r + 1);
  std::vector<std::vector<int>> facesOf(regions);
  for (int f = 0; f < nf; ++f) facesOf[faceRegion[f]].push_back(f);

  std::vector<SharedPocket> out;
  for (int r = 0; r < regions; ++r) {
    // Border edges of the region, as seen from its faces, grouped into loops by shared vertices.
    std::vector<std::pair<int, int>> border;
    for (int f : facesOf[r])
      for (int k = 0; k < 3; ++k) {
        const int g = graph.faceAcross(f, k);
        if (g >= 0 && faceRegion[g] == r) continue;
        border.emplace_back(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]);
      }
    if (border.size() < 6) continue;
    std::unordered_map<int, int> local;
    for (auto [a, b] : border) {
      local.emplace(a, static_cast<int>(local.size()));
      local.emplace(b, static_cast<int>(local.size()));
    }
    UnionFind sets(static_cast<int>(local.size()));
    for (auto [a, b] : border) sets.join(local[a], local[b]);
    std::map<int, std::pair<std::vector<int>, std::map<int, int>>> loops;  // root -> vertices, bridge votes
    for (auto [a, b] : border) {
      auto& loop = loops[sets.find(local[a])];
      loop.first.push_back(a);
      loop.first.push_back(b);
      const auto it = bridgeOnLeft.find(directedKey(a, b));
      if (it != bridgeOnLeft.end()) ++loop.second[it->second];
    }
    SharedPocket pocket;
    for (auto& [root, loop] : loops) {
      if (loop.second.empty()) continue;  // a loop of barriers (earlier handle cuts), not a bridge's
      const auto major = std::max_element(loop.second.begin(), loop.second.end(),
                                          [](const auto& x, const auto& y) { return x.second < y.second; });
      std::sort(loop.first.begin(), loop.first.end());
      loop.first.erase(std::unique(loop.first.begin(), loop.first.end()), loop.first.end());
      pocket.loops.push_back(std::move(loop.first));
      pocket.loopBridge.push_back(major->first);
    }
    if (pocket.loops.size() < 2) continue;
    pocket.faces = std::move(facesOf[r]);
    out.push_back(std::move(pocket));
  }
  return out;
}

int closedGenus(const TriMesh& mesh) {
  std::unordered_set<std::uint64_t> edges;
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& f : mesh.faces)
    for (int k = 0; k < 3; ++k) {
      used[f[k]] = 1;
      edges.insert(edgeKey(f[k], f[(k + 1) % 3]));
    }
  const long long v = std::count(used.begin(), used.end(), 1);
  const long long chi = v - static_cast<long long>(edges.size()) + static_cast<long long>(mesh.faces.size());
  return static_cast<int>(std::max(0LL, (2 - chi) / 2));
}

}  // namespace acd
