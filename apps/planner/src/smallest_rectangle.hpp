// The smallest-area rectangle around points of a plane (rotating calipers over their convex
// hull): an opening's frame (opening_frame.hpp) and a part's section (body_parts.hpp).
#pragma once

#include <array>
#include <vector>

namespace planner {

using Point2 = std::array<double, 2>;

struct Rectangle2 {
  Point2 side{1, 0};       // unit direction of the side along the hull edge that gave it
  Point2 middle{0, 0};     // the rectangle's centre
  double half[2] = {0, 0}; // half its extent along `side` and across it
};

/// Ties keep the first hull edge (counter-clockwise from the lowest point), so the result
/// depends on the geometry only.
Rectangle2 smallestRectangle(const std::vector<Point2>& points);

}  // namespace planner
