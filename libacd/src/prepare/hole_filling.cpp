// Hole filling with CGAL Polygon Mesh Processing on a Surface_mesh copy of the input.
#define CGAL_EIGEN3_ENABLED 1  // fairing solves a sparse system with Eigen (linked publicly by libacd)
#include <acd/algo/hole_filling.hpp>

#include <acd/algo/surface_mesh_copy.hpp>
#include <acd/diagnosis.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <Eigen/Eigenvalues>

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

Vec3 toVec(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

/// How a loop is closed, tried in this order: a faired patch follows the surrounding curvature; a
/// flat one (the minimum-area triangulation of the loop) stays close to the loop; a fan from a new
/// vertex at the loop's centre needs no triangle on three loop vertices, which for loops that
/// run straight through their vertices (a triangular hole of a subdivided model) may be all the
/// other two can find. A loop that lies in a plane starts flat: a missing face of a CAD part is
/// closed by that face, where fairing would bulge it out towards the curvature of the corners
/// around it.
enum class Patch { Faired, Flat, Fan };

/// A loop lies in a plane when its vertices stand off their least-squares plane by at most this
/// share of the loop's extent: exactly planar up to the rounding of a file's coordinates.
constexpr double kPlanarLoop = 1e-6;

bool planarLoop(const Mesh& m, Mesh::Halfedge_index border) {
  std::vector<Vec3> points;
  for (Mesh::Halfedge_index h : CGAL::halfedges_around_face(border, m)) points.push_back(toVec(m.point(m.target(h))));
  Vec3 mean = Vec3::Zero();
  Box3 box;
  box.lo = box.hi = points.front();
  for (const Vec3& p : points) mean += p, box.lo = box.lo.cwiseMin(p), box.hi = box.hi.cwiseMax(p);
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) covariance += (p - mean) * (p - mean).transpose();
  const Vec3 normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(0);
  double off = 0.0;
  for (const Vec3& p : points) off = std::max(off, std::abs(normal.dot(p - mean)));
  return off <= kPlanarLoop * box.size().norm();
}

struct Filled {
  Mesh mesh;
  std::vector<int> loopOfFace;  // per face: the hole whose patch made it, -1 for input faces
  int failedLoop = -1;          // a hole that found no triangulation
  int addedVertices = 0, unfaired = 0;
};

bool zeroArea(const Mesh& m, Mesh::Halfedge_index h, double squaredDiag) {
  const std::vector<Vec3> corners = {toVec(m.point(m.source(h))), toVec(m.point(m.target(h))),
                                     toVec(m.point(m.target(m.next(h))))};
  return hasZeroArea(corners, Face{0, 1, 2}, squaredDiag);
}

/// A patch triangle on three loop vertices that lie on a line (the loop runs straight through a
/// vertex, as on a subdivided model) has no area, and prepareSolid would refuse it. Flipping its
/// longest edge, which a patch triangle on the other side shares, turns the two into proper
/// triangles covering the same surface. Faces keep their indices.
void flipZeroAreaFaces(Mesh& m, const std::vector<Mesh::Face_index>& patch, double squaredDiag) {
  std::vector<char> inPatch(m.number_of_faces(), 0);
  for (Mesh::Face_index f : patch) inPatch[f.idx()] = 1;
  for (int pass = 0; pass < 4; ++pass) {
    bool flipped = false;
    for (Mesh::Face_index f : patch) {
      Mesh::Halfedge_index longest = m.halfedge(f);
      if (!zeroArea(m, longest, squaredDiag)) continue;
      for (Mesh::Halfedge_index h : CGAL::halfedges_around_face(m.halfedge(f), m))
        if (CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h))) >
            CGAL::squared_distance(m.point(m.source(longest)), m.point(m.target(longest))))
          longest = h;
      const Mesh::Halfedge_index across = m.opposite(longest);
      if (m.is_border(across) || !inPatch[m.face(across).idx()]) continue;
      const Mesh::Vertex_index apex = m.target(m.next(longest)), otherApex = m.target(m.next(across));
      if (CGAL::halfedge(apex, otherApex, m).second) continue;  // that edge exists: no flip
      CGAL::Euler::flip_edge(longest, m);
      if (zeroArea(m, longest, squaredDiag) || zeroArea(m, across, squaredDiag)) {
        CGAL::Euler::flip_edge(longest, m);  // no better: back
        continue;
      }
      flipped = true;
    }
    if (!flipped) return;
  }
}

/// Closes the loop of `border` with a fan from a new vertex at the mean of its vertices.
std::vector<Mesh::Face_index> fanFromCentre(Mesh& m, Mesh::Halfedge_index border) {
  Kernel::Vector_3 sum(0, 0, 0);
  int n = 0;
  for (Mesh::Halfedge_index h : CGAL::halfedges_around_face(border, m))
    sum = sum + (m.point(m.target(h)) - CGAL::ORIGIN), ++n;
  CGAL::Euler::fill_hole(border, m);
  const Mesh::Halfedge_index spoke = CGAL::Euler::add_center_vertex(border, m);
  m.point(m.target(spoke)) = CGAL::ORIGIN + sum / n;
  std::vector<Mesh::Face_index> faces;
  for (Mesh::Face_index f : CGAL::faces_around_target(spoke, m)) faces.push_back(f);
  return faces;
}

/// Fills every loop (one border halfedge each, valid in a fresh copy of the input) in the given way.
Filled fillLoops(const Mesh& input, const std::vector<Mesh::Halfedge_index>& loops, const std::vector<Patch>& how,
                 double squaredDiag) {
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
    } else if (how[i] == Patch::Flat) {
      PMP::triangulate_hole(out.mesh, loops[i], std::back_inserter(faces));
    } else {
      faces = fanFromCentre(out.mesh, loops[i]);
      ++out.addedVertices;
    }
    if (faces.empty()) {
      out.failedLoop = static_cast<int>(i);
      return out;
    }
    flipZeroAreaFaces(out.mesh, faces, squaredDiag);
    out.addedVertices += static_cast<int>(vertices.size());
    out.loopOfFace.resize(out.mesh.number_of_faces(), -1);
    for (Mesh::Face_index f : faces) out.loopOfFace[f.idx()] = static_cast<int>(i);
  }
  return out;
}

enum class Flaw : char { None, ZeroArea, Crossing };

/// Per hole, what is wrong with its patch: a face that intersects any other face (intersections
/// among input faces are the input's own), or else a face with no area.
std::vector<Flaw> flawedLoops(const Filled& filled, std::size_t loops, double squaredDiag) {
  std::vector<Flaw> flaw(loops, Flaw::None);
  for (Mesh::Face_index f : filled.mesh.faces())
    if (f.idx() < filled.loopOfFace.size() && filled.loopOfFace[f.idx()] >= 0 &&
        zeroArea(filled.mesh, filled.mesh.halfedge(f), squaredDiag))
      flaw[filled.loopOfFace[f.idx()]] = Flaw::ZeroArea;
  // The patches' faces against every face (not every pair of the mesh: a few patch faces on a
  // scan of a million would pay for all its pairs). Nothing was removed: index i is face i.
  std::vector<int> patchFaces;
  for (std::size_t f = 0; f < filled.loopOfFace.size(); ++f)
    if (filled.loopOfFace[f] >= 0) patchFaces.push_back(static_cast<int>(f));
  for (int f : facesCrossingOthers(copyFromSurfaceMesh(filled.mesh), patchFaces))
    flaw[filled.loopOfFace[f]] = Flaw::Crossing;
  return flaw;
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
    return refuse("cannot fill holes: face " + std::to_string(badFace) + " does not fit an oriented manifold surface");

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
  // Each loop's patch in the first way of `Patch` that gives it neither a face through the model
  // nor one without area.
  std::vector<Patch> how(loops.size(), Patch::Faired);
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (planarLoop(m, loops[i])) how[i] = Patch::Flat;
  const double squaredDiag = boundingBox(input).size().squaredNorm();
  Filled filled;
  for (int round = 0;; ++round) {
    filled = fillLoops(m, loops, how, squaredDiag);
    if (filled.failedLoop >= 0)
      return refuse("cannot fill " + describeLoop(m, loops[filled.failedLoop], lengths[filled.failedLoop]) +
                    ": no triangulation found");
    const std::vector<Flaw> flaw = flawedLoops(filled, loops.size(), squaredDiag);
    int flawed = 0, first = -1;
    bool crossing = false;
    for (std::size_t i = 0; i < loops.size(); ++i)
      if (flaw[i] != Flaw::None) {
        ++flawed;
        if (first < 0) first = static_cast<int>(i);
        crossing = crossing || flaw[i] == Flaw::Crossing;
        how[i] = how[i] == Patch::Faired ? Patch::Flat : Patch::Fan;
      }
    if (flawed == 0) break;
    if (round == 2)
      return refuse("cannot close " + std::to_string(flawed) + " of the " + std::to_string(loops.size()) + " holes " +
                    (crossing ? "without the patch passing through the surface" : "without a patch face of no area") +
                    " (first: " + describeLoop(m, loops[first], lengths[first]) + ")");
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
    for (Mesh::Vertex_index v : filled.mesh.vertices_around_face(filled.mesh.halfedge(f)))
      t[k++] = static_cast<int>(v.idx());
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
