// Self-intersection test, kept in its own translation unit: CGAL's Polygon_mesh_processing
// headers are slow to compile.
#include <acd/diagnosis.hpp>

#include <acd/algo/surface_mesh_copy.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <iterator>

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
  try {
    CGAL::Polygon_mesh_processing::self_intersections(sm, CountingOutput<Pair>{&count, limit});
  } catch (const LimitReached&) {
  }
  return count;
}

}  // namespace acd
