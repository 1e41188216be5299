// Self-intersection test and local repair, kept in their own translation unit: CGAL's
// Polygon_mesh_processing headers are slow to compile.
#include <acd/diagnosis.hpp>
#include <acd/repair.hpp>

#include <acd/algo/surface_mesh_copy.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>
#include <set>

namespace acd {

namespace {
/// Counts what it is given and stops the search (by throwing) once `limit` pairs are seen.
struct LimitReached {};
template <class Pair>
struct CountingOutput {
  using iterator_category = std::output_iterator_tag;
  using value_type = void;
  using difference_type = void;
  using pointer = void;
  using reference = void;
  int* count;
  int limit;
  CountingOutput& operator*() { return *this; }
  CountingOutput& operator++() { return *this; }
  CountingOutput operator++(int) { return *this; }
  CountingOutput& operator=(const Pair&) {
    if (++*count >= limit && limit >= 0) throw LimitReached{};
    return *this;
  }
};
}  // namespace

int countSelfIntersections(const TriMesh& mesh, int limit) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SM = CGAL::Surface_mesh<K::Point_3>;
  SM sm;
  if (copyToSurfaceMesh(mesh, sm) >= 0) return -1;  // not a manifold surface
  int count = 0;
  using Pair = std::pair<SM::Face_index, SM::Face_index>;
  // In parallel the pairs are found in any order and a few more than the limit may be found
  // before the search stops: the count is of the set, capped at the limit, so it does not depend
  // on the threads.
  try {
    if (limit >= 0)
      CGAL::Polygon_mesh_processing::self_intersections<CGAL::Parallel_if_available_tag>(
          sm, CountingOutput<Pair>{&count, -1}, CGAL::parameters::maximum_number(limit));
    else
      CGAL::Polygon_mesh_processing::self_intersections<CGAL::Parallel_if_available_tag>(sm, CountingOutput<Pair>{&count, -1});
  } catch (const LimitReached&) {
  }
  return limit >= 0 ? std::min(count, limit) : count;
}

Untangled removeSelfIntersections(const TriMesh& shell) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SM = CGAL::Surface_mesh<K::Point_3>;
  Untangled out;
  SM sm;
  if (copyToSurfaceMesh(shell, sm) >= 0) {
    out.status = Status::error(StatusCode::NonManifoldEdge, "not a manifold surface");
    return out;
  }
  try {
    // Keeping the genus and allowing patches up to 90 degrees from their rim: cow's tail reaches
    // 0.018 normalised units outside the result, against 0.034 with CGAL's defaults.
    const bool fixed = CGAL::Polygon_mesh_processing::experimental::remove_self_intersections(
        sm, CGAL::parameters::preserve_genus(true).with_dihedral_angle(90.0));
    if (!fixed || CGAL::Polygon_mesh_processing::does_self_intersect(sm)) {
      out.status = Status::error(StatusCode::InternalError, "self-intersections remain");
      return out;
    }
  } catch (const std::exception& e) {
    out.status = Status::error(StatusCode::InternalError, std::string("removing self-intersections failed: ") + e.what());
    return out;
  }
  sm.collect_garbage();
  out.mesh = copyFromSurfaceMesh(sm);
  // Faces kept from the input, by their corners' positions (a face whose corner moved counts as replaced).
  using Corners = std::array<double, 9>;
  auto key = [](const TriMesh& m, const Face& f) {
    const int first = static_cast<int>(std::min_element(f.begin(), f.end(), [&](int a, int b) {
                        return std::lexicographical_compare(m.vertices[a].data(), m.vertices[a].data() + 3,
                                                            m.vertices[b].data(), m.vertices[b].data() + 3);
                      }) - f.begin());
    Corners c;
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) c[3 * k + i] = m.vertices[f[(first + k) % 3]][i];
    return c;
  };
  std::set<Corners> before;
  for (const Face& f : shell.faces) before.insert(key(shell, f));
  int kept = 0;
  for (const Face& f : out.mesh.faces) kept += before.count(key(out.mesh, f)) > 0;
  out.facesReplaced = static_cast<int>(shell.faces.size()) - kept;
  if (!isClosedOriented(out.mesh) || !(signedVolume(out.mesh) > 0.0)) {
    out.status = Status::error(StatusCode::OpenMesh, "the repaired surface is not closed");
    return out;
  }
  out.status = Status::success();
  return out;
}

}  // namespace acd
