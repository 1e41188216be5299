#include <acd/algo/hull_set.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace acd {

bool HullSet::add(const TriMesh& convex) {
  std::vector<HalfSpace> facets;
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (const Vec3& v : convex.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  for (const Face& f : convex.faces) {
    const Vec3 &a = convex.vertices[f[0]], &b = convex.vertices[f[1]], &c = convex.vertices[f[2]];
    Vec3 n = (b - a).cross(c - a);
    const double len = n.norm();
    if (!(len > 0)) continue;
    n /= len;
    double d = n.dot(a);
    for (const Vec3& v : convex.vertices) d = std::max(d, n.dot(v));
    bool duplicate = false;  // coplanar triangles of one facet give one plane
    for (const HalfSpace& p : facets)
      if (p.normal.x() * n.x() + p.normal.y() * n.y() + p.normal.z() * n.z() > 1 - 1e-12 && std::abs(p.offset - d) <= slack_) {
        duplicate = true;
        break;
      }
    if (!duplicate) facets.push_back({n, d});
  }
  if (facets.empty()) return false;
  add(Box3{lo, hi}, facets);
  return true;
}

void HullSet::add(const Box3& box, const std::vector<HalfSpace>& facets) {
  const Vec3 &lo = box.lo, &hi = box.hi;
  // The box as six planes, tested first: they reject most points at once, and the scan and
  // the grid then test exactly the same set.
  planes_.push_back({Vec3(-1, 0, 0), -lo.x()});
  planes_.push_back({Vec3(1, 0, 0), hi.x()});
  planes_.push_back({Vec3(0, -1, 0), -lo.y()});
  planes_.push_back({Vec3(0, 1, 0), hi.y()});
  planes_.push_back({Vec3(0, 0, -1), -lo.z()});
  planes_.push_back({Vec3(0, 0, 1), hi.z()});
  planes_.insert(planes_.end(), facets.begin(), facets.end());
  first_.push_back(static_cast<int>(planes_.size()));
  indexed_ = false;
}

bool HullSet::contains(int h, const Vec3& p) const {
  for (int k = first_[h], e = first_[h + 1]; k < e; ++k) {
    const HalfSpace& q = planes_[k];
    if (q.normal.x() * p.x() + q.normal.y() * p.y() + q.normal.z() * p.z() > q.offset + slack_) return false;
  }
  return true;
}

int HullSet::firstContaining(const Vec3& p) const {
  for (int h = 0, n = size(); h < n; ++h)
    if (contains(h, p)) return h;
  return -1;
}

namespace {

/// How a box stands against one polyhedron's planes.
enum class Standing { kApart, kWithin, kCrossed };

using Crossing = std::vector<std::pair<double, std::uint32_t>>;  // (share of the box it cuts off, plane)

/// The grid's cells as inflated boxes: one formula for a cell and a block of cells, monotone in
/// the indices, so a cell's box lies within its block's in floating point too.
struct CellBoxes {
  Vec3 lo, cell;
  double margin;
  /// The box of cells [i0, i1) x [j0, j1) x [k0, k1).
  std::pair<Vec3, Vec3> of(int i0, int j0, int k0, int i1, int j1, int k1) const {
    return {lo + Vec3(i0 * cell.x(), j0 * cell.y(), k0 * cell.z()) - Vec3::Constant(margin),
            lo + Vec3(i1 * cell.x(), j1 * cell.y(), k1 * cell.z()) + Vec3::Constant(margin)};
  }
};

/// Where the box [lo, hi] stands against the planes `ks` (indices into `planes`): apart if one
/// plane rejects all of it, within if none rejects any of it, else crossed, with the crossing
/// planes in `crossing`, in the order given. `tol` covers the dot products' rounding.
Standing standingOf(const std::vector<HalfSpace>& planes, double limitSlack, double tol, const Vec3& lo,
                    const Vec3& hi, const int* ks, int count, Crossing& crossing) {
  crossing.clear();
  for (int i = 0; i < count; ++i) {
    const HalfSpace& q = planes[ks[i]];
    const double mn = (q.normal.x() > 0 ? q.normal.x() * lo.x() : q.normal.x() * hi.x()) +
                      (q.normal.y() > 0 ? q.normal.y() * lo.y() : q.normal.y() * hi.y()) +
                      (q.normal.z() > 0 ? q.normal.z() * lo.z() : q.normal.z() * hi.z());
    const double mx = (q.normal.x() > 0 ? q.normal.x() * hi.x() : q.normal.x() * lo.x()) +
                      (q.normal.y() > 0 ? q.normal.y() * hi.y() : q.normal.y() * lo.y()) +
                      (q.normal.z() > 0 ? q.normal.z() * hi.z() : q.normal.z() * lo.z());
    if (mn - tol > q.offset + limitSlack) return Standing::kApart;  // no point of the box passes this plane
    if (mx + tol > q.offset + limitSlack)                           // may reject some point of the box
      crossing.emplace_back((mx - q.offset) / std::max(mx - mn, 1e-300), static_cast<std::uint32_t>(ks[i]));
  }
  return crossing.empty() ? Standing::kWithin : Standing::kCrossed;
}

/// Kept for the cells of a block: each polyhedron that may hold part of the block, with the
/// planes crossing it, in plane order; or that one polyhedron holds the whole block.
struct BlockStanding {
  bool within = false;
  std::vector<int> runs;  // per polyhedron: h, the plane count n, then n plane indices

  void classify(const std::vector<HalfSpace>& planes, const std::vector<int>& first, double limitSlack, double tol,
                const std::pair<Vec3, Vec3>& box, const std::vector<int>& everyPlane, Crossing& crossing) {
    within = false;
    runs.clear();
    for (int h = 0; h + 1 < static_cast<int>(first.size()) && !within; ++h) {
      const Standing s = standingOf(planes, limitSlack, tol, box.first, box.second, &everyPlane[first[h]],
                                    first[h + 1] - first[h], crossing);
      within = s == Standing::kWithin;
      if (s != Standing::kCrossed) continue;
      runs.push_back(h);
      runs.push_back(static_cast<int>(crossing.size()));
      for (const auto& c : crossing) runs.push_back(static_cast<int>(c.second));
    }
  }
};

}  // namespace

void HullSet::buildIndex(const Box3& box, std::size_t targetCells, tbb::task_arena& arena) {
  const Vec3 extent = box.size().cwiseMax(Vec3::Constant(1e-300));
  const double unit = std::cbrt(extent.prod() / static_cast<double>(std::max<std::size_t>(targetCells, 1)));
  gx_ = std::clamp(static_cast<int>(std::ceil(extent.x() / unit)), 1, 2048);
  gy_ = std::clamp(static_cast<int>(std::ceil(extent.y() / unit)), 1, 2048);
  gz_ = std::clamp(static_cast<int>(std::ceil(extent.z() / unit)), 1, 2048);
  gridLo_ = box.lo;
  gridScale_ = Vec3(gx_ / extent.x(), gy_ / extent.y(), gz_ / extent.z());
  // Rounding allowances: the cell a point lands in (index arithmetic) and the dot products.
  const double scale = std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff()) + extent.norm();
  const CellBoxes boxes{box.lo, Vec3(extent.x() / gx_, extent.y() / gy_, extent.z() / gz_),
                        1e-9 * extent.norm() + 1e-13 * scale};
  const double tol = 1e-12 * scale;

  // Cells are classified block by block. A plane whose half-space holds a whole block holds
  // each of its cells; a polyhedron that misses the block, or holds all of it, does the same to
  // each cell. So a cell tests only the planes crossing its block, and is classified as it would
  // be by testing every plane (the same records, in the same order), for a fraction of the tests.
  constexpr int kBlock = 4;
  const int bx = (gx_ + kBlock - 1) / kBlock, by = (gy_ + kBlock - 1) / kBlock, bz = (gz_ + kBlock - 1) / kBlock;
  std::vector<int> everyPlane(planes_.size());
  for (std::size_t k = 0; k < planes_.size(); ++k) everyPlane[k] = static_cast<int>(k);

  const std::size_t slab = static_cast<std::size_t>(gx_) * gy_;
  cellCode_.assign(slab * gz_, kOutside);
  struct Slab {
    std::vector<Slot> slots;  // boundary records, offsets local to the slab until concatenated
    std::size_t inside = 0, boundary = 0, runs = 0;
  };
  std::vector<Slab> slabs(gz_);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, bz), [&](const tbb::blocked_range<int>& r) {
      Crossing crossing;
      std::vector<BlockStanding> blocks(static_cast<std::size_t>(bx) * by);
      for (int kz = r.begin(); kz != r.end(); ++kz) {
        const int z0 = kz * kBlock, z1 = std::min(z0 + kBlock, gz_);
        for (int ky = 0; ky < by; ++ky)
          for (int kx = 0; kx < bx; ++kx)
            blocks[static_cast<std::size_t>(ky) * bx + kx].classify(
                planes_, first_, slack_, tol,
                boxes.of(kx * kBlock, ky * kBlock, z0, std::min((kx + 1) * kBlock, gx_), std::min((ky + 1) * kBlock, gy_), z1),
                everyPlane, crossing);
        for (int iz = z0; iz < z1; ++iz) {
          Slab& s = slabs[iz];
          for (int iy = 0; iy < gy_; ++iy)
            for (int ix = 0; ix < gx_; ++ix) {
              const BlockStanding& b = blocks[static_cast<std::size_t>(iy / kBlock) * bx + ix / kBlock];
              const std::size_t c = static_cast<std::size_t>(iz) * slab + static_cast<std::size_t>(iy) * gx_ + ix;
              if (b.within) {  // some polyhedron holds the whole block
                cellCode_[c] = kInside;
                ++s.inside;
                continue;
              }
              const auto [clo, chi] = boxes.of(ix, iy, iz, ix + 1, iy + 1, iz + 1);
              const std::size_t before = s.slots.size(), runsBefore = s.runs;
              std::size_t lastHeader = 0;
              bool full = false;
              for (std::size_t at = 0; at < b.runs.size() && !full;) {
                const int n = b.runs[at + 1];
                const int* planes = &b.runs[at + 2];
                at += 2 + static_cast<std::size_t>(n);
                const Standing st = standingOf(planes_, slack_, tol, clo, chi, planes, n, crossing);
                if (st == Standing::kApart) continue;
                if (st == Standing::kWithin) {
                  full = true;  // the cell lies in this polyhedron
                  break;
                }
                // Planes that cut off most of the cell first: points outside leave early.
                std::stable_sort(crossing.begin(), crossing.end(),
                                 [](const auto& x, const auto& y) { return x.first > y.first; });
                lastHeader = s.slots.size();
                s.slots.push_back({static_cast<double>(crossing.size()), 0.0, 0.0, 0.0});
                for (const auto& [share, k] : crossing) {
                  const HalfSpace& q = planes_[k];
                  s.slots.push_back({q.normal.x(), q.normal.y(), q.normal.z(), q.offset});
                }
                ++s.runs;
              }
              if (full) {
                s.slots.resize(before);
                s.runs = runsBefore;
                cellCode_[c] = kInside;
                ++s.inside;
              } else if (s.slots.size() > before) {
                s.slots[lastHeader].b = 1.0;
                cellCode_[c] = kBoundary + static_cast<std::uint32_t>(before);  // local for now
                ++s.boundary;
              }
            }
        }
      }
    });
  });
  // Concatenate the slabs in order: the layout never depends on the threads.
  // One allocation: growing by copies took most of the build (tens of MB on a scan's hulls).
  std::size_t total = 0;
  for (const Slab& s : slabs) total += s.slots.size();
  slots_.clear();
  slots_.shrink_to_fit();
  slots_.reserve(total);
  insideCells_ = boundaryCells_ = runs_ = 0;
  std::vector<std::uint32_t> slotOffset(gz_);
  for (int iz = 0; iz < gz_; ++iz) {
    const Slab& s = slabs[iz];
    slotOffset[iz] = static_cast<std::uint32_t>(slots_.size());
    slots_.insert(slots_.end(), s.slots.begin(), s.slots.end());
    insideCells_ += s.inside;
    boundaryCells_ += s.boundary;
    runs_ += s.runs;
  }
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, gz_), [&](const tbb::blocked_range<int>& r) {
      for (int iz = r.begin(); iz != r.end(); ++iz)
        for (std::size_t c = iz * slab, e = c + slab; c < e; ++c)
          if (cellCode_[c] >= kBoundary) cellCode_[c] += slotOffset[iz];
    });
  });
  indexed_ = true;
}

}  // namespace acd
