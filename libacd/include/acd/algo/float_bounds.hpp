// Doubles rounded outward to floats, for boxes and bounds kept in half the memory: the float
// still bounds the double (clamped first: a double beyond float's range does not convert).
#pragma once

#include <acd/mesh.hpp>

#include <algorithm>
#include <array>
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

/// An axis-aligned box in floats, rounded outward: it holds whatever the doubles' box holds.
struct FloatBox {
  std::array<float, 3> lo, hi;
};

/// The box of the triangle abc, in floats rounded outward.
inline FloatBox floatBoxOf(const Vec3& a, const Vec3& b, const Vec3& c) {
  FloatBox box;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = floatBelow(std::min({a[k], b[k], c[k]}));
    box.hi[k] = floatAbove(std::max({a[k], b[k], c[k]}));
  }
  return box;
}

}  // namespace acd
