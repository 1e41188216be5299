// Small statistics for the error estimates and the timing summary.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pointloc {

/// 95% Wilson score interval of a binomial proportion k / n (exact ends at k = 0 and k = n).
struct Interval {
  double lo, hi;
};
inline Interval wilson95(std::uint64_t k, std::uint64_t n) {
  if (n == 0) return {0.0, 1.0};
  const double z = 1.959963984540054, nn = static_cast<double>(n), p = static_cast<double>(k) / nn;
  const double denom = 1 + z * z / nn;
  const double center = (p + z * z / (2 * nn)) / denom;
  const double half = z * std::sqrt(p * (1 - p) / nn + z * z / (4 * nn * nn)) / denom;
  return {k == 0 ? 0.0 : std::max(0.0, center - half), k == n ? 1.0 : std::min(1.0, center + half)};
}

}  // namespace pointloc
