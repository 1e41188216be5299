// Fork, caps and waiting for one child. The parent polls (the pipe when there is one, else a short
// sleep), hands what arrives to the caller as it comes (onData) or keeps it, ticks (onTick), and
// reaps with wait4, which also gives the child's peak memory; at the wall-clock cap, or when the
// caller says stop, it kills the child's whole process group, so helpers the child started die with it.
#include <acd/algo/address_sanitizer.hpp>
#include <sandbox/child_process.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace acdsandbox {

namespace {

using Clock = std::chrono::steady_clock;

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

/// Whether the child's log says an allocation failed (C++ bad_alloc, C's ENOMEM, TBB, CGAL).
bool logSaysOutOfMemory(const std::string& path) {
  if (path.empty()) return false;
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  // (a capped address space also fails to map shared libraries and thread stacks)
  for (const char* needle : {"bad_alloc", "out of memory", "Out of memory", "Cannot allocate memory", "memory cap",
                             "failed to map segment", "pthread_create", "Resource temporarily unavailable"})
    if (text.find(needle) != std::string::npos) return true;
  return false;
}

struct Reaped {
  int status = 0;
  rusage usage{};
  bool timedOut = false;  // killed at the wall-clock cap
  bool stopped = false;   // killed because onData said stop
};

/// Hands the child's bytes to onData, or keeps them in out.data; false: stop the child.
bool deliver(const ChildOptions& options, const char* bytes, std::size_t n, ChildOutcome& out) {
  if (!options.onData) {
    out.data.append(bytes, n);
    return true;
  }
  return options.onData(std::string_view(bytes, n));
}

void killGroup(pid_t pid) {
  ::kill(-pid, SIGKILL);
  ::kill(pid, SIGKILL);
}

/// The parent's side: reads the pipe (readFd, -1 without one), enforces the wall-clock cap,
/// ticks, and reaps the child. False (with out.error) when waiting itself failed.
template <class Elapsed>
bool waitFor(pid_t pid, int readFd, const ChildOptions& options, const Elapsed& elapsed, ChildOutcome& out,
             Reaped& reaped) {
  // Readable when the child ends, so short jobs are reaped at once; without it (kernels before
  // 5.3) the loop polls with a short, growing sleep.
  const int pidFd = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));
  bool done = false;
  char chunk[1 << 16];
  int sleepMs = 1;
  double lastTick = 0;
  auto killAndReap = [&] {
    killGroup(pid);
    while (::wait4(pid, &reaped.status, 0, &reaped.usage) < 0 && errno == EINTR) {
    }
    done = true;
  };
  while (!done) {
    int waitMs = pidFd >= 0 ? -1 : sleepMs;
    sleepMs = std::min(sleepMs * 2, 50);
    if (options.limits.wallSeconds > 0) {
      const double left = options.limits.wallSeconds - elapsed();
      if (left <= 0) {
        reaped.timedOut = true;
        killAndReap();
        break;
      }
      const int leftMs = static_cast<int>(left * 1000.0) + 1;
      waitMs = waitMs < 0 ? leftMs : std::min(waitMs, leftMs);
    }
    if (options.onTick) {
      const int tickMs = std::max(1, static_cast<int>(options.tickSeconds * 1000.0));
      waitMs = waitMs < 0 ? tickMs : std::min(waitMs, tickMs);
    }
    pollfd watched[2];
    nfds_t count = 0;
    if (pidFd >= 0) watched[count++] = {pidFd, POLLIN, 0};
    if (readFd >= 0) watched[count++] = {readFd, POLLIN, 0};
    if (count > 0) {
      if (::poll(watched, count, waitMs) > 0 && readFd >= 0 && (watched[count - 1].revents & (POLLIN | POLLHUP))) {
        const ssize_t n = ::read(readFd, chunk, sizeof chunk);
        if (n > 0 && !deliver(options, chunk, static_cast<std::size_t>(n), out)) {
          reaped.stopped = true;
          killAndReap();
          break;
        }
        if (n == 0) ::close(readFd), readFd = -1;  // the child closed it (or ended)
      }
    } else {
      ::usleep(static_cast<useconds_t>(waitMs) * 1000);
    }
    if (options.onTick && elapsed() - lastTick >= options.tickSeconds) {
      lastTick = elapsed();
      options.onTick();
    }
    const pid_t r = ::wait4(pid, &reaped.status, WNOHANG, &reaped.usage);
    if (r == pid) done = true;
    if (r < 0 && errno != EINTR) {
      out.error = std::string("wait: ") + std::strerror(errno);
      if (pidFd >= 0) ::close(pidFd);
      if (readFd >= 0) ::close(readFd);
      return false;
    }
  }
  if (pidFd >= 0) ::close(pidFd);
  if (readFd >= 0) {  // what the child wrote just before it ended
    ::fcntl(readFd, F_SETFL, O_NONBLOCK);
    bool more = !reaped.stopped;
    for (ssize_t n; more && (n = ::read(readFd, chunk, sizeof chunk)) > 0;)
      more = deliver(options, chunk, static_cast<std::size_t>(n), out);
    ::close(readFd);
  }
  return true;
}

}  // namespace

std::string ChildOutcome::describe(const ChildLimits& limits) const {
  switch (end) {
    case ChildEnd::Exited: return "exit code " + std::to_string(exitCode);
    case ChildEnd::Signaled: return "killed by signal " + std::to_string(signal) + " (" + strsignal(signal) + ")";
    case ChildEnd::TimedOut: return "time cap of " + number(limits.wallSeconds) + " s reached";
    case ChildEnd::MemoryCap:
      return "memory cap of " + std::to_string(limits.memoryBytes >> 20) + " MiB reached (" +
             (signal != 0 ? "killed by signal " + std::to_string(signal) : "exit code " + std::to_string(exitCode)) + ")";
    case ChildEnd::Stopped: return "stopped by the caller";
    case ChildEnd::StartFailed: return "could not start: " + error;
  }
  return "unknown";
}

ChildOutcome runInChild(const std::function<int(int pipeFd)>& body, const ChildOptions& options) {
  ChildOutcome out;
  const auto start = Clock::now();
  int fds[2] = {-1, -1};
  if (options.pipe && ::pipe2(fds, O_CLOEXEC) != 0) {
    out.error = std::string("pipe: ") + std::strerror(errno);
    return out;
  }
  int logFd = -1;
  if (!options.logPath.empty()) {
    logFd = ::open(options.logPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (logFd < 0) {
      out.error = "cannot open " + options.logPath + ": " + std::strerror(errno);
      if (fds[0] >= 0) ::close(fds[0]), ::close(fds[1]);
      return out;
    }
  }
  std::fflush(nullptr);  // the child must not flush the parent's buffered output a second time
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    out.error = std::string("fork: ") + std::strerror(errno);
    if (fds[0] >= 0) ::close(fds[0]), ::close(fds[1]);
    if (logFd >= 0) ::close(logFd);
    return out;
  }
  if (pid == 0) {
    // Only async-signal-safe calls from here on: the parent may have other threads.
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the caller: an interrupted batch leaves nothing behind
    if (::getppid() != parent) ::_exit(127);
    if (options.limits.memoryBytes > 0 && !acd::kAddressSanitizer) {
      const rlimit cap{options.limits.memoryBytes, options.limits.memoryBytes};
      ::setrlimit(RLIMIT_AS, &cap);
    }
    const int in = ::open("/dev/null", O_RDONLY);
    if (in >= 0) ::dup2(in, STDIN_FILENO);
    if (logFd >= 0) ::dup2(logFd, STDOUT_FILENO), ::dup2(logFd, STDERR_FILENO);
    int writeEnd = -1;
    if (fds[1] >= 0) {
      ::close(fds[0]);
      writeEnd = ::fcntl(fds[1], F_DUPFD, 3);  // a copy without close-on-exec
    }
    ::_exit(body(writeEnd));
  }
  if (logFd >= 0) ::close(logFd);
  if (fds[1] >= 0) ::close(fds[1]);

  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  Reaped reaped;
  if (!waitFor(pid, fds[0], options, elapsed, out, reaped)) return out;
  out.seconds = elapsed();
  out.peakMemoryBytes = static_cast<std::uint64_t>(reaped.usage.ru_maxrss) * 1024;
  const int status = reaped.status;
  if (reaped.timedOut || reaped.stopped) {
    out.end = reaped.timedOut ? ChildEnd::TimedOut : ChildEnd::Stopped;
    out.signal = SIGKILL;
    return out;
  }
  if (WIFEXITED(status)) {
    out.end = ChildEnd::Exited;
    out.exitCode = WEXITSTATUS(status);
  } else {
    out.end = ChildEnd::Signaled;
    out.signal = WTERMSIG(status);
  }
  if (!out.ok() && options.limits.memoryBytes > 0 && logSaysOutOfMemory(options.logPath)) out.end = ChildEnd::MemoryCap;
  return out;
}

ChildOutcome runProgram(const std::vector<std::string>& argv, const ChildOptions& options) {
  if (argv.empty()) {
    ChildOutcome out;
    out.error = "no program";
    return out;
  }
  // Built before the fork: the child only calls execv.
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  ChildOutcome out = runInChild(
      [&](int) {
        ::execv(args[0], args.data());
        return 127;
      },
      options);
  if (out.end == ChildEnd::Exited && out.exitCode == 127 && out.error.empty()) {
    // execve failed (or the program itself said 127): check that it exists at all
    if (::access(argv[0].c_str(), X_OK) != 0) {
      out.end = ChildEnd::StartFailed;
      out.error = "cannot run " + argv[0] + ": " + std::strerror(errno);
    }
  }
  return out;
}

std::string selfExecutable(const std::string& fallback) {
  char buffer[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buffer, sizeof buffer - 1);
  if (n <= 0) return fallback;
  return std::string(buffer, static_cast<std::size_t>(n));
}

}  // namespace acdsandbox
