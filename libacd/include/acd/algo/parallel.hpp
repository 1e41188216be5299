// The one threading policy of libacd and its programs: parallel work runs in a TBB task arena
// of the number of threads asked for (0: all cores), in fixed blocks or slots whose results are
// read in order afterwards, so that no result depends on the number of threads.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <cstddef>

namespace acd {

/// The arena for `threads` workers; 0 (or less): as many as the machine has.
inline tbb::task_arena workerArena(int threads) {
  return tbb::task_arena(threads > 0 ? threads : static_cast<int>(tbb::task_arena::automatic));
}

/// Calls f(b) for every block b in [begin, end) on the arena's workers, one task per block.
template <class Index, class F>
void forEachBlock(tbb::task_arena& arena, Index begin, Index end, const F& f) {
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<Index>(begin, end, 1),
        [&](const tbb::blocked_range<Index>& r) {
          for (Index b = r.begin(); b != r.end(); ++b) f(b);
        },
        tbb::simple_partitioner());
  });
}

}  // namespace acd
