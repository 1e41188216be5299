// Wall time of a phase, for the timings the reports give: the library's one clock.
#pragma once

#include <chrono>

namespace acd {

using Clock = std::chrono::steady_clock;

/// Seconds from `start` to now.
inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace acd
