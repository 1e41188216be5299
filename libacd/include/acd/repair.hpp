// Repairs of the soups people export (Blender, CAD, scans, game assets) before the solid
// decomposition: the steps that change the mesh without changing the shape it describes by
// more than a negligible share of its size. What is left unrepairable goes to the watertight
// wrap (acd/algo/alpha_wrap.hpp) or is refused. docs/ERRORS.md lists every step.
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>
#include <vector>

namespace acd {

struct RepairOptions {
  /// Vertices closer than this share of the bounding-box diagonal are merged (float exports,
  /// STL corners, cracks between parts). Far below any tau, which starts at 1e-4 of the radius.
  double mergeTolerance = 1e-6;
  /// Needles (longest / shortest edge above this) are collapsed along their shortest edge when
  /// that edge is shorter than `collapseLength` of the diagonal; caps (an angle above
  /// `capDegrees`) are removed by flipping their longest edge.
  double needleRatio = 1e4;
  double collapseLength = 1e-5;
  double capDegrees = 179.9;
  /// A mesh that is already a closed, oriented, manifold surface with no face near the needle
  /// and cap limits skips CGAL's steps, which would give it back unchanged (a tenth of the time
  /// of a clean model's decomposition); one that is such a surface but for needle or cap faces
  /// skips only the soup's orientation and its check. false runs every step always; tests compare.
  bool skipWhenClean = true;
};

/// What repairMesh changed; every count is also one line of `repairs` when it is not zero.
struct MeshRepair {
  Status status;                      // not ok only when nothing can be made of the input
  TriMesh mesh;                       // repaired: edge-manifold, each piece consistently oriented
  std::vector<std::string> repairs;   // one line each, naming the problem and what was done
  int mergedVertices = 0;             // within mergeTolerance of another vertex (exact copies included)
  int droppedCollapsedFaces = 0;      // faces left with a repeated vertex by the merge
  int droppedDuplicateFaces = 0;      // exact copies (same orientation)
  int doubleSidedKeptOne = 0;         // a face and its reverse: the reverse dropped
  int doubleSidedDroppedBoth = 0;     // faces dropped as pairs that closed nothing
  int tJunctionEdges = 0;             // boundary edges split at vertices lying on them (acd/algo/t_junctions.hpp)
  int tJunctionVertices = 0;          // the vertices they were split at
  int splitVertices = 0;              // copies made to cut non-manifold edges and vertices apart
  int flippedFaces = 0;               // turned to agree with their neighbours
  int stitchedEdges = 0;              // boundary edge pairs sewn together
  int removedDegenerateFaces = 0;     // zero-area, needle and cap faces removed by collapse or flip
  int leftDegenerateFaces = 0;        // zero-area faces the collapse could not remove
  /// The mesh was found clean (skipWhenClean) and given back as it was: oriented, edge-manifold,
  /// one fan a vertex, every vertex used and none at another's position (PrepareOptions::knownClean).
  bool clean = false;
  double seconds = 0.0;
};

/// Repairs, in this order: refuse empty meshes, non-finite coordinates and bad indices; merge
/// close vertices; drop faces with a repeated vertex and exact duplicate faces; for a face and
/// its reverse, drop the reverse when the face is needed to close its edges, or both when the
/// two close nothing (an inner double-sided wall); split boundary edges at the boundary vertices
/// lying on them (T-junctions, acd/algo/t_junctions.hpp); cut non-manifold edges and vertices apart
/// and orient every piece consistently (CGAL orient_polygon_soup); stitch borders; remove
/// zero-area, needle and cap faces (CGAL remove_degenerate_faces and
/// remove_almost_degenerate_faces); split vertices left non-manifold
/// (duplicate_non_manifold_vertices). Holes are not closed here (acd/algo/hole_filling.hpp), and
/// self-intersections are left as they are. Never throws.
MeshRepair repairMesh(const TriMesh& mesh, const RepairOptions& options = {});

/// A closed surface that passes through itself, with the faces around each crossing replaced by a
/// patch that does not cross (CGAL's experimental remove_self_intersections: the faces near the
/// crossing are removed and the hole is filled from its rim). Local, unlike the wrap: the rest of
/// the surface is kept exactly. The patch may cut off a fold of the input; the caller measures
/// how far the input lies from the result.
struct Untangled {
  Status status;          // not ok when crossings remain or the result is not a closed surface
  TriMesh mesh;           // closed, oriented, without self-intersections
  int facesReplaced = 0;  // input faces not in the result
};
Untangled removeSelfIntersections(const TriMesh& shell);

}  // namespace acd
