#include "working_model.hpp"

#include <acd/algo/closest_point.hpp>
#include <acd/algo/working_mesh.hpp>
#include <acd/diagnosis.hpp>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace acd {

namespace {

/// A uniform grid over the faces of some meshes, for the mesh nearest to a point near them.
class NearestMesh {
 public:
  explicit NearestMesh(const std::vector<const TriMesh*>& meshes) : meshes_(meshes) {
    Box3 box;
    box.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    box.hi = -box.lo;
    std::size_t faces = 0;
    for (const TriMesh* m : meshes) {
      for (const Vec3& v : m->vertices) box.lo = box.lo.cwiseMin(v), box.hi = box.hi.cwiseMax(v);
      faces += m->faces.size();
    }
    const Vec3 size = box.size().cwiseMax(1e-9);
    // About one face per cell.
    cell_ = std::max(1e-6, std::cbrt(size.prod() / std::max<std::size_t>(1, faces)));
    lo_ = box.lo;
    for (int k = 0; k < 3; ++k) dims_[k] = std::max(1, static_cast<int>(std::ceil(size[k] / cell_)) + 1);
    start_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
    forEachFaceCell([&](std::size_t c, int, int) { ++start_[c + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    entries_.resize(start_.back());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    forEachFaceCell([&](std::size_t c, int m, int f) { entries_[fill[c]++] = {m, f}; });
  }

  /// The mesh with the face nearest to p; equal distances go to the lower mesh index.
  int nearest(const Vec3& p) const { return nearestWithDistance(p).first; }

  /// The nearest mesh and the distance to it.
  std::pair<int, double> nearestWithDistance(const Vec3& p) const {
    std::array<int, 3> at;
    for (int k = 0; k < 3; ++k) at[k] = std::clamp(static_cast<int>((p[k] - lo_[k]) / cell_), 0, dims_[k] - 1);
    // How far p stands inside its own cell: a face unseen after ring r is at least r cells and this
    // far away (less a little for the rounding of cell indices; none when p lies outside the grid).
    double inside = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
      const double from = p[k] - (lo_[k] + at[k] * cell_);
      inside = std::min({inside, from, cell_ - from});
    }
    inside = std::max(0.0, inside - 1e-6 * cell_);
    double best = std::numeric_limits<double>::infinity();
    int bestMesh = -1;
    const int rings = std::max({dims_[0], dims_[1], dims_[2]});
    for (int r = 0; r <= rings; ++r) {
      for (int i = at[0] - r; i <= at[0] + r; ++i)
        for (int j = at[1] - r; j <= at[1] + r; ++j)
          for (int k = at[2] - r; k <= at[2] + r; ++k) {
            if (std::max({std::abs(i - at[0]), std::abs(j - at[1]), std::abs(k - at[2])}) != r)
              continue;  // this ring only
            if (i < 0 || j < 0 || k < 0 || i >= dims_[0] || j >= dims_[1] || k >= dims_[2]) continue;
            const std::size_t c = (static_cast<std::size_t>(i) * dims_[1] + j) * dims_[2] + k;
            for (std::size_t e = start_[c]; e < start_[c + 1]; ++e) {
              const auto [m, f] = entries_[e];
              const TriMesh& mesh = *meshes_[m];
              const Face& t = mesh.faces[f];
              const double d =
                  (closestPointOnTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]) - p)
                      .squaredNorm();
              if (d < best || (d == best && m < bestMesh)) best = d, bestMesh = m;
            }
          }
      // Every face nearer than r cells' width, and than `inside` more, has been seen (strictly
      // nearer, so that an equal distance elsewhere cannot be missed).
      if (bestMesh >= 0 && (std::sqrt(best) <= r * cell_ || std::sqrt(best) < r * cell_ + inside)) break;
    }
    return {bestMesh, std::sqrt(best)};
  }

 private:
  template <class Visit>
  void forEachFaceCell(const Visit& visit) const {
    for (std::size_t m = 0; m < meshes_.size(); ++m) {
      const TriMesh& mesh = *meshes_[m];
      for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        Vec3 lo = mesh.vertices[mesh.faces[f][0]], hi = lo;
        for (int v : mesh.faces[f]) lo = lo.cwiseMin(mesh.vertices[v]), hi = hi.cwiseMax(mesh.vertices[v]);
        std::array<int, 3> a, b;
        for (int k = 0; k < 3; ++k) {
          a[k] = std::clamp(static_cast<int>((lo[k] - lo_[k]) / cell_), 0, dims_[k] - 1);
          b[k] = std::clamp(static_cast<int>((hi[k] - lo_[k]) / cell_), 0, dims_[k] - 1);
        }
        for (int i = a[0]; i <= b[0]; ++i)
          for (int j = a[1]; j <= b[1]; ++j)
            for (int k = a[2]; k <= b[2]; ++k)
              visit((static_cast<std::size_t>(i) * dims_[1] + j) * dims_[2] + k, static_cast<int>(m),
                    static_cast<int>(f));
      }
    }
  }

  const std::vector<const TriMesh*>& meshes_;
  double cell_ = 1.0;
  Vec3 lo_;
  std::array<int, 3> dims_{};
  std::vector<std::size_t> start_;
  std::vector<std::pair<int, int>> entries_;  // (mesh, face) by cell
};

/// How far the working surface stands off the input, measured at each working face's centroid and
/// edge middles and at the middles of its corners and centroid (its corners lie on the input).
double workingToInput(const TriMesh& working, const TriMesh& input) {
  const std::vector<const TriMesh*> meshes{&input};
  const NearestMesh grid(meshes);
  std::vector<double> far(working.faces.size());
  tbb::parallel_for(std::size_t(0), working.faces.size(), [&](std::size_t f) {
    const Vec3& u = working.vertices[working.faces[f][0]];
    const Vec3& v = working.vertices[working.faces[f][1]];
    const Vec3& w = working.vertices[working.faces[f][2]];
    const Vec3 c = (u + v + w) / 3.0;
    double d = 0.0;
    for (const Vec3& q : {c, Vec3(0.5 * (u + v)), Vec3(0.5 * (v + w)), Vec3(0.5 * (w + u)), Vec3(0.5 * (u + c)),
                          Vec3(0.5 * (v + c)), Vec3(0.5 * (w + c))})
      d = std::max(d, grid.nearestWithDistance(q).second);
    far[f] = d;
  });
  return far.empty() ? 0.0 : *std::max_element(far.begin(), far.end());
}

}  // namespace

WorkingModel simplifyPieces(std::vector<TriMesh>& meshes, double tolerance) {
  WorkingModel out;
  std::vector<WorkingMesh> simplified(meshes.size());
  // The collapses keep each face near the input, not apart from the others: where two sheets of
  // the surface run closer than the tolerance and curve (a thin bent plate), a face of one may
  // pass through the other, and the pieces cut from such a mesh cross themselves (wrong volumes;
  // a cut there may find no clean section). Such a piece is simplified again within half, then a
  // quarter, and kept as it is if that does not help either; unless the input itself crosses
  // itself, which the decomposition accepts (and redoes at full resolution if a cut fails).
  tbb::parallel_for(std::size_t(0), meshes.size(), [&](std::size_t i) {
    for (double within = tolerance; within >= tolerance / 4; within /= 2) {
      simplified[i] = simplifyWithin(meshes[i], within);
      if (countSelfIntersections(simplified[i].mesh, 1) == 0) return;
      if (within == tolerance && countSelfIntersections(meshes[i], 1) != 0) return;
    }
    simplified[i] = WorkingMesh{};
  });
  out.inputVertices.resize(meshes.size());
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    WorkingMesh& w = simplified[i];
    out.inputFaces += static_cast<int>(meshes[i].faces.size());
    if (w.mesh.faces.empty() || w.mesh.faces.size() >= meshes[i].faces.size()) {
      out.workingFaces += static_cast<int>(meshes[i].faces.size());
      continue;
    }
    out.workingFaces += static_cast<int>(w.mesh.faces.size());
    out.distance = std::max({out.distance, w.inputToWorking, workingToInput(w.mesh, meshes[i])});
    out.inputVertices[i] = std::move(meshes[i].vertices);
    meshes[i] = std::move(w.mesh);
  }
  return out;
}

std::vector<std::vector<Vec3>> inputVerticesOf(const WorkingModel& working, const std::vector<const TriMesh*>& finals,
                                               const std::vector<int>& sources) {
  std::vector<std::vector<Vec3>> out(finals.size());
  for (std::size_t s = 0; s < working.inputVertices.size(); ++s) {
    const std::vector<Vec3>& input = working.inputVertices[s];
    if (input.empty()) continue;
    std::vector<const TriMesh*> meshes;
    std::vector<int> piece;
    for (std::size_t k = 0; k < finals.size(); ++k)
      if (sources[k] == static_cast<int>(s)) meshes.push_back(finals[k]), piece.push_back(static_cast<int>(k));
    if (meshes.empty()) continue;
    const NearestMesh grid(meshes);
    std::vector<int> owner(input.size());
    tbb::parallel_for(std::size_t(0), input.size(), [&](std::size_t x) { owner[x] = grid.nearest(input[x]); });
    for (std::size_t x = 0; x < input.size(); ++x) out[piece[owner[x]]].push_back(input[x]);
  }
  return out;
}

}  // namespace acd
