// The frame of an opening: its plane's normal and the two in-plane directions of its
// smallest enclosing rectangle (long side first). The aligned poses of the acd sampler put the
// robot's long axis along the normal and its wider cross-section axis along the long side.
#pragma once

#include "openings.hpp"

#include <acd/mesh.hpp>

namespace planner {

struct OpeningFrame {
  acd::Vec3 center = acd::Vec3::Zero();  // centre of the rectangle, in the opening's mean plane
  acd::Vec3 normal = acd::Vec3::UnitX(); // the opening's normal (unit)
  acd::Vec3 longSide = acd::Vec3::UnitY();   // unit, in the plane
  acd::Vec3 shortSide = acd::Vec3::UnitZ();  // unit, normal x longSide
  double halfLong = 0.0, halfShort = 0.0;    // half the rectangle's sides
};

/// The minimum-area rectangle enclosing the opening's corners projected on its plane
/// (rotating calipers over their convex hull; ties keep the first hull edge, so the result
/// depends on the geometry only).
OpeningFrame openingFrame(const Opening& opening);

}  // namespace planner
