// The union of meeting shells by corefinement in exact arithmetic (acd/algo/shell_union.hpp). Its
// own translation unit: CGAL's corefinement with an exact kernel is slow to compile.
#include <acd/algo/shell_union.hpp>
#include <acd/algo/stopwatch.hpp>

#include <acd/algo/canonical_frame.hpp>
#include <acd/algo/surface_mesh_copy.hpp>
#include <acd/algo/union_find.hpp>
#include <acd/diagnosis.hpp>
#include <acd/repair.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <optional>

namespace acd {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactMesh = CGAL::Surface_mesh<Kernel::Point_3>;

TriMesh toTriMesh(const ExactMesh& in) {
  TriMesh out;
  std::map<ExactMesh::Vertex_index, int> index;
  for (auto v : in.vertices()) {
    // The nearest doubles to the exact coordinates: a lazy number's own to_double may give its
    // interval's approximation, which depends on what was evaluated before (and so on threads).
    const auto& p = CGAL::exact(in.point(v));
    index[v] = static_cast<int>(out.vertices.size());
    out.vertices.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  for (auto f : in.faces()) {
    const auto h = in.halfedge(f);
    out.faces.push_back({index[in.source(h)], index[in.target(h)], index[in.target(in.next(h))]});
  }
  return out;
}

/// The mesh with its vertices in lexicographic order of their exact coordinates, each face from
/// its smallest vertex, faces sorted. CGAL's corefinement gives the same surface in an order that
/// changes from run to run (it follows memory addresses: chair_model.obj's union came out in a
/// different order on each of four calls in one process), and what comes after it (the next
/// union, the rounding repairs) follows the order.
ExactMesh inCanonicalOrder(const ExactMesh& in) {
  std::vector<ExactMesh::Vertex_index> vertices(in.vertices().begin(), in.vertices().end());
  std::stable_sort(vertices.begin(), vertices.end(), [&](ExactMesh::Vertex_index a, ExactMesh::Vertex_index b) {
    return CGAL::lexicographically_xyz_smaller(in.point(a), in.point(b));
  });
  ExactMesh out;
  std::map<ExactMesh::Vertex_index, int> rank;
  std::vector<ExactMesh::Vertex_index> added;
  for (ExactMesh::Vertex_index v : vertices) {
    rank[v] = static_cast<int>(added.size());
    added.push_back(out.add_vertex(in.point(v)));
  }
  std::vector<std::array<int, 3>> faces;
  for (auto f : in.faces()) {
    const auto h = in.halfedge(f);
    std::array<int, 3> t = {rank[in.source(h)], rank[in.target(h)], rank[in.target(in.next(h))]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  for (const auto& t : faces)
    if (out.add_face(added[t[0]], added[t[1]], added[t[2]]) == ExactMesh::null_face())
      return in;  // a fan this order cannot link (not met so far): the surface as it came
  return out;
}

bool boxesMeet(const Box3& a, const Box3& b) {
  return (a.lo.array() <= b.hi.array()).all() && (b.lo.array() <= a.hi.array()).all();
}

/// The shells as everything below sees them (`work`), the order they are united in, and the way
/// back to the input's coordinates. With `invariant`, each shell in canonical form in the frame
/// turned onto the assembly's largest planes (faceAlignedFrame), shells in canonical order: the
/// union's input is then the same, bit for bit, in every pose and order. In that frame the planes
/// in which CAD shells touch (the axis planes of the part) keep exact coordinates: rounded in an
/// arbitrary frame, touching shells would cross one another by a grid step, and in a rotated
/// input by an ulp, and the union would be full of slivers.
std::optional<CanonicalInverse> canonicalWork(const std::vector<TriMesh>& shells, bool invariant,
                                              std::vector<TriMesh>& work, std::vector<int>& order) {
  const int n = static_cast<int>(shells.size());
  order.resize(n);
  std::iota(order.begin(), order.end(), 0);
  if (!invariant) {
    work = shells;
    return std::nullopt;
  }
  work.assign(n, TriMesh());
  const Normalization frame = faceAlignedFrame(shells, canonicalFrame(shells));
  CanonicalInverse back(frame);
  for (int i = 0; i < n; ++i) {
    CanonicalMesh c = canonicalMesh(shells[i], frame);
    back.add(c, shells[i]);
    work[i] = std::move(c.mesh);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return canonicalLess(work[a], work[b]); });
  return back;
}

/// Rounding the exact union to doubles leaves slivers and specks where the shells cross (faces
/// of 1e-8 of the diagonal): the repair merges their vertices. Its usual tolerance can merge
/// more than those (a thin wall between two shells), so the smallest tolerance that gives a
/// clean surface is taken: closed, no zero-area face, not passing through itself; `parts` are
/// its edge-connected pieces. (Where shells touch in many planes, rounding can leave crossings
/// of an ulp at every tolerance; the local repair of crossings then takes minutes, so such a
/// group stays apart: false.)
bool cleanRounded(const TriMesh& united, std::vector<TriMesh>& parts) {
  for (double tolerance : {1e-12, 1e-10, 1e-8, 1e-7, 1e-6}) {
    RepairOptions gentle;
    gentle.mergeTolerance = tolerance;
    const MeshRepair repaired = repairMesh(united, gentle);
    bool clean = repaired.status.ok() && repaired.leftDegenerateFaces == 0 && isClosedOriented(repaired.mesh) &&
                 countSelfIntersections(repaired.mesh, 1) == 0;
    if (!clean) continue;
    parts = splitEdgeConnected(repaired.mesh);
    for (const TriMesh& part : parts) clean = clean && firstZeroAreaFace(part) < 0;
    if (clean) return true;
  }
  return false;
}

}  // namespace

ShellUnion uniteMeetingShells(const std::vector<TriMesh>& shells, bool invariant) {
  const auto start = acd::Clock::now();
  ShellUnion out;
  const int n = static_cast<int>(shells.size());
  auto finish = [&] {
    out.seconds = acd::secondsSince(start);
    return out;
  };
  if (n < 2) {
    out.shells = shells;
    return finish();
  }

  std::vector<TriMesh> work;
  std::vector<int> order;
  const std::optional<CanonicalInverse> back = canonicalWork(shells, invariant, work, order);
  std::vector<Box3> boxes(n);
  for (int i = 0; i < n; ++i) boxes[i] = boundingBox(work[i]);

  std::vector<std::optional<ExactMesh>> exact(n);
  std::vector<char> usable(n, 1);  // bounds a volume and does not cross itself
  auto exactOf = [&](int i) -> ExactMesh* {
    if (!usable[i]) return nullptr;
    if (!exact[i]) {
      exact[i].emplace();
      if (copyToSurfaceMesh(work[i], *exact[i]) >= 0 || PMP::does_self_intersect(*exact[i]) ||
          !PMP::does_bound_a_volume(*exact[i])) {
        usable[i] = 0;
        if (out.firstFailure.empty()) out.firstFailure = "a shell passes through itself or does not bound a volume";
        return nullptr;
      }
    }
    return &*exact[i];
  };

  // Shells meet when their surfaces intersect or touch, or one lies inside the other.
  UnionFind groups(n);
  std::vector<char> meets(n, 0);
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      if (!boxesMeet(boxes[a], boxes[b])) continue;
      ExactMesh* ea = exactOf(a);
      ExactMesh* eb = exactOf(b);
      if (!ea || !eb) continue;
      if (PMP::do_intersect(*ea, *eb, CGAL::parameters::do_overlap_test_of_bounded_sides(true),
                            CGAL::parameters::do_overlap_test_of_bounded_sides(true))) {
        groups.joinKeepingSmallest(a, b);
        meets[a] = meets[b] = 1;
      }
    }

  // Each group united in canonical order; a shell the union refuses stays on its own.
  std::vector<char> consumed(n, 0);
  std::vector<TriMesh> solids;
  std::vector<std::vector<int>> members(n);
  for (int i : order)
    if (meets[i]) members[groups.find(i)].push_back(i);
  std::vector<int> leaders;
  for (int i : order)
    if (meets[i] && groups.find(i) == i) leaders.push_back(i);
  std::stable_sort(leaders.begin(), leaders.end(), [&](int a, int b) {
    return std::find(order.begin(), order.end(), members[a].front()) <
           std::find(order.begin(), order.end(), members[b].front());
  });
  for (int leader : leaders) {
    const std::vector<int>& group = members[leader];
    ExactMesh acc = *exactOf(group.front());
    std::vector<int> taken = {group.front()};
    for (std::size_t k = 1; k < group.size(); ++k) {
      ExactMesh left = acc, right = *exactOf(group[k]), result;
      bool ok = false;
      try {
        ok = PMP::corefine_and_compute_union(left, right, result);
      } catch (const std::exception&) {
        ok = false;
      }
      if (!ok) {
        if (out.firstFailure.empty()) out.firstFailure = "their union is not a manifold surface: shells touch along an edge or at a point";
        continue;
      }
      acc = inCanonicalOrder(result);
      taken.push_back(group[k]);
    }
    if (taken.size() < 2) {
      // Nothing joined it: the first shell stays on its own too.
      continue;
    }
    const TriMesh united = toTriMesh(acc);
    std::vector<TriMesh> parts;
    const bool clean = cleanRounded(united, parts);
    if (!clean) {
      out.firstFailure = "their union, rounded to doubles, is not a clean surface";  // it left the most shells
      continue;
    }
    for (int i : taken) consumed[i] = 1;
    out.united += static_cast<int>(taken.size());
    for (TriMesh& part : parts) {
      if (back) part = (*back)(part);  // input vertices exactly, the crossings' points through the frame
      if (signedVolume(part) < 0.0)
        for (Face& f : part.faces) std::swap(f[1], f[2]);
      solids.push_back(std::move(part));
    }
  }
  out.solids = static_cast<int>(solids.size());
  out.shells = std::move(solids);
  for (int i = 0; i < n; ++i) {
    if (consumed[i]) continue;
    out.shells.push_back(shells[i]);
  }
  // Shells that meet another, or that could not be tested, and went into no union.
  for (int i = 0; i < n; ++i) {
    if (consumed[i]) continue;
    bool near = meets[i];
    for (int j = 0; j < n && !near && !usable[i]; ++j) near = j != i && boxesMeet(boxes[i], boxes[j]);
    out.leftAlone += near;
  }
  return finish();
}

}  // namespace acd
