// Exact convex decomposition with CGAL's convex_decomposition_3 (Nef polyhedra, exact kernel), in
// the calling process: the input's checks, the decomposition solid by solid (telling a listener
// its stages and pieces), the pieces' hulls. The capped run in a child process is the sandbox's
// (sandbox/src/exact_solid.cpp). This is the only translation unit that includes the Nef headers
// (they compile slowly).
#include <acd/algo/surface_mesh_copy.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/exact_decomposition.hpp>
#include <acd/algo/hull.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_decomposition_3.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace acd {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Nef = CGAL::Nef_polyhedron_3<Kernel>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

// Collects the vertices of one shell (CGAL's shell-visitor interface).
struct ShellPoints {
  std::vector<Vec3>* out;
  void visit(Nef::Vertex_const_handle v) {
    const auto& p = v->point();
    out->emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  void visit(Nef::Halfedge_const_handle) {}
  void visit(Nef::Halffacet_const_handle) {}
  void visit(Nef::SHalfedge_const_handle) {}
  void visit(Nef::SHalfloop_const_handle) {}
  void visit(Nef::SFace_const_handle) {}
};

Nef toNef(const TriMesh& mesh) {
  SurfaceMesh sm;
  copyToSurfaceMesh(mesh, sm, RefusedFace::Skip);
  return Nef(sm);
}

const char* stageName(ExactStage stage) {
  switch (stage) {
    case ExactStage::Building: return "building the Nef polyhedron of";
    case ExactStage::Decomposing: return "decomposing";
    case ExactStage::Extracting: return "extracting the pieces of";
    case ExactStage::Starting: break;
  }
  return "starting on";
}

}  // namespace

std::string exactStageText(ExactStage stage, std::size_t solid, std::size_t solids) {
  return std::string(stageName(stage)) + " solid " + std::to_string(solid + 1) + " of " + std::to_string(solids);
}

ExactDecomposition prepareExactSolids(const TriMesh& mesh, const ExactOptions& options, std::vector<TriMesh>& solids) {
  ExactDecomposition out;
  solids.clear();
  PrepareOptions prepare;
  prepare.openMeshes = options.fillHoles ? OpenMeshPolicy::FillHoles : OpenMeshPolicy::Refuse;
  PreparedSolid prepared = prepareSolid(mesh, prepare);
  if (!prepared.status.ok()) {
    out.status = prepared.status;
    return out;
  }
  out.holesFilled = prepared.holesFilled;
  out.repairs = prepared.repairs;
  TriMesh all;  // the repaired solids together: self-intersections between them count too
  for (const TriMesh& c : prepared.components) {
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), c.vertices.begin(), c.vertices.end());
    for (const Face& f : c.faces) all.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  if (countSelfIntersections(all, 1) > 0) {
    out.status = Status::error(StatusCode::DegenerateFace,
                               "the surface intersects itself (see `acd info`): it bounds no solid that an exact "
                               "decomposition could partition");
    return out;
  }
  out.solids = prepared.components.size();
  out.reflexEdges = countNotches(all);
  solids = std::move(prepared.components);
  return out;
}

void decomposeExactSolids(const std::vector<TriMesh>& solids, std::size_t maxPieces, ExactListener& listener) {
  std::size_t sent = 0;
  for (std::size_t s = 0; s < solids.size(); ++s) {
    listener.stage(ExactStage::Building, s);
    Nef nef = toNef(solids[s]);
    if (!nef.is_simple()) throw std::runtime_error("solid " + std::to_string(s) + " is not a 2-manifold Nef polyhedron");
    listener.stage(ExactStage::Decomposing, s);
    CGAL::convex_decomposition_3(nef);
    listener.stage(ExactStage::Extracting, s);
    std::uint64_t pieces = 0;
    // The first volume is the unbounded outside; marked volumes are the convex pieces.
    for (auto c = ++nef.volumes_begin(); c != nef.volumes_end(); ++c) {
      if (!c->mark()) continue;
      ++pieces;
      if (sent >= maxPieces) continue;
      std::vector<Vec3> points;
      ShellPoints visitor{&points};
      for (auto shell = c->shells_begin(); shell != c->shells_end(); ++shell)
        nef.visit_shell_objects(Nef::SFace_const_handle(shell), visitor);
      listener.piece(points);
      ++sent;
    }
    listener.solidDone(s, pieces);
  }
}

std::size_t addExactPieces(const std::vector<std::vector<Vec3>>& vertexSets, ExactDecomposition& out) {
  std::size_t degenerate = 0;
  for (const auto& points : vertexSets) {
    TriMesh hull = hullMesh(points);
    if (hull.faces.empty()) {
      ++degenerate;  // a sliver flattened by rounding to doubles
      continue;
    }
    out.pieces.push_back(std::move(hull));
  }
  if (degenerate > 0)
    out.note += (out.note.empty() ? "" : "; ") + std::to_string(degenerate) +
                " sliver pieces have no volume in double precision and were left out";
  return degenerate;
}

}  // namespace acd
