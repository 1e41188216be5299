// Checks shared by tetmesh's tests: conformity of a labelled tet mesh.
#pragma once

#include "tet_mesh.hpp"

#include <algorithm>
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
