#include "surface_embedding.hpp"

#include <acd/algo/closest_point.hpp>
#include <acd/algo/stopwatch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace tetmesh {

namespace {

/// Uniform grid over the tets: each cell lists the tets whose bounding box meets it.
class TetGrid {
 public:
  explicit TetGrid(const TetMesh& mesh) : mesh_(mesh) {
    lo_ = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = -lo_;
    for (const auto& t : mesh.tets)
      for (int v : t) lo_ = lo_.cwiseMin(mesh.points[v]), hi = hi.cwiseMax(mesh.points[v]);
    const Vec3 extent = (hi - lo_).cwiseMax(Vec3::Constant(1e-300));
    // About one cell per tet, cubic cells.
    const double volume = extent.x() * extent.y() * extent.z();
    cell_ = std::cbrt(volume / std::max<std::size_t>(mesh.tets.size(), 1));
    if (!(cell_ > 0)) cell_ = extent.maxCoeff();
    for (int k = 0; k < 3; ++k)
      dims_[k] = static_cast<int>(std::clamp(std::ceil(extent[k] / cell_), 1.0, 256.0));
    cell_ = std::max({extent.x() / dims_[0], extent.y() / dims_[1], extent.z() / dims_[2]});
    start_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
    // Counting pass, then fill (compressed rows).
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        items_.resize(start_.back());
        fill_ = std::vector<int>(start_.begin(), start_.end() - 1);
      }
      for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t) {
        Vec3 a = mesh.points[mesh.tets[t][0]], b = a;
        for (int v : mesh.tets[t]) a = a.cwiseMin(mesh.points[v]), b = b.cwiseMax(mesh.points[v]);
        const std::array<int, 3> i0 = clampedCell(a), i1 = clampedCell(b);
        for (int z = i0[2]; z <= i1[2]; ++z)
          for (int y = i0[1]; y <= i1[1]; ++y)
            for (int x = i0[0]; x <= i1[0]; ++x) {
              const std::size_t c = index(x, y, z);
              if (pass == 0)
                ++start_[c + 1];
              else
                items_[fill_[c]++] = t;
            }
      }
    }
    stamp_.assign(mesh.tets.size(), -1);
  }

  /// Tet and weights of p; `distance` is 0 when p lies in a tet (within kInsideTolerance),
  /// else the distance to the closest tet, in whose affine frame p is written.
  int locate(const Vec3& p, std::array<double, 4>& weights, double& distance) {
    ++query_;
    const std::array<long long, 3> home = rawCell(p);
    // Inside test in p's own cell: the tet in which p is deepest (largest smallest weight).
    int best = -1;
    double bestMin = -std::numeric_limits<double>::infinity();
    if (inGrid(home))
      for (int k = start_[index(home)]; k < start_[index(home) + 1]; ++k) {
        const int t = items_[k];
        const auto w = weightsIn(t, p);
        const double m = *std::min_element(w.begin(), w.end());
        if (m > bestMin) bestMin = m, best = t, weights = w;
      }
    if (best >= 0 && bestMin >= -kInsideTolerance) {
      distance = 0.0;
      return best;
    }
    // Closest tet, ring by ring of cells around p's cell. A tet's closest point lies in its
    // bounding box, hence in a cell listing it; cells of ring r + 1 are at least r cells away.
    best = -1;
    double bestD2 = std::numeric_limits<double>::infinity();
    Vec3 bestPoint = p;
    // Rings before `first` lie wholly outside the grid; ring `last` covers all of it.
    long long first = 0, last = 0;
    for (int k = 0; k < 3; ++k) {
      first = std::max({first, -home[k], home[k] - (dims_[k] - 1)});
      last = std::max({last, std::llabs(home[k]), std::llabs(home[k] - (dims_[k] - 1))});
    }
    auto visit = [&](long long x, long long y, long long z) {
      const std::array<long long, 3> c{x, y, z};
      for (int k = start_[index(c)]; k < start_[index(c) + 1]; ++k) {
        const int t = items_[k];
        if (stamp_[t] == query_) continue;
        stamp_[t] = query_;
        const auto& v = mesh_.tets[t];
        const Vec3 q = closestPointInTet(p, mesh_.points[v[0]], mesh_.points[v[1]], mesh_.points[v[2]], mesh_.points[v[3]]);
        const double d2 = (q - p).squaredNorm();
        if (d2 < bestD2) bestD2 = d2, best = t, bestPoint = q;
      }
    };
    for (long long r = first; r <= last; ++r) {
      // The cells of the ring that are in the grid: full rows on the ring's two z and y
      // faces, the two ends of every other row.
      const long long z0 = std::max(home[2] - r, 0LL), z1 = std::min(home[2] + r, dims_[2] - 1LL);
      const long long y0 = std::max(home[1] - r, 0LL), y1 = std::min(home[1] + r, dims_[1] - 1LL);
      const long long x0 = std::max(home[0] - r, 0LL), x1 = std::min(home[0] + r, dims_[0] - 1LL);
      for (long long z = z0; z <= z1; ++z)
        for (long long y = y0; y <= y1; ++y) {
          if (std::llabs(z - home[2]) == r || std::llabs(y - home[1]) == r) {
            for (long long x = x0; x <= x1; ++x) visit(x, y, z);
          } else {
            if (home[0] - r >= 0 && home[0] - r < dims_[0]) visit(home[0] - r, y, z);
            if (r > 0 && home[0] + r >= 0 && home[0] + r < dims_[0]) visit(home[0] + r, y, z);
          }
        }
      if (best >= 0 && std::sqrt(bestD2) <= static_cast<double>(r) * cell_) break;
    }
    // p's own coordinates in that tet, not its closest point's: the tet's affine map carries the
    // offset too, so p stays where it is at rest and moves rigidly with a rigid tet (clamped
    // weights put it onto the mesh: the coarse elephant's surface lost 13 % of its volume so).
    weights = weightsIn(best, p);
    distance = std::sqrt(bestD2);
    return best;
  }

 private:
  std::array<double, 4> weightsIn(int t, const Vec3& p) const {
    const auto& v = mesh_.tets[t];
    return barycentric(p, mesh_.points[v[0]], mesh_.points[v[1]], mesh_.points[v[2]], mesh_.points[v[3]]);
  }
  std::array<long long, 3> rawCell(const Vec3& p) const {
    std::array<long long, 3> c{};
    for (int k = 0; k < 3; ++k) {
      const double f = std::floor((p[k] - lo_[k]) / cell_);
      c[k] = static_cast<long long>(std::clamp(f, -1e15, 1e15));
      if (c[k] == dims_[k] && p[k] - lo_[k] <= dims_[k] * cell_) c[k] = dims_[k] - 1;  // the far faces
    }
    return c;
  }
  std::array<int, 3> clampedCell(const Vec3& p) const {
    const auto c = rawCell(p);
    return {static_cast<int>(std::clamp<long long>(c[0], 0, dims_[0] - 1)),
            static_cast<int>(std::clamp<long long>(c[1], 0, dims_[1] - 1)),
            static_cast<int>(std::clamp<long long>(c[2], 0, dims_[2] - 1))};
  }
  bool inGrid(const std::array<long long, 3>& c) const {
    for (int k = 0; k < 3; ++k)
      if (c[k] < 0 || c[k] >= dims_[k]) return false;
    return true;
  }
  std::size_t index(long long x, long long y, long long z) const {
    return (static_cast<std::size_t>(z) * dims_[1] + static_cast<std::size_t>(y)) * dims_[0] + static_cast<std::size_t>(x);
  }
  std::size_t index(const std::array<long long, 3>& c) const { return index(c[0], c[1], c[2]); }

  const TetMesh& mesh_;
  Vec3 lo_;
  double cell_ = 1.0;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<int> start_, items_, fill_;
  std::vector<std::int64_t> stamp_;  // last query that measured this tet
  std::int64_t query_ = 0;
};

}  // namespace

std::array<double, 4> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Everything relative to a, so that coordinates far from the origin lose no digits.
  const Vec3 ab = b - a, ac = c - a, ad = d - a, ap = p - a;
  const double v = ab.cross(ac).dot(ad);
  const double wb = ap.cross(ac).dot(ad) / v;
  const double wc = ab.cross(ap).dot(ad) / v;
  const double wd = ab.cross(ac).dot(ap) / v;
  return {1.0 - wb - wc - wd, wb, wc, wd};
}

Vec3 closestPointInTet(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const auto w = barycentric(p, a, b, c, d);
  if (*std::min_element(w.begin(), w.end()) >= 0) return p;
  Vec3 best = acd::closestPointOnTriangle(p, b, c, d);
  for (const Vec3& q : {acd::closestPointOnTriangle(p, a, c, d), acd::closestPointOnTriangle(p, a, b, d), acd::closestPointOnTriangle(p, a, b, c)})
    if ((q - p).squaredNorm() < (best - p).squaredNorm()) best = q;
  return best;
}

SurfaceEmbedding embedPoints(const TetMesh& mesh, const std::vector<Vec3>& points) {
  const auto t0 = acd::Clock::now();
  SurfaceEmbedding e;
  e.tet.resize(points.size(), -1);
  e.weights.resize(points.size());
  if (mesh.tets.empty()) return e;
  TetGrid grid(mesh);
  for (std::size_t i = 0; i < points.size(); ++i) {
    double distance = 0;
    e.tet[i] = grid.locate(points[i], e.weights[i], distance);
    if (distance > 0) {
      ++e.outside;
      e.maxOutsideDistance = std::max(e.maxOutsideDistance, distance);
    }
  }
  e.seconds = acd::secondsSince(t0);
  return e;
}

std::vector<Vec3> interpolate(const SurfaceEmbedding& embedding, const TetMesh& mesh, const std::vector<Vec3>& field) {
  std::vector<Vec3> out(embedding.tet.size(), Vec3::Zero());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const int t = embedding.tet[i];
    if (t < 0) continue;
    for (int k = 0; k < 4; ++k) out[i] += embedding.weights[i][k] * field[mesh.tets[t][k]];
  }
  return out;
}

}  // namespace tetmesh
