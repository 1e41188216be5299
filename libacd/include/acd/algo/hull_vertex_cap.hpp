// Hulls with a vertex budget: each convex hull replaced by a convex polytope of at most K
// vertices that contains it, so that no part of the component it stands for is left uncovered.
// Physics engines ask for this (PhysX on the GPU: hulls of at most 60 vertices; MuJoCo, Isaac
// and Unity have similar limits).
//
// How. A supporting plane of a hull (any direction u, offset max of u . x over the hull) keeps
// the whole hull on its inner side, so every intersection of supporting half-spaces contains
// the hull. A hull within the budget is its own polytope (its facet planes). Any other starts
// as its bounding box (K >= 8) or as the smallest of a few enclosing tetrahedra and triangular
// prisms (K < 8), and is cut greedily by the supporting plane, among the hull's facet
// directions and 26 fixed directions, that removes the most volume while the polytope keeps at
// most K corners and no edge shorter than a minimum length. The volume a plane removes can only
// shrink as the polytope shrinks, so stale values bound fresh ones from above and most
// candidates are never re-evaluated (lazy greedy).
#pragma once

#include <acd/algo/convex_polytope.hpp>
#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <vector>

namespace acd {

/// One hull, lengths absolute (in the hull's units).
struct VertexCapOptions {
  int maxVertices = 60;         // K >= 4
  double eps = 0.0;             // points closer than this to a plane are on it
  double minEdge = 0.0;         // no edge of the result shorter than this (unless the hull's own)
  double margin = 0.0;          // supporting planes (and the start) pushed out by this much
  std::vector<HalfSpace> keep;  // half-spaces the result must also lie in (may cut the hull)
  /// Axes of the starting box and of the 26 fixed directions (columns, orthonormal). The
  /// identity keeps them on the coordinate axes; capHullVertices uses the hull's principal
  /// axes of inertia, so that the result turns with the input.
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
};

/// The polytope for one closed convex hull with volume; `facetNormals` are its
/// uniqueFacetNormals. `reached`: at most K corners (false only when `keep` planes added
/// corners, or a budget below 8 could not be met from the start shapes).
ConvexPolytope capVertices(const TriMesh& hull, const std::vector<Vec3>& facetNormals, const VertexCapOptions& options,
                           bool& reached);

/// Every hull of a decomposition, lengths relative to each hull's own half-diagonal, in the
/// frame of each hull's principal axes of inertia (where two principal moments are equal,
/// as on a solid of revolution, the axes in their plane are whatever the eigensolver gives).
struct HullCapOptions {
  int maxVertices = 60;  // K >= 4
  double minEdge = 1e-6; // relative: no edge shorter (engines merge near-coincident corners)
};

struct CappedHulls {
  Status status;                    // InvalidParameter for K < 4
  std::vector<TriMesh> hulls;       // convex, closed, outward; each contains its input hull
  std::vector<int> vertices;        // of each result
  std::vector<double> hullVolume;   // of each input hull (its units cubed)
  std::vector<double> addedVolume;  // result volume minus input hull volume, >= 0
  int reached = 0;                  // results with at most K vertices
  int unchanged = 0;                // hulls already within the budget, kept as they were
};

/// Caps each hull (closed, convex, outward). A hull too flat to have volume is kept as it is.
CappedHulls capHullVertices(const std::vector<TriMesh>& hulls, const HullCapOptions& options = {});

}  // namespace acd
