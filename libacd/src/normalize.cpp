// Minimum enclosing sphere with CGAL's Min_sphere_of_spheres_d (exact enough for a unit of length).
#include <acd/normalize.hpp>

#include <CGAL/Min_sphere_of_points_d_traits_3.h>
#include <CGAL/Min_sphere_of_spheres_d.h>
#include <CGAL/Simple_cartesian.h>

namespace acd {

Normalization minimumSphereNormalization(const TriMesh& mesh) {
  using K = CGAL::Simple_cartesian<double>;
  using Traits = CGAL::Min_sphere_of_points_d_traits_3<K, double>;
  std::vector<K::Point_3> points;
  points.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) points.emplace_back(p.x(), p.y(), p.z());
  Normalization n;
  if (points.empty()) return n;
  CGAL::Min_sphere_of_spheres_d<Traits> sphere(points.begin(), points.end());
  auto c = sphere.center_cartesian_begin();
  n.center = Vec3(c[0], c[1], c[2]);
  const double r = sphere.radius();
  n.scale = r > 0.0 ? 1.0 / r : 1.0;
  return n;
}

TriMesh applyNormalization(const TriMesh& mesh, const Normalization& n) {
  TriMesh out = mesh;
  for (Vec3& p : out.vertices) p = n.apply(p);
  return out;
}

TriMesh undoNormalization(const TriMesh& mesh, const Normalization& n) {
  TriMesh out = mesh;
  for (Vec3& p : out.vertices) p = n.undo(p);
  return out;
}

}  // namespace acd
