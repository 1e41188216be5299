// Doubles rounded outward to floats, for boxes and bounds kept in half the memory: the float
// still bounds the double (clamped first: a double beyond float's range does not convert).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace acd {

/// The greatest float no greater than x (-inf below float's range).
inline float floatBelow(double x) {
  const double most = std::numeric_limits<float>::max();
  const float f = static_cast<float>(std::clamp(x, -most, most));
  return f > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

/// The least float no less than x (+inf above float's range).
inline float floatAbove(double x) {
  const double most = std::numeric_limits<float>::max();
  const float f = static_cast<float>(std::clamp(x, -most, most));
  return f < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

}  // namespace acd
