// Convex hulls with at most K vertices that still contain the original hull.
//
// Greedy edge collapse after Sander et al., "Silhouette clipping" (progressive hulls): an edge
// ab of the current hull is replaced by one point p that lies on or outside every face plane
// around a and b, chosen among the corners of that region to add the least volume (the sum
// of face area times the distance p moves beyond the face). The collapse is kept only if the
// new hull contains every vertex of the current one (checked against each new face plane),
// so by induction the result contains the input hull and hence the component.
#pragma once

#include <acd/mesh.hpp>

namespace tetmesh {

struct SimplifiedHull {
  acd::TriMesh mesh;     // convex, outward; the input hull when nothing could be collapsed
  bool reached = false;  // at most `maxVertices` vertices
  int collapses = 0;
};

/// `maxVertices` >= 4. The hull must be a closed convex triangle mesh.
SimplifiedHull simplifyHull(const acd::TriMesh& hull, int maxVertices);

/// Largest distance by which any point lies outside a face plane of the convex mesh (0 if inside all).
double maxOutsideDistance(const acd::TriMesh& convex, const std::vector<acd::Vec3>& points);

}  // namespace tetmesh
