#include "deformation_files.hpp"

#include <appcli/exit_codes.hpp>

#include <acd/io.hpp>

#include <filesystem>

namespace tetmesh {

using json = nlohmann::json;
using appcli::kBadParameter;
using appcli::kOk;
using appcli::kOutputFailed;
constexpr int kMeshFailed = appcli::kInternal;

int runDeformation(const DeformArgs& d, const DeformationOptions& o, const TetMesh& tets, const acd::TriMesh& surface,
                   DeformationResult& r) {
  r = deformSurface(tets, surface, o);
  if (!r.status.ok()) {
    kConsole.say(r.status.message);
    return r.status.code == acd::StatusCode::InvalidParameter ? kBadParameter : kMeshFailed;
  }
  std::error_code ec;
  std::filesystem::create_directories(d.dir, ec);
  TetMesh after = tets;
  after.points = r.tetPositionsAfter;
  const std::string base = (std::filesystem::path(d.dir) / "").string();
  std::vector<acd::TriMesh> before, moved;
  std::vector<std::string> names;
  splitByPart(surface, r.facePart, before, names);
  splitByPart(r.surfaceAfter, r.facePart, moved, names);
  for (const acd::Status& s : {acd::writeMesh(base + "surface_before.off", surface), acd::writeMesh(base + "surface_after.off", r.surfaceAfter),
                               writeVtk(base + "tets_before.vtk", tets), writeVtk(base + "tets_after.vtk", after),
                               acd::writeObjObjects(base + "parts_before.obj", before, names),
                               acd::writeObjObjects(base + "parts_after.obj", moved, names)})
    if (!s.ok()) {
      return kConsole.fail(kOutputFailed, s.message);
    }
  return kOk;
}

json deformationJson(const DeformArgs& d, const DeformationResult& r) {
  const ArapResult& a = r.arap;
  return {{"directory", d.dir},
          {"handle", r.handle},
          {"anchor", r.anchor},
          {"motion", r.motion},
          {"translation", {r.translation.x(), r.translation.y(), r.translation.z()}},
          {"angle_deg", r.angleDegrees},
          {"axis", {r.axis.x(), r.axis.y(), r.axis.z()}},
          {"pivot", {r.pivot.x(), r.pivot.y(), r.pivot.z()}},
          {"handle_vertices", r.handleVertices},
          {"anchor_vertices", r.anchorVertices},
          {"shared_vertices", r.sharedVertices},
          {"embedding",
           {{"vertices", r.embedding.tet.size()},
            {"outside", r.embedding.outside},
            {"max_outside_distance", r.embedding.maxOutsideDistance},
            {"seconds", r.embedding.seconds}}},
          {"arap",
           {{"iterations", a.iterations},
            {"min_weight", d.minWeight},
            {"converged", a.converged},
            {"energy", a.energy},
            {"free_vertices", a.freeVertices},
            {"pinned_vertices", a.pinnedVertices},
            {"inverted_tets", a.invertedTets},
            {"linear_inverted_tets", a.linearInvertedTets},
            {"inverted_rest_volume", a.invertedRestVolume},
            {"surface_vertices_in_inverted_tets", r.surfaceInInverted},
            {"surface_vertices_on_handle", r.surfaceOnHandle},
            {"surface_handle_error", r.surfaceHandleError},
            {"max_constraint_error", a.maxConstraintError},
            {"factor_seconds", a.factorSeconds},
            {"solve_seconds", a.solveSeconds}}},
          {"inverted_tets", a.invertedTets},
          {"tet_volume", {{"rest", a.restVolume}, {"after", a.volume}, {"linear", a.linearVolume}}},
          {"surface_volume", {{"rest", r.surfaceVolumeBefore}, {"after", r.surfaceVolumeAfter}, {"linear", r.surfaceVolumeLinear}}},
          {"max_surface_displacement", r.maxSurfaceDisplacement},
          {"self_intersections", {{"before", r.selfIntersectionsBefore}, {"after", r.selfIntersectionsAfter}}},
          {"seconds", r.seconds}};
}

}  // namespace tetmesh
