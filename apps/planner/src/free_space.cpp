// CGAL-heavy code (exact kernel, corefinement, Nef polyhedra) kept in this one translation unit.
#include "free_space.hpp"

#include <acd/algo/surface_mesh_copy.hpp>
#include <acd/algo/shapes.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Nef_polyhedron_3.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/convert_nef_polyhedron_to_polygon_mesh.h>

#include <algorithm>
#include <map>

namespace planner {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Nef = CGAL::Nef_polyhedron_3<Kernel>;
namespace PMP = CGAL::Polygon_mesh_processing;

/// The library's one TriMesh -> Surface_mesh copy; a face CGAL refuses is left out (the
/// obstacles and boxes here are closed, oriented solids, so none is).
Mesh toCgal(const acd::TriMesh& m) {
  Mesh out;
  acd::copyToSurfaceMesh(m, out, acd::RefusedFace::Skip);
  return out;
}

/// The mesh in a form that depends on its exact geometry only, not on how CGAL got there.
/// The corefinement's inner order follows memory addresses (its bounding boxes are told apart
/// by address), so the same Boolean can list its vertices and faces in another order from one
/// call to the next, and build its intersection points by other chains of lazy constructions,
/// whose double approximations differ in the last bits. Hence: each coordinate is the exact
/// value rounded, vertices are sorted by exact position (lexicographically), each face starts
/// at its smallest vertex (orientation kept) and the faces are sorted.
acd::TriMesh fromCgal(Mesh m) {
  PMP::triangulate_faces(m);
  std::vector<Mesh::Vertex_index> order;
  for (Mesh::Vertex_index v : m.vertices()) {
    CGAL::exact(m.point(v));  // the approximation becomes the exact value's tight interval
    order.push_back(v);
  }
  std::sort(order.begin(), order.end(), [&](Mesh::Vertex_index a, Mesh::Vertex_index b) {
    return CGAL::compare_xyz(m.point(a), m.point(b)) == CGAL::SMALLER;
  });
  acd::TriMesh out;
  std::map<Mesh::Vertex_index, int> index;
  for (Mesh::Vertex_index v : order) {
    const Point& p = m.point(v);
    index[v] = static_cast<int>(out.vertices.size());
    out.vertices.emplace_back(CGAL::to_double(CGAL::exact(p.x())), CGAL::to_double(CGAL::exact(p.y())),
                              CGAL::to_double(CGAL::exact(p.z())));
  }
  for (Mesh::Face_index f : m.faces()) {
    acd::Face tri{};
    int k = 0;
    for (Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) tri[k++] = index[v];
    const int first = static_cast<int>(std::min_element(tri.begin(), tri.end()) - tri.begin());
    std::rotate(tri.begin(), tri.begin() + first, tri.end());
    out.faces.push_back(tri);
  }
  std::sort(out.faces.begin(), out.faces.end());
  return acd::compact(out);
}

bool checkObstacle(const acd::TriMesh& m, const std::string& name, std::string& error) {
  if (m.empty()) {
    error = "obstacle " + name + " has no faces";
    return false;
  }
  if (!acd::isClosedOriented(m)) {
    error = "obstacle " + name + " is not a closed, consistently oriented mesh";
    return false;
  }
  return true;
}

FreeSpace viaCorefinement(const Mesh& box, const std::vector<Mesh>& obstacles) {
  FreeSpace out;
  Mesh result = box;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    Mesh obstacle = obstacles[i];
    Mesh next;
    if (!PMP::corefine_and_compute_difference(result, obstacle, next)) return out;
    result = std::move(next);
  }
  out.ok = true;
  out.method = "corefinement";
  out.mesh = fromCgal(std::move(result));
  return out;
}

FreeSpace viaNef(const Mesh& box, const std::vector<Mesh>& obstacles) {
  FreeSpace out;
  Nef free(box);
  for (const Mesh& o : obstacles) free -= Nef(o);
  free.regularization();
  if (!free.is_simple()) {
    out.error = "the free space is not a 2-manifold (obstacles meet the free space along an edge or a corner)";
    return out;
  }
  Mesh result;
  CGAL::convert_nef_polyhedron_to_polygon_mesh(free, result, true);
  out.ok = true;
  out.method = "nef";
  out.mesh = fromCgal(std::move(result));
  return out;
}

/// Shells of negative volume: the boundaries of cavities.
std::vector<acd::TriMesh> cavitiesOf(const acd::TriMesh& m) {
  std::vector<acd::TriMesh> out;
  for (acd::TriMesh& shell : acd::splitEdgeConnected(m))
    if (acd::signedVolume(shell) < 0) out.push_back(std::move(shell));
  return out;
}

/// The part of `piece` on one side of the plane x[axis] = at, as a closed mesh.
bool clipped(const acd::TriMesh& piece, int axis, double at, bool below, acd::TriMesh& out) {
  acd::Box3 half = acd::boundingBox(piece);
  const acd::Vec3 margin = acd::Vec3::Constant(0.1 * half.size().norm() + 1.0);
  half.lo -= margin, half.hi += margin;
  (below ? half.hi : half.lo)[axis] = at;
  Mesh a = toCgal(piece), b = toCgal(acd::shapes::box(half.lo, half.hi)), result;
  if (!PMP::corefine_and_compute_intersection(a, b, result)) return false;
  out = fromCgal(std::move(result));
  return out.empty() || acd::isClosedOriented(out);
}

}  // namespace

std::vector<acd::TriMesh> cavityFreePieces(const acd::TriMesh& freeSpace, std::string& error) {
  std::vector<acd::TriMesh> done, pending{freeSpace};
  while (!pending.empty()) {
    acd::TriMesh piece = std::move(pending.back());
    pending.pop_back();
    const std::vector<acd::TriMesh> cavities = cavitiesOf(piece);
    if (cavities.empty()) {
      done.push_back(std::move(piece));
      continue;
    }
    // A plane across the first cavity's box, along its longest side, splits the cavity's
    // boundary and joins each half to the cut face. Off-centre by an odd fraction so that it
    // does not run along the faces of the grid-aligned models people make.
    const acd::Box3 box = acd::boundingBox(cavities.front());
    int axis = 0;
    box.size().maxCoeff(&axis);
    bool cut = false;
    for (int attempt = 0; attempt < 3 && !cut; ++attempt) {
      const int a = (axis + attempt) % 3;
      const double at = box.lo[a] + (0.5 + 0.0173 * (attempt + 1)) * box.size()[a];
      acd::TriMesh below, above;
      if (!clipped(piece, a, at, true, below) || !clipped(piece, a, at, false, above)) continue;
      if (cavitiesOf(below).size() + cavitiesOf(above).size() >= cavities.size()) continue;  // no progress
      for (acd::TriMesh* half : {&below, &above})
        if (!half->empty()) pending.push_back(std::move(*half));
      cut = true;
    }
    if (!cut) {
      error = "cannot cut the free space through the cavity around " + std::to_string(box.center().x()) + ", " +
              std::to_string(box.center().y()) + ", " + std::to_string(box.center().z());
      return {};
    }
  }
  return done;
}

FreeSpace buildFreeSpace(const acd::Box3& workspace, const std::vector<acd::TriMesh>& obstacles,
                         const std::vector<std::string>& names) {
  FreeSpace out;
  if (!((workspace.hi - workspace.lo).array() > 0).all()) {
    out.error = "the workspace bounds are empty";
    return out;
  }
  std::vector<Mesh> cgalObstacles;
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const std::string name = i < names.size() ? names[i] : "#" + std::to_string(i);
    if (!checkObstacle(obstacles[i], name, out.error)) return out;
    Mesh m = toCgal(obstacles[i]);
    if (!CGAL::is_closed(m) || !PMP::is_outward_oriented(m)) {
      out.error = "obstacle " + name + " is not closed and outward oriented";
      return out;
    }
    if (PMP::does_self_intersect(m)) {
      out.error = "obstacle " + name + " intersects itself";
      return out;
    }
    cgalObstacles.push_back(std::move(m));
  }
  const Mesh box = toCgal(acd::shapes::box(workspace.lo, workspace.hi));
  out = viaCorefinement(box, cgalObstacles);
  if (!out.ok) out = viaNef(box, cgalObstacles);
  if (out.ok && out.mesh.empty()) {
    out.ok = false;
    out.error = "the obstacles fill the whole workspace: no free space";
  }
  if (out.ok && !acd::isClosedOriented(out.mesh)) {
    out.ok = false;
    out.error = "the free space computed with " + out.method + " is not a closed oriented mesh";
  }
  return out;
}

}  // namespace planner
