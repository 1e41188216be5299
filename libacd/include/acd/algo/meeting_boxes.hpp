// Every pair of boxes that meet, each once: a uniform grid for the many boxes of a mesh's faces,
// most of them about one size, where a search over all pairs or a general tree does more work.
#pragma once

#include <acd/algo/float_bounds.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace acd {

/// Whether two closed boxes meet (touching counts).
inline bool boxesMeet(const FloatBox& a, const FloatBox& b) {
  for (int k = 0; k < 3; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

/// Calls visit(i, j), i < j, once for each pair of `boxes` that meet, in an order fixed by the
/// boxes alone. The grid has about one cell per box over their common box; a pair is visited in
/// the one cell that holds the low corner of the two boxes' common part (both boxes are listed
/// there). Returns false, having visited nothing, when the boxes are too unlike in size for a
/// grid (their cell listings would exceed eight per box): the caller then searches otherwise.
template <class Visit>
bool forEachMeetingPair(const std::vector<FloatBox>& boxes, const Visit& visit) {
  const std::size_t n = boxes.size();
  if (n < 2) return true;
  std::array<double, 3> lo, size;
  double largest = 0.0;
  for (int k = 0; k < 3; ++k) {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (const FloatBox& b : boxes) low = std::min<double>(low, b.lo[k]), high = std::max<double>(high, b.hi[k]);
    lo[k] = low;
    size[k] = high - low;
    largest = std::max(largest, size[k]);
  }
  if (!std::isfinite(largest)) return false;
  // A flat or empty extent would make the cells vanishingly thin: each side at least a
  // billionth of the longest.
  double volume = 1.0;
  for (int k = 0; k < 3; ++k) volume *= std::max(size[k], 1e-9 * largest);
  double cell = largest > 0 ? std::cbrt(volume / static_cast<double>(n)) : 1.0;
  std::array<int, 3> dims{};
  const double mostCells = 2.0 * static_cast<double>(n) + 4096.0;
  auto cellsAlong = [&](int k) { return std::floor(size[k] / cell) + 1.0; };
  while (cellsAlong(0) * cellsAlong(1) * cellsAlong(2) > mostCells) cell *= 1.25;
  for (int k = 0; k < 3; ++k) dims[k] = static_cast<int>(cellsAlong(k));
  auto cellOf = [&](double x, int k) {
    return static_cast<int>(std::clamp((x - lo[k]) / cell, 0.0, static_cast<double>(dims[k] - 1)));
  };
  auto index = [&](int i, int j, int k) { return (static_cast<std::size_t>(i) * dims[1] + j) * dims[2] + k; };

  // Count each cell's listings, give up if they are too many, then list the boxes cell by cell
  // (in box order within a cell).
  std::vector<std::uint32_t> start(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2] + 1, 0);
  std::size_t listings = 0;
  auto forEachCellOf = [&](const FloatBox& b, const auto& each) {
    const std::array<int, 3> from{cellOf(b.lo[0], 0), cellOf(b.lo[1], 1), cellOf(b.lo[2], 2)};
    const std::array<int, 3> to{cellOf(b.hi[0], 0), cellOf(b.hi[1], 1), cellOf(b.hi[2], 2)};
    for (int i = from[0]; i <= to[0]; ++i)
      for (int j = from[1]; j <= to[1]; ++j)
        for (int k = from[2]; k <= to[2]; ++k) each(index(i, j, k));
  };
  for (const FloatBox& b : boxes) {
    std::size_t cells = 1;
    for (int k = 0; k < 3; ++k) cells *= static_cast<std::size_t>(cellOf(b.hi[k], k) - cellOf(b.lo[k], k) + 1);
    listings += cells;
    if (listings > 8 * n + 4096) return false;
  }
  for (const FloatBox& b : boxes) forEachCellOf(b, [&](std::size_t c) { ++start[c + 1]; });
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<std::uint32_t> listed(listings);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t b = 0; b < n; ++b)
      forEachCellOf(boxes[b], [&](std::size_t c) { listed[fill[c]++] = static_cast<std::uint32_t>(b); });
  }
  // Cell by cell, its boxes copied side by side in order of their low x (then number) and swept
  // along x: a box meets only those that start before it ends.
  struct Entry {
    FloatBox box;
    std::array<int, 3> from;  // the cell of the box's low corner
    std::uint32_t number;
  };
  std::vector<Entry> cellBoxes;
  for (int i = 0; i < dims[0]; ++i)
    for (int j = 0; j < dims[1]; ++j)
      for (int k = 0; k < dims[2]; ++k) {
        const std::size_t c = index(i, j, k);
        if (start[c + 1] - start[c] < 2) continue;
        cellBoxes.clear();
        for (std::uint32_t x = start[c]; x < start[c + 1]; ++x) {
          const FloatBox& b = boxes[listed[x]];
          cellBoxes.push_back({b, {cellOf(b.lo[0], 0), cellOf(b.lo[1], 1), cellOf(b.lo[2], 2)}, listed[x]});
        }
        std::sort(cellBoxes.begin(), cellBoxes.end(), [](const Entry& a, const Entry& b) {
          return a.box.lo[0] != b.box.lo[0] ? a.box.lo[0] < b.box.lo[0] : a.number < b.number;
        });
        for (std::size_t x = 0; x < cellBoxes.size(); ++x) {
          const Entry& a = cellBoxes[x];
          for (std::size_t y = x + 1; y < cellBoxes.size() && cellBoxes[y].box.lo[0] <= a.box.hi[0]; ++y) {
            const Entry& b = cellBoxes[y];
            if (!boxesMeet(a.box, b.box)) continue;
            // Visited here only if the common part's low corner lies in this cell (cells grow
            // with the coordinate, so its cell is the larger of the two low corners' cells).
            if (std::max(a.from[0], b.from[0]) != i || std::max(a.from[1], b.from[1]) != j ||
                std::max(a.from[2], b.from[2]) != k)
              continue;
            visit(static_cast<int>(std::min(a.number, b.number)), static_cast<int>(std::max(a.number, b.number)));
          }
        }
      }
  return true;
}

}  // namespace acd
