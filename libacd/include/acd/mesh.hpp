// Indexed triangle mesh: the one geometry type that crosses libacd's API.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <vector>

namespace acd {

using Vec3 = Eigen::Vector3d;
using Face = std::array<int, 3>;

/// A triangle soup with shared vertices. Faces are counter-clockwise seen from
/// outside (outward normals) when the mesh bounds a solid.
struct TriMesh {
  std::vector<Vec3> vertices;
  std::vector<Face> faces;

  bool empty() const { return faces.empty(); }
};

/// Axis-aligned bounding box.
struct Box3 {
  Vec3 lo = Vec3::Constant(0.0);
  Vec3 hi = Vec3::Constant(0.0);
  Vec3 size() const { return hi - lo; }
  Vec3 center() const { return 0.5 * (lo + hi); }
};

Box3 boundingBox(const TriMesh& mesh);

/// Signed volume (divergence theorem); positive for outward-oriented closed meshes.
double signedVolume(const TriMesh& mesh);

double surfaceArea(const TriMesh& mesh);

/// Unnormalised face normal (cross product of two edges; length = 2 * area).
Vec3 faceNormal(const TriMesh& mesh, int face);

/// Undirected edge key for hash maps: (min << 32) | max.
inline std::uint64_t edgeKey(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint64_t>(a < b ? b : a);
  return (lo << 32) | hi;
}

/// Each face side (3 * face + k, from corner k to k + 1) by the undirected edge it lies on, the
/// edges numbered in edgeKey order; -1 for a side whose ends are one vertex. Bucketed by vertex
/// rather than hashed: millions of edges, no allocation per edge.
struct SideEdges {
  std::vector<int> edgeOfSide;
  int edges = 0;
};
SideEdges numberEdges(const std::vector<Face>& faces);

/// Splits a mesh into edge-connected pieces, each with compacted vertices.
std::vector<TriMesh> splitEdgeConnected(const TriMesh& mesh);

/// The meshes one after the other in one mesh (vertex indices shifted; nothing merged).
TriMesh concatenate(const std::vector<TriMesh>& meshes);

/// Drops vertices no face uses and renumbers the rest (order kept).
TriMesh compact(const TriMesh& mesh);

/// The faces with the vertices they use, renumbered in the order of their original indices (so
/// that output is stable), without copying `vertices`. `remap` is all -1 on entry and on return,
/// sized for `vertices`.
TriMesh compactFaces(const std::vector<Vec3>& vertices, const std::vector<Face>& faces, std::vector<int>& remap);

/// True when every edge has exactly two faces that use it in opposite directions.
bool isClosedOriented(const TriMesh& mesh);

/// True when every edge has one face, or two that use it in opposite directions, and no face
/// repeats a vertex: an oriented surface, closed or not (vertices where fans meet allowed).
bool isOrientedEdgeManifold(const std::vector<Face>& faces);

/// For an oriented edge-manifold surface, the number of vertices whose faces form more than one
/// fan (a pinch: parts that meet at a point), as diagnose() counts them; -1 when the surface is
/// not oriented edge-manifold. One pass of sides by vertex, with no edge numbering.
int pinchedVertices(const std::vector<Face>& faces);

/// For each vertex, the first vertex with exactly the same position, or itself (+0 and -0 are
/// equal; a non-finite position equals nothing).
std::vector<int> firstAtSamePosition(const std::vector<Vec3>& vertices);

}  // namespace acd
