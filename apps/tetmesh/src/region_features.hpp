// The sharp edges of the hull regions that the refinement keeps exactly (CGAL protects them with
// balls before it refines): a box stays a box, and a flat face is not refined towards its rim.
//
// Only clean features are kept, since a feature is a promise to resolve it: an edge of a region
// counts when its two faces turn by more than `minTurnDegrees` and it does not lie inside
// another region; edges of neighbours that coincide (the two sides of a cut section) are one;
// an edge that passes through another feature's corner is split there, two edges that cross are
// split at the crossing; and features that come closer than `clearance` without meeting (a
// corner a hair from another region's edge, two rims nearly overlapping) are dropped, smaller
// first: the refinement would need balls smaller than that gap there, and tets of that size
// are exactly the slivers this mesher avoids. A dropped feature is rounded within the facet
// distance like any other.
#pragma once

#include <acd/mesh.hpp>

#include <array>
#include <vector>

namespace tetmesh {

using acd::Vec3;

struct RegionFeatures {
  std::vector<std::array<Vec3, 2>> segments;  // meeting only at their ends
  int candidates = 0;                         // sharp edges before merging and dropping
  int dropped = 0;                            // segments dropped for coming too close to others
};

class RegionLabels;

/// The segments chained into polylines through points where exactly two of them meet (closed
/// loops end where they start), as CGAL's feature protection takes them.
std::vector<std::vector<Vec3>> chainSegments(const std::vector<std::array<Vec3, 2>>& segments);

RegionFeatures regionFeatures(const std::vector<acd::TriMesh>& regions, const RegionLabels& labels,
                              double minTurnDegrees, double clearance);

}  // namespace tetmesh
