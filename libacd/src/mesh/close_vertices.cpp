// Vertices closer than a tolerance, grouped by a grid of sorted cell keys.
#include <acd/algo/close_vertices.hpp>
#include <acd/algo/union_find.hpp>
#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

namespace acd {

// Cells a few tolerances wide: a vertex farther than the tolerance from its cell's walls has every
// vertex close to it in its own cell (the usual case), so only the cells across near walls are
// looked up. The cells are runs of one key in a sorted array: no allocation per cell.
std::vector<int> closeVertexRoots(const std::vector<Vec3>& vertices, const Box3& box, double tolerance) {
  const int n = static_cast<int>(vertices.size());
  UnionFind sets(n);
  if (tolerance > 0.0) {
    // Cells no smaller than 2^-20 of the diagonal, so that a cell index fits the key's 21 bits.
    const double cell = std::max(4 * tolerance, box.size().norm() * 0x1p-20);
    const double slack = 1e-6 * cell;  // the rounding of a cell index, and more
    auto cellOf = [&](const Vec3& p) { return Eigen::Array3i(((p - box.lo) / cell).array().floor().cast<int>()); };
    auto key = [](const Eigen::Array3i& c) {
      return (static_cast<std::uint64_t>(c.x() + 1) << 42) | (static_cast<std::uint64_t>(c.y() + 1) << 21) |
             static_cast<std::uint64_t>(c.z() + 1);
    };
    std::vector<std::pair<std::uint64_t, int>> byCell(n);
    for (int v = 0; v < n; ++v) byCell[v] = {key(cellOf(vertices[v])), v};
    std::sort(byCell.begin(), byCell.end());
    const double tolerance2 = tolerance * tolerance;
    auto joinWithin = [&](int v, std::size_t from, std::size_t to) {
      for (std::size_t i = from; i < to; ++i) {
        const int u = byCell[i].second;
        if (u != v && (vertices[u] - vertices[v]).squaredNorm() <= tolerance2) sets.joinKeepingSmallest(u, v);
      }
    };
    for (std::size_t i = 0; i < byCell.size();) {
      std::size_t j = i;
      while (j < byCell.size() && byCell[j].first == byCell[i].first) ++j;
      for (std::size_t k = i; k < j; ++k) {
        const int v = byCell[k].second;
        const Vec3& p = vertices[v];
        const Eigen::Array3i c = cellOf(p);
        joinWithin(v, k + 1, j);  // its own cell: each pair once
        // Per axis, the neighbour across a wall nearer than the tolerance (0: none).
        std::array<int, 3> across{};
        for (int a = 0; a < 3; ++a) {
          const double fromLow = p[a] - (box.lo[a] + c[a] * cell);
          across[a] = fromLow <= tolerance + slack ? -1 : cell - fromLow <= tolerance + slack ? 1 : 0;
        }
        for (int dx = std::min(0, across[0]); dx <= std::max(0, across[0]); ++dx)
          for (int dy = std::min(0, across[1]); dy <= std::max(0, across[1]); ++dy)
            for (int dz = std::min(0, across[2]); dz <= std::max(0, across[2]); ++dz) {
              if (dx == 0 && dy == 0 && dz == 0) continue;
              const std::uint64_t other = key(c + Eigen::Array3i(dx, dy, dz));
              const auto lo = std::lower_bound(byCell.begin(), byCell.end(), std::make_pair(other, -1));
              auto hi = lo;
              while (hi != byCell.end() && hi->first == other) ++hi;
              joinWithin(v, lo - byCell.begin(), hi - byCell.begin());
            }
      }
      i = j;
    }
  }
  std::vector<int> rep(n);
  for (int v = 0; v < n; ++v) rep[v] = sets.find(v);
  return rep;
}

}  // namespace acd
