// Knots (Lien & Amato 2007, Section 4.2.1): critical points of a pocket boundary
// found by Douglas-Peucker simplification in concavity space.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace acd {

using Vec2 = Eigen::Vector2d;

/// Douglas-Peucker: indices of the points kept (first and last always), in order.
std::vector<int> douglasPeucker(const std::vector<Vec2>& polyline, double tolerance);

/// Knots of a profile (x = position along the boundary, y = concavity): the interior
/// vertices of the simplified profile that are notches (the profile turns downward
/// there, a peak in concavity) and whose concavity exceeds delta. Indices into `profile`.
std::vector<int> findKnots(const std::vector<Vec2>& profile, double delta);

}  // namespace acd
