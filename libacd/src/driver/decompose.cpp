// Algorithm 1, breadth first: every round measures all pending pieces in parallel,
// and each piece either is final (concavity <= tau) or is cut into children that
// join the next round. Results land in per-piece slots and are gathered in piece
// order, so the output is the same for any number of threads.
#include <acd/algo/canonical_frame.hpp>
#include <acd/algo/concavity.hpp>
#include <acd/algo/cut_plane.hpp>
#include <acd/algo/features.hpp>
#include <acd/algo/hull_excess.hpp>
#include <acd/algo/knot_graph.hpp>
#include <acd/algo/merge.hpp>
#include <acd/algo/parallel.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/hull.hpp>
#include <acd/robust.hpp>

#include "rounds.hpp"

#include <Eigen/Eigenvalues>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace acd {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct Piece {
  TriMesh mesh;  // normalised
  int depth = 0;
  int source = 0;
  // The notch the parent's cut was meant to resolve: if it comes back unchanged, the cut stalled
  // and this piece escalates to planes that cut deeper (bisector, then planes along the bridge normal).
  Vec3 parentNotch = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  double parentConcavity = -1.0;
  int stalls = 0;
  std::vector<Plane> cuts;  // every plane this piece's ancestors were cut by
};

std::vector<Plane> withCut(std::vector<Plane> cuts, const Plane& p) {
  cuts.push_back(p);
  return cuts;
}

struct Outcome {
  bool final = true;
  Component component;
  std::vector<Piece> children;
  PhaseTimes times;
  DecomposeStats stats;
};

/// Cuts `piece` by `plane`; succeeds only if it really splits into pieces with volume.
bool tryCut(const Piece& piece, Plane plane, const Vec3& notch, double concavity, int stalls,
            std::vector<Piece>& children) {
  // Small shifts get past degenerate sections; the larger ones past local self-intersections of the
  // input (whose sections have crossing loops), at the price of a cut slightly off the notch.
  const double nudges[] = {0.0, 1e-7, -1e-7, 1e-5, -1e-5, 1e-3, -1e-3, 4e-3, -4e-3};
  // A piece this much smaller than its parent is a sliver: the plane grazed a face and resolved nothing.
  const double minVolume = 1e-7 * signedVolume(piece.mesh);
  for (double nudge : nudges) {
    Plane p = plane;
    p.offset += nudge * p.normal.norm();
    CutResult cut = cutByPlane(piece.mesh, p);
    if (!cut.ok || cut.below.empty() || cut.above.empty()) continue;
    std::vector<Piece> out;
    bool valid = true;
    for (auto* side : {&cut.below, &cut.above})
      for (TriMesh& m : *side) {
        if (signedVolume(m) <= minVolume) valid = false;
        out.push_back({std::move(m), piece.depth + 1, piece.source, notch, concavity, stalls, withCut(piece.cuts, p)});
      }
    if (!valid) continue;
    children = std::move(out);
    return true;
  }
  return false;
}

/// Figure 13: a plane through the notch that contains the bridge normal, across the pocket's longest
/// extent (principal axis of the pocket's vertices projected on the bridge plane).
Plane splitCupPlane(const TriMesh& mesh, const ConcavityMap& map, int notch) {
  const int bridge = map.vertexBridge[notch];
  const Vec3 n = map.bridges[bridge].normal;
  std::vector<char> in(mesh.vertices.size(), 0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    if (map.facePocket[f] == bridge)
      for (int v : mesh.faces[f]) in[v] = 1;
  Vec3 mean = Vec3::Zero();
  int count = 0;
  for (std::size_t v = 0; v < in.size(); ++v)
    if (in[v]) mean += mesh.vertices[v], ++count;
  const Vec3& x = mesh.vertices[notch];
  if (count < 3) return Plane::through(x, n.unitOrthogonal());
  mean /= count;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t v = 0; v < in.size(); ++v)
    if (in[v]) {
      Vec3 d = mesh.vertices[v] - mean;
      d -= d.dot(n) * n;  // projected on the bridge plane
      cov += d * d.transpose();
    }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Vec3 axis = eig.eigenvectors().col(2);
  axis -= axis.dot(n) * n;
  if (axis.norm() < 1e-12) axis = n.unitOrthogonal();
  return Plane::through(x, axis.normalized());
}

/// A piece is final when its hull stands at most this share of tau off its surface, measured to
/// within kExcessResolution * tau: 0.96 + 1/32 < 1, so a final hull is within tau of its piece.
constexpr double kExcessLimit = 0.96;
constexpr double kExcessResolution = 1.0 / 32;

/// The vertex nearest to p; ties go to the smaller index (vertex order is canonical).
int nearestVertex(const TriMesh& mesh, const Vec3& p) {
  int best = 0;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const double d = (mesh.vertices[v] - p).squaredNorm();
    if (d < bestDistance) bestDistance = d, best = static_cast<int>(v);
  }
  return best;
}

/// Back to the input's coordinates: an input vertex exactly, unless it lies on a plane the piece
/// was cut by; there, like every point a cut made, through the inverse transform. Cut faces thus
/// stay planar (an input vertex on one is off it by up to the canonical grid) and every piece
/// that shares a vertex maps it alike (pieces that share a vertex were parted by a plane through it).
TriMesh toInput(const Piece& piece, const CanonicalInverse& inverse) {
  TriMesh out = piece.mesh;
  for (Vec3& p : out.vertices) {
    bool onCut = false;
    for (const Plane& plane : piece.cuts)
      if (std::abs(plane.signedDistance(p)) <= 1e-12) {
        onCut = true;
        break;
      }
    p = onCut ? inverse.undo(p) : inverse(p);
  }
  return out;
}

/// A merge may add at most this share of the union's volume to the hull volume beyond the two
/// hulls it replaces (elephant at tau 0.05: 0.03 keeps IoU at the level without merging).
constexpr double kMergeHullGrowth = 0.03;

/// The planes that compete to cut a piece at its notch: the global cuts of feature grouping
/// (Section 4.2) first, then the bisector and a fan of planes through the notch that contain the
/// bridge normal. After stalls the fan widens; the lookahead in processPiece picks among them.
std::vector<Plane> candidatePlanes(const Piece& piece, const SurfaceGraph& graph, const ConcavityMap& map,
                                   const DecomposeOptions& o, int notchIndex, const Vec3& bridgeNormal, int stalls,
                                   bool fromExcess, double& groupingSeconds) {
  const Vec3& notch = piece.mesh.vertices[notchIndex];
  std::vector<Plane> candidates;
  if (o.featureGrouping && stalls == 0 && !fromExcess) {
    const auto t = Clock::now();
    // The paper's global cut: the minimum-weight cycle of the knot graph G_K through the root
    // pocket cut (Section 4.2.4). Four greedily grown cuts compete with it (they also reach
    // pockets without knots, where G_K has no edges): legs restricted to matched knots or free
    // to take the cheapest knot, with a notch on a boundary taken as an end of the root cut or
    // not. The lookahead (cutByLookahead) keeps whichever plane serves better.
    {
      const KnotGraph kg = buildKnotGraph(piece.mesh, graph, map, o.delta);
      const GlobalCut cycle = knotGraphCycle(piece.mesh, map, kg);
      if (cycle.vertices.size() >= 3)
        candidates.push_back(Plane::through(notch, fitCutPlane(piece.mesh, cycle, bridgeNormal, 0.5 * o.tau).normal));
    }
    for (int variant = 0; variant < 4; ++variant) {
      const bool matchKnots = variant < 2;
      FeatureOptions fo;
      fo.delta = o.delta;
      fo.matchKnots = matchKnots;
      fo.notchAsEnd = variant % 2 == 0;
      const GlobalCut cut = findGlobalCut(piece.mesh, graph, map, fo);
      if (cut.vertices.size() < 2) continue;
      const Plane plane = fitCutPlane(piece.mesh, cut, bridgeNormal, 0.5 * o.tau);
      // A plane (nearly) parallel to the bridge only skims the pocket: the cup-shaped case of
      // Figure 13. Split the cup through its deepest point instead, across its longest extent.
      if (variant == 0 && (cut.cupShaped || std::abs(plane.normal.normalized().dot(bridgeNormal)) > 0.9))
        candidates.push_back(splitCupPlane(piece.mesh, map, map.notch));
      // The plane must resolve the notch it was grown from: it passes through it. (A plane a hair
      // away from the notch would only shave off a sliver and leave the notch as it was.)
      candidates.push_back(Plane::through(notch, plane.normal));
    }
    groupingSeconds += secondsSince(t);
  }
  if (stalls <= 1) candidates.push_back(bisectorPlane(piece.mesh, graph, notchIndex, bridgeNormal));
  // Planes through the notch that contain the bridge normal split the pocket between the bridge's
  // ends (two orthogonal ones; a different pair after each stall).
  // (unitOrthogonal follows the frame's axes: the canonical frame's, so the fan is the shape's.)
  const Vec3 u = bridgeNormal.unitOrthogonal(), w = bridgeNormal.cross(u);
  const double pi = std::acos(-1.0);
  // After repeated stalls, a wider fan (and the plane parallel to the bridge) compete by lookahead.
  const int fan = stalls >= 2 || fromExcess ? 8 : 2;
  if (stalls >= 2) candidates.push_back(Plane::through(notch, bridgeNormal));
  for (int k = 0; k < fan; ++k) {
    const double angle = pi * k / fan + 0.25 * pi * (stalls % 2);  // a different set on each stall
    candidates.push_back(Plane::through(notch, std::cos(angle) * u + std::sin(angle) * w));
  }
  return candidates;
}

/// The paper's baseline: the first plane that cuts cleanly.
void cutByFirstPlane(const Piece& piece, const std::vector<Plane>& candidates, const Vec3& notch, double concavity,
                     int stalls, const DecomposeOptions& o, Outcome& out) {
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (tryCut(piece, candidates[i], notch, concavity, stalls, out.children)) {
      out.final = false;
      ++out.stats.cuts;
      if (o.featureGrouping && (i > 0 || stalls > 0)) ++out.stats.fallbackCuts;
      break;
    }
    ++out.stats.failedCuts;
  }
}

/// One step of lookahead: cut with every candidate and keep the plane whose children are best
/// approximated by their hulls (least hull volume beyond the children's own volume). After a
/// stall the notch itself is the problem: keep the plane whose children are least concave.
/// Candidates are cut and scored in parallel into their own slots; the best is picked in order.
void cutByLookahead(const Piece& piece, const std::vector<Plane>& candidates, const Vec3& notch, double concavity,
                    int stalls, bool fromExcess, const ConcavityOptions& co, const DecomposeOptions& o, Outcome& out) {
  std::vector<std::vector<Piece>> children(candidates.size());
  std::vector<char> cutOk(candidates.size(), 0);
  std::vector<double> score(candidates.size(), 0.0);
  std::vector<int> exceeding(candidates.size(), 0);
  tbb::parallel_for(std::size_t(0), candidates.size(), [&](std::size_t i) {
    cutOk[i] = tryCut(piece, candidates[i], notch, concavity, stalls, children[i]);
    if (!cutOk[i]) return;
    for (const Piece& child : children[i]) {
      if (stalls > 0) {
        SurfaceGraph childGraph(child.mesh);
        score[i] = std::max(score[i], measureConcavity(child.mesh, childGraph, co).concavity);
      } else {
        const TriMesh hull = convexHull(child.mesh.vertices).mesh;
        score[i] += signedVolume(hull) - signedVolume(child.mesh);
        // A cut for a hull standing off its piece is judged first by how many children still do.
        if (fromExcess)
          exceeding[i] += measureHullExcess(child.mesh, hull, kExcessLimit * o.tau, kExcessResolution * o.tau).exceeds;
      }
    }
  });
  double bestScore = std::numeric_limits<double>::infinity();
  std::size_t bestIndex = 0;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!cutOk[i]) {
      ++out.stats.failedCuts;
      continue;
    }
    if (out.final || exceeding[i] < exceeding[bestIndex] ||
        (exceeding[i] == exceeding[bestIndex] && score[i] < bestScore)) {
      bestScore = score[i];
      bestIndex = i;
      out.final = false;
    }
  }
  if (!out.final) out.children = std::move(children[bestIndex]);
  if (!out.final) {
    ++out.stats.cuts;
    if (bestIndex > 0 || stalls > 0) ++out.stats.fallbackCuts;
  }
}

Outcome processPiece(const Piece& piece, const DecomposeOptions& o) {
  Outcome out;
  auto t = Clock::now();
  SurfaceGraph graph(piece.mesh);
  ConcavityOptions co;
  co.epsilon = o.epsilon;
  const ConcavityMap map = measureConcavity(piece.mesh, graph, co);
  out.times.concavity += secondsSince(t);
  out.stats.bridges += static_cast<int>(map.bridges.size());
  out.stats.refinements += map.refinements;

  Component& c = out.component;
  c.depth = piece.depth;
  c.source = piece.source;
  c.concavity = map.concavity;
  int notchIndex = map.notch;
  double concavity = map.concavity;
  Vec3 bridgeNormal = Vec3::Zero();
  // The pocket measure can miss a thin or bent piece whose hull still stands far off its surface:
  // a piece is final only when its hull, measured directly, is within tau too. If not, the cut
  // goes through the surface point deepest below the hull, across the hull face above it.
  bool fromExcess = false;
  if (map.concavity <= o.tau || map.notch < 0) {
    t = Clock::now();
    const TriMesh hull = convexHull(piece.mesh.vertices).mesh;
    const HullExcess e = measureHullExcess(piece.mesh, hull, kExcessLimit * o.tau, kExcessResolution * o.tau);
    out.times.concavity += secondsSince(t);
    c.concavity = std::max(c.concavity, e.distance);
    if (!e.exceeds) return out;
    fromExcess = true;
    concavity = e.distance;
    bridgeNormal = faceNormal(hull, e.hullFace).normalized();
    notchIndex = nearestVertex(piece.mesh, e.surfacePoint);
  } else {
    bridgeNormal = map.bridges[map.vertexBridge[map.notch]].normal;
  }
  if (piece.depth >= o.maxDepth) {
    c.unresolved = true;
    c.note = "maximum cut depth reached";
    return out;
  }
  const Vec3& notch = piece.mesh.vertices[notchIndex];

  // The estimate wobbles a little with the bridge clustering, so "unchanged" means within a tenth of tau.
  const bool stalled = piece.parentConcavity >= 0 && concavity > piece.parentConcavity - 0.1 * o.tau &&
                       (notch - piece.parentNotch).norm() < 0.5 * o.tau;
  const int stalls = stalled ? piece.stalls + 1 : 0;
  if (stalls > 8) {  // nothing we know resolves this notch: report it rather than loop
    c.unresolved = true;
    c.note = "nine cuts in a row left the notch's concavity unchanged";
    return out;
  }
  const std::vector<Plane> candidates =
      candidatePlanes(piece, graph, map, o, notchIndex, bridgeNormal, stalls, fromExcess, out.times.grouping);
  t = Clock::now();
  if ((!o.featureGrouping && stalls == 0) || candidates.size() == 1)
    cutByFirstPlane(piece, candidates, notch, concavity, stalls, o, out);
  else
    cutByLookahead(piece, candidates, notch, concavity, stalls, fromExcess, co, o, out);
  out.times.cutting += secondsSince(t);
  if (out.final) {
    c.unresolved = true;
    c.note = "no plane through the notch gives a clean section (crossing section loops: the input self-intersects there)";
  }
  return out;
}

/// The prepared components as the first round's pieces, in normalised units; with `invariant` in
/// the shape's own frame and in canonical order, so that the result does not depend on the
/// input's pose or on the order of its vertices, faces and pieces. `inverse` learns the way back.
std::vector<Piece> firstPieces(const std::vector<TriMesh>& components, bool invariant, Decomposition& result,
                               CanonicalInverse& inverse) {
  std::vector<CanonicalMesh> canonical;
  for (const TriMesh& c : components) {
    if (invariant) {
      canonical.push_back(canonicalMesh(c, result.normalization));
    } else {
      std::vector<int> same(c.vertices.size());
      std::iota(same.begin(), same.end(), 0);
      canonical.push_back({applyNormalization(c, result.normalization), std::move(same)});
    }
    inverse.add(canonical.back(), c);  // input vertices come back exactly
  }
  std::vector<int> order(canonical.size());
  std::iota(order.begin(), order.end(), 0);
  if (invariant)
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return canonicalLess(canonical[a].mesh, canonical[b].mesh); });
  std::vector<Piece> pending;
  for (int i : order) {
    Piece p{std::move(canonical[i].mesh), 0, i};
    result.stats.inputEdges += static_cast<int>(p.mesh.faces.size() * 3 / 2);
    result.stats.inputNotches += countNotches(p.mesh);
    result.stats.inputVolume += signedVolume(applyNormalization(components[i], result.normalization));
    pending.push_back(std::move(p));
  }
  return pending;
}

/// Merge pass: the greedy recursion sometimes cuts where a coarser split would have done. Glue
/// neighbours back along their shared cut faces while the union stays within tau, largest contact
/// first. Sequential and in a fixed order, so the result does not depend on the thread count.
void mergePieces(std::vector<Piece>& finals, std::vector<Component>& finalInfo, const DecomposeOptions& o,
                 DecomposeStats& stats) {
  ConcavityOptions co;
  co.epsilon = o.epsilon;
  std::vector<char> alive(finals.size(), 1);
  for (bool merged = true; merged;) {
    merged = false;
    std::vector<TriMesh> meshes;
    std::vector<int> id;
    for (std::size_t i = 0; i < finals.size(); ++i)
      if (alive[i] && !finalInfo[i].unresolved) meshes.push_back(finals[i].mesh), id.push_back(static_cast<int>(i));
    // Every candidate union is measured in parallel; then, in order, a union is taken if neither
    // side has changed in this round. Pairs that touch a changed piece are looked at again next round.
    const std::vector<SharedFaces> pairs = sharedFacePairs(meshes);
    std::vector<TriMesh> glued(pairs.size());
    std::vector<double> concavity(pairs.size(), std::numeric_limits<double>::infinity());
    tbb::parallel_for(std::size_t(0), pairs.size(), [&](std::size_t k) {
      const int i = id[pairs[k].a], j = id[pairs[k].b];
      if (!glueAlongSharedFaces(finals[i].mesh, finals[j].mesh, glued[k])) return;
      // The union's hull may not swell much beyond the two hulls: a merge must not cost fidelity.
      const TriMesh hull = convexHull(glued[k].vertices).mesh;
      auto excess = [](const TriMesh& m) { return signedVolume(convexHull(m.vertices).mesh) - signedVolume(m); };
      const double growth = signedVolume(hull) - signedVolume(glued[k]) - excess(finals[i].mesh) - excess(finals[j].mesh);
      if (growth > kMergeHullGrowth * signedVolume(glued[k])) return;
      SurfaceGraph graph(glued[k]);
      const double measured = measureConcavity(glued[k], graph, co).concavity;
      if (measured > o.tau) return;
      // A union is held to the same promise as a final piece: its hull within tau of it.
      const HullExcess e = measureHullExcess(glued[k], hull, kExcessLimit * o.tau, kExcessResolution * o.tau);
      if (!e.exceeds) concavity[k] = std::max(measured, e.distance);
    });
    std::vector<char> changed(finals.size(), 0);
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const int i = id[pairs[k].a], j = id[pairs[k].b];
      if (concavity[k] > o.tau || changed[i] || changed[j]) continue;
      finals[i].mesh = std::move(glued[k]);
      finals[i].cuts.insert(finals[i].cuts.end(), finals[j].cuts.begin(), finals[j].cuts.end());
      finalInfo[i].concavity = concavity[k];
      finalInfo[i].depth = std::min(finalInfo[i].depth, finalInfo[j].depth);
      alive[j] = 0;
      changed[i] = changed[j] = 1;
      ++stats.merges;
      merged = true;
    }
  }
  std::vector<Piece> keptPieces;
  std::vector<Component> keptInfo;
  for (std::size_t i = 0; i < finals.size(); ++i)
    if (alive[i]) keptPieces.push_back(std::move(finals[i])), keptInfo.push_back(finalInfo[i]);
  finals = std::move(keptPieces);
  finalInfo = std::move(keptInfo);
}

void accumulate(PhaseTimes& into, const PhaseTimes& t) {
  into.concavity += t.concavity;
  into.grouping += t.grouping;
  into.cutting += t.cutting;
}

void accumulate(DecomposeStats& into, const DecomposeStats& s) {
  into.cuts += s.cuts;
  into.fallbackCuts += s.fallbackCuts;
  into.failedCuts += s.failedCuts;
  into.bridges += s.bridges;
  into.refinements += s.refinements;
}

}  // namespace

DecomposeOptions resolvedOptions(const DecomposeOptions& options) {
  DecomposeOptions o = options;
  if (o.epsilon < 0) o.epsilon = o.tau / 2;
  if (o.delta < 0) o.delta = o.tau / 20;
  return o;
}

Status validate(const DecomposeOptions& o) {
  auto bad = [](const std::string& m) { return Status::error(StatusCode::InvalidParameter, m); };
  std::ostringstream s;
  if (!std::isfinite(o.tau) || o.tau <= 0) return bad("tau must be a positive number (got " + std::to_string(o.tau) + ")");
  if (o.tau > 2.0)
    return bad("tau = " + std::to_string(o.tau) + " exceeds 2, the diameter of the normalised model: every model would be one component");
  if (o.tau < 1e-4) return bad("tau = " + std::to_string(o.tau) + " is below 1e-4; such a decomposition is an exact convex decomposition in all but name");
  if (!std::isfinite(o.epsilon) || (o.epsilon != -1.0 && (o.epsilon < 0 || o.epsilon > o.tau)))
    return bad("epsilon must lie in [0, tau]");
  if (!std::isfinite(o.delta) || (o.delta != -1.0 && (o.delta < 0 || o.delta > o.tau)))
    return bad("delta must lie in [0, tau]");
  if (o.threads < 0 || o.threads > 1024) return bad("threads must lie in [0, 1024]");
  if (o.maxComponents < 1) return bad("maxComponents must be at least 1");
  return Status::success();
}

int countNotches(const TriMesh& mesh, double angle) {
  SurfaceGraph graph(mesh);
  int notches = 0;
  for (int f = 0; f < graph.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int g = graph.faceAcross(f, k);
      if (g < f) continue;  // each interior edge once
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      const Vec3 nl = faceNormal(mesh, f).normalized(), nr = faceNormal(mesh, g).normalized();
      const Vec3 c = nl.cross(nr);
      const double turn = std::atan2(c.norm(), nl.dot(nr));
      if (c.dot(mesh.vertices[b] - mesh.vertices[a]) < 0 && turn > angle) ++notches;
    }
  return notches;
}

Decomposition decompose(const TriMesh& mesh, const DecomposeOptions& options) {
  if (options.repair) return decomposeRepaired(mesh, options);  // acd/robust.hpp; comes back with repair off
  const auto start = Clock::now();
  Decomposition result;
  result.status = validate(options);
  if (!result.status.ok()) return result;
  const DecomposeOptions o = resolvedOptions(options);
  result.options = o;

  auto t = Clock::now();
  PrepareOptions po;
  po.openMeshes = o.fillHoles ? OpenMeshPolicy::FillHoles : OpenMeshPolicy::Refuse;
  PreparedSolid prepared = prepareSolid(mesh, po);
  result.status = prepared.status;
  result.repairs = prepared.repairs;
  result.stats.holesFilled = prepared.holesFilled;
  if (!result.status.ok()) return result;
  // With o.invariant everything below works in the shape's own frame, on meshes in canonical order:
  // the result does not depend on the input's pose or on the order of its vertices, faces and pieces.
  result.normalization = o.invariant ? canonicalFrame(prepared.components)
                                     : minimumSphereNormalization(concatenate(prepared.components));
  CanonicalInverse inverse(result.normalization);
  std::vector<Piece> pending = firstPieces(prepared.components, o.invariant, result, inverse);
  result.times.prepare = secondsSince(t);

  // Every parallel loop below, nested ones included, runs on these workers only.
  tbb::task_arena arena = workerArena(o.threads);
  arena.execute([&] {
    FinalPieces<Piece, Outcome> rounds = runRounds(
        std::move(pending), o.maxComponents, [&](const Piece& piece) { return processPiece(piece, o); },
        [&](const Outcome& out) {
          accumulate(result.times, out.times);
          accumulate(result.stats, out.stats);
        },
        [](Outcome& out) {
          out.component.unresolved = true;
          out.component.note = "maximum number of components reached";
        },
        [](const Piece&, Outcome& out, std::vector<Piece>& next) {
          for (Piece& child : out.children) next.push_back(std::move(child));
        },
        o.progress);
    std::vector<Piece> finals = std::move(rounds.pieces);
    std::vector<Component> finalInfo;
    for (Outcome& out : rounds.outcomes) finalInfo.push_back(std::move(out.component));

    t = Clock::now();
    if (o.merge) mergePieces(finals, finalInfo, o, result.stats);
    result.times.merging = secondsSince(t);

    t = Clock::now();
    result.components.resize(finals.size());
    tbb::parallel_for(std::size_t(0), finals.size(), [&](std::size_t i) {
      Component& c = result.components[i];
      c = finalInfo[i];
      // The hull is computed in the input's coordinates, so that it contains the component (vertex
      // order is canonical, so is the hull's triangulation). Volumes are measured on both brought to
      // the normalised frame: in the input's coordinates a model far from the origin loses digits.
      c.mesh = o.invariant ? toInput(finals[i], inverse) : inverse(finals[i].mesh);
      c.hull = convexHull(c.mesh.vertices).mesh;
      c.volume = signedVolume(applyNormalization(c.mesh, result.normalization));
      c.hullVolume = signedVolume(applyNormalization(c.hull, result.normalization));
    });
    result.times.hulls = secondsSince(t);
  });
  result.times.total = secondsSince(start);
  return result;
}

}  // namespace acd
