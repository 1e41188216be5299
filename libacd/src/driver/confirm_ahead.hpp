// The merge pass's costlier tests, made ahead of need on the other threads (mergePieces).
#pragma once

#include <tbb/task_group.h>

#include <atomic>
#include <cstddef>
#include <memory>
#include <thread>

namespace acd {

/// Runs `confirm(n)` for positions n = 0, 1, ... of a list, each at most once, while the caller
/// asks for them in order (`await(n)`). Waiting for one, the caller has up to `window` of the next
/// positions still `wanted` queued for the arena's other threads, and runs any of them not yet
/// begun itself. So no thread idles behind the slowest of a fixed batch. For the answers not to
/// depend on the threads, `confirm(n)` must read nothing the caller changes before `finish()`.
template <class Confirm, class Wanted>
class ConfirmAhead {
 public:
  /// `done(n)`: position n needs no confirmation (asked here, before any thread starts).
  template <class Done>
  ConfirmAhead(std::size_t count, std::size_t window, const Confirm& confirm, const Wanted& wanted, const Done& done)
      : state_(new std::atomic<int>[count]), count_(count), window_(window), confirm_(confirm), wanted_(wanted) {
    for (std::size_t n = 0; n < count; ++n) state_[n].store(done(n) ? kDone : kWaiting, std::memory_order_relaxed);
  }
  ~ConfirmAhead() {
    try {
      finish();
    } catch (...) {  // already thrown once by finish(), or the caller is unwinding
    }
  }
  ConfirmAhead(const ConfirmAhead&) = delete;
  ConfirmAhead& operator=(const ConfirmAhead&) = delete;

  /// Returns once position n is confirmed (or needed none).
  void await(std::size_t n) {
    queueAhead(n);
    if (claim(n)) return run(n);
    while (state_[n].load(std::memory_order_acquire) != kDone) {
      bool helped = false;  // the caller waits doing the next queued one that no one has begun
      for (std::size_t m = n + 1; m < queued_ && !helped; ++m)
        if (wanted_(m) && claim(m)) run(m), helped = true;
      if (!helped) std::this_thread::yield();
    }
  }

  /// Stops what has not begun and waits for what has (rethrowing what a confirmation threw).
  void finish() {
    stopped_.store(true, std::memory_order_relaxed);
    group_.wait();
  }

 private:
  enum { kWaiting = 0, kRunning = 1, kDone = 2 };

  bool claim(std::size_t n) {
    int waiting = kWaiting;
    return state_[n].compare_exchange_strong(waiting, kRunning, std::memory_order_acq_rel);
  }
  /// Done even when confirm throws (the exception reaches the caller through finish(), or at
  /// once when the caller ran it): no one waits for a position forever.
  void run(std::size_t n) {
    struct MarkDone {
      std::atomic<int>& state;
      ~MarkDone() { state.store(kDone, std::memory_order_release); }
    } markDone{state_[n]};
    confirm_(n);
  }
  /// Queues positions after n until `window` wanted ones after n are queued and not done.
  void queueAhead(std::size_t n) {
    if (queued_ <= n) queued_ = n + 1;
    std::size_t ahead = 0;
    for (std::size_t m = n + 1; m < queued_; ++m)
      ahead += wanted_(m) && state_[m].load(std::memory_order_relaxed) != kDone;
    for (; queued_ < count_ && ahead < window_; ++queued_) {
      const std::size_t m = queued_;
      if (state_[m].load(std::memory_order_relaxed) == kDone || !wanted_(m)) continue;
      ++ahead;
      group_.run([this, m] {
        if (!stopped_.load(std::memory_order_relaxed) && wanted_(m) && claim(m)) run(m);
      });
    }
  }

  std::unique_ptr<std::atomic<int>[]> state_;
  std::size_t count_, window_, queued_ = 0;  // positions below queued_ have been queued (or passed)
  const Confirm& confirm_;
  const Wanted& wanted_;
  std::atomic<bool> stopped_{false};
  tbb::task_group group_;
};

}  // namespace acd
