// Surface ACD (Section 4.3), breadth first like the solid decomposition: every round measures
// all pending patches in parallel; a patch within tau is final, any other is split along mesh
// edges into edge-connected children. Results land in per-patch slots and are gathered in
// order, so the output does not depend on the number of threads.
#include <acd/surface_decompose.hpp>

#include <acd/algo/concavity.hpp>
#include <acd/algo/cut_plane.hpp>
#include <acd/algo/features.hpp>
#include <acd/algo/knot_graph.hpp>
#include <acd/algo/open_surface.hpp>
#include <acd/algo/parallel.hpp>
#include <acd/algo/stopwatch.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/algo/hull.hpp>

#include "rounds.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <unordered_set>

namespace acd {

namespace {


struct Piece {
  std::vector<int> faces;  // faces of the normalised surface, ascending
  int depth = 0;
  int source = 0;
  double concavity = -1.0;  // already measured (by the parent's lookahead), or -1
};

struct Outcome {
  bool final = true;
  double concavity = 0.0;
  bool unresolved = false;
  std::string note;
  std::vector<std::vector<int>> children;  // faces of the surface
  SplitKind kind = SplitKind::GlobalCut;
  std::vector<double> childConcavity;
  double concavitySeconds = 0.0, splittingSeconds = 0.0;
};

/// The faces as a mesh of their own; `vertexOf` maps its vertices back to the surface's.
TriMesh subMesh(const TriMesh& surface, const std::vector<int>& faces) {
  TriMesh m;
  std::unordered_map<int, int> local;
  local.reserve(faces.size() * 2);
  for (int f : faces) {
    Face t{};
    for (int k = 0; k < 3; ++k) {
      const int v = surface.faces[f][k];
      auto [it, inserted] = local.emplace(v, static_cast<int>(m.vertices.size()));
      if (inserted) m.vertices.push_back(surface.vertices[v]);
      t[k] = it->second;
    }
    m.faces.push_back(t);
  }
  return m;
}

/// Edge-connected regions of faces with equal labels that do not cross a barrier edge.
std::vector<std::vector<int>> regions(const TriMesh& mesh, const SurfaceGraph& graph, const std::vector<int>& label,
                                      const std::unordered_set<std::uint64_t>& barrier) {
  const int nf = static_cast<int>(mesh.faces.size());
  std::vector<int> region(nf, -1);
  std::vector<std::vector<int>> out;
  std::vector<int> stack;
  for (int seed = 0; seed < nf; ++seed) {
    if (region[seed] >= 0) continue;
    const int id = static_cast<int>(out.size());
    out.emplace_back();
    region[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      out[id].push_back(f);
      for (int k = 0; k < 3; ++k) {
        const int g = graph.faceAcross(f, k);
        if (g < 0 || region[g] >= 0 || label[g] != label[f]) continue;
        if (barrier.count(edgeKey(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]))) continue;
        region[g] = id;
        stack.push_back(g);
      }
    }
  }
  return out;
}

/// Edges of a global cut, completed so that it can separate the patch: a chain is extended from
/// each end to the patch's opening (open patch) or closed into a loop by the shortest path
/// between its ends that avoids it (closed patch).
std::unordered_set<std::uint64_t> cutEdges(const TriMesh& mesh, const SurfaceGraph& graph, const GlobalCut& cut,
                                           const std::vector<char>& boundary) {
  std::unordered_set<std::uint64_t> edges;
  const std::vector<int>& chain = cut.vertices;
  auto adjacent = [&](int a, int b) { return graph.faceLeftOf(a, b) >= 0 || graph.faceLeftOf(b, a) >= 0; };
  auto addPath = [&](const std::vector<int>& path) {
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
      if (path[i] != path[i + 1] && adjacent(path[i], path[i + 1])) edges.insert(edgeKey(path[i], path[i + 1]));
  };
  addPath(chain);
  if (chain.size() < 2) return edges;
  const int a = chain.front(), b = chain.back();
  if (cut.closed && adjacent(a, b)) {
    edges.insert(edgeKey(a, b));
    return edges;
  }
  if (a == b) return edges;
  std::vector<char> allowed(mesh.vertices.size(), 1);
  for (int v : chain) allowed[v] = 0;
  PathFinder finder(graph);
  const bool open = std::find(boundary.begin(), boundary.end(), 1) != boundary.end();
  if (!open) {
    addPath(finder.path(a, b, {}, &allowed));
    return edges;
  }
  allowed[a] = allowed[b] = 1;
  std::vector<int> sources;
  for (int v = 0; v < static_cast<int>(boundary.size()); ++v)
    if (boundary[v]) sources.push_back(v);
  std::vector<double> distance;
  std::vector<int> parent;
  finder.flood(sources, {}, &allowed, distance, parent);
  for (int end : {a, b}) {
    if (boundary[end] || !(distance[end] < std::numeric_limits<double>::infinity())) continue;
    std::vector<int> path;
    for (int x = end; x != -1; x = parent[x]) path.push_back(x);
    addPath(path);
  }
  return edges;
}

/// Faces labelled by the side of `plane` their centroid lies on.
std::vector<int> sideLabels(const TriMesh& mesh, const Plane& plane) {
  std::vector<int> label(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Face& t = mesh.faces[f];
    const Vec3 c = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    label[f] = plane.signedDistance(c) > 0 ? 1 : 0;
  }
  return label;
}

/// Last resort: the faces nearer (geodesically) the notch than the vertex farthest from it, and the rest.
std::vector<int> geodesicLabels(const TriMesh& mesh, const SurfaceGraph& graph, int notch) {
  PathFinder finder(graph);
  std::vector<double> fromNotch, fromFar;
  std::vector<int> parent;
  finder.flood({notch}, {}, nullptr, fromNotch, parent);
  int far = notch;
  for (int v = 0; v < static_cast<int>(fromNotch.size()); ++v)
    if (fromNotch[v] < std::numeric_limits<double>::infinity() && fromNotch[v] > fromNotch[far]) far = v;
  finder.flood({far}, {}, nullptr, fromFar, parent);
  std::vector<int> label(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    double near = 0, away = 0;
    for (int v : mesh.faces[f]) near += fromNotch[v], away += fromFar[v];
    label[f] = near <= away ? 0 : 1;
  }
  return label;
}

double measure(const TriMesh& mesh, double epsilon) {
  SurfaceGraph graph(mesh);
  ConcavityOptions co;
  co.epsilon = epsilon;
  return measureConcavity(mesh, graph, co).concavity;
}

Outcome processPiece(const TriMesh& surface, const Piece& piece, const SurfaceDecomposeOptions& o) {
  Outcome out;
  auto t = Clock::now();
  if (piece.concavity >= 0 && piece.concavity <= o.tau) {
    out.concavity = piece.concavity;
    return out;
  }
  const TriMesh mesh = subMesh(surface, piece.faces);
  SurfaceGraph graph(mesh);
  ConcavityOptions co;
  co.epsilon = o.epsilon;
  const ConcavityMap map = measureConcavity(mesh, graph, co);
  out.concavity = map.concavity;
  out.concavitySeconds = secondsSince(t);
  if (map.concavity <= o.tau || map.notch < 0 || mesh.faces.size() < 2) return out;

  t = Clock::now();
  const int notch = map.notch;
  const Vec3 bridgeNormal = map.bridges[map.vertexBridge[notch]].normal;
  const std::vector<char> boundary = boundaryVertices(graph);
  const std::vector<int> oneLabel(mesh.faces.size(), 0);
  struct Candidate {
    std::vector<std::vector<int>> parts;  // local faces
    SplitKind kind;
  };
  std::vector<Candidate> candidates;
  std::vector<std::unordered_set<std::uint64_t>> seen;
  // Different cuts often give the same parts: each distinct partition is measured once.
  std::vector<std::vector<int>> partitions;
  auto admit = [&](std::vector<std::vector<int>>&& parts, SplitKind kind) {
    if (parts.size() < 2) return;
    std::vector<int> label(mesh.faces.size());
    for (auto& part : parts) {
      std::sort(part.begin(), part.end());
      for (int f : part) label[f] = part.front();
    }
    if (std::find(partitions.begin(), partitions.end(), label) != partitions.end()) return;
    partitions.push_back(std::move(label));
    candidates.push_back({std::move(parts), kind});
  };
  auto addCut = [&](const GlobalCut& cut) {
    if (cut.vertices.size() < 2) return;
    std::unordered_set<std::uint64_t> edges = cutEdges(mesh, graph, cut, boundary);
    if (edges.empty() || std::find(seen.begin(), seen.end(), edges) != seen.end()) return;
    seen.push_back(edges);
    admit(regions(mesh, graph, oneLabel, edges), SplitKind::GlobalCut);
  };
  auto addPlane = [&](const Plane& plane) { admit(regions(mesh, graph, sideLabels(mesh, plane), {}), SplitKind::Plane); };
  const Vec3& x = mesh.vertices[notch];
  std::optional<Plane> fitted;  // best-fit plane of the first grown cut
  if (o.featureGrouping) {
    // The paper's global cut (the minimum-weight cycle of G_K) and the greedily grown variants
    // the solid decomposition also tries; the split is along the cut's own edges.
    const KnotGraph kg = buildKnotGraph(mesh, graph, map, o.delta);
    addCut(knotGraphCycle(mesh, map, kg));
    for (int variant = 0; variant < 4; ++variant) {
      FeatureOptions fo;
      fo.delta = o.delta;
      fo.matchKnots = variant < 2;
      fo.notchAsEnd = variant % 2 == 0;
      const GlobalCut cut = findGlobalCut(mesh, graph, map, fo);
      addCut(cut);
      if (variant == 0 && cut.vertices.size() >= 3) fitted = fitCutPlane(mesh, cut, bridgeNormal, 0.5 * o.tau);
    }
    // After every cut, so that a plane giving the same parts as a cut does not take its place.
    if (fitted) addPlane(Plane::through(x, fitted->normal));
  }
  // Planes through the notch: the bisector of its dihedral angle, and two that contain the bridge normal.
  addPlane(bisectorPlane(mesh, graph, notch, bridgeNormal));
  const Vec3 u = bridgeNormal.unitOrthogonal(), w = bridgeNormal.cross(u);
  addPlane(Plane::through(x, u));
  addPlane(Plane::through(x, w));
  if (candidates.empty()) admit(regions(mesh, graph, geodesicLabels(mesh, graph, notch), {}), SplitKind::Geodesic);
  if (candidates.empty()) {
    out.unresolved = true;
    out.note = "no split of the patch along its edges was found";
    out.splittingSeconds = secondsSince(t);
    return out;
  }

  // One step of lookahead: keep the split whose most concave child is least concave; a global cut
  // wins ties within a tenth of tau (it follows the feature; a plane only approximates it).
  std::vector<std::vector<double>> childConcavity(candidates.size());
  std::vector<double> score(candidates.size(), 0.0);
  const bool lookahead = candidates.size() > 1;
  tbb::parallel_for(std::size_t(0), candidates.size(), [&](std::size_t i) {
    for (const auto& part : candidates[i].parts) {
      std::vector<int> faces;
      for (int f : part) faces.push_back(piece.faces[f]);
      std::sort(faces.begin(), faces.end());
      const double c = lookahead || part.size() < 4 ? measure(subMesh(surface, faces), o.epsilon) : -1.0;
      childConcavity[i].push_back(c);
      score[i] = std::max(score[i], c);
    }
    if (candidates[i].kind != SplitKind::GlobalCut) score[i] += 0.1 * o.tau;
  });
  std::size_t best = 0;
  for (std::size_t i = 1; i < candidates.size(); ++i)
    if (score[i] < score[best]) best = i;
  out.final = false;
  out.kind = candidates[best].kind;
  out.childConcavity = childConcavity[best];
  for (const auto& part : candidates[best].parts) {
    std::vector<int> faces;
    for (int f : part) faces.push_back(piece.faces[f]);
    std::sort(faces.begin(), faces.end());
    out.children.push_back(std::move(faces));
  }
  out.splittingSeconds = secondsSince(t);
  return out;
}

/// Number of interior edges whose faces belong to different patches, per unordered patch pair.
std::map<std::pair<int, int>, int> sharedEdges(const TriMesh& surface, const SurfaceGraph& graph,
                                               const std::vector<int>& patchOf) {
  std::map<std::pair<int, int>, int> shared;
  for (int f = 0; f < static_cast<int>(surface.faces.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = graph.faceAcross(f, k);
      if (g < 0 || g < f) continue;
      const int a = patchOf[f], b = patchOf[g];
      if (a < 0 || b < 0 || a == b) continue;
      ++shared[{std::min(a, b), std::max(a, b)}];
    }
  return shared;
}

}  // namespace

double patchConcavity(const TriMesh& patch, double epsilon) { return measure(patch, epsilon); }

SurfaceDecomposeOptions resolvedOptions(const SurfaceDecomposeOptions& options) {
  // epsilon's and delta's defaults are the solid decomposition's (one home for the rule).
  DecomposeOptions solid;
  solid.tau = options.tau;
  solid.epsilon = options.epsilon;
  solid.delta = options.delta;
  solid = resolvedOptions(solid);
  SurfaceDecomposeOptions o = options;
  o.epsilon = solid.epsilon;
  o.delta = solid.delta;
  return o;
}

/// The prepared components as one surface, piece after piece, and the first round's pieces; each
/// open piece is turned to face away from its hull (Extension 2 needs "outward").
std::vector<Piece> firstPieces(std::vector<TriMesh>& components, TriMesh& surface, std::vector<std::string>& repairs) {
  std::vector<Piece> pending;
  int turned = 0;
  for (std::size_t i = 0; i < components.size(); ++i) {
    TriMesh& c = components[i];
    turned += orientTowardHull(c);
    const int vbase = static_cast<int>(surface.vertices.size());
    const int fbase = static_cast<int>(surface.faces.size());
    surface.vertices.insert(surface.vertices.end(), c.vertices.begin(), c.vertices.end());
    Piece p;
    p.source = static_cast<int>(i);
    for (std::size_t f = 0; f < c.faces.size(); ++f) {
      const Face& x = c.faces[f];
      surface.faces.push_back({x[0] + vbase, x[1] + vbase, x[2] + vbase});
      p.faces.push_back(fbase + static_cast<int>(f));
    }
    pending.push_back(std::move(p));
  }
  if (turned > 0)
    repairs.push_back("turned " + std::to_string(turned) + " open piece(s) to face away from their hull");
  return pending;
}

/// Merge pass: neighbours that share edges are glued back while their union stays within tau,
/// longest shared boundary first; sequential and in a fixed order.
void mergePatches(const TriMesh& surface, const SurfaceGraph& graph, std::vector<Piece>& finals,
                  std::vector<Outcome>& finalInfo, const SurfaceDecomposeOptions& o, SurfaceDecomposeStats& stats) {
  std::vector<char> alive(finals.size(), 1);
  // Union concavity of pairs measured in earlier rounds, dropped when either side changes:
  // a round only measures the pairs next to the patches the previous round glued.
  std::map<std::pair<int, int>, double> known;
  for (bool merged = true; merged;) {
    merged = false;
    std::vector<int> patchOf(surface.faces.size(), -1);
    for (std::size_t i = 0; i < finals.size(); ++i)
      if (alive[i] && !finalInfo[i].unresolved)
        for (int f : finals[i].faces) patchOf[f] = static_cast<int>(i);
    const auto shared = sharedEdges(surface, graph, patchOf);
    std::vector<std::pair<int, int>> pairs;
    std::vector<int> length;
    for (const auto& [pair, count] : shared) pairs.push_back(pair), length.push_back(count);
    std::vector<std::size_t> order(pairs.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return length[a] > length[b]; });
    std::vector<double> concavity(pairs.size());
    std::vector<char> cached(pairs.size(), 0);
    for (std::size_t k = 0; k < pairs.size(); ++k)
      if (auto it = known.find(pairs[k]); it != known.end()) concavity[k] = it->second, cached[k] = 1;
    auto unionOf = [&](int a, int b) {
      std::vector<int> faces;
      std::merge(finals[a].faces.begin(), finals[a].faces.end(), finals[b].faces.begin(), finals[b].faces.end(),
                 std::back_inserter(faces));
      return faces;
    };
    tbb::parallel_for(std::size_t(0), pairs.size(), [&](std::size_t k) {
      if (!cached[k]) concavity[k] = measure(subMesh(surface, unionOf(pairs[k].first, pairs[k].second)), o.epsilon);
    });
    for (std::size_t k = 0; k < pairs.size(); ++k) known[pairs[k]] = concavity[k];
    std::vector<char> changed(finals.size(), 0);
    for (std::size_t k : order) {
      const auto [a, b] = pairs[k];
      if (concavity[k] > o.tau || changed[a] || changed[b]) continue;
      finals[a].faces = unionOf(a, b);
      finals[a].depth = std::min(finals[a].depth, finals[b].depth);
      finalInfo[a].concavity = concavity[k];
      alive[b] = 0;
      changed[a] = changed[b] = 1;
      ++stats.merges;
      merged = true;
    }
    for (auto it = known.begin(); it != known.end();)
      it = changed[it->first.first] || changed[it->first.second] ? known.erase(it) : std::next(it);
  }
  std::vector<Piece> keptPieces;
  std::vector<Outcome> keptInfo;
  for (std::size_t i = 0; i < finals.size(); ++i)
    if (alive[i]) keptPieces.push_back(std::move(finals[i])), keptInfo.push_back(std::move(finalInfo[i]));
  finals = std::move(keptPieces);
  finalInfo = std::move(keptInfo);

}

Status validate(const SurfaceDecomposeOptions& options) {
  DecomposeOptions d;
  d.tau = options.tau;
  d.epsilon = options.epsilon;
  d.delta = options.delta;
  d.threads = options.threads;
  const Status s = validate(d);
  if (!s.ok()) return s;
  if (options.maxPatches < 1) return Status::error(StatusCode::InvalidParameter, "maxPatches must be at least 1");
  return Status::success();
}

SurfaceDecomposition decomposeSurface(const TriMesh& mesh, const SurfaceDecomposeOptions& options) {
  const auto start = Clock::now();
  SurfaceDecomposition result;
  result.status = validate(options);
  if (!result.status.ok()) return result;
  const SurfaceDecomposeOptions o = resolvedOptions(options);
  result.options = o;

  auto t = Clock::now();
  PrepareOptions po;
  po.openMeshes = OpenMeshPolicy::KeepOpen;
  PreparedSolid prepared = prepareSolid(mesh, po);
  result.status = prepared.status;
  result.repairs = prepared.repairs;
  if (!result.status.ok()) return result;
  std::vector<Piece> pending = firstPieces(prepared.components, result.surface, result.repairs);
  result.normalization = minimumSphereNormalization(result.surface);
  const TriMesh surface = applyNormalization(result.surface, result.normalization);
  const SurfaceGraph graph(surface);
  result.stats.inputEdges = 0;
  for (int f = 0; f < graph.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = graph.faceAcross(f, k);
      if (g < 0) ++result.stats.boundaryEdges, ++result.stats.inputEdges;
      else if (g > f) ++result.stats.inputEdges;
    }
  result.stats.inputNotches = countNotches(surface);
  result.stats.inputArea = surfaceArea(surface);
  for (const Piece& p : pending) {
    const TriMesh piece = subMesh(surface, p.faces);
    const ConvexHull hull = convexHull(piece.vertices);
    const std::vector<char> concave = concaveHullVertices(piece, hull);
    if (!isClosedOriented(piece)) result.stats.concaveHullVertices += static_cast<int>(std::count(concave.begin(), concave.end(), 1));
  }
  result.times.prepare = secondsSince(t);

  // Every parallel loop below, nested ones included, runs on these workers only.
  tbb::task_arena arena = workerArena(o.threads);
  arena.execute([&] {
    FinalPieces<Piece, Outcome> rounds = runRounds(
        std::move(pending), o.maxPatches, [&](const Piece& piece) { return processPiece(surface, piece, o); },
        [](const Piece& parent, Outcome& out) {
          std::vector<Piece> next;
          for (std::size_t c = 0; c < out.children.size(); ++c) {
            Piece child;
            child.faces = std::move(out.children[c]);
            child.depth = parent.depth + 1;
            child.source = parent.source;
            child.concavity = c < out.childConcavity.size() ? out.childConcavity[c] : -1.0;
            next.push_back(std::move(child));
          }
          return next;
        },
        [&](const Outcome& out) {
          result.times.concavity += out.concavitySeconds;
          result.times.splitting += out.splittingSeconds;
        },
        [](Outcome& out) {
          out.unresolved = true;
          out.note = "maximum number of patches reached";
        },
        [&](const Piece&, const Outcome& out) {
          ++result.stats.splits;
          if (out.kind == SplitKind::GlobalCut) ++result.stats.globalCutSplits;
          if (out.kind == SplitKind::Plane) ++result.stats.planeSplits;
          if (out.kind == SplitKind::Geodesic) ++result.stats.geodesicSplits;
        },
        o.progress);
    std::vector<Piece> finals = std::move(rounds.pieces);
    std::vector<Outcome> finalInfo = std::move(rounds.outcomes);

    t = Clock::now();
    if (o.merge) mergePatches(surface, graph, finals, finalInfo, o, result.stats);
    result.times.merging = secondsSince(t);

    // Patches in order of their first face: a stable, readable numbering.
    std::vector<std::size_t> order(finals.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return finals[a].faces.front() < finals[b].faces.front(); });
    t = Clock::now();
    result.patches.resize(finals.size());
    tbb::parallel_for(std::size_t(0), finals.size(), [&](std::size_t k) {
      const std::size_t i = order[k];
      SurfacePatch& p = result.patches[k];
      p.faces = finals[i].faces;
      p.depth = finals[i].depth;
      p.source = finals[i].source;
      p.concavity = finalInfo[i].concavity;
      p.unresolved = finalInfo[i].unresolved;
      p.note = finalInfo[i].note;
      const TriMesh normalised = subMesh(surface, p.faces);
      p.area = surfaceArea(normalised);
      const ConvexHull hull = convexHull(normalised.vertices);
      p.mesh = undoNormalization(normalised, result.normalization);
      if (!hull.degenerate) p.hull = undoNormalization(hull.mesh, result.normalization);
    });
    result.times.hulls = secondsSince(t);
  });
  result.times.total = secondsSince(start);
  return result;
}

}  // namespace acd
