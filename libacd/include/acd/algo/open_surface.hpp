// Open surfaces in the concavity measure (Lien & Amato 2007, Section 4.1, Extension 2).
//
// Where a surface with openings shows its inner side to its convex hull, some hull
// vertices are concave: their outward normal on the hull and on the surface point in
// opposite directions. A bridge edge then projects onto the surface by three rules:
// both ends convex, as on a closed surface (shortest path); both ends concave, no
// projection; one of each, the shortest path from the convex end to the opening.
#pragma once

#include <acd/algo/bridge.hpp>
#include <acd/algo/surface_graph.hpp>
#include <acd/algo/hull.hpp>
#include <acd/mesh.hpp>

#include <vector>

namespace acd {

/// Vertex normals weighted by corner angle (unit; zero for a vertex without area).
std::vector<Vec3> vertexNormals(const TriMesh& mesh);

/// Vertices on a boundary edge (an edge with a face on one side only).
std::vector<char> boundaryVertices(const SurfaceGraph& graph);

/// Per hull vertex: 1 when its outward normal on the hull (mean of its facets' normals,
/// weighted by corner angle) and its normal on the surface point in opposite directions.
std::vector<char> concaveHullVertices(const TriMesh& mesh, const ConvexHull& hull);

/// Turns every face of an open surface when most of its hull vertices are concave: the
/// surface then faces into its hull, and the measure expects it to face out. Closed
/// meshes are left alone. Returns true when it turned the faces.
bool orientTowardHull(TriMesh& mesh);

/// Extension 2's projection of bridge edges on an open surface. Inactive (closed surface,
/// or no concave hull vertex and no opening) means: every edge projects as a shortest path.
class OpenSurfaceProjection {
 public:
  OpenSurfaceProjection(const TriMesh& mesh, const SurfaceGraph& graph, const ConvexHull& hull);

  bool open() const { return open_; }

  /// Path for the hull edge between hull vertices u and v, running from u's side to v's side;
  /// empty when the edge has no projection (both ends concave, or the opening is unreachable).
  std::vector<int> project(PathFinder& finder, int u, int v) const;

  /// The bridge a region bounded only by the opening belongs to: the one whose supporting plane
  /// it lies closest to (for a point inside a convex hull, the distance to the hull boundary
  /// is its least distance to a facet plane).
  static int nearestBridge(const TriMesh& mesh, const std::vector<int>& faces, const std::vector<Bridge>& bridges);

  int concaveVertices() const;

 private:
  const TriMesh& mesh_;
  const SurfaceGraph& graph_;
  const ConvexHull& hull_;
  bool open_ = false;
  std::vector<char> concave_;  // per hull vertex
  std::vector<double> toOpening_;
  std::vector<int> towardOpening_;  // next vertex on a shortest path to the opening
};

}  // namespace acd
