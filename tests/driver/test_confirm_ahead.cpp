// ConfirmAhead (libacd/src/driver/confirm_ahead.hpp): the merge pass's confirmations made ahead
// of need. What the merge pass relies on: every position awaited is confirmed before await
// returns, none twice, none that needed none, and what is no longer wanted is not begun after it.
#include "../../libacd/src/driver/confirm_ahead.hpp"

#include <tbb/task_arena.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

namespace {

struct Confirmations {
  std::vector<int> confirmedAt;  // by position: how many times confirmed
  std::vector<int> awaited;      // positions awaited, in order
};

/// Positions 0..count-1, those with done(n) needing none; every third one turns unwanted once
/// position n - 1 has been awaited (as the merge pass closes pairs whose pieces merged). Odd
/// positions take longer, so the threads finish out of order.
Confirmations runOnce(int threads, int count) {
  Confirmations r;
  std::unique_ptr<std::atomic<int>[]> times(new std::atomic<int>[count]);
  std::unique_ptr<std::atomic<bool>[]> unwanted(new std::atomic<bool>[count]);
  for (int n = 0; n < count; ++n) times[n] = 0, unwanted[n] = false;
  auto confirm = [&](std::size_t n) {
    if (n % 2) std::this_thread::sleep_for(std::chrono::microseconds(300));
    ++times[n];
  };
  auto wanted = [&](std::size_t n) { return !unwanted[n].load(); };
  auto done = [](std::size_t n) { return n % 5 == 4; };
  tbb::task_arena arena(threads);
  arena.execute([&] {
    acd::ConfirmAhead<decltype(confirm), decltype(wanted)> ahead(count, 2 * threads, confirm, wanted, done);
    for (int n = 0; n < count; ++n) {
      if (!wanted(n)) continue;
      ahead.await(n);
      // Confirmed, by whichever thread, before await returns; never twice.
      EXPECT_EQ(times[n].load(), done(n) ? 0 : 1) << n;
      r.awaited.push_back(n);
      if (n + 1 < count && (n + 1) % 3 == 0) unwanted[n + 1] = true;
    }
    ahead.finish();
  });
  for (int n = 0; n < count; ++n) r.confirmedAt.push_back(times[n].load());
  return r;
}

}  // namespace

TEST(ConfirmAhead, EachAwaitedPositionIsConfirmedOnceAndThoseDoneNever) {
  for (int threads : {1, 2, 4}) {
    const Confirmations r = runOnce(threads, 200);
    for (int n = 0; n < 200; ++n) {
      EXPECT_LE(r.confirmedAt[n], 1) << n << " on " << threads << " threads";
      if (n % 5 == 4) EXPECT_EQ(r.confirmedAt[n], 0) << n;
    }
    // Which positions were awaited depends on the list, never on the threads.
    EXPECT_EQ(r.awaited, runOnce(1, 200).awaited) << threads << " threads";
  }
}

TEST(ConfirmAhead, OneThreadConfirmsOnlyWhatIsAwaited) {
  // With no other thread, nothing runs ahead: a position unwanted before its turn is never begun.
  const Confirmations r = runOnce(1, 60);
  for (int n = 0; n < 60; ++n) {
    const bool awaited = std::find(r.awaited.begin(), r.awaited.end(), n) != r.awaited.end();
    EXPECT_EQ(r.confirmedAt[n], awaited && n % 5 != 4 ? 1 : 0) << n;
  }
}

TEST(ConfirmAhead, FinishingEarlyLeavesNothingRunning) {
  // The caller stops after a few positions: finish() returns only when no confirmation still
  // runs, so what the caller frees afterwards is not read.
  for (int round = 0; round < 20; ++round) {
    const int threads = round % 2 ? 2 : 1;
    std::atomic<int> running{0}, begun{0};
    auto confirm = [&](std::size_t) {
      ++running, ++begun;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      --running;
    };
    auto wanted = [](std::size_t) { return true; };
    tbb::task_arena arena(threads);
    arena.execute([&] {
      acd::ConfirmAhead<decltype(confirm), decltype(wanted)> ahead(100, 4, confirm, wanted, [](std::size_t) { return false; });
      ahead.await(0);
      ahead.await(1);
      ahead.finish();
      EXPECT_EQ(running.load(), 0);
    });
    // At most the window beyond what was awaited; on one thread, nothing queued is begun after.
    EXPECT_GE(begun.load(), 2);
    EXPECT_LE(begun.load(), threads == 1 ? 2 : 2 + 4 + 1);
  }
}

TEST(ConfirmAhead, AConfirmationThatThrowsReachesTheCallerAndNothingHangs) {
  // Whichever thread runs the throwing position, the caller does not wait for it forever: the
  // exception comes out of await (the caller ran it) or out of finish (another thread did).
  for (int threads : {1, 2}) {
    for (int round = 0; round < 20; ++round) {
      auto confirm = [](std::size_t n) {
        std::this_thread::sleep_for(std::chrono::microseconds(100));
        if (n == 3) throw std::runtime_error("no memory left");
      };
      auto wanted = [](std::size_t) { return true; };
      tbb::task_arena arena(threads);
      bool thrown = false;
      arena.execute([&] {
        acd::ConfirmAhead<decltype(confirm), decltype(wanted)> ahead(10, 4, confirm, wanted, [](std::size_t) { return false; });
        try {
          for (std::size_t n = 0; n < 10; ++n) ahead.await(n);
          ahead.finish();
        } catch (const std::runtime_error&) {
          thrown = true;
        }
      });
      EXPECT_TRUE(thrown) << threads << " threads";
    }
  }
}
