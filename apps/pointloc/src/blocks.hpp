// Work over fixed blocks of the point stream, and the clocks the report reads. Points go in
// blocks of a fixed size whose counts are combined in block order, so every count is the same
// for any number of threads.
#pragma once

#include <acd/algo/parallel.hpp>
#include <acd/algo/stopwatch.hpp>

#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <numeric>
#include <vector>

namespace pointloc {

constexpr std::uint64_t kBlock = 1u << 16;  // points per block (fixed: results never depend on threads)

using acd::Clock;
using acd::secondsSince;

/// Runs body(i0, i1) -> count over fixed blocks of [0, n) and returns the sum, combined in block
/// order. With `progress`, the blocks go in about 100 rounds, each followed by a percentage.
template <class Body>
std::uint64_t overBlocks(tbb::task_arena& arena, std::uint64_t n, const char* progress, const Body& body) {
  const std::uint64_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<std::uint64_t> counts(blocks, 0);
  const std::uint64_t round = progress ? std::max<std::uint64_t>(1, blocks / 100) : std::max<std::uint64_t>(blocks, 1);
  for (std::uint64_t b0 = 0; b0 < blocks; b0 += round) {
    const std::uint64_t b1 = std::min(blocks, b0 + round);
    acd::forEachBlock(arena, b0, b1, [&](std::uint64_t b) { counts[b] = body(b * kBlock, std::min(n, (b + 1) * kBlock)); });
    if (progress) std::fprintf(stderr, "\r%s: %3.0f%%", progress, 100.0 * static_cast<double>(b1) / blocks);
  }
  if (progress && blocks > 0) std::fprintf(stderr, "\n");
  return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
}

/// CPU seconds of the process (all threads), or of the calling thread only: a pass on a
/// one-thread arena runs in the calling thread, and idle spinning of the other threads'
/// workers must not count against it.
inline double cpuNow(bool callingThreadOnly) {
  timespec t{};
  clock_gettime(callingThreadOnly ? CLOCK_THREAD_CPUTIME_ID : CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

inline double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace pointloc
