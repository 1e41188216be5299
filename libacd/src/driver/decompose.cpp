// Algorithm 1, breadth first: every round measures all pending pieces in parallel,
// and each piece either is final (concavity <= tau) or is cut into children that
// join the next round. Results land in per-piece slots and are gathered in piece
// order, so the output is the same for any number of threads.
#include <acd/algo/canonical_frame.hpp>
#include <acd/algo/concavity.hpp>
#include <acd/algo/cut_choice.hpp>
#include <acd/algo/hull_depth.hpp>
#include <acd/algo/hull_excess.hpp>
#include <acd/algo/merge.hpp>
#include <acd/algo/parallel.hpp>
#include <acd/algo/random.hpp>
#include <acd/algo/stopwatch.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/algo/hull.hpp>
#include <acd/robust.hpp>

#include "clean_shell.hpp"
#include "confirm_ahead.hpp"
#include "held_to.hpp"
#include "rounds.hpp"
#include "working_model.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <set>
#include <sstream>

namespace acd {

namespace {


struct Piece {
  TriMesh mesh;  // normalised
  int depth = 0;
  int source = 0;
  // The notch the parent's cut was meant to resolve: if it comes back unchanged, the cut stalled
  // and this piece escalates to planes that cut deeper (bisector, then planes along the bridge normal).
  Vec3 parentNotch = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  double parentConcavity = -1.0;
  int stalls = 0;
};

struct Outcome {
  bool final = true;
  Component component;
  std::vector<Piece> children;
  PhaseTimes times;
  DecomposeStats stats;
};

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

/// A merge may add at most this share of the union's volume to the hull volume beyond the two
/// hulls it replaces (elephant at tau 0.05: 0.03 keeps IoU at the level without merging).
constexpr double kMergeHullGrowth = 0.03;

/// Stalls of a pocket notch before its piece's hull is measured directly (processPiece).
constexpr int kStallsBeforeDirectMeasure = 3;

/// The children of a cut: one piece per side's part, remembering the notch they were cut for.
std::vector<Piece> childrenOf(const Piece& piece, CutChoice& choice, const Vec3& notch, double concavity, int stalls) {
  std::vector<Piece> children;
  for (TriMesh& m : choice.pieces)
    children.push_back({std::move(m), piece.depth + 1, piece.source, notch, concavity, stalls});
  return children;
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
  // True when the hull is within tau (the piece is final); else the notch becomes the surface
  // point deepest below it.
  auto hullWithinTau = [&] {
    t = Clock::now();
    const TriMesh& hull = map.hull.mesh;  // the hull of the piece's vertices
    const HullExcess e = measureHullExcess(piece.mesh, hull, kExcessLimit * o.tau, kExcessResolution * o.tau);
    out.times.concavity += secondsSince(t);
    c.hullExcess = e.distance;
    if (!e.exceeds) {
      c.hull = hull;  // normalised units, for the merge pass (decomposeSolid replaces it)
      return true;
    }
    fromExcess = true;
    concavity = e.distance;
    bridgeNormal = faceNormal(hull, e.hullFace).normalized();
    notchIndex = nearestVertex(piece.mesh, e.surfacePoint);
    return false;
  };
  if (map.concavity <= o.tau || map.notch < 0) {
    const bool final = hullWithinTau();
    c.concavity = std::max(c.concavity, c.hullExcess);
    if (final) return out;
  } else {
    bridgeNormal = map.bridges[map.vertexBridge[map.notch]].normal;
  }
  if (piece.depth >= o.maxDepth) {
    c.unresolved = true;
    c.note = "maximum cut depth reached";
    return out;
  }

  // The estimate wobbles a little with the bridge clustering, so "unchanged" means within a tenth of tau.
  auto stalledAt = [&](int notchAt, double measured) {
    return piece.parentConcavity >= 0 && measured > piece.parentConcavity - 0.1 * o.tau &&
           (piece.mesh.vertices[notchAt] - piece.parentNotch).norm() < 0.5 * o.tau;
  };
  int stalls = stalledAt(notchIndex, concavity) ? piece.stalls + 1 : 0;
  // Cuts through a pocket notch that leave it as it was, again and again, mean the pocket measure
  // is misled there (slivers that earlier cuts left along a CAD face can join a pocket to a bridge
  // it does not face): from the third stall the hull is measured directly, as for a final piece.
  // Final then needs the surface within tau of the hull straight through the inside as well (a
  // lower bound of the concavity the pocket measure could not see): the component's concavity.
  if (stalls >= kStallsBeforeDirectMeasure && !fromExcess) {
    if (hullWithinTau()) {
      t = Clock::now();
      const HullDepth depth = deepestBelowHull(piece.mesh, map.hull.mesh);
      out.times.concavity += secondsSince(t);
      if (depth.distance <= o.tau) {  // the notch was the estimate's alone
        c.concavity = std::max(depth.distance, c.hullExcess);
        return out;
      }
      fromExcess = true;  // a real notch elsewhere: cut there, across the hull face above it
      concavity = depth.distance;
      bridgeNormal = faceNormal(map.hull.mesh, depth.hullFace).normalized();
      notchIndex = depth.vertex;
    }
    stalls = stalledAt(notchIndex, concavity) ? piece.stalls + 1 : 0;
  }
  if (stalls > 8) {  // nothing we know resolves this notch: report it rather than loop
    c.unresolved = true;
    c.note = "nine cuts in a row left the notch's concavity unchanged";
    return out;
  }
  const Vec3& notch = piece.mesh.vertices[notchIndex];
  const CutSite site{notchIndex, bridgeNormal, stalls, fromExcess, o.cutAtNotchOnly};
  const std::vector<Plane> candidates = candidatePlanes(piece.mesh, graph, map, o, site, out.times.grouping);
  t = Clock::now();
  const bool firstPlane = (!o.featureGrouping && stalls == 0) || candidates.size() == 1;
  CutChoice choice = firstPlane ? cutByFirstPlane(piece.mesh, candidates)
                                : cutByLookahead(piece.mesh, candidates, site, co, o.tau);
  out.stats.failedCuts += choice.failed;
  if (choice.ok) {
    out.final = false;
    ++out.stats.cuts;
    if ((firstPlane ? o.featureGrouping : true) && (choice.index > 0 || stalls > 0)) ++out.stats.fallbackCuts;
    out.children = childrenOf(piece, choice, notch, concavity, stalls);
  }
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

/// Adds to `pairs` the pairs of `more` that it does not hold yet.
void appendNewPairs(std::vector<SharedFaces>& pairs, const std::vector<SharedFaces>& more) {
  std::set<std::pair<int, int>> have;
  for (const SharedFaces& p : pairs) have.insert({p.a, p.b});
  for (const SharedFaces& p : more)
    if (!have.count({p.a, p.b})) pairs.push_back(p);
}

/// A component's hull distance to the model, for a working mesh: against the working model (or
/// the working piece, MergeScope::Component) plus what the working mesh stands off the input, and
/// where that sum exceeds tau, against the input itself (its grid built once, when first needed).
class ExcessAgainstInput {
 public:
  ExcessAgainstInput(const TriMesh& workingModel, std::vector<TriMesh> input, double standOff, double tau)
      : workingModel_(workingModel), working_(workingModel), input_(std::move(input)), standOff_(standOff), tau_(tau) {}

  double tau() const { return tau_; }
  /// How far apart the working model's surface and the input's may lie, with room for what the
  /// stand-off's samples missed: beyond it from one, a point is on the same side of both.
  double sideMargin() const { return 2 * standOff_; }
  /// The working model's own measure.
  const ModelExcess& workingMeasure() const { return working_; }

  double operator()(const TriMesh& hull, const TriMesh& piece, MergeScope scope) {
    const HullExcess e = scope == MergeScope::Model
                             ? working_.measure(hull, tau_ - standOff_, kExcessResolution * tau_)
                             : measureHullExcess(piece, hull, tau_ - standOff_, kExcessResolution * tau_);
    if (!e.exceeds) return e.distance + standOff_;
    return againstInput(hull, tau_).distance;
  }

  /// Against the input itself, to `limit`; the working model tells inside from outside farther
  /// than sideMargin() from the input's surface.
  HullExcess againstInput(const TriMesh& hull, double limit, int firstFace = -1) {
    std::call_once(built_, [&] {
      input_model_ = std::make_unique<InputExcess>(concatenate(input_), workingModel_, sideMargin());
      input_ = {};
    });
    // A hull vertex is an input vertex (on the input), a working vertex (an input vertex too) or a
    // cut point inside the working model: inside the input, or within two side margins of it.
    return input_model_->measure(hull, limit, kExcessResolution * tau_, firstFace, 2 * sideMargin());
  }

 private:
  const TriMesh& workingModel_;
  ModelExcess working_;
  std::vector<TriMesh> input_;
  double standOff_, tau_;
  std::once_flag built_;
  std::unique_ptr<InputExcess> input_model_;
};

/// With a working mesh, what a piece stands for of the input: the input vertices nearest to it
/// (before the merge; a union takes both pieces') and the hull with them, its component's hull.
struct InputShare {
  std::vector<Vec3> points;
  TriMesh hull;
};

/// One candidate union of the merge pass: screened by the cheaper test, then confirmed by the
/// costlier one only when its turn comes (screenUnion, confirmUnion).
struct MergeCandidate {
  TriMesh hull;                // the union's hull (the glued piece's, if it is taken)
  TriMesh inputHull;           // with the input's vertices the pieces stand for (a working mesh's)
  double volume = 0.0;         // the union's
  bool screened = false;       // passes the cheaper test
  bool confirmed = false;      // the costlier test was made
  bool ok = false;             // passes both
  TriMesh glued;               // the union, once confirmed
  double cost = 0.0;           // the order in which passing unions are taken (lower first)
  double concavity = 0.0;      // MergeScope::Component: the union's measured concavity
  double hullExcess = 0.0;     // how far its hull stands off the union (Component) or the model (Model)
};

/// The cheaper test: what the union's hull adds beyond the two it replaces, outside the model
/// (Model) or beyond the union (Component).
MergeCandidate screenUnion(const Piece& a, const Piece& b, const TriMesh& hullA, const TriMesh& hullB,
                           std::uint64_t key, const ModelExcess* model) {
  MergeCandidate m;
  // The union's hull is the hull of the two hulls' corners: far fewer points than the union's.
  std::vector<Vec3> corners = hullA.vertices;
  corners.insert(corners.end(), hullB.vertices.begin(), hullB.vertices.end());
  m.hull = convexHull(corners).mesh;
  m.volume = signedVolume(a.mesh) + signedVolume(b.mesh);
  if (model) {
    // The union's hull only has to stay within tau of the model: where it reaches beyond the union,
    // it reaches into other components, which are model too.
    m.cost = model->addedVolume(m.hull, {&hullA, &hullB}, kModelMergeSamples, key, kModelMergeGrowth * m.volume);
    m.screened = m.cost <= kModelMergeGrowth * m.volume;
    return m;
  }
  // The union's hull may not swell much beyond the two hulls: a merge must not cost fidelity.
  const double growth = signedVolume(m.hull) - m.volume - (signedVolume(hullA) - signedVolume(a.mesh)) -
                        (signedVolume(hullB) - signedVolume(b.mesh));
  m.screened = growth <= kMergeHullGrowth * m.volume;
  return m;
}

/// The costlier test, on a screened union: its hull within tau of the model (Model), or its own
/// concavity and its hull within tau of it (Component).
void confirmUnion(MergeCandidate& m, const Piece& a, const Piece& b, const ModelExcess* model,
                  ExcessAgainstInput* input, const TriMesh* inputHullA, const TriMesh* inputHullB,
                  const DecomposeOptions& o, const ConcavityOptions& co) {
  m.confirmed = true;
  if (model) {
    // Pieces that touch but do not glue into one solid (a cap that a later cut split on one side
    // only) may still share one hull: the component keeps them as two shells.
    // With a working mesh, the hull measured is the one the component would have: with the
    // input's vertices (screening, a cheaper test, keeps to the pieces' own).
    if (inputHullA && inputHullB) {
      std::vector<Vec3> corners = inputHullA->vertices;
      corners.insert(corners.end(), inputHullB->vertices.begin(), inputHullB->vertices.end());
      m.inputHull = convexHull(corners).mesh;
    }
    const TriMesh& hull = inputHullA && inputHullB ? m.inputHull : m.hull;
    HullExcess e = model->measure(hull, kExcessLimit * o.tau, kExcessResolution * o.tau);
    // A working model is held to tau less its stand-off; what that refuses, the input decides,
    // unless the union is beyond by more than the side margin on the working model too (the
    // cheaper measure; about half the unions the input would have to refuse, on bunny00).
    // Both start where the working model's measure found the union beyond.
    if (e.exceeds && input) {
      const double limit = kExcessLimit * input->tau();
      if (!model->measure(hull, limit + input->sideMargin(), kExcessResolution * o.tau, e.hullFace).exceeds)
        e = input->againstInput(hull, limit, e.hullFace);
    }
    m.ok = !e.exceeds;
    m.hullExcess = e.distance;
    if (m.ok) m.glued = joinPieces(a.mesh, b.mesh);
    return;
  }
  if (!glueAlongSharedFaces(a.mesh, b.mesh, m.glued)) return;
  SurfaceGraph graph(m.glued);
  m.concavity = measureConcavity(m.glued, graph, co).concavity;
  if (m.concavity > o.tau) return;
  // A union is held to the same promise as a final piece: its hull within tau of it.
  const HullExcess e = measureHullExcess(m.glued, m.hull, kExcessLimit * o.tau, kExcessResolution * o.tau);
  m.ok = !e.exceeds;
  m.hullExcess = e.distance;
  m.concavity = std::max(m.concavity, e.distance);
}

/// Merge pass: the greedy recursion sometimes cuts where a coarser split would have done. Glue
/// neighbours back along their shared cut faces while the union passes the test of o.mergeScope;
/// held to the model, every pair of pieces that touch is tried. Each round screens every
/// candidate union not screened before, in parallel; then the screened ones are taken in order
/// (Component: largest contact first; Model: least volume added outside the model first, ties by
/// pair order), each confirmed when its turn comes, skipping pairs whose pieces changed in that
/// round; rounds repeat until nothing merges. The next few unions that may be taken are confirmed
/// ahead, on the other threads, while the one whose turn it is waits (ConfirmAhead); which ones
/// are confirmed early never changes a decision, so the result does not depend on the thread count.
void mergePieces(std::vector<Piece>& finals, std::vector<Component>& finalInfo, const TriMesh& input,
                 ExcessAgainstInput* againstInput, std::vector<InputShare>* shares, const DecomposeOptions& o,
                 DecomposeStats& stats) {
  ConcavityOptions co;
  co.epsilon = o.epsilon;
  // Held to the input, the working model's measure is the one againstInput already has.
  std::unique_ptr<ModelExcess> own;
  const ModelExcess* model = nullptr;
  if (o.mergeScope == MergeScope::Model)
    model = againstInput ? &againstInput->workingMeasure() : (own = std::make_unique<ModelExcess>(input)).get();
  std::vector<char> alive(finals.size(), 1), mergedInModel(finals.size(), 0);
  std::map<std::pair<int, int>, MergeCandidate> measured;  // by the pieces' indices
  std::vector<TriMesh> hulls(finals.size());                 // each piece's hull, kept through merges
  tbb::parallel_for(std::size_t(0), finals.size(), [&](std::size_t i) {
    hulls[i] = finalInfo[i].hull.faces.empty() ? convexHull(finals[i].mesh.vertices).mesh : std::move(finalInfo[i].hull);
  });
  for (bool merged = true; merged;) {
    merged = false;
    std::vector<const TriMesh*> meshes;
    std::vector<int> id;
    for (std::size_t i = 0; i < finals.size(); ++i)
      if (alive[i] && !finalInfo[i].unresolved) meshes.push_back(&finals[i].mesh), id.push_back(static_cast<int>(i));
    std::vector<SharedFaces> pairs = sharedFacePairs(meshes);
    if (model) appendNewPairs(pairs, touchingPairs(meshes));
    // A pair whose pieces are unchanged since it was screened keeps its screening (and confirmation).
    std::vector<std::size_t> fresh;
    for (std::size_t k = 0; k < pairs.size(); ++k)
      if (!measured.count({id[pairs[k].a], id[pairs[k].b]})) fresh.push_back(k);
    std::vector<MergeCandidate> screenedNow(fresh.size());
    tbb::parallel_for(std::size_t(0), fresh.size(), [&](std::size_t f) {
      const int i = id[pairs[fresh[f]].a], j = id[pairs[fresh[f]].b];
      screenedNow[f] = screenUnion(finals[i], finals[j], hulls[i], hulls[j],
                                   mix64(static_cast<std::uint64_t>(i) << 32 | static_cast<std::uint32_t>(j)), model);
    });
    for (std::size_t f = 0; f < fresh.size(); ++f)
      measured[{id[pairs[fresh[f]].a], id[pairs[fresh[f]].b]}] = std::move(screenedNow[f]);
    std::vector<MergeCandidate*> unions(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) unions[k] = &measured.at({id[pairs[k].a], id[pairs[k].b]});
    std::vector<std::size_t> order;
    for (std::size_t k = 0; k < pairs.size(); ++k)
      if (unions[k]->screened) order.push_back(k);
    if (model)
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return unions[a]->cost < unions[b]->cost; });
    // Pieces are changed at the end of the round: until then, every confirmation reads them as
    // they were screened, whichever thread makes it and when (ConfirmAhead).
    std::vector<std::atomic<char>> changed(finals.size());
    auto open = [&](std::size_t n) {
      const std::size_t k = order[n];
      return !changed[id[pairs[k].a]].load(std::memory_order_relaxed) &&
             !changed[id[pairs[k].b]].load(std::memory_order_relaxed);
    };
    auto confirm = [&](std::size_t n) {
      const std::size_t k = order[n];
      const int i = id[pairs[k].a], j = id[pairs[k].b];
      confirmUnion(*unions[k], finals[i], finals[j], model, againstInput, shares ? &(*shares)[i].hull : nullptr,
                   shares ? &(*shares)[j].hull : nullptr, o, co);
    };
    ConfirmAhead<decltype(confirm), decltype(open)> confirmations(
        order.size(), 2 * static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()), confirm, open,
        [&](std::size_t n) { return unions[order[n]]->confirmed; });
    std::vector<std::size_t> taken;
    for (std::size_t n = 0; n < order.size(); ++n) {
      if (!open(n)) continue;
      confirmations.await(n);
      const std::size_t k = order[n];
      if (!unions[k]->ok) continue;
      taken.push_back(k);
      changed[id[pairs[k].a]].store(1, std::memory_order_relaxed);
      changed[id[pairs[k].b]].store(1, std::memory_order_relaxed);
    }
    confirmations.finish();
    for (const std::size_t k : taken) {
      const int i = id[pairs[k].a], j = id[pairs[k].b];
      finals[i].mesh = std::move(unions[k]->glued);
      hulls[i] = std::move(unions[k]->hull);
      if (shares) {
        InputShare &into = (*shares)[i], &from = (*shares)[j];
        into.hull = std::move(unions[k]->inputHull);
        into.points.insert(into.points.end(), from.points.begin(), from.points.end());
        from = {};
      }
      finalInfo[i].concavity = unions[k]->concavity;
      finalInfo[i].hullExcess = unions[k]->hullExcess;
      finalInfo[i].depth = std::min(finalInfo[i].depth, finalInfo[j].depth);
      mergedInModel[i] = model != nullptr;
      alive[j] = 0;
      ++stats.merges;
      merged = true;
    }
    for (auto it = measured.begin(); it != measured.end();)
      it = changed[it->first.first] || changed[it->first.second] ? measured.erase(it) : std::next(it);
  }
  std::vector<Piece> keptPieces;
  std::vector<Component> keptInfo;
  std::vector<InputShare> keptShares;
  std::vector<std::size_t> measure;
  for (std::size_t i = 0; i < finals.size(); ++i)
    if (alive[i]) {
      if (mergedInModel[i]) measure.push_back(keptPieces.size());
      keptPieces.push_back(std::move(finals[i]));
      keptInfo.push_back(finalInfo[i]);
      if (shares) keptShares.push_back(std::move((*shares)[i]));
    }
  if (shares) *shares = std::move(keptShares);
  // A union kept for its hull may be more concave than tau (its pockets lie in other components):
  // its concavity is measured as it is and reported, never assumed.
  tbb::parallel_for(std::size_t(0), measure.size(), [&](std::size_t k) {
    const TriMesh& mesh = keptPieces[measure[k]].mesh;
    SurfaceGraph graph(mesh);
    keptInfo[measure[k]].concavity = measureConcavity(mesh, graph, co).concavity;
  });
  finals = std::move(keptPieces);
  finalInfo = std::move(keptInfo);
}

/// The input's own vertices each working piece stands for (its nearest), which join its hull;
/// `firstOf` gives a piece's place among the first pieces from its source.
std::vector<std::vector<Vec3>> inputPointsOf(const WorkingModel& working, const std::vector<Piece>& pieces,
                                             const std::map<int, int>& firstOf) {
  std::vector<const TriMesh*> meshes;
  std::vector<int> sources;
  for (const Piece& p : pieces) meshes.push_back(&p.mesh), sources.push_back(firstOf.at(p.source));
  return inputVerticesOf(working, meshes, sources);
}

/// The merge pass. Held to the input (`againstInput`, a working mesh's), each piece first gets the
/// hull its component would have, with the input vertices it stands for (`points`, by piece), so
/// that unions are measured against the input to the full tau where the working model's tau less
/// the stand-off refuses them, and what the merge accepts is what the hulls will be; the input
/// vertices of each final piece come back (nothing when not held to the input).
std::vector<std::vector<Vec3>> mergeHeldToInput(std::vector<Piece>& finals, std::vector<Component>& finalInfo,
                                                const TriMesh& model, ExcessAgainstInput* againstInput,
                                                std::vector<std::vector<Vec3>> points, const DecomposeOptions& o,
                                                DecomposeStats& stats) {
  std::vector<InputShare> shares;
  if (againstInput) {
    shares.resize(finals.size());
    tbb::parallel_for(std::size_t(0), finals.size(), [&](std::size_t i) {
      std::vector<Vec3> all = finals[i].mesh.vertices;
      all.insert(all.end(), points[i].begin(), points[i].end());
      shares[i].hull = convexHull(all).mesh;
      shares[i].points = std::move(points[i]);
    });
  }
  mergePieces(finals, finalInfo, model, againstInput, againstInput ? &shares : nullptr, o, stats);
  std::vector<std::vector<Vec3>> kept;
  for (InputShare& share : shares) kept.push_back(std::move(share.points));
  return kept;
}

}  // namespace

PhaseTimes& operator+=(PhaseTimes& into, const PhaseTimes& t) {
  into.prepare += t.prepare;
  into.concavity += t.concavity;
  into.grouping += t.grouping;
  into.cutting += t.cutting;
  into.merging += t.merging;
  into.hulls += t.hulls;
  return into;
}

DecomposeStats& operator+=(DecomposeStats& into, const DecomposeStats& s) {
  into.cuts += s.cuts;
  into.fallbackCuts += s.fallbackCuts;
  into.failedCuts += s.failedCuts;
  into.bridges += s.bridges;
  into.refinements += s.refinements;
  into.merges += s.merges;
  into.inputEdges += s.inputEdges;
  into.inputNotches += s.inputNotches;
  into.inputVolume += s.inputVolume;
  into.workingFaces += s.workingFaces;
  into.workingDistance = std::max(into.workingDistance, s.workingDistance);
  return into;
}

DecomposeOptions recommendedOptions() { return DecomposeOptions{}; }

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
  if (!std::isfinite(o.workingShare) || o.workingShare < 0 || o.workingShare > 0.5)
    return bad("workingShare must lie in [0, 0.5]");
  if (o.workingFromFaces < 0) return bad("workingFromFaces must not be negative");
  if (o.threads < 0 || o.threads > 1024) return bad("threads must lie in [0, 1024]");
  if (o.maxComponents < 1) return bad("maxComponents must be at least 1");
  return Status::success();
}

int countNotches(const TriMesh& mesh, double angle) {
  // Each edge's two sides by bucket (acd/mesh.hpp) rather than through a SurfaceGraph: this runs on
  // the whole input, which may have millions of faces. The test is the same from either side.
  const SideEdges numbered = numberEdges(mesh.faces);
  const std::vector<int>& edgeOf = numbered.edgeOfSide;
  std::vector<int> firstSide(numbered.edges, -1), uses(numbered.edges, 0);
  for (std::size_t s = 0; s < edgeOf.size(); ++s)
    if (edgeOf[s] >= 0 && uses[edgeOf[s]]++ == 0) firstSide[edgeOf[s]] = static_cast<int>(s);
  int notches = 0;
  for (std::size_t s = 0; s < edgeOf.size(); ++s) {
    const int e = edgeOf[s];
    if (e < 0 || uses[e] != 2 || firstSide[e] == static_cast<int>(s)) continue;  // each interior edge once
    const int f = firstSide[e] / 3, k = firstSide[e] % 3, g = static_cast<int>(s / 3);
    const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
    const Vec3 nl = faceNormal(mesh, f).normalized(), nr = faceNormal(mesh, g).normalized();
    const Vec3 c = nl.cross(nr);
    if (c.dot(mesh.vertices[b] - mesh.vertices[a]) < 0 && std::atan2(c.norm(), nl.dot(nr)) > angle) ++notches;
  }
  return notches;
}

namespace {

/// prepareSolid, or for a `clean` shell (acd/clean_shell.hpp) the shell as it is.
PreparedSolid prepareUnlessClean(const TriMesh& mesh, const PrepareOptions& po, bool clean) {
  if (!clean || firstZeroAreaFace(mesh) >= 0) return prepareSolid(mesh, po);
  PreparedSolid p;
  p.status = Status::success();
  p.components = {mesh};
  return p;
}

/// The working model of a solid's first pieces when the options ask for one: `meshes` become the
/// working meshes and `inputMeshes` keeps what they were (acd/algo/working_mesh.hpp).
WorkingModel workingModelOf(std::vector<TriMesh>& meshes, std::vector<TriMesh>& inputMeshes, bool wrap,
                            const DecomposeOptions& o) {
  std::size_t faces = 0;
  for (const TriMesh& m : meshes) faces += m.faces.size();
  // A wrap is held to its input by decomposeHeldTo's own rules.
  if (o.workingShare <= 0 || wrap || faces < static_cast<std::size_t>(o.workingFromFaces)) return {};
  inputMeshes = meshes;
  return simplifyPieces(meshes, o.workingShare * o.tau);
}

/// The decomposition of a solid with repairs done; the merge pass held to the model measures
/// against `heldTo` (input coordinates) to `mergeTau` when given, else against the solid itself.
/// A `clean` mesh is one of prepareModel's clean shells (acd/clean_shell.hpp).
Decomposition decomposeSolid(const TriMesh& mesh, const TriMesh* heldTo, double mergeTau, bool clean,
                             const DecomposeOptions& options) {
  const auto start = Clock::now();
  Decomposition result;
  result.status = validate(options);
  if (!result.status.ok()) return result;
  const DecomposeOptions o = resolvedOptions(options);
  result.options = o;

  auto t = Clock::now();
  PrepareOptions po;
  po.openMeshes = o.fillHoles ? OpenMeshPolicy::FillHoles : OpenMeshPolicy::Refuse;
  PreparedSolid prepared = prepareUnlessClean(mesh, po, clean);
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

  // Every parallel loop below, nested ones included, runs on these workers only.
  tbb::task_arena arena = workerArena(o.threads);
  bool redoAtFullResolution = false;
  arena.execute([&] {
    // Detail below what tau can see goes first: the recursion works on the working meshes, at tau
    // less what they may stand off the input (acd/algo/working_mesh.hpp).
    std::vector<TriMesh> firstMeshes, inputMeshes;
    std::map<int, int> firstOf;  // a piece's source -> its place among the first pieces
    for (std::size_t k = 0; k < pending.size(); ++k) {
      firstMeshes.push_back(std::move(pending[k].mesh));
      firstOf[pending[k].source] = static_cast<int>(k);
    }
    WorkingModel working = workingModelOf(firstMeshes, inputMeshes, heldTo != nullptr, o);
    for (std::size_t k = 0; k < pending.size(); ++k) pending[k].mesh = firstMeshes[k];
    const double allowance = working.used() ? o.workingShare * o.tau : 0.0;
    result.stats.workingFaces = working.workingFaces;
    result.stats.workingDistance = working.distance;
    DecomposeOptions inner = o;
    inner.tau = o.tau - allowance;
    const TriMesh model = heldTo ? applyNormalization(*heldTo, result.normalization) : concatenate(firstMeshes);
    result.times.prepare = secondsSince(t);

    FinalPieces<Piece, Outcome> rounds = runRounds(
        std::move(pending), o.maxComponents, [&](const Piece& piece) { return processPiece(piece, inner); },
        [](const Piece&, Outcome& out) { return std::move(out.children); },
        [&](const Outcome& out) {
          result.times += out.times;  // a piece's own work: concavity, grouping, cutting
          result.stats += out.stats;
        },
        [](Outcome& out) {
          out.component.unresolved = true;
          out.component.note = "maximum number of components reached";
        },
        [](const Piece&, Outcome&) {}, o.progress);
    std::vector<Piece> finals = std::move(rounds.pieces);
    std::vector<Component> finalInfo;
    for (Outcome& out : rounds.outcomes) finalInfo.push_back(std::move(out.component));
    if (working.used() && std::any_of(finalInfo.begin(), finalInfo.end(), [](const Component& c) { return c.unresolved; })) {
      redoAtFullResolution = true;  // the working mesh may have made a notch no plane can resolve
      return;
    }

    t = Clock::now();
    std::unique_ptr<ExcessAgainstInput> excess;
    if (working.used())
      excess = std::make_unique<ExcessAgainstInput>(model, std::move(inputMeshes), working.distance, mergeTau);
    DecomposeOptions mergeOptions = inner;
    mergeOptions.tau = mergeTau - allowance;
    std::vector<std::vector<Vec3>> inputPoints;  // by final piece, with a working mesh
    if (o.merge) {
      const bool heldToInput = excess && o.mergeScope == MergeScope::Model;
      inputPoints = mergeHeldToInput(finals, finalInfo, model, heldToInput ? excess.get() : nullptr,
                                     heldToInput ? inputPointsOf(working, finals, firstOf) : std::vector<std::vector<Vec3>>{},
                                     mergeOptions, result.stats);
    }
    result.times.merging = secondsSince(t);

    t = Clock::now();
    if (inputPoints.empty() && working.used()) inputPoints = inputPointsOf(working, finals, firstOf);
    result.components.resize(finals.size());
    tbb::parallel_for(std::size_t(0), finals.size(), [&](std::size_t i) {
      Component& c = result.components[i];
      c = finalInfo[i];
      // Back to the input's coordinates: an input vertex exactly, a point a cut made through the
      // inverse transform (every piece that shares a vertex maps it alike, so neighbours still share
      // their cut faces). A cut face through both kinds is planar to within the canonical grid.
      // The hull is computed in the input's coordinates, so that it contains the component (vertex
      // order is canonical, so is the hull's triangulation). Volumes are measured on both brought to
      // the normalised frame: in the input's coordinates a model far from the origin loses digits.
      c.mesh = inverse(finals[i].mesh);
      std::vector<Vec3> points = c.mesh.vertices;
      if (!inputPoints.empty())
        for (const Vec3& x : inputPoints[i]) points.push_back(inverse(x));
      c.hull = convexHull(points).mesh;
      c.volume = signedVolume(applyNormalization(c.mesh, result.normalization));
      const TriMesh hull = applyNormalization(c.hull, result.normalization);
      c.hullVolume = signedVolume(hull);
      if (excess) c.hullExcess = (*excess)(hull, finals[i].mesh, o.mergeScope);
    });
    result.times.hulls = secondsSince(t);
    // The promise is kept on the input or the working mesh is not used.
    redoAtFullResolution = excess && std::any_of(result.components.begin(), result.components.end(),
                                                 [&](const Component& c) { return c.hullExcess > mergeTau; });
  });
  if (redoAtFullResolution) {
    DecomposeOptions full = options;
    full.workingShare = 0.0;
    return decomposeSolid(mesh, heldTo, mergeTau, clean, full);
  }
  result.times.total = secondsSince(start);
  return result;
}

}  // namespace

Decomposition decompose(const TriMesh& mesh, const DecomposeOptions& options) {
  if (options.repair) return decomposeRepaired(mesh, options);  // acd/robust.hpp; comes back with repair off
  return decomposeSolid(mesh, nullptr, options.tau, false, options);
}

Decomposition decomposeHeldTo(const TriMesh& mesh, const TriMesh& wrapped, const DecomposeOptions& options,
                              double mergeTau) {
  DecomposeOptions o = options;
  o.repair = false;
  return decomposeSolid(mesh, &wrapped, mergeTau, false, o);
}

Decomposition decomposeCleanShell(const TriMesh& shell, const DecomposeOptions& options) {
  DecomposeOptions o = options;
  o.repair = false;
  return decomposeSolid(shell, nullptr, options.tau, true, o);
}

}  // namespace acd
