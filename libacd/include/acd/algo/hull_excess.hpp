// How far a mesh's convex hull sticks out of the mesh: the largest distance from a point of the
// hull's surface to the mesh's surface. It bounds how far the hull can stick out of the model, the
// quantity users measure, so a piece is final only when it is within tau.
#pragma once

#include <acd/mesh.hpp>

namespace acd {

struct HullExcess {
  double distance = 0.0;  // the largest distance found: a lower bound of the excess
  double bound = 0.0;     // an upper bound of the excess (at most distance + resolution unless stopped early)
  Vec3 hullPoint = Vec3::Zero();     // where on the hull `distance` was found
  Vec3 surfacePoint = Vec3::Zero();  // its nearest point on the mesh
  int hullFace = -1;                 // the hull face holding hullPoint
  bool exceeds = false;              // distance > limit (the search stops there)
};

/// Branch and bound over the hull's faces: each face is split in four while the distance at its
/// centroid plus its radius (distance is 1-Lipschitz) could still exceed `limit` and the face is
/// wider than `resolution`. Stops at the first point farther than `limit`.
HullExcess measureHullExcess(const TriMesh& mesh, const TriMesh& hull, double limit, double resolution);

}  // namespace acd
