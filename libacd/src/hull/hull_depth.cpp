#include <acd/algo/hull_depth.hpp>

#include <acd/algo/convex_polytope.hpp>

#include <algorithm>
#include <limits>
#include <vector>

namespace acd {

HullDepth deepestBelowHull(const TriMesh& mesh, const TriMesh& hull) {
  struct FacePlane {
    Vec3 normal;
    double offset;
    int face;
  };
  std::vector<FacePlane> planes;
  for (std::size_t f = 0; f < hull.faces.size(); ++f) {
    const Vec3 n = faceNormal(hull, static_cast<int>(f));
    const double length = n.norm();
    if (!(length > 0)) continue;
    const Vec3 unit = n / length;
    planes.push_back({unit, maxAlong(hull.vertices, unit), static_cast<int>(f)});
  }
  HullDepth deepest;
  if (planes.empty()) return deepest;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    double depth = std::numeric_limits<double>::infinity();
    int face = -1;
    for (const FacePlane& p : planes) {
      const double d = p.offset - p.normal.dot(mesh.vertices[v]);
      if (d < depth) depth = d, face = p.face;
    }
    if (depth > deepest.distance) deepest = {depth, static_cast<int>(v), face};
  }
  return deepest;
}

}  // namespace acd
