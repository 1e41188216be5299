// Measures any decomposition (a set of convex hulls) against the model it approximates.
#pragma once

#include <acd/decompose.hpp>
#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <cstdint>
#include <vector>

namespace acd {

struct EvaluateOptions {
  std::int64_t volumeSamples = 2'000'000;  // Monte-Carlo points in the joint bounding box
  std::int64_t surfaceSamples = 200'000;   // points on surfaces for the distance measures
  std::uint64_t seed = 1;
  int threads = 0;                         // 0 = all cores; results do not depend on it
};

/// Every length and volume is in the model's normalised units (minimum enclosing sphere radius 1).
struct Evaluation {
  Status status;                     // ok; its message notes skipped hulls when there are any
  int hulls = 0;                     // hulls measured (input hulls minus skipped ones)
  int skippedHulls = 0;              // hulls with fewer than 4 non-coplanar vertices: ignored
  double modelVolume = 0.0;          // exact (divergence theorem)
  double unionVolume = 0.0;          // Monte-Carlo volume of the union of the hulls
  double unionVolumeStdErr = 0.0;
  double unionToModelRatio = 0.0;
  double misclassifiedShare = 0.0;   // of the sampled points in the box: inside exactly one of model / union
  double iou = 0.0;                  // |model ∩ union| / |model ∪ union|
  double iouStdErr = 0.0;            // binomial given the K samples in model or union: sqrt(iou (1 - iou) / K)
  double hullOutsideMax = 0.0;       // largest distance from a hull-surface point to the model's solid
  double hullOutsideMean = 0.0;      // means are over all surface samples, covered ones counting 0
  double modelToHullsMax = 0.0;      // largest distance from a model-surface point to the union of hulls
  double modelToHullsMean = 0.0;
  double seconds = 0.0;              // wall time of the call

  // Raw Monte-Carlo counts (identical for any thread count with the same seed and sample counts).
  double boxVolume = 0.0;            // sampling box: bounding box of the model and the hulls
  std::int64_t volumeSamples = 0;
  std::int64_t samplesInModel = 0;
  std::int64_t samplesInUnion = 0;
  std::int64_t samplesInBoth = 0;
};

Evaluation evaluate(const TriMesh& model, const std::vector<TriMesh>& hulls,
                    const EvaluateOptions& options = {});

/// How far a surface reaches outside a set of hulls: the largest distance from a point of
/// `surface` (each vertex, and `samples` points spread over its faces by area from `seed`) to the
/// union of the hulls, 0 when every one is inside some hull; in the surface's own units. Any
/// triangles will do (a soup, an open sheet): nothing is asked of the surface but faces. On
/// `threads` workers (0: all cores); the answer does not depend on their number.
struct Coverage {
  double max = 0.0;
  Vec3 worst = Vec3::Zero();  // the point that reaches furthest out
};
Coverage surfaceOutsideHulls(const TriMesh& surface, const std::vector<TriMesh>& hulls,
                             std::int64_t samples = 20000, std::uint64_t seed = 1, int threads = 1);

/// The input as read against a decomposition's hulls: surfaceOutsideHulls with `max` in the
/// decomposition's normalised units (tau's). The second half of the promise: at most tau.
Coverage inputOutsideHulls(const TriMesh& input, const Decomposition& d);

/// The first half of the promise, on the input as read: how far each hull stands outside the
/// input's solid (ShellsInside: what its closed shells bound, and where its open shells wind
/// around a point at least half way), in the decomposition's normalised units. Every repair, wrap, union and dropped
/// cavity is thereby checked against what the user gave: at most tau (to the measure's resolution,
/// tau/32) unless the result says otherwise. A value above tau is within 5% of the hull's excess
/// (from below); one at most tau is a lower bound of an excess at most tau + tau/32.
struct HullsOffInput {
  std::vector<double> excess;  // per component, in order
  double max = 0.0;
  int component = -1;          // the one standing furthest off; -1 when none stands off at all
  Vec3 worst = Vec3::Zero();   // where, in the input's coordinates
  int openShells = 0;          // input shells that are open (bounding by their winding number)
  bool kept = true;            // max at most tau, to the resolution the decomposition promises it (tau/32)
};
/// `hullsAsDecomposed`: the hulls are as decompose() made them (no post-pass enlarged them). Then,
/// where no repair changed the input and no wrap stood in for it, the decomposition measured this
/// same quantity against this same surface, and its figures (`hullExcess`) are returned instead
/// of measuring again (seconds on a million faces).
HullsOffInput hullsOffInput(const TriMesh& input, const Decomposition& d, bool hullsAsDecomposed = false);

/// evaluate() on a mesh as read (what `acd evaluate` does): the model is first checked and
/// repaired by prepareSolid (open meshes refused); a model it refuses comes back in `status`.
Evaluation evaluateModel(const TriMesh& model, const std::vector<TriMesh>& hulls,
                         const EvaluateOptions& options = {});

}  // namespace acd
