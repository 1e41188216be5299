#include <acd/algo/face_grid.hpp>

#include <acd/algo/closest_point.hpp>
#include <acd/algo/float_bounds.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace acd {

FaceGrid::FaceGrid(std::vector<const TriMesh*> meshes) : meshes_(std::move(meshes)) {
  Box3 box;
  box.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  box.hi = -box.lo;
  std::size_t faces = 0;
  for (const TriMesh* m : meshes_) {
    for (const Vec3& v : m->vertices) box.lo = box.lo.cwiseMin(v), box.hi = box.hi.cwiseMax(v);
    faces += m->faces.size();
  }
  if (faces == 0) return;
  firstFace_.reserve(meshes_.size() + 1);
  boxes_.reserve(faces);
  firstFace_.push_back(0);
  for (const TriMesh* m : meshes_) {
    for (const Face& t : m->faces) {
      boxes_.push_back(floatBoxOf(m->vertices[t[0]], m->vertices[t[1]], m->vertices[t[2]]));
    }
    firstFace_.push_back(static_cast<int>(boxes_.size()));
  }
  const Vec3 size = box.size().cwiseMax(1e-9);
  cell_ = std::max(1e-6, std::cbrt(size.prod() / static_cast<double>(faces)));
  lo_ = box.lo;
  // A box flat in one direction gives cells far more than faces (a plate a nanometre thick, a
  // billion): coarser cells, until the grid is about the size of the mesh.
  const double most = 8.0 * static_cast<double>(faces) + 4096.0;
  auto cellsAlong = [&](int k) { return std::ceil(size[k] / cell_) + 1.0; };
  while (cellsAlong(0) * cellsAlong(1) * cellsAlong(2) > most) cell_ *= 1.25;
  for (int k = 0; k < 3; ++k) dims_[k] = static_cast<int>(cellsAlong(k));
  start_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
  forEachFaceCell([&](std::size_t c, int, int) { ++start_[c + 1]; });
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  entries_.resize(start_.back());
  std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
  forEachFaceCell([&](std::size_t c, int m, int f) { entries_[fill[c]++] = firstFace_[m] + f; });
}

FaceGrid::Nearest FaceGrid::nearest(const Vec3& p, double within) const {
  if (entries_.empty()) return {};
  std::array<int, 3> at;
  for (int k = 0; k < 3; ++k) at[k] = cellOf(p[k], k);
  // How far p stands inside its own cell: a face unseen after ring r is at least r cells and this
  // far away (less a little for the rounding of cell indices; none when p lies outside the grid).
  double inside = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const double from = p[k] - (lo_[k] + at[k] * cell_);
    inside = std::min({inside, from, cell_ - from});
  }
  inside = std::max(0.0, inside - 1e-6 * cell_);
  double best = std::numeric_limits<double>::infinity();
  int bestMesh = -1, bestFace = -1;
  const double slack2 = 1e-18 * cell_ * cell_;  // rounding's worth, squared, for the box tests
  const int rings = std::max({dims_[0], dims_[1], dims_[2]});
  for (int r = 0; r <= rings; ++r) {
    for (int i = std::max(0, at[0] - r); i <= std::min(dims_[0] - 1, at[0] + r); ++i)
      for (int j = std::max(0, at[1] - r); j <= std::min(dims_[1] - 1, at[1] + r); ++j) {
        // On the ring's faces in i or j, the whole column in k; else only its two ends.
        const bool side = std::abs(i - at[0]) == r || std::abs(j - at[1]) == r;
        for (int k = at[2] - r; k <= at[2] + r; k += side || r == 0 ? 1 : 2 * r) {
          if (k < 0 || k >= dims_[2]) continue;
          // A cell whose box lies farther than the best found (or than `within`) holds no nearer
          // face: a face is listed in every cell its box meets, so a nearer part is met elsewhere.
          const double box = cellDistance2(p, i, j, k);
          if (box > best * (1 + 1e-9) || box > within * within * (1 + 1e-9)) continue;
          const std::size_t c = (static_cast<std::size_t>(i) * dims_[1] + j) * dims_[2] + k;
          for (std::size_t e = start_[c]; e < start_[c + 1]; ++e) {
            const int number = entries_[e];
            // A face whose box lies farther than the best found cannot be nearer, nor tie: skip the
            // exact distance (most faces of a cell are such). The float box holds the face's, so
            // its distance is no greater: it skips no face the exact box would keep.
            const FloatBox& fb = boxes_[number];
            double box = 0.0;
            for (int x = 0; x < 3; ++x) {
              const double gap = std::max({fb.lo[x] - p[x], p[x] - fb.hi[x], 0.0});
              box += gap * gap;
            }
            if (box > best * (1 + 1e-9) + slack2) continue;
            const int m = static_cast<int>(std::upper_bound(firstFace_.begin(), firstFace_.end(), number) - firstFace_.begin()) - 1;
            const int f = number - firstFace_[m];
            const TriMesh& mesh = *meshes_[m];
            const Face& t = mesh.faces[f];
            const Vec3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
            const double d = (closestPointOnTriangle(p, a, b, c) - p).squaredNorm();
            if (d < best || (d == best && m < bestMesh)) best = d, bestMesh = m, bestFace = f;
          }
        }
      }
    // Every face nearer than r cells' width, and than `inside` more, has been seen (strictly
    // nearer, so that an equal distance elsewhere cannot be missed).
    const double seen = r * cell_ + inside;
    if (bestMesh >= 0 && (std::sqrt(best) <= r * cell_ || std::sqrt(best) < seen)) break;
    if (seen > within) break;  // what is left lies beyond `within`
  }
  return {bestMesh, bestFace, std::sqrt(best)};
}

int FaceGrid::cellOf(double x, int axis) const {
  // Clamped before the conversion: a point far off the grid must not overflow an int.
  return static_cast<int>(std::clamp((x - lo_[axis]) / cell_, 0.0, static_cast<double>(dims_[axis] - 1)));
}

double FaceGrid::cellDistance2(const Vec3& p, int i, int j, int k) const {
  const std::array<int, 3> at{i, j, k};
  double d2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double lo = lo_[a] + at[a] * cell_, hi = lo + cell_;
    // The first and last cells reach as far as the clamped indices of points beyond the grid.
    const double gap = at[a] > 0 && p[a] < lo ? lo - p[a] : at[a] < dims_[a] - 1 && p[a] > hi ? p[a] - hi : 0.0;
    const double slack = std::max(0.0, gap - 1e-9 * cell_);  // a vertex on a cell's wall may be listed either side
    d2 += slack * slack;
  }
  return d2;
}

template <class Visit>
void FaceGrid::forEachFaceCell(const Visit& visit) const {
  for (std::size_t m = 0; m < meshes_.size(); ++m) {
    const TriMesh& mesh = *meshes_[m];
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
      Vec3 lo = mesh.vertices[mesh.faces[f][0]], hi = lo;
      for (int v : mesh.faces[f]) lo = lo.cwiseMin(mesh.vertices[v]), hi = hi.cwiseMax(mesh.vertices[v]);
      std::array<int, 3> a, b;
      for (int k = 0; k < 3; ++k) {
        a[k] = cellOf(lo[k], k);
        b[k] = cellOf(hi[k], k);
      }
      for (int i = a[0]; i <= b[0]; ++i)
        for (int j = a[1]; j <= b[1]; ++j)
          for (int k = a[2]; k <= b[2]; ++k)
            visit((static_cast<std::size_t>(i) * dims_[1] + j) * dims_[2] + k, static_cast<int>(m), static_cast<int>(f));
    }
  }
}

}  // namespace acd
