// A union of convex polyhedra (hulls) as half-spaces, with a cell grid for point location whose
// boundary cells keep only the planes that cross them: the one home of "is this point in the
// union of the hulls" (acd evaluate's volume and surface samples, pointloc's queries).
#pragma once

#include <acd/algo/convex_polytope.hpp>
#include <acd/mesh.hpp>

#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace acd {

/// The union of convex polyhedra (the ACD hulls, or the pieces of an exact decomposition).
///
/// Index: a uniform grid over a box. Each cell is classified once: outside every polyhedron,
/// inside one of them as a whole, or a boundary cell that keeps, per polyhedron that may hold
/// part of it, only the planes crossing the cell (a plane whose half-space holds the whole cell
/// cannot reject a point in it). A query then costs one cell look-up, and for the few boundary
/// points a handful of plane tests, instead of scanning polyhedra and all their facets.
/// Every answer equals that of `insideDirect`, which tests every plane (the grid is exact: cells
/// are classified with an inflated box that covers the rounding of the cell index).
class HullSet {
 public:
  /// `slack`: a point is inside a half-space when n.p <= d + slack.
  explicit HullSet(double slack) : slack_(slack) {}

  /// Adds one closed convex triangle mesh; returns false (and adds nothing) if it has no
  /// non-degenerate face. Its first six planes are its bounding box; facet planes use the
  /// support value over all its vertices, so a rounded sliver facet can never cut it.
  bool add(const TriMesh& convex);

  /// Adds one convex polyhedron given by its box and its facets' half-spaces (unit normals,
  /// supporting offsets), tested in that order as `add` does.
  void add(const Box3& box, const std::vector<HalfSpace>& facets);

  /// Builds the grid over `box` with about `targetCells` cells, in parallel in `arena`.
  void buildIndex(const Box3& box, std::size_t targetCells, tbb::task_arena& arena);

  int size() const { return static_cast<int>(first_.size()) - 1; }
  std::size_t planeCount() const { return planes_.size(); }

  /// Inside the union, through the grid (points outside the grid's box fall back to the scan).
  bool inside(const Vec3& p) const {
    const std::size_t c = indexed_ ? cellOf(p) : kNoCell;
    if (c == kNoCell) return insideDirect(p);
    const std::uint32_t code = cellCode_[c];
    return code < kBoundary ? code == kInside : insideBoundary(code - kBoundary, p);
  }

  /// Number of points point(i), i in [i0, i1), inside the union: the same answers as `inside`,
  /// in batches whose cells are looked up (and prefetched) before any is read, so the memory
  /// latency of the random cell accesses overlaps.
  template <class PointOf>
  std::uint64_t countInside(const PointOf& point, std::uint64_t i0, std::uint64_t i1) const {
    if (!indexed_) {
      std::uint64_t in = 0;
      for (std::uint64_t i = i0; i < i1; ++i) in += insideDirect(point(i)) ? 1 : 0;
      return in;
    }
    constexpr int kBatch = 32;
    Vec3 p[kBatch];
    std::size_t cell[kBatch];
    std::uint32_t code[kBatch];
    std::uint64_t in = 0;
    for (std::uint64_t b = i0; b < i1; b += kBatch) {
      const int n = static_cast<int>(std::min<std::uint64_t>(kBatch, i1 - b));
      for (int t = 0; t < n; ++t) {  // cells, their codes requested
        p[t] = point(b + t);
        cell[t] = cellOf(p[t]);
        if (cell[t] != kNoCell) __builtin_prefetch(&cellCode_[cell[t]]);
      }
      for (int t = 0; t < n; ++t) {  // codes read, boundary records requested
        code[t] = cell[t] == kNoCell ? kOffGrid : cellCode_[cell[t]];
        if (code[t] >= kBoundary) __builtin_prefetch(&slots_[code[t] - kBoundary]);
      }
      for (int t = 0; t < n; ++t) {
        if (code[t] <= kInside)
          in += code[t];
        else
          in += (code[t] == kOffGrid ? insideDirect(p[t]) : insideBoundary(code[t] - kBoundary, p[t])) ? 1 : 0;
      }
    }
    return in;
  }

  /// Inside the union by testing every polyhedron's bounding box and planes (no index).
  bool insideDirect(const Vec3& p) const { return firstContaining(p) >= 0; }

  /// Lowest index of a polyhedron that contains p, or -1 (no index).
  int firstContaining(const Vec3& p) const;

  /// Whether polyhedron h contains p (all its planes).
  bool contains(int h, const Vec3& p) const;

  // ---- index statistics
  int gridX() const { return gx_; }
  int gridY() const { return gy_; }
  int gridZ() const { return gz_; }
  std::size_t boundaryCells() const { return boundaryCells_; }
  std::size_t insideCells() const { return insideCells_; }
  std::size_t cellCount() const { return cellCode_.size(); }
  /// Plane tests a boundary cell needs at most, on average over boundary cells.
  double planesPerBoundaryCell() const {
    return boundaryCells_ ? static_cast<double>(slots_.size() - runs_) / static_cast<double>(boundaryCells_) : 0.0;
  }
  std::size_t indexBytes() const {
    return cellCode_.size() * sizeof(std::uint32_t) + slots_.size() * sizeof(Slot);
  }

 private:
  // Cell codes; kOffGrid is never stored (points outside the grid's box).
  static constexpr std::uint32_t kOutside = 0, kInside = 1, kOffGrid = 2, kBoundary = 3;
  static constexpr std::size_t kNoCell = ~std::size_t{0};

  /// The grid cell of p, or kNoCell outside the grid's box.
  std::size_t cellOf(const Vec3& p) const {
    const double fx = (p.x() - gridLo_.x()) * gridScale_.x(), fy = (p.y() - gridLo_.y()) * gridScale_.y(),
                 fz = (p.z() - gridLo_.z()) * gridScale_.z();
    if (!(fx >= 0 && fy >= 0 && fz >= 0 && fx <= gx_ && fy <= gy_ && fz <= gz_)) return kNoCell;
    const int ix = std::min(static_cast<int>(fx), gx_ - 1), iy = std::min(static_cast<int>(fy), gy_ - 1),
              iz = std::min(static_cast<int>(fz), gz_ - 1);
    return (static_cast<std::size_t>(iz) * gy_ + iy) * gx_ + ix;
  }

  /// Boundary record at slots_[offset]: some polyhedron holds p by the planes that cross the cell.
  bool insideBoundary(std::uint32_t offset, const Vec3& p) const {
    const Slot* run = &slots_[offset];
    for (;;) {
      const int n = static_cast<int>(run->a);
      const Slot* q = run + 1;
      bool in = true;
      for (int k = 0; k < n; ++k)
        if (q[k].a * p.x() + q[k].b * p.y() + q[k].c * p.z() > q[k].d + slack_) {
          in = false;
          break;
        }
      if (in) return true;
      if (run->b != 0.0) return false;  // the cell's last run
      run = q + n;
    }
  }

  double slack_;
  std::vector<HalfSpace> planes_;   // all polyhedra's planes; polyhedron h owns [first_[h], first_[h + 1])
  std::vector<int> first_{0};

  bool indexed_ = false;
  Vec3 gridLo_ = Vec3::Zero(), gridScale_ = Vec3::Ones();
  int gx_ = 1, gy_ = 1, gz_ = 1;
  std::vector<std::uint32_t> cellCode_;  // kOutside, kInside, or kBoundary + offset of the cell's record in slots_
  /// Boundary records, one per boundary cell, each contiguous (one cache miss per query): per
  /// polyhedron that may hold part of the cell, a header slot (a = its plane count, b = 1 for the
  /// cell's last polyhedron) and then its planes crossing the cell (a, b, c = normal, d).
  struct Slot {
    double a, b, c, d;
  };
  std::vector<Slot> slots_;
  std::size_t boundaryCells_ = 0, runs_ = 0;
  std::size_t insideCells_ = 0;
};

}  // namespace acd
