// Mesh diagnosis (what `acd info` prints) and the safe repairs done before decomposition.
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>
#include <vector>

namespace acd {

struct MeshDiagnosis {
  int vertices = 0;
  int faces = 0;
  int edges = 0;
  int boundaryEdges = 0;
  int nonManifoldEdges = 0;    // edges with more than two faces
  int nonManifoldVertices = 0; // vertices whose faces form several fans
  int components = 0;          // edge-connected
  int degenerateFaces = 0;     // repeated index or zero area
  int duplicateFaces = 0;      // same vertex set as an earlier face
  int duplicateVertices = 0;   // same position as an earlier vertex
  int unreferencedVertices = 0;
  int nonFiniteVertices = 0;
  int indexOutOfRange = 0;
  bool orientationConsistent = true;
  bool closed = false;         // no boundary and no non-manifold edges
  int genus = -1;              // from Euler's formula, per closed component summed; -1 when not defined
  double volume = 0.0;         // signed, in input units; meaningful when closed
  double area = 0.0;
  Box3 bbox;
  std::string firstProblem;    // one line naming the first offending element, empty when none
};

MeshDiagnosis diagnose(const TriMesh& mesh);

/// diagnose()'s nonManifoldVertices alone, for faces whose indices lie in [0, vertexCount): the
/// edge topology and the fans, without the sorts for duplicates (millions of faces).
int countNonManifoldVertices(const std::vector<Face>& faces, int vertexCount);

/// Pairs of faces that intersect other than along a shared edge or vertex (exact predicates;
/// CGAL's box-intersection filter, on one thread), a degenerate face counting as one; -1 when
/// the faces are no oriented edge-manifold surface or a coordinate is not finite. Stops counting
/// at `limit` (< 0: count all). The solid decomposition accepts such meshes, but where the
/// surface passes through itself a section can have crossing loops and a component may stay
/// unresolved; see docs/ERRORS.md.
int countSelfIntersections(const TriMesh& mesh, int limit = -1);

/// The faces of `among` that cross some other face of the mesh, by countSelfIntersections's rule
/// (a degenerate face crosses itself), sorted; all of `among` when the mesh is no oriented
/// edge-manifold surface or a coordinate is not finite. One box search of `among` against the
/// mesh: a patch of a few faces on a mesh of millions costs the sorting of the mesh's boxes, not
/// all its pairs.
std::vector<int> facesCrossingOthers(const TriMesh& mesh, const std::vector<int>& among);

/// What prepareSolid does with boundary edges.
enum class OpenMeshPolicy {
  FillHoles,  // close every hole (acd/algo/hole_filling.hpp); refuse when that cannot be done safely
  Refuse,     // refuse open meshes (OpenMesh)
  KeepOpen,   // keep the holes: pieces may be open surfaces, consistently oriented (surface ACD)
};

struct PrepareOptions {
  OpenMeshPolicy openMeshes = OpenMeshPolicy::Refuse;
  /// The caller knows the mesh is an oriented edge-manifold surface with one fan of faces around
  /// each vertex, no two vertices at one position and no vertex unused (MeshRepair::clean): a
  /// closed one then skips the checks and repairs that would give it back unchanged.
  bool knownClean = false;
};

/// Result of checking and repairing a mesh for solid decomposition.
struct PreparedSolid {
  Status status;                      // not ok: the mesh cannot be decomposed as a solid
  std::vector<TriMesh> components;    // closed, consistently outward-oriented pieces (open ones only with KeepOpen)
  std::vector<std::string> repairs;   // what was changed, one line each, for the report
  int holesFilled = 0;                // boundary loops closed by OpenMeshPolicy::FillHoles
};

/// Validates in a fixed order and applies only safe repairs: merge duplicate
/// vertices, drop faces with a repeated index and exact duplicate faces, orient
/// each piece consistently and outward, split into edge-connected components.
/// Refuses (status not ok) non-finite coordinates, bad indices, empty meshes,
/// non-manifold edges or vertices and zero-area faces it cannot drop safely. Open meshes are
/// closed by hole filling, refused, or kept open, as `options` says.
PreparedSolid prepareSolid(const TriMesh& mesh, const PrepareOptions& options = {});

/// Whether face `f` has too small an area for a usable normal: at most 1e-14 of
/// `squaredDiagonal`, the squared bounding-box diagonal of its mesh.
bool hasZeroArea(const std::vector<Vec3>& vertices, const Face& f, double squaredDiagonal);

/// The first face whose area is too small for a usable normal (at most 1e-14 of the squared
/// bounding-box diagonal), which prepareSolid refuses; -1 when there is none.
int firstZeroAreaFace(const TriMesh& mesh);

}  // namespace acd
