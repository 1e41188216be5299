// Bridges, pockets and vertex concavity (Lien & Amato 2007, Section 4.1, Appendix A).
#include <acd/algo/concavity.hpp>
#include <acd/algo/handles.hpp>
#include <acd/algo/open_surface.hpp>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>

namespace acd {

namespace {

struct HullFacets {
  std::vector<Vec3> normal;
  std::vector<double> offset, area;
  std::vector<std::array<int, 3>> neighbour;  // facet across each edge
};

HullFacets facetsOf(const TriMesh& hull) {
  HullFacets h;
  const int n = static_cast<int>(hull.faces.size());
  h.normal.resize(n);
  h.offset.resize(n);
  h.area.resize(n);
  h.neighbour.resize(n);
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(3 * n * 2);
  const double extent = boundingBox(hull).size().maxCoeff();
  for (int f = 0; f < n; ++f) {
    const Vec3 c = faceNormal(hull, f);
    h.area[f] = 0.5 * c.norm();
    h.normal[f] = c.normalized();
    h.offset[f] = h.normal[f].dot(hull.vertices[hull.faces[f][0]]);
    // A sliver facet (nearly collinear corners, e.g. from a section flat only up to rounding) has
    // a normal that is noise: lift its plane onto the hull so that it is a supporting plane anyway.
    if (!(h.area[f] > 0.0) || !h.normal[f].allFinite()) {
      // No normal at all (collinear corners): borrow a valid direction, lifted below.
      h.normal[f] = (hull.vertices[hull.faces[f][0]] - boundingBox(hull).center()).normalized();
      if (!h.normal[f].allFinite() || h.normal[f].norm() < 0.5) h.normal[f] = Vec3::UnitZ();
    }
    if (h.area[f] < 1e-8 * extent * extent)
      for (const Vec3& p : hull.vertices) h.offset[f] = std::max(h.offset[f], h.normal[f].dot(p));
    for (int k = 0; k < 3; ++k)
      directed[(static_cast<std::uint64_t>(hull.faces[f][k]) << 32) | static_cast<std::uint32_t>(hull.faces[f][(k + 1) % 3])] = f;
  }
  for (int f = 0; f < n; ++f)
    for (int k = 0; k < 3; ++k) {
      auto it = directed.find((static_cast<std::uint64_t>(hull.faces[f][(k + 1) % 3]) << 32) |
                              static_cast<std::uint32_t>(hull.faces[f][k]));
      h.neighbour[f][k] = it == directed.end() ? -1 : it->second;
    }
  return h;
}

/// How far facet f lies below the plane n.x = d (the plane is tangent to the hull, so this is >= 0).
double facetDepth(const TriMesh& hull, int f, const Vec3& n, double d) {
  double depth = 0.0;
  for (int v : hull.faces[f]) depth = std::max(depth, d - n.dot(hull.vertices[v]));
  return depth;
}

/// Lloyd-style clustering (after Cohen-Steiner et al. 2004): grow clusters from
/// their seeds with a priority queue keyed by depth below the seed plane, then
/// move each seed to the facet whose plane fits its cluster best.
std::vector<int> growClusters(const TriMesh& hull, const HullFacets& h, const std::vector<int>& seeds) {
  std::vector<int> label(hull.faces.size(), -1);
  using Item = std::tuple<double, int, int>;  // depth, facet, cluster
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  // Seeds own their facet before anything floods: a neighbour at depth 0 must not take it.
  for (int c = 0; c < static_cast<int>(seeds.size()); ++c)
    if (label[seeds[c]] < 0) label[seeds[c]] = c;
  for (int c = 0; c < static_cast<int>(seeds.size()); ++c)
    if (label[seeds[c]] == c) open.emplace(0.0, seeds[c], c);
  while (!open.empty()) {
    const auto [depth, f, c] = open.top();
    open.pop();
    if (label[f] >= 0 && label[f] != c) continue;
    if (label[f] < 0) label[f] = c;
    else if (f != seeds[c]) continue;
    const int s = seeds[c];
    for (int g : h.neighbour[f])
      if (g >= 0 && label[g] < 0) open.emplace(facetDepth(hull, g, h.normal[s], h.offset[s]), g, c);
  }
  return label;
}

double clusterDepth(const TriMesh& hull, const HullFacets& h, const std::vector<int>& members, int seed,
                    int* deepest = nullptr) {
  double worst = -1.0;
  for (int f : members) {
    const double d = facetDepth(hull, f, h.normal[seed], h.offset[seed]);
    if (d > worst) {
      worst = d;
      if (deepest) *deepest = f;
    }
  }
  return worst;
}

std::vector<std::vector<int>> membersOf(const std::vector<int>& label, int clusters) {
  std::vector<std::vector<int>> m(clusters);
  for (int f = 0; f < static_cast<int>(label.size()); ++f) m[label[f]].push_back(f);
  return m;
}

}  // namespace

int estimateBridgeCount(const TriMesh& hull, double epsilon, std::vector<int>* seedsOut) {
  const HullFacets h = facetsOf(hull);
  const int n = static_cast<int>(hull.faces.size());
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return h.area[a] > h.area[b]; });
  std::vector<char> covered(n, 0);
  std::vector<int> seeds;
  std::vector<int> stack, seen(n, -1);
  for (int beta : order) {
    if (covered[beta]) continue;
    seeds.push_back(beta);
    // C(beta): contiguous facets within epsilon of beta's (tangent) plane.
    stack.assign(1, beta);
    seen[beta] = beta;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      covered[f] = 1;
      for (int g : h.neighbour[f])
        if (g >= 0 && seen[g] != beta && facetDepth(hull, g, h.normal[beta], h.offset[beta]) < epsilon) {
          seen[g] = beta;
          stack.push_back(g);
        }
    }
  }
  if (seedsOut) *seedsOut = seeds;
  return static_cast<int>(seeds.size());
}

namespace {

/// Step 1, bridge clustering: Algorithm 2's seeds, Lloyd relaxation, then splits until every
/// patch lies within epsilon of its seed's plane. `label` gives each hull facet its cluster.
void clusterBridges(const TriMesh& hull, const HullFacets& h, double eps, int lloydIterations, std::vector<int>& seeds,
                    std::vector<int>& label) {
  for (int round = 0;; ++round) {
    label = growClusters(hull, h, seeds);
    if (eps <= 0.0) return;
    auto members = membersOf(label, static_cast<int>(seeds.size()));
    bool moved = false;
    if (round < lloydIterations) {
      for (int c = 0; c < static_cast<int>(seeds.size()); ++c) {
        // Candidate: the facet whose normal is closest to the cluster's area-weighted mean normal.
        Vec3 mean = Vec3::Zero();
        for (int f : members[c]) mean += h.area[f] * h.normal[f];
        int best = seeds[c];
        double bestScore = -2.0;
        for (int f : members[c]) {
          const double score = h.normal[f].dot(mean);
          if (score > bestScore) bestScore = score, best = f;
        }
        if (best != seeds[c] && clusterDepth(hull, h, members[c], best) < clusterDepth(hull, h, members[c], seeds[c])) {
          seeds[c] = best;
          moved = true;
        }
      }
      if (moved) continue;
    }
    bool split = false;
    for (int c = 0; c < static_cast<int>(members.size()); ++c) {
      int deepest = -1;
      if (clusterDepth(hull, h, members[c], seeds[c], &deepest) >= eps && label[deepest] == c &&
          deepest != seeds[c]) {
        seeds.push_back(deepest);
        split = true;
      }
    }
    if (!split) return;
  }
}

/// The bridges of the clustering: each cluster's facets and its seed's plane.
std::vector<Bridge> bridgesOf(const HullFacets& h, const std::vector<int>& seeds, const std::vector<int>& label) {
  const int nb = static_cast<int>(seeds.size());
  std::vector<Bridge> bridges(nb, Bridge{});
  for (int c = 0; c < nb; ++c) {
    bridges[c].normal = h.normal[seeds[c]];
    bridges[c].offset = h.offset[seeds[c]];
    bridges[c].seedFace = seeds[c];
  }
  for (int f = 0; f < static_cast<int>(label.size()); ++f) bridges[label[f]].hullFaces.push_back(f);
  return bridges;
}

/// Step 2: the hull edges between different bridges, projected onto the surface (paths cached
/// across refinements: a hull edge projects the same whatever its bridges).
std::vector<ProjectedEdge> projectBridgeEdges(const TriMesh& hull, const HullFacets& h, const std::vector<int>& label,
                                              const OpenSurfaceProjection& openSurface,
                                              tbb::enumerable_thread_specific<PathFinder>& finders,
                                              std::unordered_map<std::uint64_t, std::vector<int>>& pathCache) {
  // The paths not projected yet, each on its own (a path search does not depend on the one
  // before it), in parallel with a finder per thread; then taken in edge order.
  std::vector<std::pair<int, int>> missing;
  for (int f = 0; f < static_cast<int>(hull.faces.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = h.neighbour[f][k];
      const int u = hull.faces[f][k], v = hull.faces[f][(k + 1) % 3];
      if (g >= 0 && label[g] != label[f] && u < v && !pathCache.count(edgeKey(u, v))) missing.emplace_back(u, v);
    }
  std::vector<std::vector<int>> paths(missing.size());
  tbb::parallel_for(std::size_t(0), missing.size(),
                    [&](std::size_t i) { paths[i] = openSurface.project(finders.local(), missing[i].first, missing[i].second); });
  for (std::size_t i = 0; i < missing.size(); ++i) pathCache[edgeKey(missing[i].first, missing[i].second)] = std::move(paths[i]);
  std::vector<ProjectedEdge> projections;
  for (int f = 0; f < static_cast<int>(hull.faces.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = h.neighbour[f][k];
      if (g < 0 || label[g] == label[f]) continue;
      const int u = hull.faces[f][k], v = hull.faces[f][(k + 1) % 3];
      if (u > v) continue;  // each undirected edge once, from the facet that has it as u->v with u < v
      ProjectedEdge pe;
      pe.leftBridge = label[f];
      pe.rightBridge = label[g];
      const std::vector<int>& cached = pathCache.at(edgeKey(u, v));
      if (cached.empty()) continue;  // no projection (both ends concave, or unreachable)
      pe.path = cached;
      projections.push_back(std::move(pe));
    }
  return projections;
}

/// What the projected paths tell the faces: the edges pockets may not grow across, each face's
/// votes for the bridges whose paths run along it, and the bridge on each side of a path edge.
struct PocketBorders {
  std::unordered_map<std::uint64_t, char> onPath;
  std::vector<std::vector<std::pair<int, int>>> votes;  // per face: (bridge, count)
  std::unordered_map<std::uint64_t, int> bridgeOnLeft;  // directed path edge -> bridge on that side
};

PocketBorders pocketBorders(const SurfaceGraph& graph, int faces, const std::vector<ProjectedEdge>& projections,
                            const std::vector<std::uint64_t>& barrierEdges) {
  PocketBorders b;
  for (std::uint64_t e : barrierEdges) b.onPath[e] = 1;
  b.votes.resize(faces);
  auto vote = [&](int face, int bridge) {
    if (face < 0) return;
    for (auto& [id, count] : b.votes[face])
      if (id == bridge) {
        ++count;
        return;
      }
    b.votes[face].emplace_back(bridge, 1);
  };
  for (const auto& pe : projections)
    for (std::size_t i = 0; i + 1 < pe.path.size(); ++i) {
      const int u = pe.path[i], v = pe.path[i + 1];
      b.bridgeOnLeft[directedKey(u, v)] = pe.leftBridge;
      b.bridgeOnLeft[directedKey(v, u)] = pe.rightBridge;
      b.onPath[edgeKey(u, v)] = 1;
      vote(graph.faceLeftOf(u, v), pe.leftBridge);
      vote(graph.faceLeftOf(v, u), pe.rightBridge);
    }
  return b;
}

/// Step 3: pockets, the faces enclosed by the projected paths. Each region goes to the bridge its
/// border votes for; returns the region of every face and sets `facePocket`.
std::vector<int> assignPockets(const TriMesh& mesh, const SurfaceGraph& graph, const PocketBorders& borders,
                               const std::vector<Bridge>& bridges, std::vector<int>& facePocket) {
  const int nf = static_cast<int>(mesh.faces.size());
  const int nb = static_cast<int>(bridges.size());
  std::vector<int> region(nf, -1);
  std::vector<int> stack;
  int regions = 0;
  for (int seed = 0; seed < nf; ++seed) {
    if (region[seed] >= 0) continue;
    std::vector<int> faces;
    std::unordered_map<int, int> tally;
    bool opening = false;  // the region reaches the opening of an open surface
    stack.assign(1, seed);
    region[seed] = regions;
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      faces.push_back(f);
      for (auto [b, count] : borders.votes[f]) tally[b] += count;
      for (int k = 0; k < 3; ++k) {
        const int g = graph.faceAcross(f, k);
        if (g < 0) opening = true;
        if (g < 0 || region[g] >= 0) continue;
        if (borders.onPath.count(edgeKey(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]))) continue;
        region[g] = regions;
        stack.push_back(g);
      }
    }
    // Usually one bridge encloses the region. Where projected paths cross, several claim it: the
    // region then goes to the claimant it lies closest to (smallest depth below the supporting
    // plane), so a crossing path cannot hand a region to a bridge on the far side of the model.
    int bridge = 0;
    double bestDepth = std::numeric_limits<double>::infinity();
    std::vector<std::pair<int, int>> claims(tally.begin(), tally.end());
    // A region enclosed by handle cuts alone has no claimant: every bridge may claim it.
    // Through an opening (Extension 2) a region faces the whole hull: the concavity of a point is
    // its distance to the hull boundary, so every bridge may claim it too.
    if (claims.empty() || opening) {
      claims.clear();
      for (int b = 0; b < nb; ++b) claims.emplace_back(b, 0);
    }
    std::sort(claims.begin(), claims.end());
    for (auto [b, count] : claims) {
      const Bridge& br = bridges[b];
      double depth = 0.0;
      for (int f : faces)
        for (int v : mesh.faces[f]) depth = std::max(depth, br.offset - br.normal.dot(mesh.vertices[v]));
      if (depth < bestDepth) bestDepth = depth, bridge = b;
    }
    for (int f : faces) facePocket[f] = bridge;
    ++regions;
  }
  return region;
}

/// Section 5, genus reduction: on a surface of genus > 0 some regions are enclosed only by several
/// bridges together (handle caps). Their handle cuts become barriers and the pockets are found
/// again, up to eight times. `genus` is computed on first use (-1: not yet).
void assignPocketsCuttingHandles(const TriMesh& mesh, const SurfaceGraph& graph, PocketBorders& borders, int& genus,
                                 ConcavityMap& out) {
  out.handleCuts.clear();
  out.pocketDivides.clear();
  std::vector<std::uint64_t> handleBarriers;
  for (int handlePass = 0;; ++handlePass) {
    const std::vector<int> region = assignPockets(mesh, graph, borders, out.bridges, out.facePocket);
    if (genus < 0) genus = closedGenus(mesh);
    if (genus == 0) break;
    const auto shared = findSharedPockets(mesh, graph, region, borders.bridgeOnLeft);
    out.sharedPockets = static_cast<int>(
        std::count_if(shared.begin(), shared.end(), [](const SharedPocket& p) { return distinctBridges(p) >= 2; }));
    if (shared.empty() || handlePass >= 8) break;
    auto cuts = findHandleCuts(mesh, graph, shared, handleBarriers);
    const bool dividing = cuts.empty();
    if (dividing && out.sharedPockets > 0) cuts = findPocketDivides(mesh, graph, shared, handleBarriers);
    if (cuts.empty()) break;
    for (auto& cut : cuts) {
      for (std::uint64_t e : cut.edges) borders.onPath[e] = 1, handleBarriers.push_back(e);
      (dividing ? out.pocketDivides : out.handleCuts).push_back(std::move(cut));
    }
  }
}

/// Step 4, vertex concavity: the distance to the supporting plane of the pocket's bridge (max over
/// the pockets a vertex touches), and the per-facet value: the distance to the nearest facet plane
/// of that patch. Observation 4.1: the estimate may exceed the per-facet value by less than
/// epsilon; where it does not, the offending patch is split at the facet its worst vertex is
/// nearest to (a new seed). Returns true when it added seeds: the measure must run again.
bool measureVertices(const TriMesh& mesh, const HullFacets& h, const ConcavityMap& out, double eps, bool refine,
                     std::vector<double>& bestEstimate, std::vector<double>& bestFacet, std::vector<int>& bestBridge,
                     std::vector<int>& seeds) {
  const int nv = static_cast<int>(mesh.vertices.size());
  std::fill(bestEstimate.begin(), bestEstimate.end(), -1.0);
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) {
    const Bridge& b = out.bridges[out.facePocket[f]];
    for (int v : mesh.faces[f]) {
      const double c = b.concavityOf(mesh.vertices[v]);
      if (c > bestEstimate[v]) bestEstimate[v] = c, bestBridge[v] = out.facePocket[f];
    }
  }
  std::vector<double> worstGap(out.bridges.size(), 0.0);
  std::vector<int> worstFacet(out.bridges.size(), -1);
  for (int v = 0; v < nv; ++v) {
    const Bridge& b = out.bridges[bestBridge[v]];
    double facet = std::numeric_limits<double>::infinity();
    int argFacet = -1;
    for (int f : b.hullFaces) {
      const double d = h.offset[f] - h.normal[f].dot(mesh.vertices[v]);
      if (d < facet) facet = d, argFacet = f;
    }
    bestFacet[v] = std::max(0.0, facet);
    const double gap = bestEstimate[v] - bestFacet[v];
    if (gap > worstGap[bestBridge[v]]) worstGap[bestBridge[v]] = gap, worstFacet[bestBridge[v]] = argFacet;
  }
  bool split = false;
  for (std::size_t b = 0; b < out.bridges.size() && refine; ++b)
    if (worstGap[b] >= eps && worstFacet[b] >= 0 &&
        std::find(seeds.begin(), seeds.end(), worstFacet[b]) == seeds.end()) {
      seeds.push_back(worstFacet[b]);
      split = true;
    }
  return split;
}

}  // namespace

ConcavityMap measureConcavity(const TriMesh& mesh, const SurfaceGraph& graph, const ConcavityOptions& options) {
  ConcavityMap out;
  const int nv = static_cast<int>(mesh.vertices.size());
  const int nf = static_cast<int>(mesh.faces.size());
  out.vertexConcavity.assign(nv, 0.0);
  out.facetConcavity.assign(nv, 0.0);
  out.vertexBridge.assign(nv, -1);
  out.facePocket.assign(nf, -1);
  out.hull = convexHull(mesh.vertices);
  if (out.hull.degenerate) return out;
  const TriMesh& hull = out.hull.mesh;
  const HullFacets h = facetsOf(hull);
  const int nh = static_cast<int>(hull.faces.size());
  const double eps = options.epsilon;

  std::vector<int> seeds;
  if (eps > 0.0) {
    out.bridgeEstimate = estimateBridgeCount(hull, eps, &seeds);
  } else {
    seeds.resize(nh);
    std::iota(seeds.begin(), seeds.end(), 0);
    out.bridgeEstimate = nh;
  }
  std::vector<int> label;
  tbb::enumerable_thread_specific<PathFinder> finders([&] { return PathFinder(graph); });  // one per thread
  // Extension 2: on an open surface a bridge edge with a concave end projects to the opening, or not at all.
  const OpenSurfaceProjection openSurface(mesh, graph, out.hull);
  std::unordered_map<std::uint64_t, std::vector<int>> pathCache;  // hull edge (u<v) -> mesh path u..v
  std::vector<double> bestEstimate(nv), bestFacet(nv);
  std::vector<int> bestBridge(nv);
  int genus = -1;  // computed when first needed
  for (int attempt = 0;; ++attempt) {
    clusterBridges(hull, h, eps, options.lloydIterations, seeds, label);
    out.bridges = bridgesOf(h, seeds, label);
    out.projections = projectBridgeEdges(hull, h, label, openSurface, finders, pathCache);
    PocketBorders borders = pocketBorders(graph, nf, out.projections, options.barrierEdges);
    assignPocketsCuttingHandles(mesh, graph, borders, genus, out);
    const std::size_t seedsBefore = seeds.size();
    if (!measureVertices(mesh, h, out, eps, eps > 0.0 && attempt < 64, bestEstimate, bestFacet, bestBridge, seeds)) break;
    out.refinements += static_cast<int>(seeds.size() - seedsBefore);
  }
  out.vertexConcavity = bestEstimate;
  out.facetConcavity = bestFacet;
  out.vertexBridge = bestBridge;
  out.concavity = 0.0;
  out.notch = 0;
  for (int v = 0; v < nv; ++v)
    if (out.vertexConcavity[v] > out.concavity) out.concavity = out.vertexConcavity[v], out.notch = v;
  return out;
}

}  // namespace acd
