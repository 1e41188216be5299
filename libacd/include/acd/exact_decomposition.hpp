// Exact convex decomposition (ECD) of a closed solid: the baseline the paper compares ACD with
// (Section 6, Table 1). CGAL's convex_decomposition_3 on an exact Nef polyhedron, run in a
// separate process so that a time or memory cap can stop it.
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace acd {

struct ExactOptions {
  double timeLimitSeconds = 60.0;                     // wall clock for the whole run; <= 0: no limit
  std::size_t maxPieces = 1000000;                    // pieces beyond this are counted, not returned
  std::size_t memoryLimitBytes = std::size_t(8) << 30;  // address space of the worker; 0: no limit
  bool fillHoles = true;  // close an open mesh's holes first, as solid ACD does (false: refuse it)
  /// Called from the calling thread about once a second and at each stage: what the worker is
  /// doing ("decomposing solid 1 of 1") and the seconds since the start.
  std::function<void(const std::string& stage, double seconds)> progress;
};

struct ExactDecomposition {
  Status status;                   // input refused (open, non-manifold, self-intersecting, ...)
  std::vector<TriMesh> pieces;     // closed, outward, convex; input coordinates
  bool finished = false;           // every solid of the input was decomposed within the caps
  std::size_t pieceCount = 0;      // pieces made; more than pieces.size() when maxPieces was hit
  std::size_t solids = 0;          // closed connected pieces of the input, decomposed one by one
  std::size_t unfinishedSolids = 0;  // solids whose decomposition the cap stopped (no pieces from them)
  int reflexEdges = 0;             // concave edges of the (repaired) input: what the decomposition resolves
  int holesFilled = 0;             // boundary loops closed before decomposing
  std::vector<std::string> repairs;  // what was changed before decomposing, one line each
  double seconds = 0.0;            // wall time, including the hulls of the pieces
  std::string note;                // one line: why it did not finish, or what was capped
};

/// Decomposes a closed (or, with fillHoles, hole-filled), non-self-intersecting mesh into interior-disjoint convex pieces whose
/// union is the input. Input problems come back in `status`; hitting a cap is not an error
/// (`finished` is false and `note` says which cap and where it stopped). Nothing throws.
ExactDecomposition exactSolidDecomposition(const TriMesh& closedMesh, const ExactOptions& options = {});

}  // namespace acd
