// Running a job in a child process under a wall-clock cap and a memory cap, and telling how it
// ended: exit code, signal, time cap or memory cap, with its wall time and peak memory.
// The one home for process isolation (sandbox/): acd batch, acd-table, tetmesh, the scene reader.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace acdsandbox {

struct ChildLimits {
  double wallSeconds = 0;         // > 0: the child (and its process group) is killed when it runs longer
  std::uint64_t memoryBytes = 0;  // > 0: address-space cap (RLIMIT_AS); allocations beyond it fail
};

struct ChildOptions {
  ChildLimits limits;
  std::string logPath;  // non-empty: the child's stdout and stderr go to this file (truncated)
  bool pipe = false;    // give the child a pipe: its write end is the body's argument, the bytes
                        // come back in ChildOutcome::data
  /// With `pipe`: the bytes as they arrive, in order, instead of in ChildOutcome::data (for a
  /// child that reports while it runs). Returning false stops the child (ChildEnd::Stopped).
  std::function<bool(std::string_view bytes)> onData;
  /// Called in the parent about every `tickSeconds` while the child runs (progress reports).
  std::function<void()> onTick;
  double tickSeconds = 1.0;
};

enum class ChildEnd {
  Exited,       // exit() with exitCode
  Signaled,     // killed by `signal` (a crash: abort, segmentation fault, ...)
  TimedOut,     // killed by us at the wall-clock cap
  MemoryCap,    // failed (any way) after running into the memory cap
  Stopped,      // killed by us because ChildOptions::onData said stop
  StartFailed,  // no child: fork, pipe or exec failed (see error)
};

struct ChildOutcome {
  ChildEnd end = ChildEnd::StartFailed;
  int exitCode = -1;  // Exited and MemoryCap (when it exited)
  int signal = 0;     // Signaled and MemoryCap (when killed)
  double seconds = 0;
  std::uint64_t peakMemoryBytes = 0;  // the child's peak resident set size
  std::string data;                   // what the child wrote into the pipe (ChildOptions::pipe, no onData)
  std::string error;                  // StartFailed: why

  bool ok() const { return end == ChildEnd::Exited && exitCode == 0; }
  /// "exit code 2", "killed by signal 6 (Aborted)", "time cap of 5 s reached", ...
  std::string describe(const ChildLimits& limits) const;
};

/// Forks a child that runs `body(pipeWriteFd)` (-1 without a pipe) and exits with its return
/// value; the parent waits, enforcing the caps. The child runs in its own process group (the
/// time cap kills the whole group) and dies with the calling thread. In a multi-threaded caller
/// the body must only make async-signal-safe calls (exec, write, _exit, ...).
ChildOutcome runInChild(const std::function<int(int pipeFd)>& body, const ChildOptions& options);

/// Runs the program argv[0] (a path) with arguments argv[1..] in a child process.
ChildOutcome runProgram(const std::vector<std::string>& argv, const ChildOptions& options);

/// The path of the running executable (/proc/self/exe), or `fallback`.
std::string selfExecutable(const std::string& fallback);

}  // namespace acdsandbox
