#include <acd/algo/knot_graph.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>

namespace acd {

namespace {

int loopPosition(const ConcavityMap& map, const Knot& k) {
  const auto& pe = map.projections[k.projection];
  return pe.leftBridge == k.pocket ? k.along : static_cast<int>(pe.path.size()) - 1 - k.along;
}

}  // namespace

KnotGraph buildKnotGraph(const TriMesh& mesh, const SurfaceGraph& graph, const ConcavityMap& map, double delta,
                         const std::vector<double>* slotCurvature) {
  KnotGraph kg;
  PathFinder finder(graph);
  std::vector<double> ownCurvature;
  if (!slotCurvature) ownCurvature = slotCurvatures(mesh, graph);
  const std::vector<double>& curvature = slotCurvature ? *slotCurvature : ownCurvature;
  const int bridges = static_cast<int>(map.bridges.size());
  std::vector<std::vector<char>> inPocket(bridges, std::vector<char>(mesh.vertices.size(), 0));
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f]) inPocket[map.facePocket[f]][v] = 1;

  for (int pocket = 0; pocket < bridges; ++pocket) {
    const std::vector<Knot> knots = pocketKnots(mesh, map, pocket, delta);
    if (knots.empty()) continue;
    const int base = static_cast<int>(kg.nodes.size());
    kg.nodes.insert(kg.nodes.end(), knots.begin(), knots.end());
    std::map<int, std::vector<int>> byBoundary;  // projection -> node indices in loop order
    for (int k = 0; k < static_cast<int>(knots.size()); ++k) byBoundary[knots[k].projection].push_back(base + k);
    for (auto& [p, list] : byBoundary)
      std::sort(list.begin(), list.end(),
                [&](int a, int b) { return loopPosition(map, kg.nodes[a]) < loopPosition(map, kg.nodes[b]); });
    if (byBoundary.size() < 2) continue;
    // One flood per knot inside the pocket, with the Eq. 4 edge weight.
    const Bridge& bridge = map.bridges[pocket];
    std::vector<double> concavity(mesh.vertices.size(), 0.0);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      if (inPocket[pocket][v]) concavity[v] = bridge.concavityOf(mesh.vertices[v]);
    const EdgeWeight weight = [&](int a, int b, int slot) {
      return cutEdgeWeight(concavity[a], concavity[b], curvature[slot], graph.length(slot));
    };
    // Per knot, the distance and path to each knot node of a later boundary.
    std::vector<std::map<int, std::pair<double, std::vector<int>>>> reach(knots.size());
    std::vector<char>& mask = inPocket[pocket];
    // Pairs are matched from an earlier boundary to a later one, so a knot needs the distances to
    // the knots of later boundaries only; its flood stops once they are settled.
    for (auto i = byBoundary.begin(); i != byBoundary.end(); ++i) {
      std::vector<int> later;
      for (auto j = std::next(i); j != byBoundary.end(); ++j)
        for (int node : j->second) later.push_back(kg.nodes[node].vertex);
      if (later.empty()) continue;
      for (int node : i->second) {
        const int k = node - base;
        const char saved = mask[knots[k].vertex];
        mask[knots[k].vertex] = 1;
        finder.search({knots[k].vertex}, weight, &mask, &later);
        mask[knots[k].vertex] = saved;
        for (int v : later) reach[k].emplace(v, std::pair{finder.distance(v), finder.pathTo(v)});
      }
    }
    for (auto i = byBoundary.begin(); i != byBoundary.end(); ++i)
      for (auto j = std::next(i); j != byBoundary.end(); ++j) {
        const std::vector<int>& rows = i->second;
        const std::vector<int>& cols = j->second;
        std::vector<std::vector<double>> cost(rows.size(), std::vector<double>(cols.size()));
        for (std::size_t r = 0; r < rows.size(); ++r)
          for (std::size_t c = 0; c < cols.size(); ++c) cost[r][c] = reach[rows[r] - base].at(kg.nodes[cols[c]].vertex).first;
        for (const auto& [r, c] : nonCrossingMatching(cost)) {
          KnotGraph::Edge e;
          e.a = rows[r];
          e.b = cols[c];
          e.weight = cost[r][c];
          e.pocket = pocket;
          e.path = reach[rows[r] - base].at(kg.nodes[e.b].vertex).second;
          kg.edges.push_back(std::move(e));
        }
      }
  }
  // Links: a knot of one pocket joins the nearest knot the pocket across the same boundary found.
  std::map<int, std::vector<int>> onProjection;
  for (int n = 0; n < static_cast<int>(kg.nodes.size()); ++n) onProjection[kg.nodes[n].projection].push_back(n);
  for (const auto& [p, list] : onProjection) {
    const auto& path = map.projections[p].path;
    for (int a : list) {
      int best = -1;
      for (int b : list)
        if (kg.nodes[b].pocket != kg.nodes[a].pocket && kg.nodes[a].pocket < kg.nodes[b].pocket &&
            (best < 0 || std::abs(kg.nodes[b].along - kg.nodes[a].along) < std::abs(kg.nodes[best].along - kg.nodes[a].along)))
          best = b;
      if (best < 0) continue;
      KnotGraph::Edge e;
      e.a = a;
      e.b = best;
      const int lo = std::min(kg.nodes[a].along, kg.nodes[best].along), hi = std::max(kg.nodes[a].along, kg.nodes[best].along);
      for (int i = lo; i <= hi; ++i) e.path.push_back(path[i]);
      if (kg.nodes[a].along > kg.nodes[best].along) std::reverse(e.path.begin(), e.path.end());
      for (std::size_t i = 1; i < e.path.size(); ++i)
        e.weight += (mesh.vertices[e.path[i]] - mesh.vertices[e.path[i - 1]]).norm();
      kg.edges.push_back(std::move(e));
    }
  }
  return kg;
}

GlobalCut knotGraphCycle(const TriMesh& mesh, const ConcavityMap& map, const KnotGraph& kg) {
  GlobalCut cut;
  if (map.notch < 0 || kg.edges.empty()) return cut;
  const int root = map.vertexBridge[map.notch];
  const Vec3& x = mesh.vertices[map.notch];
  // Root: the pocket cut of the notch's pocket that holds the notch or passes nearest to it.
  int rootEdge = -1;
  double nearest = std::numeric_limits<double>::infinity();
  for (int e = 0; e < static_cast<int>(kg.edges.size()); ++e) {
    if (kg.edges[e].pocket != root) continue;
    for (int v : kg.edges[e].path) {
      const double d = (mesh.vertices[v] - x).norm();
      if (d < nearest) nearest = d, rootEdge = e;
    }
  }
  if (rootEdge < 0) return cut;
  // Minimum-weight cycle through the root edge: shortest path between its ends without it.
  const int n = static_cast<int>(kg.nodes.size());
  std::vector<std::vector<int>> incident(n);
  for (int e = 0; e < static_cast<int>(kg.edges.size()); ++e) {
    incident[kg.edges[e].a].push_back(e);
    incident[kg.edges[e].b].push_back(e);
  }
  const int s = kg.edges[rootEdge].b, t = kg.edges[rootEdge].a;
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> via(n, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[s] = 0.0;
  open.emplace(0.0, s);
  while (!open.empty()) {
    const auto [d, u] = open.top();
    open.pop();
    if (d > dist[u] || u == t) continue;
    for (int e : incident[u]) {
      if (e == rootEdge) continue;
      const int w = kg.edges[e].a == u ? kg.edges[e].b : kg.edges[e].a;
      if (d + kg.edges[e].weight < dist[w]) {
        dist[w] = d + kg.edges[e].weight;
        via[w] = e;
        open.emplace(dist[w], w);
      }
    }
  }
  if (via[t] < 0) return cut;
  auto append = [&](const KnotGraph::Edge& e, bool forward) {
    const int pocket = e.pocket >= 0 ? e.pocket : kg.nodes[e.a].pocket;
    std::vector<int> path = e.path;
    if (!forward) std::reverse(path.begin(), path.end());
    for (std::size_t i = cut.vertices.empty() ? 0 : 1; i < path.size(); ++i) {
      cut.vertices.push_back(path[i]);
      cut.weight.push_back(map.bridges[pocket].concavityOf(mesh.vertices[path[i]]));
    }
    if (e.pocket >= 0) cut.pockets.push_back(e.pocket);
  };
  append(kg.edges[rootEdge], true);  // a -> b
  std::vector<int> chain;            // edges from s (= b) to t (= a)
  for (int u = t; u != s; u = kg.edges[via[u]].a == u ? kg.edges[via[u]].b : kg.edges[via[u]].a) chain.push_back(via[u]);
  std::reverse(chain.begin(), chain.end());
  int at = s;
  for (int e : chain) {
    const bool forward = kg.edges[e].a == at;
    append(kg.edges[e], forward);
    at = forward ? kg.edges[e].b : kg.edges[e].a;
  }
  for (int v : {kg.edges[rootEdge].a, kg.edges[rootEdge].b}) cut.knots.push_back(kg.nodes[v]);
  cut.closed = true;
  return cut;
}

}  // namespace acd
