// Convex hull of a point set, with each hull vertex traced back to its input point.
#pragma once

#include <acd/mesh.hpp>

#include <vector>

namespace acd {

struct ConvexHull {
  TriMesh mesh;             // triangulated, outward-oriented; empty when the points are degenerate
  std::vector<int> source;  // hull vertex -> index of the input point it is
  bool degenerate = false;  // fewer than 4 affinely independent points: no volume
};

/// Exact-predicate hull (quickhull, acd/algo/quickhull.hpp), in canonical form: corners only, sorted by
/// input index. Duplicate input points map to the first occurrence. A point with a coordinate that
/// is not finite makes the hull degenerate.
ConvexHull convexHull(const std::vector<Vec3>& points);

/// Convenience: hull mesh only.
inline TriMesh hullMesh(const std::vector<Vec3>& points) { return convexHull(points).mesh; }

}  // namespace acd
