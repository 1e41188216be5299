// Moving the corners of the last slivers; see sliver_repair.hpp.
#include "sliver_repair.hpp"

#include "mesh_quality.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace tetmesh {

namespace {

double smallestDihedral(const TetMesh& m, int t) {
  const auto& v = m.tets[t];
  const auto angles = dihedralAngles(m.points[v[0]], m.points[v[1]], m.points[v[2]], m.points[v[3]]);
  return *std::min_element(angles.begin(), angles.end());
}

/// The smallest dihedral angle over the tets around a vertex; -1 if one of them is not positive.
double starQuality(const TetMesh& m, const std::vector<int>& star) {
  double worst = 180.0;
  for (int t : star) {
    if (!(tetVolume(m, t) > 0)) return -1.0;
    worst = std::min(worst, smallestDihedral(m, t));
  }
  return worst;
}

/// The 26 directions to a cube's faces, edges and corners, unit length.
std::vector<Vec3> trialDirections() {
  std::vector<Vec3> d;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) d.push_back(Vec3(x, y, z).normalized());
  return d;
}

}  // namespace

SliverRepair repairSlivers(TetMesh& mesh, double boundDegrees, double maxMove) {
  SliverRepair r;
  const int n = static_cast<int>(mesh.tets.size());
  std::vector<std::vector<int>> stars(mesh.points.size());
  for (int t = 0; t < n; ++t)
    for (int v : mesh.tets[t]) stars[v].push_back(t);
  std::vector<int> slivers;
  for (int t = 0; t < n; ++t)
    if (smallestDihedral(mesh, t) < boundDegrees) slivers.push_back(t);
  r.before = static_cast<int>(slivers.size());
  const std::vector<Vec3> directions = trialDirections();
  const std::vector<Vec3> original = mesh.points;
  for (int pass = 0; pass < 4; ++pass) {
    bool moved = false;
    for (int t : slivers) {
      if (smallestDihedral(mesh, t) >= boundDegrees) continue;
      double shortest = std::numeric_limits<double>::infinity();
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          shortest = std::min(shortest, (mesh.points[mesh.tets[t][i]] - mesh.points[mesh.tets[t][j]]).norm());
      for (int v : mesh.tets[t]) {
        const Vec3 start = mesh.points[v];
        double best = starQuality(mesh, stars[v]);
        Vec3 bestAt = start;
        for (double step : {0.5, 0.25, 0.125, 0.0625})
          for (const Vec3& d : directions) {
            const Vec3 at = start + step * shortest * d;
            if ((at - original[v]).norm() > maxMove) continue;
            mesh.points[v] = at;
            const double q = starQuality(mesh, stars[v]);
            if (q > best) best = q, bestAt = at;
          }
        mesh.points[v] = bestAt;
        if (bestAt != start) ++r.moves, moved = true;
        if (smallestDihedral(mesh, t) >= boundDegrees) break;
      }
    }
    if (!moved) break;
  }
  for (int t = 0; t < n; ++t) r.after += smallestDihedral(mesh, t) < boundDegrees ? 1 : 0;
  return r;
}

}  // namespace tetmesh
