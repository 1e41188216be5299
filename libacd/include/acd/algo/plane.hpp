// The library's one plane type: the plane normal . x = offset, and the half-space
// normal . x <= offset below it. Cut planes, hull facets as half-spaces and clipping planes
// are all this.
#pragma once

#include <acd/mesh.hpp>

namespace acd {

struct Plane {
  Vec3 normal = Vec3::UnitZ();  // need not be unit length (half-spaces of hulls keep it unit)
  double offset = 0.0;

  /// normal . p - offset: positive above the plane, outside the half-space; the distance when
  /// `normal` is unit length.
  double distance(const Vec3& p) const { return normal.dot(p) - offset; }
  /// Signed distance for a normal of any length.
  double signedDistance(const Vec3& p) const { return (normal.dot(p) - offset) / normal.norm(); }
  static Plane through(const Vec3& point, const Vec3& normal) { return {normal, normal.dot(point)}; }
};

/// The name for a plane used as the half-space normal . x <= offset (unit normal).
using HalfSpace = Plane;

}  // namespace acd
