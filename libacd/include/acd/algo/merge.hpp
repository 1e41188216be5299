// Gluing components back together along the cut faces they share: the merge pass that
// undoes cuts the greedy recursion did not need.
#pragma once

#include <acd/mesh.hpp>

#include <vector>

namespace acd {

/// Glues two closed, outward meshes along the triangles they share (same corner positions,
/// opposite orientations), which both drop. Corners at the same position become one vertex.
/// Returns false, leaving `out` unspecified, when they share no triangle, the result is not a
/// closed, consistently oriented mesh, or gluing joined no two shells into one.
bool glueAlongSharedFaces(const TriMesh& a, const TriMesh& b, TriMesh& out);

/// Pairs (i, j), i < j, of meshes that share at least one triangle, with the shared area,
/// sorted by decreasing shared area (ties by index).
struct SharedFaces {
  int a = -1, b = -1;
  double area = 0.0;
};
std::vector<SharedFaces> sharedFacePairs(const std::vector<TriMesh>& meshes);

/// Pairs (i, j), i < j, of meshes whose bounding boxes lie within `reach` of each other (touching
/// or not), sorted by (i, j): the pieces the merge pass held to the model may join under one hull.
std::vector<SharedFaces> nearbyPairs(const std::vector<TriMesh>& meshes, double reach);

}  // namespace acd
