// Global cuts (Section 4.2). The root pocket cut joins the component's notch to the
// two cheapest knots on different boundaries of its pocket; each end then grows
// into the neighbouring pocket across its boundary, to the cheapest knot on another
// boundary of that pocket, alternating ends, until both ends reach the same pocket
// and are joined there (the cycle of Section 4.2.4) or the pocket budget runs out.
// Pocket boundaries without knots are reached through their nearest vertex, the
// dynamic pocket cuts of Figure 14.
#include <acd/algo/features.hpp>
#include <acd/algo/knots.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace acd {

namespace {

std::vector<char> pocketVertices(const TriMesh& mesh, const ConcavityMap& map, int bridge) {
  std::vector<char> in(mesh.vertices.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (map.facePocket[f] == bridge)
      for (int v : mesh.faces[f]) in[v] = 1;
  return in;
}

/// Position of a knot walking around `pocket` with the pocket on the left.
int loopOrder(const ConcavityMap& map, const Knot& k, int pocket) {
  const auto& pe = map.projections[k.projection];
  return pe.leftBridge == pocket ? k.along : static_cast<int>(pe.path.size()) - 1 - k.along;
}

/// Eq. 4's weight of the edge over `slot` in the pocket of `bridge`, the curvature looked up in
/// slotCurvatures (computed once per piece, not once per relaxation).
EdgeWeight pocketCutWeight(const TriMesh& mesh, const SurfaceGraph& graph, const Bridge& bridge,
                           const std::vector<double>& curvature) {
  return [&mesh, &graph, &bridge, &curvature](int a, int b, int slot) {
    return cutEdgeWeight(bridge.concavityOf(mesh.vertices[a]), bridge.concavityOf(mesh.vertices[b]), curvature[slot],
                         graph.length(slot));
  };
}

/// Knots (indices into `knots`) matched to the entry knot nearest `start` on boundary `entry`,
/// one per other boundary at most. Empty when the entry boundary has no knots of this pocket.
std::vector<int> matchedPartners(const TriMesh& mesh, const SurfaceGraph& graph, PathFinder& finder,
                                 const ConcavityMap& map, const std::vector<double>& curvature,
                                 const std::vector<Knot>& knots, int pocket, int start, int entry) {
  std::vector<int> result;
  if (entry < 0) return result;
  std::map<int, std::vector<int>> byBoundary;  // projection -> knots in loop order
  for (int k = 0; k < static_cast<int>(knots.size()); ++k) byBoundary[knots[k].projection].push_back(k);
  auto entryIt = byBoundary.find(entry);
  if (entryIt == byBoundary.end()) return result;
  for (auto& [p, list] : byBoundary)
    std::sort(list.begin(), list.end(), [&](int a, int b) { return loopOrder(map, knots[a], pocket) < loopOrder(map, knots[b], pocket); });
  const std::vector<int>& rows = entryIt->second;
  // Entry knot: the one nearest the chain's end along the boundary path.
  const auto& path = map.projections[entry].path;
  const int startAlong = static_cast<int>(std::find(path.begin(), path.end(), start) - path.begin());
  int entryRow = 0;
  for (int r = 0; r < static_cast<int>(rows.size()); ++r)
    if (std::abs(knots[rows[r]].along - startAlong) < std::abs(knots[rows[entryRow]].along - startAlong)) entryRow = r;
  // Pocket-cut weights from every entry knot (Eq. 4 per edge, inside the pocket).
  std::vector<char> mask = pocketVertices(mesh, map, pocket);
  const Bridge& bridge = map.bridges[pocket];
  const EdgeWeight weight = pocketCutWeight(mesh, graph, bridge, curvature);
  std::vector<std::vector<double>> dist(rows.size());  // entry knot -> distance to each knot
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const int source = knots[rows[r]].vertex;
    const char saved = mask[source];
    mask[source] = 1;
    finder.search({source}, weight, &mask);
    mask[source] = saved;
    for (const Knot& k : knots) dist[r].push_back(finder.distance(k.vertex));
  }
  for (const auto& [p, columns] : byBoundary) {
    if (p == entry) continue;
    std::vector<std::vector<double>> cost(rows.size(), std::vector<double>(columns.size()));
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (std::size_t c = 0; c < columns.size(); ++c) cost[r][c] = dist[r][columns[c]];
    for (const auto& [r, c] : nonCrossingMatching(cost))
      if (r == entryRow) result.push_back(columns[c]);
  }
  return result;
}

struct Leg {
  std::vector<int> path;  // from the chain end into the pocket, ending at the next end vertex
  int endVertex = -1;
  int nextPocket = -1;    // pocket across the boundary the leg ends on (-1: none)
  int projection = -1;
  double cost = std::numeric_limits<double>::infinity();
};

/// Cheapest leg inside `pocket` from `start` to a knot (or, failing that, any vertex) on a
/// boundary of the pocket other than `excludeProjection`.
Leg bestLeg(const TriMesh& mesh, const SurfaceGraph& graph, PathFinder& finder, const ConcavityMap& map,
            const std::vector<double>& curvature, int pocket, int start, int excludeProjection, double delta,
            bool matchKnots) {
  Leg leg;
  const std::vector<Knot> knots = pocketKnots(mesh, map, pocket, delta);
  // Entering across a boundary that has knots of this pocket: the leg may only end at a knot
  // matched (Observation 4.2) to the entry knot nearest the chain's end. (Its searches come first:
  // the finder holds one search's result at a time.)
  const std::vector<int> partners =
      matchKnots ? matchedPartners(mesh, graph, finder, map, curvature, knots, pocket, start, excludeProjection) : std::vector<int>{};
  std::vector<char> mask = pocketVertices(mesh, map, pocket);
  mask[start] = 1;
  finder.search({start}, pocketCutWeight(mesh, graph, map.bridges[pocket], curvature), &mask);
  auto consider = [&](int v, int projection, bool knot) {
    if (v == start || !std::isfinite(finder.distance(v))) return;
    // Knots are preferred: a knot-less end costs twice as much.
    const double cost = finder.distance(v) * (knot ? 1.0 : 2.0);
    if (cost < leg.cost) {
      leg.cost = cost;
      leg.endVertex = v;
      leg.projection = projection;
    }
  };
  for (int k : partners) consider(knots[k].vertex, knots[k].projection, true);
  if (partners.empty())
    for (const Knot& k : knots)
      if (k.projection != excludeProjection) consider(k.vertex, k.projection, true);
  if (leg.endVertex < 0)
    for (int p = 0; p < static_cast<int>(map.projections.size()); ++p) {
      const auto& pe = map.projections[p];
      if (p == excludeProjection || (pe.leftBridge != pocket && pe.rightBridge != pocket)) continue;
      for (std::size_t i = 1; i + 1 < pe.path.size(); ++i) consider(pe.path[i], p, false);
    }
  if (leg.endVertex < 0) return leg;
  leg.path = finder.pathTo(leg.endVertex);
  const auto& pe = map.projections[leg.projection];
  leg.nextPocket = pe.leftBridge == pocket ? pe.rightBridge : pe.leftBridge;
  return leg;
}


}  // namespace

std::vector<std::pair<int, int>> nonCrossingMatching(const std::vector<std::vector<double>>& cost) {
  const int n = static_cast<int>(cost.size());
  const int m = n > 0 ? static_cast<int>(cost[0].size()) : 0;
  // Both lists run the same way around the pocket, so a non-crossing matching pairs rows in
  // ascending order with columns in descending order: align rows with the reversed columns.
  struct Cell {
    int pairs = 0;
    double weight = 0.0;
    bool better(const Cell& o) const { return pairs != o.pairs ? pairs > o.pairs : weight < o.weight; }
  };
  std::vector<std::vector<Cell>> best(n + 1, std::vector<Cell>(m + 1));
  for (int i = 1; i <= n; ++i)
    for (int j = 1; j <= m; ++j) {
      Cell cell = best[i - 1][j].better(best[i][j - 1]) ? best[i - 1][j] : best[i][j - 1];
      const double w = cost[i - 1][m - j];
      if (std::isfinite(w)) {
        const Cell take{best[i - 1][j - 1].pairs + 1, best[i - 1][j - 1].weight + w};
        if (take.better(cell)) cell = take;
      }
      best[i][j] = cell;
    }
  std::vector<std::pair<int, int>> pairs;
  for (int i = n, j = m; i > 0 && j > 0;) {
    const double w = cost[i - 1][m - j];
    if (std::isfinite(w) && best[i][j].pairs == best[i - 1][j - 1].pairs + 1 &&
        best[i][j].weight == best[i - 1][j - 1].weight + w) {
      pairs.emplace_back(i - 1, m - j);
      --i, --j;
    } else if (best[i][j].pairs == best[i - 1][j].pairs && best[i][j].weight == best[i - 1][j].weight) {
      --i;
    } else {
      --j;
    }
  }
  std::reverse(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<Knot> pocketKnots(const TriMesh& mesh, const ConcavityMap& map, int bridge, double delta) {
  std::vector<Knot> knots;
  const Bridge& b = map.bridges[bridge];
  for (int p = 0; p < static_cast<int>(map.projections.size()); ++p) {
    const ProjectedEdge& pe = map.projections[p];
    if (pe.leftBridge != bridge && pe.rightBridge != bridge) continue;
    if (pe.path.size() < 3) continue;
    // Eq. 3: position along the projected edge scaled to the hull edge's length, against concavity.
    const double hullLength = (mesh.vertices[pe.path.front()] - mesh.vertices[pe.path.back()]).norm();
    std::vector<double> along(pe.path.size(), 0.0);
    for (std::size_t i = 1; i < pe.path.size(); ++i)
      along[i] = along[i - 1] + (mesh.vertices[pe.path[i]] - mesh.vertices[pe.path[i - 1]]).norm();
    const double scale = along.back() > 0 ? hullLength / along.back() : 0.0;
    std::vector<Vec2> profile(pe.path.size());
    for (std::size_t i = 0; i < pe.path.size(); ++i)
      profile[i] = Vec2(along[i] * scale, b.concavityOf(mesh.vertices[pe.path[i]]));
    for (int i : findKnots(profile, delta)) knots.push_back({pe.path[i], bridge, p, profile[i].y(), i});
  }
  return knots;
}

namespace {
/// Concave dihedral angle of edge a-b (0 for convex, flat or boundary edges): the curvature term of Eq. 4.
double concaveDihedral(const TriMesh& mesh, const SurfaceGraph& graph, int a, int b) {
  const int fl = graph.faceLeftOf(a, b), fr = graph.faceLeftOf(b, a);
  if (fl < 0 || fr < 0) return 0.0;
  const Vec3 nl = faceNormal(mesh, fl).normalized(), nr = faceNormal(mesh, fr).normalized();
  const Vec3 c = nl.cross(nr);
  return c.dot(mesh.vertices[b] - mesh.vertices[a]) < 0 ? std::atan2(c.norm(), nl.dot(nr)) : 0.0;
}
}  // namespace

std::vector<double> slotCurvatures(const TriMesh& mesh, const SurfaceGraph& graph) {
  std::vector<double> curvature(graph.end(graph.vertexCount() - 1), 0.0);
  for (int a = 0; a < graph.vertexCount(); ++a)
    for (int slot = graph.begin(a); slot < graph.end(a); ++slot)
      curvature[slot] = concaveDihedral(mesh, graph, a, graph.neighbour(slot));
  return curvature;
}

GlobalCut findGlobalCut(const TriMesh& mesh, const SurfaceGraph& graph, const ConcavityMap& map,
                        const FeatureOptions& options) {
  GlobalCut cut;
  const int notch = map.notch;
  if (notch < 0 || map.bridges.empty()) return cut;
  const int root = map.vertexBridge[notch];
  PathFinder finder(graph);
  std::vector<double> ownCurvature;
  if (!options.slotCurvature) ownCurvature = slotCurvatures(mesh, graph);
  const std::vector<double>& curvature = options.slotCurvature ? *options.slotCurvature : ownCurvature;

  // Root pocket cut: notch to its two cheapest ends on different boundaries. A notch that lies on
  // a boundary itself is one end already: the cut continues across that boundary from it.
  int notchProjection = -1;
  for (int p = 0; options.notchAsEnd && p < static_cast<int>(map.projections.size()) && notchProjection < 0; ++p) {
    const auto& pe = map.projections[p];
    if (pe.leftBridge != root && pe.rightBridge != root) continue;
    for (std::size_t i = 1; i + 1 < pe.path.size(); ++i)
      if (pe.path[i] == notch) notchProjection = p;
  }
  Leg first = bestLeg(mesh, graph, finder, map, curvature, root, notch, notchProjection, options.delta, options.matchKnots);
  if (first.endVertex < 0) return cut;
  Leg second;
  if (notchProjection >= 0) {
    const auto& pe = map.projections[notchProjection];
    second.path = {notch};
    second.endVertex = notch;
    second.projection = notchProjection;
    second.nextPocket = pe.leftBridge == root ? pe.rightBridge : pe.leftBridge;
  } else {
    second = bestLeg(mesh, graph, finder, map, curvature, root, notch, first.projection, options.delta, options.matchKnots);
  }
  cut.cupShaped = pocketKnots(mesh, map, root, options.delta).size() < 2;

  auto append = [&](std::vector<int>& chain, std::vector<double>& weight, const std::vector<int>& path, int pocket) {
    for (std::size_t i = chain.empty() ? 0 : 1; i < path.size(); ++i) {
      chain.push_back(path[i]);
      weight.push_back(map.bridges[pocket].concavityOf(mesh.vertices[path[i]]));
    }
  };
  // Two ends grow independently; each keeps its chain from the notch outward.
  struct End {
    std::vector<int> chain;
    std::vector<double> weight;
    int pocket = -1;       // pocket the end will grow into next
    int projection = -1;   // boundary it sits on
    bool stuck = false;
  } ends[2];
  for (int e = 0; e < 2; ++e) {
    const Leg& leg = e == 0 ? first : second;
    if (leg.endVertex < 0) {
      ends[e].chain = {notch};
      ends[e].weight = {map.vertexConcavity[notch]};
      ends[e].stuck = true;
      continue;
    }
    append(ends[e].chain, ends[e].weight, leg.path, root);
    ends[e].pocket = leg.nextPocket;
    ends[e].projection = leg.projection;
  }
  cut.pockets.push_back(root);
  std::vector<int> visitedBy(map.bridges.size(), -1);
  visitedBy[root] = 2;  // both
  for (int step = 0; step < 2 * options.maxPockets && !(ends[0].stuck && ends[1].stuck); ++step) {
    End& end = ends[step % 2];
    const End& other = ends[1 - step % 2];
    if (end.stuck) continue;
    const int pocket = end.pocket;
    // The ends meet: both sit on boundaries of the same pocket, or on the same boundary.
    const bool otherBorders = !other.stuck && (other.pocket == pocket || other.projection == end.projection);
    if (otherBorders) {
      const std::vector<char> allowed = pocketVertices(mesh, map, pocket);
      std::vector<int> join = finder.path(end.chain.back(), other.chain.back(), {}, &allowed);
      if (!join.empty()) {
        append(end.chain, end.weight, join, pocket);
        end.chain.pop_back();  // the joint vertex is the other end's last vertex
        end.weight.pop_back();
        cut.closed = true;
        cut.pockets.push_back(pocket);
        break;
      }
    }
    if (pocket < 0 || (visitedBy[pocket] >= 0 && visitedBy[pocket] != step % 2)) {
      end.stuck = true;
      continue;
    }
    Leg leg = bestLeg(mesh, graph, finder, map, curvature, pocket, end.chain.back(), end.projection, options.delta, options.matchKnots);
    if (leg.endVertex < 0) {
      end.stuck = true;
      continue;
    }
    visitedBy[pocket] = step % 2;
    cut.pockets.push_back(pocket);
    append(end.chain, end.weight, leg.path, pocket);
    end.pocket = leg.nextPocket;
    end.projection = leg.projection;
  }
  // Chain: end 0 reversed (outer end first), then end 1 without the shared notch.
  for (int i = static_cast<int>(ends[0].chain.size()) - 1; i >= 0; --i) {
    cut.vertices.push_back(ends[0].chain[i]);
    cut.weight.push_back(ends[0].weight[i]);
  }
  for (std::size_t i = 1; i < ends[1].chain.size(); ++i) {
    cut.vertices.push_back(ends[1].chain[i]);
    cut.weight.push_back(ends[1].weight[i]);
  }
  const std::vector<Knot> rootKnots = pocketKnots(mesh, map, root, options.delta);
  for (int v : cut.vertices)
    for (const Knot& k : rootKnots)
      if (k.vertex == v) cut.knots.push_back(k);
  return cut;
}

}  // namespace acd
