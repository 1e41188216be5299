// Mesh repairs before the solid decomposition (acd/repair.hpp). The topological steps that
// CGAL's Polygon Mesh Processing provides are CGAL's; what is ours is the merge of close
// vertices (CGAL 5.5 merges exact copies only) and the choice between the two sides of a
// double-sided face, which needs the faces around it.
#include <acd/algo/close_vertices.hpp>
#include <acd/algo/duplicate_faces.hpp>
#include <acd/algo/stopwatch.hpp>
#include <acd/algo/surface_mesh_copy.hpp>
#include <acd/algo/t_junctions.hpp>
#include <acd/algo/touching_solids.hpp>
#include <acd/diagnosis.hpp>
#include <acd/repair.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/stitch_borders.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace acd {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Polygon = std::array<std::size_t, 3>;

bool finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

std::string count(int n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

/// Whether steps 3 to 6 would give `mesh` back as it is: every edge used at most once in each
/// direction (an oriented surface, closed or with holes: orienting finds nothing to flip, and with
/// close vertices merged no two borders run along each other to stitch), the faces around every
/// vertex one fan (diagnose's checks), and every face clear of the needle and cap limits by a wide
/// margin (so no rounding decides).
bool cleanSurface(const TriMesh& mesh, const RepairOptions& options) {
  const double ratio2 = 0.25 * options.needleRatio * options.needleRatio;  // half the ratio, squared
  const double capCos = std::cos((options.capDegrees - 1.0) * std::acos(-1.0) / 180.0);
  for (const Face& f : mesh.faces) {
    double shortest2 = std::numeric_limits<double>::infinity(), longest2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3& a = mesh.vertices[f[k]];
      const Vec3 u = mesh.vertices[f[(k + 1) % 3]] - a, w = mesh.vertices[f[(k + 2) % 3]] - a;
      const double l2 = u.squaredNorm();
      shortest2 = std::min(shortest2, l2);
      longest2 = std::max(longest2, l2);
      if (!(u.dot(w) > capCos * std::sqrt(l2 * w.squaredNorm()))) return false;
    }
    if (!(shortest2 > 0.0 && longest2 < ratio2 * shortest2)) return false;
  }
  return pinchedVertices(mesh.faces) == 0;  // oriented, edge-manifold, one fan a vertex
}

/// Steps 3 to 6, with CGAL's polygon-soup and mesh repairs; `r.mesh` is the result. Should CGAL
/// give up, `r.mesh` is `merged`, what the steps before it made. `manifold`: `merged` is known to
/// be an oriented surface, one fan per vertex (step 3 would change nothing).
void repairWithCgal(const TriMesh& merged, const RepairOptions& options, double diagonal, bool manifold,
                    MeshRepair& r) {
  // 3. Manifold and oriented (CGAL): points are copied where edges or vertices are non-manifold.
  std::vector<Point> points;
  points.reserve(merged.vertices.size());
  for (const Vec3& p : merged.vertices) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<Polygon> polygons;
  polygons.reserve(merged.faces.size());
  for (const Face& f : merged.faces) polygons.push_back({std::size_t(f[0]), std::size_t(f[1]), std::size_t(f[2])});
  const std::vector<Polygon> before = polygons;
  std::string failure;
  SurfaceMesh sm;
  try {
    // A scan with a few cap faces is such a surface: the soup's orientation and its check (a
    // std::set of its edges) were most of its repair (ChineseDragon x2, 320k faces: ~6 s).
    if (!manifold) {
      const std::size_t pointsBefore = points.size();
      PMP::orient_polygon_soup(points, polygons);
      r.splitVertices += static_cast<int>(points.size() - pointsBefore);
      // orient_polygon_soup keeps the polygon order; a polygon is flipped when its positions run backwards.
      for (std::size_t i = 0; i < polygons.size(); ++i) {
        const Point& a = points[polygons[i][0]];
        const Polygon& b = before[i];
        const int at = points[b[0]] == a ? 0 : points[b[1]] == a ? 1 : 2;
        if (points[polygons[i][1]] != points[b[(at + 1) % 3]]) ++r.flippedFaces;
      }
      if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
        throw std::runtime_error("the oriented soup is not a polygon mesh");
    }
    PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
    // 4. Borders that run along each other.
    r.stitchedEdges = static_cast<int>(PMP::stitch_borders(sm));
    // 5. Degenerate faces: zero area (collinear corners) first, then needles and caps.
    auto degenerateCount = [&]() {
      int n = 0;
      for (auto f : sm.faces()) n += PMP::is_degenerate_triangle_face(f, sm);
      return n;
    };
    const int degenerateBefore = degenerateCount();
    if (degenerateBefore > 0) PMP::remove_degenerate_faces(sm);
    const double capCos = std::cos(options.capDegrees * std::acos(-1.0) / 180.0);
    auto almostCount = [&]() {
      int n = 0;
      for (auto f : sm.faces())
        n += PMP::is_needle_triangle_face(f, sm, options.needleRatio) != SurfaceMesh::null_halfedge() ||
             PMP::is_cap_triangle_face(f, sm, capCos) != SurfaceMesh::null_halfedge();
      return n;
    };
    const int almostBefore = almostCount();
    if (almostBefore > 0)
      PMP::experimental::remove_almost_degenerate_faces(sm, capCos, options.needleRatio,
                                                        options.collapseLength * diagonal);
    r.leftDegenerateFaces = degenerateCount();
    r.removedDegenerateFaces = std::max(0, degenerateBefore + almostBefore - r.leftDegenerateFaces - almostCount());
    // 6. Collapses can pinch the surface at a vertex: one copy per fan.
    r.splitVertices += static_cast<int>(PMP::duplicate_non_manifold_vertices(sm));
    sm.collect_garbage();
  } catch (const std::exception& e) {
    failure = e.what();
  }

  if (failure.empty()) {
    r.mesh = copyFromSurfaceMesh(sm);
  } else {
    // CGAL gave up (it should not): keep what the steps before it did; the checks that follow
    // (prepareSolid) refuse or send the mesh to the wrap.
    r.mesh = merged;
    r.repairs.push_back("mesh repair stopped early (" + failure + "); later checks decide");
  }
}

/// What the repair did, one line per kind of change, for report.json and `acd info`.
void describeRepairs(const RepairOptions& options, MeshRepair& r) {
  if (r.mergedVertices > 0)
    r.repairs.push_back("merged " + count(r.mergedVertices, "vertex", "vertices") + " lying within " +
                        std::to_string(options.mergeTolerance) + " of the model's diagonal of another vertex");
  if (r.droppedCollapsedFaces > 0)
    r.repairs.push_back("dropped " + count(r.droppedCollapsedFaces, "zero-area face", "zero-area faces") +
                        " with a repeated vertex");
  if (r.droppedDuplicateFaces > 0)
    r.repairs.push_back("dropped " + count(r.droppedDuplicateFaces, "duplicate face", "duplicate faces") +
                        " (the same triangle twice)");
  if (r.doubleSidedKeptOne > 0)
    r.repairs.push_back("double-sided faces: dropped the reverse side of " +
                        count(r.doubleSidedKeptOne, "face", "faces") + " given in both orientations");
  if (r.doubleSidedDroppedBoth > 0)
    r.repairs.push_back("double-sided faces: dropped both sides of " +
                        count(r.doubleSidedDroppedBoth, "face", "faces") +
                        " given in both orientations that close nothing (an inner wall)");
  if (r.tJunctionEdges > 0)
    r.repairs.push_back("T-junctions: split " + count(r.tJunctionEdges, "boundary edge", "boundary edges") +
                        " at the " + count(r.tJunctionVertices, "vertex", "vertices") +
                        " of the other side of the seam lying on them (a crack of zero width)");
  if (r.splitVertices > 0)
    r.repairs.push_back("split non-manifold edges and vertices: " + count(r.splitVertices, "vertex", "vertices") +
                        " copied so that each sheet has its own");
  if (r.flippedFaces > 0)
    r.repairs.push_back("oriented: flipped " + count(r.flippedFaces, "face", "faces") +
                        " to agree with their neighbours");
  if (r.stitchedEdges > 0)
    r.repairs.push_back("stitched " + count(r.stitchedEdges, "pair", "pairs") + " of boundary edges");
  if (r.removedDegenerateFaces > 0)
    r.repairs.push_back("removed " +
                        count(r.removedDegenerateFaces, "zero-area or needle face", "zero-area or needle faces") +
                        " by edge collapse or flip");
  if (r.leftDegenerateFaces > 0)
    r.repairs.push_back(count(r.leftDegenerateFaces, "zero-area face", "zero-area faces") + " could not be removed");
}

}  // namespace

MeshRepair repairMesh(const TriMesh& input, const RepairOptions& options) {
  const auto start = acd::Clock::now();
  MeshRepair r;
  auto refuse = [&](StatusCode code, std::string message) {
    r.status = Status::error(code, std::move(message));
    r.mesh = TriMesh{};
    return r;
  };
  const int nv = static_cast<int>(input.vertices.size());
  if (input.faces.empty()) return refuse(StatusCode::EmptyMesh, "mesh has no faces");
  for (int v = 0; v < nv; ++v)
    if (!finite(input.vertices[v]))
      return refuse(StatusCode::NonFiniteVertex, "vertex " + std::to_string(v) + " has a non-finite coordinate");
  for (int f = 0; f < static_cast<int>(input.faces.size()); ++f)
    for (int v : input.faces[f])
      if (v < 0 || v >= nv)
        return refuse(StatusCode::IndexOutOfRange, "face " + std::to_string(f) + " refers to vertex " +
                                                       std::to_string(v) + " but the mesh has " + std::to_string(nv) +
                                                       " vertices");
  const TriMesh used = compact(input);
  const Box3 box = boundingBox(used);
  const double diagonal = box.size().norm();

  // 1. Close vertices.
  const std::vector<int> rep = closeVertexRoots(used.vertices, box, options.mergeTolerance * diagonal);
  for (int v = 0; v < static_cast<int>(rep.size()); ++v) r.mergedVertices += rep[v] != v;
  std::vector<Face> faces;
  faces.reserve(used.faces.size());
  for (Face f : used.faces) {
    for (int& v : f) v = rep[v];
    if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) {
      ++r.droppedCollapsedFaces;
      continue;
    }
    faces.push_back(f);
  }
  // 2. Copies and double-sided faces.
  DuplicateOutcome dup = resolveDuplicates(faces);
  r.droppedDuplicateFaces = dup.exactCopies;
  r.doubleSidedKeptOne = dup.keptOne;
  r.doubleSidedDroppedBoth = dup.droppedBoth;
  faces = std::move(dup.faces);
  if (faces.empty()) return refuse(StatusCode::EmptyMesh, "mesh has no faces left after dropping degenerate faces");
  // T-junctions: cracks of zero width between faces meshed apart close edge for edge.
  TJunctionSplit cracks = splitTJunctions(used.vertices, faces, options.mergeTolerance * diagonal);
  r.tJunctionEdges = cracks.splitEdges;
  r.tJunctionVertices = cracks.splitVertices;
  faces = std::move(cracks.faces);
  // The merged-away vertices go; with nothing merged, dropped or split, every vertex is still
  // used and compacting would give the mesh back as it is.
  const bool unchanged = r.mergedVertices == 0 && r.droppedCollapsedFaces == 0 && dup.exactCopies == 0 &&
                         dup.keptOne == 0 && dup.droppedBoth == 0 && cracks.splitEdges == 0;
  const TriMesh merged = unchanged ? TriMesh{used.vertices, std::move(faces)} : compact(TriMesh{used.vertices, faces});

  if (options.skipWhenClean && cleanSurface(merged, options)) {
    // As CGAL's Surface_mesh gives a triangle back: from its last corner.
    r.mesh = merged;
    r.clean = options.mergeTolerance * diagonal > 0.0;  // then no two vertices share a position
    for (Face& f : r.mesh.faces) f = {f[2], f[0], f[1]};
  } else {
    // Parts welded where they touch along an edge come apart first, each face glued to the one
    // that bounds its material; CGAL's soup repair would pair them in file order.
    const TouchingSolidsSplit parts = splitTouchingSolids(merged);
    r.splitVertices = parts.copiedVertices;
    const bool manifold = options.skipWhenClean && pinchedVertices(parts.mesh.faces) == 0;
    repairWithCgal(parts.mesh, options, diagonal, manifold, r);
  }

  describeRepairs(options, r);
  r.status = Status::success();
  r.seconds = acd::secondsSince(start);
  return r;
}

}  // namespace acd
