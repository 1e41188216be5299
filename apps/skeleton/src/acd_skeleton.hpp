// Skeleton of an approximate convex decomposition (Lien & Amato 2007, Section 7, Figure 21):
// a node per component at its centroid, a node per cut at the cut's centre, and an edge from
// each cut to the two components it separates.
#pragma once

#include "graph.hpp"

#include <acd/mesh.hpp>

#include <vector>

namespace skeleton {

/// One connected patch where two components touch face to face: the cap a plane cut left on
/// both sides.
struct Cut {
  int a = -1, b = -1;          // the two components, a < b
  Vec3 centre = Vec3::Zero();  // area-weighted centroid of the patch
  Vec3 normal = Vec3::Zero();  // its area-weighted unit normal, out of component a
  double area = 0.0;
  int triangles = 0;           // of a's triangles in it
};

/// Cuts between closed components: where a face of one lies on a face of the other, turned
/// against it (within kCutTolerance). Measured on the first component's triangles, a triangle
/// split in four down to 4 levels where only part of it lies on the other (caps do not share their
/// triangles where a later cut split one side only: three pieces meeting along a line). Two
/// components that touch in several separate patches (a ring cut in two, say) get one cut per
/// patch; patches are split where they share no corner. Sorted by (a, b), then by decreasing area.
std::vector<Cut> findCuts(const std::vector<acd::TriMesh>& components);

/// Points this close to a face, in units of the components' bounding-box diagonal, lie on it:
/// cut points are rounded to the invariant frame's grid (2.4e-7 of the radius).
constexpr double kCutTolerance = 1e-6;

/// Centroid of the solid bounded by a closed, outward mesh (the vertex mean when its
/// volume is zero).
Vec3 solidCentroid(const acd::TriMesh& mesh);

/// Component nodes 0..n-1 (in component order), then one Cut node per cut, each joined to
/// the two components it separates.
Graph skeletonFromComponents(const std::vector<acd::TriMesh>& components);

}  // namespace skeleton
