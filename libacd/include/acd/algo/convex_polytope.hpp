// A convex polytope kept as its faces (convex polygons on known planes), so that cutting it by
// one more half-space, counting its corners and measuring its volume are cheap. Hulls with a
// vertex budget (acd/algo/hull_vertex_cap.hpp) are built by cutting a box down with supporting planes.
#pragma once

#include <acd/mesh.hpp>
#include <acd/algo/plane.hpp>

#include <vector>

namespace acd {

class ConvexPolytope {
 public:
  struct Face {
    std::vector<Vec3> corners;  // counter-clockwise seen from outside
    Vec3 normal;                // outward, unit: the normal of the half-space that made it
  };

  /// The axis-aligned box [lo, hi]; `eps` is the distance below which points count as on a plane.
  static ConvexPolytope box(const Vec3& lo, const Vec3& hi, double eps);

  /// Whether some corner lies farther than eps beyond the half-space's plane.
  bool cutBy(const HalfSpace& h) const;
  /// The part inside the half-space (corners within eps of the plane are kept as they are).
  ConvexPolytope clipped(const HalfSpace& h) const;

  bool empty() const { return faces_.size() < 4; }
  double volume() const;
  /// Distinct corners (corners of different faces closer than eps are one).
  std::vector<Vec3> corners() const;
  /// Shortest edge over all faces.
  double shortestEdge() const;
  const std::vector<Face>& faces() const { return faces_; }
  /// Triangulated, outward; empty when no volume is left.
  TriMesh mesh() const;

 private:
  std::vector<Face> faces_;
  double eps_ = 0.0;
};

/// Unit normals of a mesh's faces, without repeats (parallel within 1e-12).
std::vector<Vec3> uniqueFacetNormals(const TriMesh& mesh);

/// Largest and smallest of n . p over the points (the support function and its opposite).
double maxAlong(const std::vector<Vec3>& pts, const Vec3& n);
double minAlong(const std::vector<Vec3>& pts, const Vec3& n);

/// Largest distance by which any point lies outside a face plane of the convex mesh (0 if
/// inside all). Sliver faces (no reliable normal in floating point) are skipped: their wide
/// neighbours bound the same region to within their size.
double maxOutsideDistance(const TriMesh& convex, const std::vector<Vec3>& points);

}  // namespace acd
