// Gluing components back together along the cut faces they share: the merge pass that
// undoes cuts the greedy recursion did not need.
#pragma once

#include <acd/mesh.hpp>

#include <vector>

namespace acd {

/// What a merge may add outside the model and the hulls it replaces, as a share of the union's
/// volume (MergeScope::Model; measured on compare_peers' models, docs/ALGORITHM.md section 11).
constexpr double kModelMergeGrowth = 0.25;
/// Points per union for that volume: its standard error is below 0.5 % of the hull's volume.
constexpr int kModelMergeSamples = 4096;

/// Glues two closed, outward meshes along the triangles they share (same corner positions,
/// opposite orientations), which both drop. Corners at the same position become one vertex.
/// Returns false, leaving `out` unspecified, when they share no triangle, the result is not a
/// closed, consistently oriented mesh, or gluing joined no two shells into one.
bool glueAlongSharedFaces(const TriMesh& a, const TriMesh& b, TriMesh& out);

/// The two closed, outward meshes as one: glued where that makes one solid, else side by side as
/// separate shells (pieces that touch without sharing their whole contact, or apart).
TriMesh joinPieces(const TriMesh& a, const TriMesh& b);

/// Pairs (i, j), i < j, of meshes that share at least one triangle, with the shared area,
/// sorted by decreasing shared area (ties by index).
struct SharedFaces {
  int a = -1, b = -1;
  double area = 0.0;
};
std::vector<SharedFaces> sharedFacePairs(const std::vector<const TriMesh*>& meshes);
std::vector<SharedFaces> sharedFacePairs(const std::vector<TriMesh>& meshes);

/// Pairs (i, j), i < j, of meshes that share at least one corner position (touching, whether or not
/// they share a whole triangle), sorted by (i, j), with no area.
std::vector<SharedFaces> touchingPairs(const std::vector<const TriMesh*>& meshes);
std::vector<SharedFaces> touchingPairs(const std::vector<TriMesh>& meshes);

}  // namespace acd
