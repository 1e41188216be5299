// Simplified hull regions: for each component, a convex polytope with at most K corners that
// contains the component's convex hull, and that overlaps no other component's region.
//
// How. Each region is the hull's vertex-capped polytope (acd/algo/hull_vertex_cap.hpp: supporting
// planes cut greedily from the hull's box), started within the planes it must keep (below),
// and with no edge shorter than a minimum length (short edges make poor tetrahedra).
//
// Regions grow beyond their hulls and would overlap. Two components whose hulls touch (the two
// sides of a cut) or whose regions overlap get a plane between their exact hulls (the
// separating-axis test over facet normals; for touching hulls, the cut plane refitted to the
// shared section). Both regions keep their side of it, and since the plane separates the
// hulls, each region still contains its hull. Planes that agree within the tolerance are one,
// so the two sides of a cut lie on the same plane. Regions are rebuilt until none overlaps.
// Only when two exact hulls overlap (merged components, self-intersecting input) does a plane
// cut a hull; the pairs are counted.
#pragma once

#include <acd/algo/convex_polytope.hpp>
#include <acd/mesh.hpp>

#include <vector>

namespace tetmesh {

struct HullSimplifyOptions {
  int maxVertices = 24;       // K >= 4
  double tolerance = 1e-8;    // relative to the half-diagonal of all hulls: on a plane, touching
  double minEdge = 2e-3;      // relative to the half-diagonal: no region edge shorter
  double margin = 1e-3;       // relative to the half-diagonal: supporting planes pushed out by 1-2x this
};

struct SimplifiedHulls {
  std::vector<acd::TriMesh> regions;  // convex, closed, outward; one per hull
  std::vector<bool> reached;          // at most K corners
  int separatingPlanes = 0;           // distinct planes between pairs of regions
  int separatedPairs = 0;
  int overlappingHulls = 0;           // pairs of exact hulls that overlap (cut at a plane)
  int rounds = 0;                     // rebuild rounds until no regions overlapped
};

/// Each hull must be a closed convex triangle mesh with volume.
SimplifiedHulls simplifyHulls(const std::vector<acd::TriMesh>& hulls, const HullSimplifyOptions& options);

using acd::maxOutsideDistance;  // moved to libacd (acd/algo/convex_polytope.hpp)

}  // namespace tetmesh
