// Exact convex surface decomposition (surface ECD): the surface split into patches that each lie
// on the boundary of their own convex hull (Section 2, after Chazelle et al. 1995), by the
// flood-and-retract heuristic the paper uses as its surface baseline (Section 6, Figure 19).
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <vector>

namespace acd {

struct SurfaceExactOptions {
  /// How far a patch vertex may lie on the wrong side of a patch face's plane, in normalised
  /// units (minimum enclosing sphere radius 1): absorbs rounding in flat regions.
  double tolerance = 1e-7;
};

struct SurfaceExactDecomposition {
  Status status;
  std::vector<int> patchOfFace;            // input face -> patch index
  std::vector<std::vector<int>> patches;   // patch -> its input faces, edge-connected
  double seconds = 0.0;
};

/// Partitions the faces of any triangle mesh (open or closed, any genus) into convex patches.
/// Invalid input (no faces, bad indices, non-finite coordinates) comes back in `status`.
SurfaceExactDecomposition exactSurfaceDecomposition(const TriMesh& mesh, const SurfaceExactOptions& options = {});

/// The definition checked directly: the patch lies on the boundary of its convex hull, i.e. the
/// plane of every non-degenerate patch face has all patch vertices on one side (within
/// `tolerance`, in the mesh's own units).
bool isConvexPatch(const TriMesh& mesh, const std::vector<int>& faces, double tolerance);

/// One patch as a mesh of its own (compacted vertices, input coordinates).
TriMesh patchMesh(const TriMesh& mesh, const std::vector<int>& faces);

}  // namespace acd
