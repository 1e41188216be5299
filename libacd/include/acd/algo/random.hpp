// Counter-based random numbers: value i depends only on (key, i), never on threads or order.
#pragma once

#include <acd/mesh.hpp>

#include <cstdint>

namespace acd {

/// SplitMix64's finaliser: a bijective 64-bit mix.
inline std::uint64_t mix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// Uniform in [0, 1) from 53 bits of a mixed value.
inline double unitInterval(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1p-53; }

/// Uniform numbers in [0, 1): value k (< 4) of sample i depends only on (seed, stream, i, k).
/// Separate streams of one seed are independent (evaluate's volume, hull and model samples).
struct UniformStream {
  std::uint64_t key;
  UniformStream(std::uint64_t seed, std::uint64_t stream)
      : key(mix64(mix64(seed) ^ (stream * 0xD1B54A32D192ED03ull))) {}
  double uniform(std::uint64_t i, unsigned k) const { return unitInterval(mix64(key ^ mix64(i * 4 + k))); }
};

/// Points uniform in a box, point i depending only on (seed, i); two mixes per point: x from 53
/// bits of the first, y and z from the two 32-bit halves of the second (a grid of 2^32 steps per
/// axis is far finer than any model feature). Cheaper than three UniformStream values, for
/// pointloc's 10^8 points.
struct BoxPointStream {
  std::uint64_t key;
  Vec3 lo, size;

  BoxPointStream(std::uint64_t seed, const Box3& box)
      : key(mix64(seed ^ 0x5EED5EED5EED5EEDull)), lo(box.lo), size(box.size()) {}

  Vec3 operator()(std::uint64_t i) const {
    const std::uint64_t a = mix64(key + i), b = mix64(a ^ 0xA0761D6478BD642Full);
    const double u = unitInterval(a);
    const double v = static_cast<double>(b >> 32) * 0x1p-32, w = static_cast<double>(b & 0xFFFFFFFFull) * 0x1p-32;
    return {lo.x() + u * size.x(), lo.y() + v * size.y(), lo.z() + w * size.z()};
  }
};

}  // namespace acd
