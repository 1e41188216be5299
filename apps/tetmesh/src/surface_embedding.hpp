// Embedding a surface in a tetrahedral mesh: each surface vertex is written as barycentric
// coordinates in one tet, so any per-vertex field of the tet mesh (deformed positions above
// all) can be carried over to the surface by interpolation.
//
// Points are located through a uniform grid over the tets' bounding boxes. A point that lies
// in no tet (a model vertex can sit a rounding distance outside the union of the hull
// regions; a coarse mesh cuts the hulls' curves by up to tau) is written in the closest tet, with
// its own barycentric coordinates there (some negative): the tet's affine map carries it, so it
// stays put at rest and moves rigidly with a rigid tet; how many and how far is reported.
#pragma once

#include "tet_mesh.hpp"

#include <array>
#include <vector>

namespace tetmesh {

struct SurfaceEmbedding {
  std::vector<int> tet;                       // per point: the tet it is written in
  std::vector<std::array<double, 4>> weights; // per point: barycentric coordinates, sum 1
  int outside = 0;                  // points in no tet, written in the closest tet (weights outside [0, 1])
  double maxOutsideDistance = 0.0;  // farthest of those from the mesh, input units
  double seconds = 0.0;             // wall time of grid and location
};

/// Tolerance on barycentric coordinates (dimensionless) below which a point still counts as
/// inside a tet: points on shared faces and edges give coordinates of -1e-16 or so.
inline constexpr double kInsideTolerance = 1e-10;

/// Locates every point in the mesh. The mesh must have at least one tet of positive volume.
SurfaceEmbedding embedPoints(const TetMesh& mesh, const std::vector<Vec3>& points);

/// The barycentric coordinates of p in tet (a, b, c, d), from signed volumes relative to a.
std::array<double, 4> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Closest point to p in the solid tet (a, b, c, d) (p itself when inside).
Vec3 closestPointInTet(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Field value at each embedded point: sum of the weights times the field at the tet's corners.
/// `field` has one value per mesh point (e.g. deformed positions).
std::vector<Vec3> interpolate(const SurfaceEmbedding& embedding, const TetMesh& mesh, const std::vector<Vec3>& field);

}  // namespace tetmesh
