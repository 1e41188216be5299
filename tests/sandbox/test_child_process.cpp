// sandbox/child_process: exit codes, signals, the wall-clock cap (with the child's own children),
// the memory cap, peak memory and the pipe, each against what the child was made to do.
#include <sandbox/child_process.hpp>

#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using acdsandbox::ChildEnd;
using acdsandbox::ChildOptions;
using acdsandbox::runInChild;
using acdsandbox::runProgram;

namespace {

std::string tempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("acd_child_" + std::to_string(::getpid()) + "_" + name)).string();
}

}  // namespace

TEST(ChildProcess, ExitCodeAndSignal) {
  ChildOptions o;
  auto r = runInChild([](int) { return 3; }, o);
  EXPECT_EQ(r.end, ChildEnd::Exited);
  EXPECT_EQ(r.exitCode, 3);
  r = runInChild([](int) { ::abort(); return 0; }, o);
  EXPECT_EQ(r.end, ChildEnd::Signaled);
  EXPECT_EQ(r.signal, SIGABRT);
  EXPECT_NE(r.describe(o.limits).find("signal 6"), std::string::npos) << r.describe(o.limits);
}

TEST(ChildProcess, ProgramAndLog) {
  ChildOptions o;
  o.logPath = tempPath("log.txt");
  auto r = runProgram({"/bin/sh", "-c", "echo out; echo err >&2; exit 5"}, o);
  EXPECT_EQ(r.end, ChildEnd::Exited);
  EXPECT_EQ(r.exitCode, 5);
  std::ifstream in(o.logPath);
  std::string a, b;
  in >> a >> b;
  EXPECT_EQ(a + b, "outerr");
  r = runProgram({"/nonexistent/program"}, o);
  EXPECT_EQ(r.end, ChildEnd::StartFailed);
  EXPECT_NE(r.error.find("/nonexistent/program"), std::string::npos);
  fs::remove(o.logPath);
}

TEST(ChildProcess, TimeCapKillsTheChildAndItsChildren) {
  ChildOptions o;
  o.limits.wallSeconds = 0.5;
  const std::string pidFile = tempPath("grandchild.pid");
  const auto start = std::chrono::steady_clock::now();
  auto r = runProgram({"/bin/sh", "-c", "sleep 60 & echo $! > " + pidFile + "; wait"}, o);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.end, ChildEnd::TimedOut);
  EXPECT_GE(took, 0.5);
  EXPECT_LT(took, 5.0);
  EXPECT_NE(r.describe(o.limits).find("time cap of 0.5 s"), std::string::npos);
  pid_t grandchild = 0;
  std::ifstream(pidFile) >> grandchild;
  ASSERT_GT(grandchild, 0);
  bool gone = false;  // killed with the group; give the kernel a moment to reap it
  for (int i = 0; i < 100 && !gone; ++i) {
    std::ifstream stat("/proc/" + std::to_string(grandchild) + "/stat");
    std::string line;
    std::getline(stat, line);
    gone = !stat || line.find(") Z") != std::string::npos;
    if (!gone) ::usleep(20000);
  }
  EXPECT_TRUE(gone) << "the child's own child survived the time cap";
  fs::remove(pidFile);
}

TEST(ChildProcess, QuickChildIsNotDelayed) {
  ChildOptions o;
  o.limits.wallSeconds = 100;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 20; ++i) EXPECT_TRUE(runInChild([](int) { return 0; }, o).ok());
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(took, 2.0) << "20 empty children took " << took << " s";
}

TEST(ChildProcess, MemoryCapAndPeakMemory) {
  ChildOptions o;
  o.logPath = tempPath("mem.txt");
  // Touches 200 MiB: the peak must show it.
  auto r = runInChild(
      [](int) {
        std::vector<char> v(200u << 20);
        std::memset(v.data(), 1, v.size());
        return v[12345] == 1 ? 0 : 1;
      },
      o);
  EXPECT_TRUE(r.ok());
  EXPECT_GE(r.peakMemoryBytes, 200ull << 20);
  EXPECT_LT(r.peakMemoryBytes, 400ull << 20);
  // The same under a 100 MiB cap: the allocation fails and the end says so.
  o.limits.memoryBytes = 100ull << 20;
  r = runInChild(
      [](int) {
        try {
          std::vector<char> v(200u << 20);
          return int(v[1]);
        } catch (const std::bad_alloc& e) {
          std::fprintf(stderr, "error: %s\n", e.what());
          return 6;
        }
      },
      o);
  EXPECT_EQ(r.end, ChildEnd::MemoryCap) << r.describe(o.limits);
  EXPECT_EQ(r.exitCode, 6);
  EXPECT_NE(r.describe(o.limits).find("memory cap of 100 MiB"), std::string::npos);
  fs::remove(o.logPath);
}

TEST(ChildProcess, PipeCarriesTheChildsData) {
  ChildOptions o;
  o.pipe = true;
  std::string big(300000, 'x');  // more than a pipe buffer: the parent must read while waiting
  big[0] = 'a', big.back() = 'z';
  auto r = runInChild(
      [&](int fd) {
        std::size_t done = 0;
        while (done < big.size()) {
          const ssize_t n = ::write(fd, big.data() + done, big.size() - done);
          if (n <= 0) return 2;
          done += std::size_t(n);
        }
        return 0;
      },
      o);
  EXPECT_TRUE(r.ok()) << r.describe(o.limits);
  EXPECT_EQ(r.data, big);
}

// onData gets the bytes as they come, in order, while the child still runs (the child waits for
// nothing, yet its first message arrives before it ends); onTick ticks while the child sleeps;
// returning false from onData stops the child at once.
TEST(ChildProcess, StreamedDataTicksAndStop) {
  ChildOptions o;
  o.pipe = true;
  std::string got;
  int chunksBeforeEnd = 0;
  int ticks = 0;
  o.onData = [&](std::string_view bytes) {
    got.append(bytes);
    return true;
  };
  o.onTick = [&] { ++ticks; };
  o.tickSeconds = 0.05;
  auto r = runInChild(
      [](int fd) {
        ::write(fd, "first;", 6);
        ::usleep(400000);
        ::write(fd, "second", 6);
        return 0;
      },
      o);
  EXPECT_TRUE(r.ok()) << r.describe(o.limits);
  EXPECT_EQ(got, "first;second");
  EXPECT_TRUE(r.data.empty());
  EXPECT_GE(ticks, 3);

  o.onTick = nullptr;
  got.clear();
  o.onData = [&](std::string_view bytes) {
    got.append(bytes);
    ++chunksBeforeEnd;
    return false;  // stop: the child would sleep for a minute
  };
  const auto start = std::chrono::steady_clock::now();
  r = runInChild(
      [](int fd) {
        ::write(fd, "stop me", 7);
        ::sleep(60);
        return 0;
      },
      o);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.end, ChildEnd::Stopped) << r.describe(o.limits);
  EXPECT_EQ(got, "stop me");
  EXPECT_EQ(chunksBeforeEnd, 1);
  EXPECT_LT(wall, 10.0);
}
