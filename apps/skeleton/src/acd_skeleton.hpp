// Skeleton of an approximate convex decomposition (Lien & Amato 2007, Section 7, Figure 21):
// a node per component at its centroid, a node per cut at the cut's centre, and an edge from
// each cut to the two components it separates.
#pragma once

#include "graph.hpp"

#include <acd/mesh.hpp>

#include <vector>

namespace skeleton {

/// One connected patch of triangles shared by two components (same corner positions,
/// opposite orientations): the cap a plane cut left on both sides.
struct Cut {
  int a = -1, b = -1;          // the two components, a < b
  Vec3 centre = Vec3::Zero();  // area-weighted centroid of the shared triangles
  Vec3 normal = Vec3::Zero();  // their area-weighted unit normal, out of component a
  double area = 0.0;
  int triangles = 0;
};

/// Cuts between closed components. Two components that share several separate patches (a
/// ring cut in two, say) get one cut per patch; patches are split where they share no corner.
/// Sorted by (a, b), then by decreasing area.
std::vector<Cut> findCuts(const std::vector<acd::TriMesh>& components);

/// Centroid of the solid bounded by a closed, outward mesh (the vertex mean when its
/// volume is zero).
Vec3 solidCentroid(const acd::TriMesh& mesh);

/// Component nodes 0..n-1 (in component order), then one Cut node per cut, each joined to
/// the two components it separates.
Graph skeletonFromComponents(const std::vector<acd::TriMesh>& components);

}  // namespace skeleton
