// Vertices closer than a tolerance, grouped by grid hashing.
#include <acd/algo/close_vertices.hpp>
#include <acd/algo/union_find.hpp>
#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace acd {

// Grid hashing: only the 27 cells around a vertex can hold its neighbours.
std::vector<int> closeVertexRoots(const std::vector<Vec3>& vertices, const Box3& box, double tolerance) {
  const int n = static_cast<int>(vertices.size());
  UnionFind sets(n);
  if (tolerance > 0.0) {
    // Cells no smaller than 2^-20 of the diagonal, so that a cell index fits the key's 21 bits
    // (a smaller tolerance only means more vertices per cell to compare).
    const double cell = std::max(tolerance, box.size().norm() * 0x1p-20);
    auto cellOf = [&](const Vec3& p) { return Eigen::Array3i(((p - box.lo) / cell).array().floor().cast<int>()); };
    auto key = [](const Eigen::Array3i& c) {
      return (static_cast<std::uint64_t>(c.x() + 1) << 42) | (static_cast<std::uint64_t>(c.y() + 1) << 21) |
             static_cast<std::uint64_t>(c.z() + 1);
    };
    std::unordered_map<std::uint64_t, std::vector<int>> grid;
    grid.reserve(vertices.size());
    const double tolerance2 = tolerance * tolerance;
    for (int v = 0; v < n; ++v) {
      const Eigen::Array3i c = cellOf(vertices[v]);
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const auto it = grid.find(key(c + Eigen::Array3i(dx, dy, dz)));
            if (it == grid.end()) continue;
            for (int u : it->second)
              if ((vertices[u] - vertices[v]).squaredNorm() <= tolerance2) sets.joinKeepingSmallest(u, v);
          }
      grid[key(c)].push_back(v);
    }
  }
  std::vector<int> rep(n);
  for (int v = 0; v < n; ++v) rep[v] = sets.find(v);
  return rep;
}

}  // namespace acd
