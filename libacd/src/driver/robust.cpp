// Repairs, shells, hole filling and the wrap around the solid decomposition (acd/robust.hpp).
#include <acd/algo/canonical_frame.hpp>
#include <acd/algo/shell_union.hpp>
#include <acd/algo/shells.hpp>
#include <acd/algo/cut_choice.hpp>
#include <acd/algo/hull_excess.hpp>
#include <acd/algo/stopwatch.hpp>
#include <acd/diagnosis.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/repair.hpp>
#include <acd/robust.hpp>

#include "clean_shell.hpp"
#include "held_to.hpp"
#include "shell_merge.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace acd {
namespace {


std::string number(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

std::string plural(int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

/// Wraps `pieces` together at the parameters for `tau` (normalised by `modelScale`); the wrap's
/// edge-connected parts come back as closed outward shells.
struct WrapShells {
  Status status;
  std::vector<TriMesh> shells;
  WrapParameters parameters;  // normalised
  int faces = 0;
  double seconds = 0.0;
};
/// With `invariant` the pieces are wrapped in their canonical frame (acd/algo/canonical_frame.hpp): the
/// wrap follows a grid of the scene's box, so it would change with the pose otherwise.
WrapShells wrapPieces(const std::vector<TriMesh>& pieces, double tau, double modelScale, bool invariant) {
  WrapShells out;
  out.parameters = wrapParametersFor(tau);
  Normalization frame;  // identity unless invariant
  TriMesh input = concatenate(pieces);
  if (invariant) {
    frame = canonicalFrame(pieces);
    input = canonicalMesh(input, frame).mesh;
  }
  const double unit = frame.scale / modelScale;  // one normalised unit in the wrap's coordinates
  Wrap w = alphaWrap(input, out.parameters.alpha * unit, out.parameters.offset * unit);
  out.seconds = w.seconds;
  out.status = w.status;
  if (!w.status.ok()) return out;
  if (invariant) w.mesh = undoNormalization(w.mesh, frame);
  out.faces = static_cast<int>(w.mesh.faces.size());
  for (TriMesh& part : splitEdgeConnected(w.mesh)) {
    if (signedVolume(part) < 0.0)
      for (Face& f : part.faces) std::swap(f[1], f[2]);
    if (!isClosedOriented(part)) {
      out.status = Status::error(StatusCode::InternalError, "the alpha wrap is not a closed surface");
      return out;
    }
    out.shells.push_back(std::move(part));
  }
  return out;
}

void addWrapToReport(WrapReport& report, const WrapShells& w, int pieces, const std::string& reason) {
  report.used = true;
  report.reason = report.reason.empty() ? reason : report.reason + "; " + reason;
  report.wrappedPieces += pieces;
  report.alpha = w.parameters.alpha;
  report.offset = w.parameters.offset;
  report.faces += w.faces;
  report.seconds += w.seconds;
}

/// Drops the shells at odd nesting depth (cavities, or solids inside another solid).
void dropCavities(PreparedModel& out) {
  const ShellNesting nesting = classifyShells(out.shells);
  if (nesting.cavities == 0) return;
  std::vector<TriMesh> kept;
  std::vector<char> keptWrap, keptClean;
  for (std::size_t i = 0; i < out.shells.size(); ++i)
    if (nesting.depth[i] % 2 == 0) {
      kept.push_back(std::move(out.shells[i]));
      keptWrap.push_back(out.isWrap[i]);
      keptClean.push_back(out.isClean[i]);
    }
  out.shells = std::move(kept);
  out.isWrap = std::move(keptWrap);
  out.isClean = std::move(keptClean);
  out.cavitiesDropped += nesting.cavities;
  out.repairs.push_back("dropped " + plural(nesting.cavities, "inner shell", "inner shells") +
                        " bounding a cavity (inside another shell): the hulls of the shell around cover it");
}

/// Unites the shells (not the wrap's) that pass through, touch or nest in another
/// (acd/algo/shell_union.hpp); what the union could not take is decomposed shell by shell.
void uniteShells(PreparedModel& out, bool invariant) {
  std::vector<TriMesh> exact, wrapped;
  for (std::size_t i = 0; i < out.shells.size(); ++i)
    (out.isWrap[i] ? wrapped : exact).push_back(std::move(out.shells[i]));
  ShellUnion u = uniteMeetingShells(exact, invariant);
  out.shells = std::move(u.shells);
  out.isWrap.assign(out.shells.size(), 0);
  out.isClean.assign(out.shells.size(), 1);
  std::fill(out.isClean.begin(), out.isClean.begin() + u.solids, 0);  // the unions come first
  for (TriMesh& w : wrapped) {
    out.shells.push_back(std::move(w));
    out.isWrap.push_back(1);
    out.isClean.push_back(0);
  }
  out.unitedShells = u.united;
  if (u.united > 0) {
    out.repairs.push_back("united " + plural(u.united, "shell", "shells") +
                          " that pass through, touch or lie in another into " + plural(u.solids, "solid", "solids") +
                          " (their union, exact; " + number(u.seconds) + " s)");
    dropCavities(out);  // a shell may lie inside a union and in no one shell
  }
  if (u.leftAlone > 0)
    out.repairs.push_back(plural(u.leftAlone, "shell meets", "shells meet") + " another but could not be united (" +
                          u.firstFailure + "): each is decomposed on its own");
}

}  // namespace

PreparedModel prepareModel(const TriMesh& mesh, const DecomposeOptions& options, bool buildWrap) {
  const auto start = Clock::now();
  PreparedModel out;
  auto refuse = [&](const Status& s) {
    out.status = s;
    out.shells.clear();
    out.isWrap.clear();
    out.isClean.clear();
    out.seconds = secondsSince(start);
    return out;
  };
  const MeshRepair repaired = repairMesh(mesh);
  if (!repaired.status.ok()) return refuse(repaired.status);
  out.repairs = repaired.repairs;

  PrepareOptions po;
  po.openMeshes = options.fillHoles ? OpenMeshPolicy::FillHoles : OpenMeshPolicy::Refuse;
  PrepareOptions wholeOptions = po;
  wholeOptions.knownClean = repaired.clean;  // the pieces below, split apart, are not known so
  PreparedSolid whole = prepareSolid(repaired.mesh, wholeOptions);
  std::vector<TriMesh> unclosable;
  if (whole.status.ok()) {
    out.shells = std::move(whole.components);
    out.holesFilled = whole.holesFilled;
    // The copies repairMesh made of non-manifold vertices share a position: prepareSolid merges
    // and splits them again; those lines would only repeat repairMesh's.
    for (const std::string& line : whole.repairs)
      if (line.rfind("merged ", 0) != 0 && line.find("non-manifold vertices") == std::string::npos &&
          line.find("not used by any face") == std::string::npos)
        out.repairs.push_back(line);
  } else {
    // Piece by piece: the pieces that can be made solid stay exact, the rest go to the wrap.
    // (The whole can fail where no piece does: the copies repairMesh made of a non-manifold
    // vertex share its position, and prepareSolid merges exact copies again.)
    const std::vector<TriMesh> pieces = splitEdgeConnected(repaired.mesh);
    Status firstFailure;
    for (const TriMesh& piece : pieces) {
      PreparedSolid p = prepareSolid(piece, po);
      if (!p.status.ok()) {
        if (unclosable.empty()) firstFailure = p.status;
        unclosable.push_back(piece);
        continue;
      }
      out.holesFilled += p.holesFilled;
      for (TriMesh& c : p.components) out.shells.push_back(std::move(c));
    }
    if (!unclosable.empty() && !options.wrap) return refuse(firstFailure);  // today's refusal and message
    if (out.holesFilled > 0) out.repairs.push_back("filled " + plural(out.holesFilled, "hole", "holes"));
    if (!unclosable.empty())
      out.wrapReason = plural(static_cast<int>(unclosable.size()), "piece", "pieces") + " of " +
                       std::to_string(pieces.size()) + " cannot be made a clean solid (first: " + firstFailure.message +
                       ")";
  }
  out.isWrap.assign(out.shells.size(), 0);
  out.isClean.assign(out.shells.size(), 1);
  if (!unclosable.empty() && buildWrap) {
    const double scale = minimumSphereNormalization(repaired.mesh).scale;
    WrapShells w = wrapPieces(unclosable, options.tau, scale, options.invariant);
    if (!w.status.ok()) return refuse(w.status);
    addWrapToReport(out.wrap, w, static_cast<int>(unclosable.size()), out.wrapReason);
    out.repairs.push_back(out.wrapReason + ": wrapped them (alpha " + number(w.parameters.alpha) + ", offset " +
                          number(w.parameters.offset) + " normalised units, " + plural(w.faces, "face", "faces") +
                          ", " + number(w.seconds) + " s)");
    for (TriMesh& s : w.shells) {
      out.shells.push_back(std::move(s));
      out.isWrap.push_back(1);
      out.isClean.push_back(0);
    }
    out.wrappedInput = std::move(unclosable);
  } else if (!unclosable.empty()) {
    out.repairs.push_back(out.wrapReason + ": decompose wraps them");
  }

  // Shells: cavities go (the hulls of the shell around them cover them); shells that meet become
  // the solid they bound together, so that one hull may span several (an assembly from CAD).
  dropCavities(out);
  if (options.uniteShells) uniteShells(out, options.invariant);
  out.overlappingShells = classifyShells(out.shells).overlapping;
  // Without the wrap built (acd info), pieces waiting for it still make a solid.
  const bool wrapToCome = !buildWrap && !unclosable.empty();
  out.status = out.shells.empty() && !wrapToCome
                   ? Status::error(StatusCode::EmptyMesh, "no solid left after the repairs")
                   : Status::success();
  out.seconds = secondsSince(start);
  return out;
}

namespace {

/// One shell decomposed alone, at tau in the model's units, its figures brought back to them. A
/// wrap of a closed shell is given that shell (`wrapped`) and the user's tau (`wrappedTau`, model
/// units): its merges are held to them. A `clean` shell (PreparedModel::isClean) is not checked again.
Decomposition decomposeShell(const TriMesh& shell, int index, const DecomposeOptions& o, double modelScale,
                             int doneBefore, const TriMesh* wrapped = nullptr, double wrappedTau = 0.0,
                             bool clean = false) {
  DecomposeOptions inner = o;
  inner.repair = false;
  const double k = std::max(1.0, minimumSphereNormalization(shell).scale / modelScale);  // shell units per model unit
  inner.tau = std::min(2.0, o.tau * k);
  inner.epsilon = std::min(inner.tau, o.epsilon * k);
  inner.delta = std::min(inner.tau, o.delta * k);
  if (o.progress) inner.progress = [&](int done, int pending) { o.progress(doneBefore + done, pending); };
  Decomposition d = wrapped ? decomposeHeldTo(shell, *wrapped, inner, std::min(2.0, wrappedTau * k))
                    : clean  ? decomposeCleanShell(shell, inner)
                             : decompose(shell, inner);
  if (!d.status.ok()) return d;
  const double k3 = k * k * k;
  for (Component& c : d.components) {
    c.concavity /= k;
    c.hullExcess /= k;
    c.volume /= k3;
    c.hullVolume /= k3;
    c.source = index;
  }
  d.stats.inputVolume /= k3;
  d.stats.workingDistance /= k;
  return d;
}

/// A hull within t of the wrap is within t + d of the input, where d is how far the wrap stands
/// off the input (sampled, with a tenth more for what the samples miss): the wrap is decomposed at
/// tau - d so that the promise holds against the input. Never below three quarters of tau: where
/// the wrap bridges a gap narrower than alpha, d is large but the hulls there cover the gap
/// anyway, and a smaller tau would multiply the parts (cow: 116 at tau / 2, against 36).
DecomposeOptions optionsForWrap(const DecomposeOptions& o, const TriMesh& wrap, const TriMesh& input, double scale) {
  DecomposeOptions w = o;
  const double standOff = 1.1 * surfaceDistance(wrap, input).aToB * scale;
  w.tau = std::max(0.75 * o.tau, o.tau - standOff);
  w.epsilon = std::min(w.epsilon, w.tau);
  w.delta = std::min(w.delta, w.tau);
  return w;
}

/// removeSelfIntersections, in the shell's canonical frame when `invariant`: which faces it
/// removes and how it fills the hole would follow the pose and the order of faces otherwise.
Untangled untangleShell(const TriMesh& shell, bool invariant) {
  if (!invariant) return removeSelfIntersections(shell);
  const Normalization frame = canonicalFrame({shell});
  Untangled u = removeSelfIntersections(canonicalMesh(shell, frame).mesh);
  if (u.status.ok()) u.mesh = undoNormalization(u.mesh, frame);
  return u;
}

/// How far the input may lie from its repaired surface, as a share of tau: the hulls cover the
/// repaired surface, so a fold the repair cut off is left uncovered by up to that much. Within
/// tau, as the hulls may stand out of the model by tau; beyond, the wrap (which covers all).
constexpr double kUntangledCutOff = 1.0;

/// The repair is tried only on a surface with at most this many crossing face pairs: its time grows
/// with them (a crumpled sphere of 7080 faces: 594 pairs 0.3 s, 3724 pairs 2.8 s, 25006 pairs 35 s
/// and a failure), and a surface that crosses itself everywhere is the wrap's case.
constexpr int kUntangleMaxPairs = 2000;

/// `surface` (the shell, or one of its components) repaired around its crossings and decomposed
/// again, its merges held to the shell at the user's tau. A failed status when the repair fails,
/// cuts off more than kUntangledCutOff * tau, or leaves a component above tau; `facesReplaced` and
/// `cutOff` (how far `surface` reaches outside its repair, normalised) say what the repair did.
Decomposition untangleAndDecompose(const TriMesh& surface, const TriMesh& shell, int index, const DecomposeOptions& o,
                                   double scale, int done, int& facesReplaced, double& cutOff) {
  Decomposition d;
  const Untangled u = untangleShell(surface, o.invariant);
  if (!u.status.ok()) {
    d.status = u.status;
    return d;
  }
  facesReplaced = u.facesReplaced;
  cutOff = distanceOutside(surface, u.mesh) * scale;
  if (cutOff > kUntangledCutOff * o.tau) {
    d.status = Status::error(StatusCode::InvalidParameter, "the repair cuts off more than tau");
    return d;
  }
  d = decomposeShell(u.mesh, index, optionsForWrap(o, u.mesh, surface, scale), scale, done, &shell, o.tau);
  if (d.status.ok() &&
      std::any_of(d.components.begin(), d.components.end(), [](const Component& c) { return c.unresolved; }))
    d.status = Status::error(StatusCode::InternalError, "a component stays above tau");
  return d;
}

/// The whole shell repaired around its crossings and decomposed again (untangleAndDecompose);
/// `line` says what was done.
Decomposition decomposeUntangled(const TriMesh& shell, int index, const DecomposeOptions& o, double scale, int done,
                                 std::string& line) {
  int replaced = 0;
  double cutOff = 0.0;
  Decomposition d = untangleAndDecompose(shell, shell, index, o, scale, done, replaced, cutOff);
  line = "removed its self-intersections instead (" + plural(replaced, "face", "faces") +
         " replaced; the input reaches " + number(cutOff) +
         " normalised units outside the repaired surface) and decomposed it again";
  return d;
}

/// The work a second decomposition did, added to the first's (whose statistics are kept).
void addRedoneWork(Decomposition& d, const Decomposition& redo) {
  d.stats.cuts += redo.stats.cuts;
  d.times.concavity += redo.times.concavity;
  d.times.cutting += redo.times.cutting;
  d.times.grouping += redo.times.grouping;
}

/// The components of `d` left above tau give way to `redo`'s (decomposeUntangledPieces); the volume
/// decomposed is theirs repaired now, so that the components still add up to it.
void replaceUnresolved(Decomposition& d, Decomposition&& redo) {
  double dropped = 0.0;
  std::vector<Component> kept;
  for (Component& c : d.components)
    if (c.unresolved) dropped += c.volume;
    else kept.push_back(std::move(c));
  for (Component& c : redo.components) kept.push_back(std::move(c));
  d.components = std::move(kept);
  d.stats.inputVolume += redo.stats.inputVolume - dropped;
  addRedoneWork(d, redo);
}

/// The first attempt's statistics are kept (work done), its components replaced. The volume
/// decomposed is the repaired or wrapped surface's now: the components add up to it.
void replaceAll(Decomposition& d, Decomposition&& redo) {
  d.components = std::move(redo.components);
  d.stats.inputVolume = redo.stats.inputVolume;
  addRedoneWork(d, redo);
}

void accumulateShell(Decomposition& into, Decomposition&& d) {
  for (Component& c : d.components) into.components.push_back(std::move(c));
  into.stats += d.stats;
  into.times += d.times;
}

/// Only the components of `first` (the shell's decomposition) left above tau, each repaired around
/// its crossings and decomposed again, its merges held to the shell at the user's tau: the rest of
/// the shell keeps its components and the user's tau (the repaired surface stands off the input,
/// and the tau of what is decomposed on it shrinks by that: the whole cow at tau 0.05 took 22
/// parts, against 19 this way). Fails as decomposeUntangled does, for any of them.
Decomposition decomposeUntangledPieces(const Decomposition& first, const TriMesh& shell, int index,
                                       const DecomposeOptions& o, double scale, int done, std::string& line) {
  Decomposition out;
  out.status = Status::success();
  int replaced = 0, pieces = 0;
  double cutOff = 0.0;
  for (const Component& c : first.components) {
    if (!c.unresolved) continue;
    ++pieces;
    int facesReplaced = 0;
    double pieceCutOff = 0.0;
    Decomposition d = untangleAndDecompose(c.mesh, shell, index, o, scale, done + static_cast<int>(out.components.size()),
                                           facesReplaced, pieceCutOff);
    replaced += facesReplaced;
    cutOff = std::max(cutOff, pieceCutOff);
    if (!d.status.ok()) {
      out.status = d.status;
      return out;
    }
    accumulateShell(out, std::move(d));
  }
  line = "removed its self-intersections in " +
         (pieces == 1 ? std::string("that component") : "those " + std::to_string(pieces) + " components") +
         " only (" + plural(replaced, "face", "faces") + " replaced; the input reaches " + number(cutOff) +
         " normalised units outside the repaired surface) and decomposed " + (pieces == 1 ? "it" : "them") + " again";
  return out;
}

/// `d`, the shell's decomposition with components left above tau, redone on the shell repaired
/// around its crossings: those components alone first, else the whole shell. False when neither
/// works (`d` is then as it was); `line` says what was done.
bool redoUntangled(Decomposition& d, const TriMesh& shell, int index, const DecomposeOptions& o, double scale,
                   int done, std::string& line) {
  Decomposition redo = decomposeUntangledPieces(d, shell, index, o, scale, done, line);
  if (redo.status.ok()) {
    replaceUnresolved(d, std::move(redo));
    return true;
  }
  redo = decomposeUntangled(shell, index, o, scale, done, line);
  if (!redo.status.ok()) return false;
  replaceAll(d, std::move(redo));
  return true;
}

/// The promise is about the input: a component of the wrap has its hull measured against the
/// input pieces the wrap replaced (their solid where they bound one), not against the wrap, which
/// stands off them (by its offset, and more where it bridges a gap or a fold).
void measureWrapHullsAgainstInput(Decomposition& result, const TriMesh& wrappedInput) {
  const TriMesh input = applyNormalization(wrappedInput, result.normalization);
  const ModelExcess model(input, ModelSolid::Whole, result.options.threads);
  const double tau = result.options.tau;
  for (Component& c : result.components) {
    if (!c.ofWrap) continue;
    const HullExcess e = model.measure(applyNormalization(c.hull, result.normalization), 4.0 * tau,
                                       kExcessResolution * tau);
    c.hullExcess = e.distance;
  }
}

}  // namespace

namespace {

/// decomposeRepaired's one route: the shells of `prepared` (prepareModel at `options`, resolved),
/// each decomposed.
Decomposition decomposeShells(const DecomposeOptions& o, PreparedModel prepared) {
  const auto start = Clock::now();
  Decomposition result;
  result.options = o;

  result.repairs = prepared.repairs;
  result.stats.holesFilled = prepared.holesFilled;
  result.wrap = prepared.wrap;
  result.repairSeconds = prepared.seconds - prepared.wrap.seconds;
  result.status = prepared.status;
  if (!result.status.ok()) return result;
  result.normalization = minimumSphereNormalization(concatenate(prepared.shells));
  const double scale = result.normalization.scale;

  // Each shell on its own; the ones left above tau get one more chance, on their wrap.
  std::vector<std::vector<Component>> byShell(prepared.shells.size());
  std::vector<TriMesh> wrapInputs = prepared.wrappedInput;  // for the fidelity measure
  std::vector<TriMesh> wraps;
  for (std::size_t i = 0; i < prepared.shells.size(); ++i)
    if (prepared.isWrap[i]) wraps.push_back(prepared.shells[i]);
  int done = 0;
  const TriMesh wrappedInput = concatenate(prepared.wrappedInput);
  for (std::size_t i = 0; i < prepared.shells.size(); ++i) {
    const DecomposeOptions shellOptions =
        prepared.isWrap[i] ? optionsForWrap(o, prepared.shells[i], wrappedInput, scale) : o;
    Decomposition d = decomposeShell(prepared.shells[i], static_cast<int>(i), shellOptions, scale, done, nullptr, 0.0,
                                     prepared.isClean[i]);
    if (!d.status.ok()) {
      result.status = d.status;
      result.components.clear();
      return result;
    }
    const int unresolved = static_cast<int>(
        std::count_if(d.components.begin(), d.components.end(), [](const Component& c) { return c.unresolved; }));
    bool redone = false;
    if (unresolved > 0 && o.wrap && !prepared.isWrap[i]) {
      const TriMesh& shell = prepared.shells[i];
      const int crossings = countSelfIntersections(shell, kUntangleMaxPairs + 1);
      const bool crosses = crossings > 0, tooMany = crossings > kUntangleMaxPairs;
      const std::string reason =
          plural(unresolved, "component", "components") + " of shell " + std::to_string(i) + " stayed above tau" +
          (tooMany ? " (the surface passes through itself in more than " + std::to_string(kUntangleMaxPairs) +
                         " face pairs, too many for a local repair)"
                   : crosses ? " (the surface passes through itself)" : "");
      // First the local repair: only the faces around the crossings change, so the rest keeps its
      // exact surface and the user's tau (a wrap stands off everywhere and costs parts).
      std::string line;
      const bool untangled = crosses && !tooMany && redoUntangled(d, shell, static_cast<int>(i), o, scale, done, line);
      if (untangled) result.repairs.push_back(reason + ": " + line);
      WrapShells w;
      if (!untangled) w = wrapPieces({shell}, o.tau, scale, o.invariant);
      if (!untangled && w.status.ok()) {
        Decomposition redo;
        redo.status = Status::success();
        redo.components.clear();
        for (const TriMesh& s : w.shells) {
          Decomposition part = decomposeShell(s, static_cast<int>(i), optionsForWrap(o, s, shell, scale), scale, done,
                                              &shell, o.tau);
          if (!part.status.ok()) {
            redo.status = part.status;
            break;
          }
          accumulateShell(redo, std::move(part));
        }
        if (redo.status.ok()) {
          addWrapToReport(result.wrap, w, 1, reason);
          result.repairs.push_back(reason + ": decomposed its wrap instead (alpha " + number(w.parameters.alpha) +
                                   ", offset " + number(w.parameters.offset) + " normalised units, " +
                                   plural(w.faces, "face", "faces") + ")");
          wrapInputs.push_back(shell);
          for (const TriMesh& s : w.shells) wraps.push_back(s);
          replaceAll(d, std::move(redo));
          redone = true;
        }
      }
    }
    for (Component& c : d.components) c.ofWrap = prepared.isWrap[i] || redone;
    done += static_cast<int>(d.components.size());
    accumulateShell(result, std::move(d));
  }
  // A hull may span shells where that keeps it within tau of the solid they bound together.
  if (o.merge && o.mergeScope == MergeScope::Model && prepared.shells.size() > 1) {
    const auto t = Clock::now();
    result.stats.merges += mergeAcrossShells(result.components, concatenate(prepared.shells), result.normalization, o);
    result.times.merging += secondsSince(t);
  }
  if (result.wrap.used && !wraps.empty()) {
    const auto t = Clock::now();
    measureWrapHullsAgainstInput(result, concatenate(wrapInputs));
    const SurfaceDistance d = surfaceDistance(concatenate(wraps), concatenate(wrapInputs));
    result.wrap.hausdorff = d.hausdorff() * scale;
    result.wrap.wrapToInput = d.aToB * scale;
    result.wrap.inputToWrap = d.bToA * scale;
    result.wrap.seconds += secondsSince(t);
  }
  result.times.prepare += prepared.seconds;
  result.times.total = secondsSince(start);
  return result;
}

/// How many pieces, per hull of the shells decomposed apart, the union's recursion may make.
constexpr int kUnionPieces = 4;

bool anyUnresolved(const Decomposition& d) {
  return std::any_of(d.components.begin(), d.components.end(), [](const Component& c) { return c.unresolved; });
}

}  // namespace

/// Where shells were united, the shells are also decomposed one by one, and the route with fewer
/// hulls is kept (the union on a tie): both keep every hull within tau of the input. The union
/// wins where shells interlock (a gear on its shaft, a box and its lid), the shells where small,
/// nearly convex parts stand proud of a larger one (bolt heads on a plate: each is one hull, but
/// united they are pockets in the plate's surface that take cuts).
Decomposition decomposeRepaired(const TriMesh& mesh, const DecomposeOptions& options) {
  const auto start = Clock::now();
  if (Status valid = validate(options); !valid.ok()) {
    Decomposition refused;
    refused.status = std::move(valid);
    return refused;
  }
  const DecomposeOptions o = resolvedOptions(options);
  PreparedModel united = prepareModel(mesh, o);
  if (!united.status.ok() || united.unitedShells == 0) {
    Decomposition d = decomposeShells(o, std::move(united));
    d.times.total = secondsSince(start);  // the repairs included, as in d.times.prepare
    return d;
  }
  // The shells apart first (cheap: most shells of an assembly are nearly convex); the union then
  // gets at most kUnionPieces times their hull count of pieces before its merge pass: a union
  // whose shells meet in coincident faces (a bolt in a hole of its own radius) can cut into
  // slivers for minutes, and with that many pieces it would not win.
  DecomposeOptions apartOptions = o;
  apartOptions.uniteShells = false;
  Decomposition apart = decomposeShells(apartOptions, prepareModel(mesh, apartOptions));
  DecomposeOptions wholeOptions = o;
  if (apart.status.ok())
    wholeOptions.maxComponents =
        std::min(o.maxComponents, kUnionPieces * std::max<int>(1, static_cast<int>(apart.components.size())));
  Decomposition whole = decomposeShells(wholeOptions, std::move(united));
  if (!whole.status.ok()) return apart.status.ok() ? apart : whole;
  const bool keepApart = apart.status.ok() && !anyUnresolved(apart) &&
                         (anyUnresolved(whole) || apart.components.size() < whole.components.size());
  Decomposition& kept = keepApart ? apart : whole;
  kept.repairs.push_back(keepApart ? "shell by shell: " + plural(static_cast<int>(apart.components.size()), "hull", "hulls") +
                                         " against the union's " + std::to_string(whole.components.size()) +
                                         ": kept the shells apart"
                                   : "the union: " + plural(static_cast<int>(whole.components.size()), "hull", "hulls") +
                                         " against " + std::to_string(apart.components.size()) +
                                         " shell by shell: kept the union");
  kept.options = o;
  kept.times.total = secondsSince(start);
  return std::move(kept);
}

}  // namespace acd
