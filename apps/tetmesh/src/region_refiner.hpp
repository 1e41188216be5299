// Delaunay refinement of the hull regions (CGAL Mesh_3): a labelled tetrahedral mesh whose
// size and shape follow criteria tied to tau, not the small features of the hull complex.
//
// TetGen meshes a complex as given: every short edge and near-coincident face of the regions'
// overlay is kept, and the tets around them are slivers that its refinement cannot remove
// (docs/TETMESH.md). Here the regions are only a labelling of space (region_labels.hpp); the
// refinement samples its surfaces until every surface triangle lies within `facetDistance` of
// them (halved, up to three times, around a region it missed: a wall thinner than the facet
// distance) and has no angle below `facetAngle`, refines tets above `radiusEdge`, then exudes
// slivers (CGAL's vertex weights) towards `sliverBound` and moves the corners of the last ones
// (sliver_repair.hpp). CGAL's perturbation step is not used: it did not give the same mesh twice
// in one process, and the repair does its work. Features below the
// facet distance are not resolved, so they cannot force short edges; sharp edges of the regions
// are followed within the facet distance, not kept exactly.
#pragma once

#include "sliver_repair.hpp"
#include "tet_mesh.hpp"

#include <functional>
#include <string>
#include <vector>

namespace tetmesh {

struct RefineOptions {
  double facetDistance = 0.0;  // input units: surface triangles' centres within this of the regions' surfaces (> 0)
  double facetAngle = 25.0;    // degrees: smallest angle of a surface triangle (at most 30: termination)
  double facetSize = 0.0;      // input units: surface triangles' circumradius bound; 0: none
  double radiusEdge = 2.0;     // tets' circumradius over shortest edge (Mesh_3 guarantees termination from 2)
  double cellSize = 0.0;       // input units: tets' circumradius bound; 0: none
  double closedGap = 0.0;      // input units: gaps between regions narrower than this (and both regions' facet distance) are filled
  double sliverBound = 10.0;   // degrees: CGAL's sliver passes aim at no dihedral angle below this
  double sliverMove = 0.0;     // input units: how far the last slivers' corners may move (sliver_repair.hpp)
  double featureAngle = 0.0;   // degrees: sharp edges turning more are kept exactly (region_features.hpp); 0: none
  double edgeSize = 0.0;       // input units: largest protecting ball along a kept edge (> 0 with features)
};

struct RefineResult {
  bool ok = false;
  std::string error;           // one line when not ok
  TetMesh mesh;                // labels 1..n as the regions; faces: boundary and interface triangles
  SliverRepair slivers;        // below kSliverDegrees after CGAL's passes, and after the repair
  int regionsRefined = 0;      // times a missed region was meshed again with half its facet distance
  int features = 0;            // sharp-edge segments kept exactly
  int featuresDropped = 0;     // sharp edges left to be rounded (too close to others)
  long labelQueries = 0;       // how often the labelling was asked (its cost)
  double seconds = 0.0;        // wall
};

/// Meshes `regions` (closed convex triangle meshes, labels 1..n in order). When `keep` is set,
/// only points it accepts are meshed (the components clipped to the model). Deterministic: no
/// time limits, seeded generators, sequential refinement, no perturbation step; the same input
/// gives the same mesh, bit for bit, on every call.
RefineResult refineRegions(const std::vector<acd::TriMesh>& regions, const RefineOptions& options,
                           const std::function<bool(const Vec3&)>& keep = {});

}  // namespace tetmesh
