// Hole filling with CGAL Polygon Mesh Processing on a Surface_mesh copy of the input.
#define CGAL_EIGEN3_ENABLED 1  // fairing solves a sparse system with Eigen (linked publicly by libacd)
#include <acd/algo/hole_filling.hpp>

#include <acd/algo/surface_mesh_copy.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <iterator>
#include <sstream>
#include <unordered_map>
#include <vector>

namespace acd {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

std::string describeLoop(const Mesh& m, Mesh::Halfedge_index h, int length) {
  std::ostringstream s;
  s << "the hole through vertices " << m.source(h).idx() << "-" << m.target(h).idx() << " (" << length
    << " boundary edges)";
  return s.str();
}

enum class Patch { Faired, Flat };

struct Filled {
  Mesh mesh;
  std::vector<int> loopOfFace;  // per face: the hole whose patch made it, -1 for input faces
  int failedLoop = -1;          // a hole that found no triangulation
  int addedVertices = 0, unfaired = 0;
};

/// Fills every loop (one border halfedge each, valid in a fresh copy of the input) in the given way.
Filled fillLoops(const Mesh& input, const std::vector<Mesh::Halfedge_index>& loops, const std::vector<Patch>& how) {
  Filled out;
  out.mesh = input;
  out.loopOfFace.assign(input.number_of_faces(), -1);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    std::vector<Mesh::Face_index> faces;
    std::vector<Mesh::Vertex_index> vertices;
    if (how[i] == Patch::Faired) {
      const auto result = PMP::triangulate_refine_and_fair_hole(out.mesh, loops[i], std::back_inserter(faces),
                                                                std::back_inserter(vertices));
      if (!std::get<0>(result)) ++out.unfaired;
    } else {
      PMP::triangulate_hole(out.mesh, loops[i], std::back_inserter(faces));
    }
    if (faces.empty()) {
      out.failedLoop = static_cast<int>(i);
      return out;
    }
    out.addedVertices += static_cast<int>(vertices.size());
    out.loopOfFace.resize(out.mesh.number_of_faces(), -1);
    for (Mesh::Face_index f : faces) out.loopOfFace[f.idx()] = static_cast<int>(i);
  }
  return out;
}

/// Holes whose patch intersects any other face (intersections among input faces are the input's own).
std::vector<char> intersectingLoops(const Filled& filled, std::size_t loops) {
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  PMP::self_intersections(filled.mesh, std::back_inserter(pairs));
  std::vector<char> bad(loops, 0);
  for (const auto& [a, b] : pairs)
    for (Mesh::Face_index f : {a, b})
      if (filled.loopOfFace[f.idx()] >= 0) bad[filled.loopOfFace[f.idx()]] = 1;
  return bad;
}

}  // namespace

HoleFilling fillHoles(const TriMesh& input) {
  HoleFilling out;
  auto refuse = [&](std::string message) {
    out.status = Status::error(StatusCode::OpenMesh, std::move(message));
    out.mesh = TriMesh{};
    return out;
  };
  Mesh m;
  if (const long badFace = copyToSurfaceMesh(input, m); badFace >= 0)
    return refuse("cannot fill holes: face " + std::to_string(badFace) +
                  " does not fit an oriented manifold surface");

  // One halfedge per boundary loop, collected before any patch changes the mesh.
  std::vector<Mesh::Halfedge_index> loops;
  std::vector<int> lengths;
  {
    std::vector<char> seen(m.number_of_halfedges(), 0);
    for (Mesh::Halfedge_index h : m.halfedges()) {
      if (!m.is_border(h) || seen[h.idx()]) continue;
      int length = 0;
      for (Mesh::Halfedge_index g = h; !seen[g.idx()]; g = m.next(g)) seen[g.idx()] = 1, ++length;
      loops.push_back(h);
      lengths.push_back(length);
    }
  }
  // Faired patches first (they follow the surrounding curvature); a faired patch that cuts through
  // the model is replaced by the minimum-area triangulation of its loop, which stays close to the loop.
  std::vector<Patch> how(loops.size(), Patch::Faired);
  Filled filled;
  for (int round = 0; round < 2; ++round) {
    filled = fillLoops(m, loops, how);
    if (filled.failedLoop >= 0)
      return refuse("cannot fill " + describeLoop(m, loops[filled.failedLoop], lengths[filled.failedLoop]) +
                    ": no triangulation found");
    const std::vector<char> bad = intersectingLoops(filled, loops.size());
    int badCount = 0, first = -1;
    for (std::size_t i = 0; i < loops.size(); ++i)
      if (bad[i]) {
        ++badCount;
        if (first < 0) first = static_cast<int>(i);
        how[i] = Patch::Flat;
      }
    if (badCount == 0) break;
    if (round == 1)
      return refuse("cannot close " + std::to_string(badCount) + " of the " + std::to_string(loops.size()) +
                    " holes without the patch passing through the surface (first: " +
                    describeLoop(m, loops[first], lengths[first]) + ")");
  }
  for (Mesh::Halfedge_index h : filled.mesh.halfedges())
    if (filled.mesh.is_border(h)) return refuse("hole filling left boundary edges (a hole touches itself at a vertex)");

  // The input's vertices and faces keep their indices (Surface_mesh appends and nothing was removed).
  out.mesh.vertices.reserve(filled.mesh.number_of_vertices());
  for (Mesh::Vertex_index v : filled.mesh.vertices()) {
    const Point& p = filled.mesh.point(v);
    out.mesh.vertices.emplace_back(p.x(), p.y(), p.z());
    if (!out.mesh.vertices.back().allFinite()) return refuse("hole filling produced a non-finite vertex");
  }
  out.mesh.faces = input.faces;
  for (Mesh::Face_index f : filled.mesh.faces()) {
    if (f.idx() < input.faces.size()) continue;
    Face t{};
    int k = 0;
    for (Mesh::Vertex_index v : filled.mesh.vertices_around_face(filled.mesh.halfedge(f))) t[k++] = static_cast<int>(v.idx());
    out.mesh.faces.push_back(t);
  }
  out.holes = static_cast<int>(loops.size());
  out.addedFaces = static_cast<int>(out.mesh.faces.size() - input.faces.size());
  out.addedVertices = filled.addedVertices;
  out.unfairedHoles = filled.unfaired;
  const double extent = boundingBox(out.mesh).size().maxCoeff();
  if (!(std::abs(signedVolume(out.mesh)) > 1e-9 * extent * extent * extent))
    return refuse("the closed surface encloses no volume: the mesh is a sheet, not the boundary of a solid with holes");
  out.status = Status::success();
  return out;
}

}  // namespace acd
