#include "working_model.hpp"

#include <acd/algo/face_grid.hpp>
#include <acd/algo/working_mesh.hpp>
#include <acd/diagnosis.hpp>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace acd {

namespace {

/// How far the working surface stands off the input, measured at each working face's centroid and
/// edge middles and at the middles of its corners and centroid (its corners lie on the input).
double workingToInput(const TriMesh& working, const TriMesh& input) {
  const FaceGrid grid({&input});
  std::vector<double> far(working.faces.size());
  tbb::parallel_for(std::size_t(0), working.faces.size(), [&](std::size_t f) {
    const Vec3& u = working.vertices[working.faces[f][0]];
    const Vec3& v = working.vertices[working.faces[f][1]];
    const Vec3& w = working.vertices[working.faces[f][2]];
    const Vec3 c = (u + v + w) / 3.0;
    double d = 0.0;
    for (const Vec3& q : {c, Vec3(0.5 * (u + v)), Vec3(0.5 * (v + w)), Vec3(0.5 * (w + u)), Vec3(0.5 * (u + c)),
                          Vec3(0.5 * (v + c)), Vec3(0.5 * (w + c))})
      d = std::max(d, grid.nearest(q).distance);
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
    const FaceGrid grid(meshes);
    std::vector<int> owner(input.size());
    tbb::parallel_for(std::size_t(0), input.size(), [&](std::size_t x) { owner[x] = grid.nearest(input[x]).mesh; });
    for (std::size_t x = 0; x < input.size(); ++x) out[piece[owner[x]]].push_back(input[x]);
  }
  return out;
}

}  // namespace acd
