// Distances from hull points to the mesh's surface with CGAL's AABB tree (double arithmetic: a
// distance, not a predicate).
#include <acd/algo/hull_excess.hpp>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace acd {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point toPoint(const Vec3& p) { return Point(p.x(), p.y(), p.z()); }
Vec3 toVec(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

struct Patch {
  std::array<Vec3, 3> corner;
  int face;
};

/// True when all three corners of the patch lie in the triangle (its plane, and inside its
/// edges), to rounding: then the whole patch does, and its distance to the surface is zero.
bool insideFace(const Triangle& t, const Patch& p) {
  const Vec3 a = toVec(t[0]), b = toVec(t[1]), c = toVec(t[2]);
  const Vec3 n = (b - a).cross(c - a);
  const double area2 = n.norm();
  const double scale = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  const double tolerance = 1e-12 * scale;
  for (const Vec3& q : p.corner) {
    if (std::abs(n.dot(q - a)) > tolerance * area2) return false;
    // Each edge's signed distance to q, inward positive.
    for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
      if (n.dot((v - u).cross(q - u)) < -tolerance * scale * area2) return false;
  }
  return true;
}

}  // namespace

HullExcess measureHullExcess(const TriMesh& mesh, const TriMesh& hull, double limit, double resolution) {
  HullExcess out;
  std::vector<Triangle> triangles;
  triangles.reserve(mesh.faces.size());
  for (const Face& f : mesh.faces) {
    const Triangle t(toPoint(mesh.vertices[f[0]]), toPoint(mesh.vertices[f[1]]), toPoint(mesh.vertices[f[2]]));
    if (!t.is_degenerate()) triangles.push_back(t);
  }
  if (triangles.empty() || hull.faces.empty()) return out;
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();

  std::vector<Patch> stack;
  for (std::size_t f = 0; f < hull.faces.size(); ++f)
    stack.push_back({{hull.vertices[hull.faces[f][0]], hull.vertices[hull.faces[f][1]], hull.vertices[hull.faces[f][2]]},
                     static_cast<int>(f)});
  // Faces are visited in their order and split depth first, so the answer does not depend on threads.
  while (!stack.empty()) {
    const Patch p = stack.back();
    stack.pop_back();
    const Vec3 centroid = (p.corner[0] + p.corner[1] + p.corner[2]) / 3.0;
    double radius = 0.0;
    for (const Vec3& c : p.corner) radius = std::max(radius, (c - centroid).norm());
    const auto [nearest, primitive] = tree.closest_point_and_primitive(toPoint(centroid));
    const double d = (toVec(nearest) - centroid).norm();
    // On the surface all over: a patch inside the face it lies on (a hull face over a flat cap, or
    // over a face of a convex part). Without this, flat faces would be split down to the limit.
    if (d == 0.0 && insideFace(*primitive, p)) continue;
    if (d > out.distance) {
      out.distance = d;
      out.hullPoint = centroid;
      out.surfacePoint = toVec(nearest);
      out.hullFace = p.face;
    }
    if (d > limit) {
      out.exceeds = true;
      out.bound = std::max(out.bound, d + radius);
      return out;
    }
    if (d + radius <= limit) {
      out.bound = std::max(out.bound, d + radius);
      continue;
    }
    if (radius <= resolution) {  // too small to split further: its bound stands
      out.bound = std::max(out.bound, d + radius);
      continue;
    }
    const Vec3 m01 = 0.5 * (p.corner[0] + p.corner[1]), m12 = 0.5 * (p.corner[1] + p.corner[2]),
               m20 = 0.5 * (p.corner[2] + p.corner[0]);
    stack.push_back({{p.corner[0], m01, m20}, p.face});
    stack.push_back({{m01, p.corner[1], m12}, p.face});
    stack.push_back({{m20, m12, p.corner[2]}, p.face});
    stack.push_back({{m01, m12, m20}, p.face});
  }
  out.bound = std::max(out.bound, out.distance);
  return out;
}

}  // namespace acd
