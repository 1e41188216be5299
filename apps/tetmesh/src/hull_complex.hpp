// One piecewise linear complex (PLC) for the union of several convex hulls, with a region per
// hull, so that TetGen meshes the union conformingly: neighbouring regions share their
// interface triangles, and every tet lies in exactly one region.
//
// How (details in docs/TETMESH.md):
//  1. Contacts. For every pair of hulls, the facet normal of either hull along which they are
//     farthest apart (the separating-axis test restricted to facet normals) gives a plane
//     between them. Pairs closer than the tolerance along it are in contact there. Leaves of
//     a decomposition without the merge pass touch only along their cut planes (each lies on
//     one side of every plane that cut its ancestors), so the planes found are the cut planes,
//     refitted to the vertices near them. Contact planes within the tolerance are one plane.
//     Pairs apart by less than `closedGap` are in contact too, on the plane half way across.
//  2. Overlaps. Hulls that overlap (hulls of merged components, of self-intersecting input) are
//     both clipped by that plane, each keeping its own side: the overlap is split at the plane
//     of least penetration. (Simplified hulls arrive apart; see hull_simplify.hpp.) Vertices within the tolerance of a
//     contact plane are projected onto it (onto the line or point where two or three of them meet).
//  3. Interfaces. On each contact plane, the faces, edges and vertices the regions have there
//     are overlaid in a constrained Delaunay triangulation; each of its triangles covered by a
//     region becomes a facet, an interface when covered from both sides. Points the overlay
//     adds on an edge are added to every other facet with that edge (no T-junctions).
//  4. Triangles. Facets with points on their edges are split into triangles: TetGen 1.5
//     aborts on some such polygons (its own facet triangulation loses the segment).
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>
#include <vector>

#include "tet_mesh.hpp"

namespace tetmesh {

struct HullComplexOptions {
  double tolerance = 1e-8;  // snapping distance, relative to the half-diagonal of all hulls' box
  /// Hulls apart by less than this (same units) are in contact: both go onto a plane half way
  /// across the gap, so that the mesh is one conforming piece there instead of two faces a hair
  /// apart. At most the tolerance when smaller.
  double closedGap = 0.0;
};

struct HullComplex {
  acd::Status status;
  Plc plc;                            // region labels are 1 + index into `hulls`
  std::vector<acd::TriMesh> regions;  // each hull after overlap clipping and snapping; empty if it vanished
  std::vector<double> clippedVolume;  // per hull: volume given to its neighbours' side of a plane
  int contactPairs = 0;               // pairs of hulls that touch or overlap
  int overlappingPairs = 0;           // of these, pairs that overlapped by more than the tolerance
  int contactPlanes = 0;
  double maxOverlapDepth = 0.0;  // input units
  int interfaceFacets = 0, boundaryFacets = 0;
  int overlayPasses = 0;
};

/// Builds the PLC. Each hull must be a closed convex triangle mesh; degenerate ones are refused.
HullComplex buildHullComplex(const std::vector<acd::TriMesh>& hulls, const HullComplexOptions& options = {});

}  // namespace tetmesh
