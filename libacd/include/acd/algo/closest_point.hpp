// Nearest points on simple shapes, for distances between surfaces and hulls.
#pragma once

#include <acd/mesh.hpp>

namespace acd {

/// Closest point on the triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5);
/// for a degenerate triangle, the nearest of its corners.
Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace acd
