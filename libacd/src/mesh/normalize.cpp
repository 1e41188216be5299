// Minimum enclosing sphere with CGAL's Min_sphere_of_spheres_d (exact enough for a unit of length).
#include <acd/algo/normalize.hpp>

#include <CGAL/Min_sphere_of_points_d_traits_3.h>
#include <CGAL/Min_sphere_of_spheres_d.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <mutex>
#include <vector>

namespace acd {

namespace {

Normalization sphereOf(const TriMesh& mesh) {
  using K = CGAL::Simple_cartesian<double>;
  // The default (farthest-first) algorithm returns a sphere that leaves points outside for about 3%
  // of the poses of a simple 8-cell solid; the LP algorithm with square roots is exact on them.
  using Traits = CGAL::Min_sphere_of_points_d_traits_3<K, double, CGAL::Tag_true, CGAL::LP_algorithm>;
  Normalization n;
  if (mesh.vertices.empty()) return n;
  // Relative to the bounding box's centre, so that a model far from the origin loses no digits.
  const Vec3 origin = boundingBox(mesh).center();
  // Each position once: the LP algorithm can cycle for ever in doubles on repeated points (an
  // assembly's shells that share corners, each with its own copy).
  std::vector<std::array<double, 3>> unique;
  unique.reserve(mesh.vertices.size());
  for (const Vec3& v : mesh.vertices) {
    const Vec3 p = v - origin;
    unique.push_back({p.x(), p.y(), p.z()});
  }
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  std::vector<K::Point_3> points;
  points.reserve(unique.size());
  for (const auto& p : unique) points.emplace_back(p[0], p[1], p[2]);
  CGAL::Min_sphere_of_spheres_d<Traits> sphere(points.begin(), points.end());
  auto c = sphere.center_cartesian_begin();
  n.center = Vec3(c[0], c[1], c[2]) + origin;
  // A sphere that misses a point by more than rounding would change the unit of tau: never
  // trust it blindly.
  double r = sphere.radius();
  for (const Vec3& v : mesh.vertices) r = std::max(r, (v - n.center).norm());
  n.scale = r > 0.0 ? 1.0 / r : 1.0;
  return n;
}

/// The last vertex list's sphere: a model's is asked for again by each layer that takes the model
/// as its own (its shells, the one shell, the solid's frame, the promise check), on the same
/// vertices, and costs a sort of them each time (0.15 s at 400k vertices). Compared bit for bit,
/// so what comes back is what sphereOf would compute.
class LastSphere {
 public:
  Normalization of(const TriMesh& mesh) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (known_ && sameBits(mesh.vertices)) return sphere_;
    }
    const Normalization n = sphereOf(mesh);
    std::lock_guard<std::mutex> lock(mutex_);
    vertices_ = mesh.vertices;
    sphere_ = n;
    known_ = true;
    return n;
  }

 private:
  bool sameBits(const std::vector<Vec3>& v) const {
    return v.size() == vertices_.size() && (v.empty() || std::memcmp(v.data(), vertices_.data(), v.size() * sizeof(Vec3)) == 0);
  }
  std::mutex mutex_;
  bool known_ = false;
  std::vector<Vec3> vertices_;
  Normalization sphere_;
};

}  // namespace

Normalization minimumSphereNormalization(const TriMesh& mesh) {
  static LastSphere last;
  return last.of(mesh);
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
