// Exact convex decomposition (ECD) of a closed solid: the baseline the paper compares ACD with
// (Section 6, Table 1). CGAL's convex_decomposition_3 on an exact Nef polyhedron.
//
// The library computes in the calling process, in three steps: prepareExactSolids (refuse or
// repair the input), decomposeExactSolids (CGAL's call: it cannot be interrupted and may need
// hours and gigabytes) and addExactPieces (the pieces' hulls). The whole run under a time and a
// memory cap, with progress and the report of where a capped run stopped, is the sandbox's
// acdsandbox::exactSolidDecomposition (<sandbox/exact_solid.hpp>), which runs the second step in
// a capped child process: what the programs and the Python module call.
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace acd {

/// The options of the whole run. The caps and `progress` are honoured by the capped run
/// (acdsandbox::exactSolidDecomposition); the steps below use fillHoles and maxPieces.
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

/// Step 1: the input as closed solids, decomposed one by one. Repairs the mesh (and, with
/// options.fillHoles, fills its holes) as solid ACD does and refuses what bounds no solid
/// (open, non-manifold, self-intersecting). Fills status, solids, reflexEdges, holesFilled and
/// repairs of the result, and `solids` with the closed solids when status is ok.
ExactDecomposition prepareExactSolids(const TriMesh& mesh, const ExactOptions& options, std::vector<TriMesh>& solids);

/// Where decomposeExactSolids is, for progress and for the report of a run stopped half-way.
enum class ExactStage : char {
  Starting = 0,
  Building = 'B',     // converting a solid to a Nef polyhedron
  Decomposing = 'C',  // convex_decomposition_3 running
  Extracting = 'X',   // reading the pieces out
};

/// "decomposing solid 2 of 3" (`solid` counts from 0).
std::string exactStageText(ExactStage stage, std::size_t solid, std::size_t solids);

/// What decomposeExactSolids tells while it runs, in order.
class ExactListener {
 public:
  virtual ~ExactListener() = default;
  virtual void stage(ExactStage stage, std::size_t solid) = 0;
  /// The vertices of one convex piece (at most maxPieces pieces are sent in all).
  virtual void piece(const std::vector<Vec3>& vertices) = 0;
  /// Solid `solid` is done: it has `pieces` pieces (counted even beyond maxPieces).
  virtual void solidDone(std::size_t solid, std::uint64_t pieces) = 0;
};

/// Step 2: CGAL's convex_decomposition_3 of each solid, in the calling process (it cannot be
/// interrupted). Throws std::runtime_error for a solid that is not a 2-manifold Nef polyhedron,
/// std::bad_alloc when memory runs out.
void decomposeExactSolids(const std::vector<TriMesh>& solids, std::size_t maxPieces, ExactListener& listener);

/// Step 3: the pieces' vertex sets (from step 2) as hulls into out.pieces. Pieces are convex,
/// so each is the hull of its vertices; a sliver flattened to no volume by rounding to doubles
/// is left out and counted in out.note. Returns how many were left out.
std::size_t addExactPieces(const std::vector<std::vector<Vec3>>& vertexSets, ExactDecomposition& out);

}  // namespace acd
