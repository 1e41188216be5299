// Checks shared by tetmesh's tests: conformity of a labelled tet mesh.
#pragma once

#include "tet_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <array>
#include <map>
#include <vector>

namespace tmtest {

using tetmesh::TetMesh;
using tetmesh::Vec3;

/// Faces of the tets, each with the tets (up to 2 in a conforming mesh) that have it.
inline std::map<std::array<int, 3>, std::vector<int>> tetFaces(const TetMesh& m) {
  std::map<std::array<int, 3>, std::vector<int>> faces;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) {
    const auto& v = m.tets[t];
    for (int k = 0; k < 4; ++k) {
      std::array<int, 3> f{v[(k + 1) % 4], v[(k + 2) % 4], v[(k + 3) % 4]};
      std::sort(f.begin(), f.end());
      faces[f].push_back(t);
    }
  }
  return faces;
}

inline double triangleArea(const TetMesh& m, const std::array<int, 3>& f) {
  return 0.5 * (m.points[f[1]] - m.points[f[0]]).cross(m.points[f[2]] - m.points[f[0]]).norm();
}

}  // namespace tmtest

namespace tmtest {

/// The smallest dihedral angle of a tet in degrees, computed here by projecting the two other
/// corners onto the plane across each edge (mesh_quality.cpp uses face normals).
inline double smallestDihedralDegrees(const TetMesh& m, int t) {
  const auto& v = m.tets[t];
  double smallest = 180.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      int others[2], k = 0;
      for (int l = 0; l < 4; ++l)
        if (l != i && l != j) others[k++] = l;
      const Vec3& a = m.points[v[i]];
      const Vec3 e = (m.points[v[j]] - a).normalized();
      Vec3 u = m.points[v[others[0]]] - a, w = m.points[v[others[1]]] - a;
      u -= e * u.dot(e);
      w -= e * w.dot(e);
      const double c = std::clamp(u.dot(w) / (u.norm() * w.norm()), -1.0, 1.0);
      smallest = std::min(smallest, std::acos(c) * 180.0 / 3.14159265358979323846);
    }
  return smallest;
}

}  // namespace tmtest
