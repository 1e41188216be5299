#include <acd/algo/hull_set.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

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

void HullSet::buildIndex(const Box3& box, std::size_t targetCells, tbb::task_arena& arena) {
  const Vec3 extent = box.size().cwiseMax(Vec3::Constant(1e-300));
  const double unit = std::cbrt(extent.prod() / static_cast<double>(std::max<std::size_t>(targetCells, 1)));
  gx_ = std::clamp(static_cast<int>(std::ceil(extent.x() / unit)), 1, 2048);
  gy_ = std::clamp(static_cast<int>(std::ceil(extent.y() / unit)), 1, 2048);
  gz_ = std::clamp(static_cast<int>(std::ceil(extent.z() / unit)), 1, 2048);
  gridLo_ = box.lo;
  gridScale_ = Vec3(gx_ / extent.x(), gy_ / extent.y(), gz_ / extent.z());
  const Vec3 cell(extent.x() / gx_, extent.y() / gy_, extent.z() / gz_);
  // Rounding allowances: the cell a point lands in (index arithmetic) and the dot products.
  const double scale = std::max(box.lo.cwiseAbs().maxCoeff(), box.hi.cwiseAbs().maxCoeff()) + extent.norm();
  const double margin = 1e-9 * extent.norm() + 1e-13 * scale;
  const double tol = 1e-12 * scale;

  const std::size_t slab = static_cast<std::size_t>(gx_) * gy_;
  cellCode_.assign(slab * gz_, kOutside);
  struct Slab {
    std::vector<Slot> slots;  // boundary records, offsets local to the slab until concatenated
    std::size_t inside = 0, boundary = 0, runs = 0;
  };
  std::vector<Slab> slabs(gz_);
  const int nh = size();
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, gz_), [&](const tbb::blocked_range<int>& r) {
      std::vector<std::pair<double, std::uint32_t>> crossing;  // (share of the cell it cuts off, plane)
      for (int iz = r.begin(); iz != r.end(); ++iz) {
        Slab& s = slabs[iz];
        for (int iy = 0; iy < gy_; ++iy)
          for (int ix = 0; ix < gx_; ++ix) {
            const Vec3 clo = box.lo + Vec3(ix * cell.x(), iy * cell.y(), iz * cell.z()) - Vec3::Constant(margin);
            const Vec3 chi =
                box.lo + Vec3((ix + 1) * cell.x(), (iy + 1) * cell.y(), (iz + 1) * cell.z()) + Vec3::Constant(margin);
            const std::size_t before = s.slots.size(), runsBefore = s.runs;
            std::size_t lastHeader = 0;
            bool full = false;
            for (int h = 0; h < nh && !full; ++h) {
              bool excluded = false;
              crossing.clear();
              for (int k = first_[h]; k < first_[h + 1] && !excluded; ++k) {
                const HalfSpace& q = planes_[k];
                const double mn = (q.normal.x() > 0 ? q.normal.x() * clo.x() : q.normal.x() * chi.x()) +
                                  (q.normal.y() > 0 ? q.normal.y() * clo.y() : q.normal.y() * chi.y()) +
                                  (q.normal.z() > 0 ? q.normal.z() * clo.z() : q.normal.z() * chi.z());
                const double mx = (q.normal.x() > 0 ? q.normal.x() * chi.x() : q.normal.x() * clo.x()) +
                                  (q.normal.y() > 0 ? q.normal.y() * chi.y() : q.normal.y() * clo.y()) +
                                  (q.normal.z() > 0 ? q.normal.z() * chi.z() : q.normal.z() * clo.z());
                if (mn - tol > q.offset + slack_)
                  excluded = true;  // no point of the cell passes this plane
                else if (mx + tol > q.offset + slack_)  // may reject some point of the cell
                  crossing.emplace_back((mx - q.offset) / std::max(mx - mn, 1e-300), static_cast<std::uint32_t>(k));
              }
              if (excluded) continue;
              if (crossing.empty()) {
                full = true;  // the cell lies in polyhedron h
                break;
              }
              // Planes that cut off most of the cell first: points outside leave early.
              std::stable_sort(crossing.begin(), crossing.end(),
                               [](const auto& a, const auto& b) { return a.first > b.first; });
              lastHeader = s.slots.size();
              s.slots.push_back({static_cast<double>(crossing.size()), 0.0, 0.0, 0.0});
              for (const auto& [share, k] : crossing) {
                const HalfSpace& q = planes_[k];
                s.slots.push_back({q.normal.x(), q.normal.y(), q.normal.z(), q.offset});
              }
              ++s.runs;
            }
            const std::size_t c = static_cast<std::size_t>(iz) * slab + static_cast<std::size_t>(iy) * gx_ + ix;
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
    });
  });
  // Concatenate the slabs in order: the layout never depends on the threads.
  slots_.clear();
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
