// Mass properties of a closed solid: volume, centre of mass and inertia tensor, exact for the
// polyhedron (divergence theorem over signed tetrahedra), for a uniform density. What a
// simulator's rigid body needs (URDF/SDF/MJCF <inertial>).
#pragma once

#include <acd/mesh.hpp>

#include <Eigen/Core>

#include <vector>

namespace acd {

struct MassProperties {
  double volume = 0.0;                                   // mesh units cubed
  double mass = 0.0;                                     // density * volume
  Vec3 centerOfMass = Vec3::Zero();                      // mesh units
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();     // about the centre of mass, axes of the mesh
  Vec3 principalMoments = Vec3::Zero();                  // eigenvalues of `inertia`, ascending
};

/// Closed, outward-oriented meshes (several: their union, which must not overlap). A mesh
/// turned inside out gives a negative volume; the caller checks.
MassProperties massProperties(const std::vector<TriMesh>& solids, double density = 1.0);
inline MassProperties massProperties(const TriMesh& solid, double density = 1.0) {
  return massProperties(std::vector<TriMesh>{solid}, density);
}

}  // namespace acd
