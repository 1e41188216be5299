// Surface approximate convex decomposition (Lien & Amato 2007, Section 4.3): the surface is
// split along the edges of global cuts, not cut by planes, until every patch's concavity
// is at most tau. Patches are open surfaces, measured with Extension 2 of Section 4.1
// (acd/algo/open_surface.hpp). Works on open and closed meshes of any genus.
#pragma once

#include <acd/mesh.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/status.hpp>

#include <functional>
#include <string>
#include <vector>

namespace acd {

struct SurfaceDecomposeOptions {
  double tau = 0.05;            // concavity tolerance, normalised units (min enclosing sphere radius 1)
  double epsilon = -1.0;        // bridge clustering tolerance; < 0 means tau / 2
  double delta = -1.0;          // Douglas-Peucker knot tolerance; < 0 means tau / 20
  bool featureGrouping = true;  // false: split along a plane through the notch (bisector), not a global cut
  bool merge = true;            // glue neighbouring patches back while their union stays within tau
  int threads = 0;              // 0: all cores. The output never depends on it.
  int maxPatches = 100000;      // safety net against runaway recursion
  std::function<void(int done, int pending)> progress;
};

/// How a patch was split.
enum class SplitKind { GlobalCut, Plane, Geodesic };

struct SurfacePatch {
  std::vector<int> faces;    // faces of SurfaceDecomposition::surface, ascending
  TriMesh mesh;              // the patch alone (compacted), input coordinates
  TriMesh hull;              // its convex hull, input coordinates; empty when flat
  double concavity = 0.0;    // normalised units
  double area = 0.0;         // normalised units
  int depth = 0;             // splits from the input piece to this patch
  int source = 0;            // which edge-connected piece of the input it lies on
  bool unresolved = false;   // concavity > tau but it could not be split (never hidden)
  std::string note;
};

struct SurfaceDecomposeStats {
  int splits = 0;            // patches split
  int globalCutSplits = 0;   // ... along a global cut (Section 4.3)
  int planeSplits = 0;       // ... along the mesh edges a plane through the notch crosses
  int geodesicSplits = 0;    // ... into the faces nearer the notch and the rest (last resort)
  int merges = 0;
  int inputEdges = 0;
  int inputNotches = 0;      // concave edges (interior edges only)
  int boundaryEdges = 0;
  int concaveHullVertices = 0;  // Extension 2: hull vertices of the input whose surface faces the hull's inside
  double inputArea = 0.0;    // normalised units
};

struct SurfaceDecomposeTimes {
  double prepare = 0.0, concavity = 0.0, splitting = 0.0, merging = 0.0, hulls = 0.0, total = 0.0;  // seconds
};

struct SurfaceDecomposition {
  Status status;
  TriMesh surface;                    // the input after prepareSolid's repairs (holes kept); input coordinates
  std::vector<SurfacePatch> patches;  // partition the faces of `surface`
  Normalization normalization;
  std::vector<std::string> repairs;
  SurfaceDecomposeStats stats;
  SurfaceDecomposeTimes times;
  SurfaceDecomposeOptions options;    // as resolved
};

SurfaceDecomposeOptions resolvedOptions(const SurfaceDecomposeOptions& options);
Status validate(const SurfaceDecomposeOptions& options);

/// Surface ACD of any edge-manifold, orientable triangle mesh, open or closed.
/// Invalid input or parameters come back in `status`; nothing throws.
SurfaceDecomposition decomposeSurface(const TriMesh& mesh, const SurfaceDecomposeOptions& options = {});

/// Concavity of one patch (an open or closed surface, normalised units) by the library's measure.
double patchConcavity(const TriMesh& patch, double epsilon);

}  // namespace acd
