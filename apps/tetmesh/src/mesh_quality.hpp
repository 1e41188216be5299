// Size and quality figures of a tetrahedral mesh: what TetGen's `-V` reports, as numbers.
#pragma once

#include "tet_mesh.hpp"

#include <array>
#include <vector>

namespace tetmesh {

/// Upper ends of the radius-edge ratio bins (the last bin is open). A regular tet has sqrt(6)/4.
/// A tet with a dihedral angle below this is counted as a sliver (the bound docs/TETMESH.md states).
constexpr double kSliverDegrees = 5.0;

inline const std::array<double, 6> kRadiusEdgeBins = {1.0, 1.5, 2.0, 3.0, 5.0, 10.0};

struct MeshQuality {
  int tets = 0;
  int points = 0;                     // vertices used by tets
  double volume = 0.0;                // sum of tet volumes
  double minTetVolume = 0.0;
  int nonPositiveTets = 0;            // tets with volume <= 0 (must be none)
  double minDihedral = 0.0, maxDihedral = 0.0;  // degrees
  int slivers = 0;                    // tets with a dihedral angle below kSliverDegrees
  double minRadiusEdge = 0.0, medianRadiusEdge = 0.0, maxRadiusEdge = 0.0;
  std::array<int, kRadiusEdgeBins.size() + 1> radiusEdgeHistogram{};  // counts per bin
};

MeshQuality measureQuality(const TetMesh& mesh);

/// The six dihedral angles of a tet, in degrees.
std::array<double, 6> dihedralAngles(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Circumradius over shortest edge.
double radiusEdgeRatio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace tetmesh
