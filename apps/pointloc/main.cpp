// pointloc: point location against the convex hulls of an approximate convex decomposition
// (paper, Section 7, Figure 20), with error statistics against the exact answer and, with
// --compare, the same points timed against the original model and its exact decomposition.
//
//   pointloc [MODEL] [--samples 1e8] [--tau 0.02] [--threads N] [--seed S] [--exact-samples M]
//            [--compare] [--json FILE]
//
// Points are uniform in the model's bounding box; point i depends only on (seed, i) through a
// counter-based hash, and work runs over fixed blocks whose counts are combined in block order,
// so every count is identical for any number of threads.
#include "exact_cgal.hpp"
#include "exact_pieces.hpp"
#include "hull_locator.hpp"
#include "point_stream.hpp"
#include "statistics.hpp"

#include <appcli/console.hpp>
#include <appcli/exit_codes.hpp>

#include <acd/algo/parallel.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/inside.hpp>
#include <acd/io.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using json = nlohmann::json;
using acd::Vec3;
using pointloc::HullLocator;
using pointloc::PointStream;

namespace {

using appcli::kBadParameter;
using appcli::kInternal;
using appcli::kOk;
using appcli::kOutputFailed;
constexpr int kBadModel = appcli::kBadInput;

const appcli::Console kConsole("pointloc");

constexpr std::uint64_t kBlock = 1u << 16;  // points per block (fixed: results never depend on threads)

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

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
double cpuNow(bool callingThreadOnly) {
  timespec t{};
  clock_gettime(callingThreadOnly ? CLOCK_THREAD_CPUTIME_ID : CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Positive integer written as a double ("1e8" or "100000000"), at most `max`.
bool parseCount(const std::string& s, double max, bool allowZero, std::uint64_t& out) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == s.c_str() || *end != '\0' || !std::isfinite(v)) return false;
  if (v != std::floor(v) || v > max || v < 0 || (!allowZero && v == 0)) return false;
  out = static_cast<std::uint64_t>(v);
  return true;
}

std::string human(double v) {
  char buf[64];
  if (v >= 1e9)
    std::snprintf(buf, sizeof buf, "%.3g G", v / 1e9);
  else if (v >= 1e6)
    std::snprintf(buf, sizeof buf, "%.3g M", v / 1e6);
  else if (v >= 1e3)
    std::snprintf(buf, sizeof buf, "%.3g k", v / 1e3);
  else
    std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

/// One row of the --compare table: one way of answering "is point i inside?".
struct Method {
  std::string name;
  bool exact = false;           // answers the model's own question exactly
  double prepareSeconds = 0.0;  // decomposition and index
  int threads = 1;
  std::uint64_t points = 0;     // points timed
  double seconds = 0.0;         // location time for `points`
  std::uint64_t inside = 0;     // on the first `points`
  std::optional<std::uint64_t> disagreements;  // with acd::InsideTest on the compare subsample
  std::string note;             // why the row has no figures
  std::vector<double> runs;     // seconds of each repetition; `seconds` is their median
  std::vector<double> cpuRuns;  // CPU seconds (all threads) of each repetition

  double cpuSeconds() const { return median(cpuRuns); }

  bool measured() const { return points > 0 && note.empty(); }
  double rate() const { return seconds > 0 ? static_cast<double>(points) / seconds : 0.0; }
  double secondsFor(std::uint64_t n) const { return seconds * static_cast<double>(n) / static_cast<double>(points); }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "pointloc: locate random points in the union of the convex hulls of an approximate convex\n"
      "decomposition, and compare with the exact point-in-model answer on a subsample."};
  std::string model = "data/meshes/elephant.off";
  std::string samplesText = "1e8", tauText = "0.02", exactText, compareText, dumpPath;
  int threads = 0;
  std::uint64_t seed = 1;
  std::string jsonPath;
  bool noIndex = false, compare = false;
  std::size_t gridCells = 1u << 18;
  double ecdTimeLimit = 60.0;
  int repeat = 1;
  app.add_option("MODEL", model,
                 "closed mesh (OFF, OBJ, PLY, STL); default data/meshes/elephant.off (relative to the current\n"
                 "directory, else the one in the source tree)");
  app.add_option("--samples", samplesText, "points to locate, e.g. 1e8 or 100000000 (positive integer <= 1e10)")
      ->capture_default_str();
  app.add_option("--tau", tauText, "concavity tolerance, normalised units, in (0, 2]")->capture_default_str();
  app.add_option("--threads", threads, "worker threads, 0 = all cores (results never depend on it)")
      ->capture_default_str();
  app.add_option("--seed", seed, "seed of the point stream")->capture_default_str();
  app.add_option("--exact-samples", exactText, "points (the first M of the stream) checked exactly; default min(N, 2e6)");
  app.add_flag("--compare", compare,
               "also time the same points against the original model (CGAL Side_of_triangle_mesh, 1 and all\n"
               "threads; acd::InsideTest) and against the solid exact convex decomposition when libacd has one");
  app.add_option("--compare-samples", compareText,
                 "points (the first K) timed by the exact methods; default min(N, 1e6), at most 1e8");
  app.add_option("--ecd-time-limit", ecdTimeLimit, "seconds allowed for the exact convex decomposition")
      ->capture_default_str();
  app.add_option("--repeat", repeat, "time every location pass R times and report the median (1..100)")
      ->capture_default_str();
  app.add_option("--json", jsonPath, "write the report as JSON to FILE");
  app.add_option("--dump", dumpPath,
                 "write the exactly checked points as CSV: x,y,z,hulls,direct,exact (1 = inside; hulls through\n"
                 "the grid, direct by testing every hull)");
  app.add_flag("--no-index", noIndex, "test every hull for every point (no grid; same counts)");
  app.add_option("--grid-cells", gridCells, "cells of the grid over the box (about, <= 2^24)")->capture_default_str();
  app.footer(
      "Exit codes: 0 success; 1 bad command line; 2 unreadable or invalid model; 3 invalid parameter;\n"
      "5 cannot write output; 6 internal error.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return appcli::usageExit(app.exit(e));
  }

  // ---- parameters first: they need no model
  std::uint64_t samples = 0, exactSamples = 0, compareSamples = 0;
  if (!parseCount(samplesText, 1e10, false, samples)) {
    return kConsole.failf(kBadParameter, "--samples '%s' is not a positive integer <= 1e10", samplesText.c_str());
  }
  char* end = nullptr;
  const double tau = std::strtod(tauText.c_str(), &end);
  if (tauText.empty() || *end != '\0' || !(tau > 0.0 && tau <= 2.0)) {
    return kConsole.failf(kBadParameter, "--tau '%s' must be a number in (0, 2]", tauText.c_str());
  }
  if (threads < 0) {
    return kConsole.failf(kBadParameter, "--threads %d must be >= 0", threads);
  }
  if (exactText.empty()) {
    exactSamples = std::min<std::uint64_t>(samples, 2000000);
  } else if (!parseCount(exactText, 1e10, true, exactSamples)) {
    return kConsole.failf(kBadParameter, "--exact-samples '%s' is not a non-negative integer", exactText.c_str());
  } else {
    exactSamples = std::min(exactSamples, samples);
  }
  if (compareText.empty()) {
    compareSamples = std::min<std::uint64_t>(samples, 1000000);
  } else if (!parseCount(compareText, 1e8, false, compareSamples)) {  // two bytes of answers per point are kept
    return kConsole.failf(kBadParameter, "--compare-samples '%s' is not a positive integer <= 1e8", compareText.c_str());
  } else {
    compareSamples = std::min(compareSamples, samples);
  }
  if (!(ecdTimeLimit > 0) || !std::isfinite(ecdTimeLimit)) {
    return kConsole.failf(kBadParameter, "--ecd-time-limit %g must be a positive number of seconds", ecdTimeLimit);
  }
  if (repeat < 1 || repeat > 100) {
    return kConsole.failf(kBadParameter, "--repeat %d must be in [1, 100]", repeat);
  }
  if (gridCells == 0 || gridCells > (1u << 24)) {
    return kConsole.failf(kBadParameter, "--grid-cells %zu must be in [1, 16777216]", gridCells);
  }

  // Output files are checked before the work, not after a long run.
  for (const std::string* out : {&jsonPath, &dumpPath}) {
    if (out->empty()) continue;
    if (!std::ofstream(*out, std::ios::app)) {
      return kConsole.failf(kOutputFailed, "cannot write %s", out->c_str());
    }
  }

  // ---- model
  std::string modelPath = model;
  if (model == "data/meshes/elephant.off" && !fs::exists(model)) modelPath = POINTLOC_DEFAULT_MODEL;
  const auto t0 = Clock::now();
  const acd::ReadResult read = acd::readMesh(modelPath);
  if (!read.status.ok()) {
    // The reader's message usually names the file already.
    if (read.status.message.find(modelPath) != std::string::npos) return kConsole.fail(kBadModel, read.status.message);
    return kConsole.failf(kBadModel, "model %s: %s", modelPath.c_str(), read.status.message.c_str());
  }
  // The exact answer ("inside the model") is defined only for a closed surface; a decomposition
  // of a repaired copy would be compared with a question that has no answer.
  const acd::MeshDiagnosis diagnosis = acd::diagnose(read.mesh);
  if (diagnosis.boundaryEdges > 0 || diagnosis.nonManifoldEdges > 0) {
    return kConsole.failf(kBadModel, "model %s is not a closed surface (%d boundary, %d non-manifold edges): %s",
                          modelPath.c_str(), diagnosis.boundaryEdges, diagnosis.nonManifoldEdges,
                          "inside and outside are undefined");
  }
  const bool progress = isatty(STDERR_FILENO) != 0;

  // ---- decomposition
  acd::DecomposeOptions options;
  options.tau = tau;
  options.threads = threads;
  if (progress)
    options.progress = [](int done, int pending) {
      std::fprintf(stderr, "\rdecomposing: %d done, %d pending   ", done, pending);
    };
  const auto tDec = Clock::now();
  const acd::Decomposition dec = acd::decompose(read.mesh, options);
  const double decomposeSeconds = since(tDec);
  if (progress) std::fprintf(stderr, "\n");
  if (!dec.status.ok()) {
    kConsole.sayf("model %s: %s", modelPath.c_str(), dec.status.message.c_str());
    return appcli::exitFor(dec.status);
  }

  const acd::Box3 box = acd::boundingBox(read.mesh);
  const double boxVolume = box.size().prod();
  const double slack = 1e-10 * std::max(box.size().norm(), 1e-300);
  HullLocator hulls(slack);
  std::vector<int> hullComponent;  // hull index -> component index
  int unresolved = 0;
  for (std::size_t c = 0; c < dec.components.size(); ++c) {
    unresolved += dec.components[c].unresolved ? 1 : 0;
    if (hulls.add(dec.components[c].hull)) hullComponent.push_back(static_cast<int>(c));
  }

  const PointStream points(seed, box);
  tbb::task_arena arena = acd::workerArena(threads);
  const int usedThreads = arena.max_concurrency();
  const auto tGrid = Clock::now();
  if (!noIndex) hulls.buildIndex(box, gridCells, arena);
  const double indexSeconds = since(tGrid);
  const auto hullInside = [&](const Vec3& p) { return noIndex ? hulls.insideDirect(p) : hulls.inside(p); };

  // ---- fast location over all N points (--repeat times; the median time is reported)
  std::uint64_t inside = 0;
  std::vector<double> locateRuns, locateCpuRuns;
  for (int r = 0; r < repeat; ++r) {
    const auto tLoc = Clock::now();
    const double cpuLoc = cpuNow(usedThreads == 1);
    const std::uint64_t in =
        overBlocks(arena, samples, progress ? "locating" : nullptr,
                   [&](std::uint64_t i0, std::uint64_t i1) { return hulls.countInside(points, i0, i1); });
    locateRuns.push_back(since(tLoc));
    // CPU seconds of all threads: on a busy machine the better guide to what location costs.
    locateCpuRuns.push_back(cpuNow(usedThreads == 1) - cpuLoc);
    if (r > 0 && in != inside) {
      return kConsole.failf(kInternal, "internal error: repeated location counted %llu, then %llu",
                            static_cast<unsigned long long>(inside), static_cast<unsigned long long>(in));
    }
    inside = in;
  }
  const double locateSeconds = median(locateRuns), locateCpuSeconds = median(locateCpuRuns);

  // ---- exact answer on the first M points: the exact test alone (timed), then the errors
  const auto tExact = Clock::now();
  const acd::InsideTest exact(read.mesh);
  const double exactBuildSeconds = since(tExact);
  const auto tExactRun = Clock::now();
  const std::uint64_t exactInside = overBlocks(arena, exactSamples, nullptr, [&](std::uint64_t i0, std::uint64_t i1) {
    std::uint64_t in = 0;
    for (std::uint64_t i = i0; i < i1; ++i) in += exact.inside(points(i)) ? 1 : 0;
    return in;
  });
  const double exactRunSeconds = since(tExactRun);
  const int nh = hulls.size();
  const std::uint64_t eblocks = (exactSamples + kBlock - 1) / kBlock;
  // Per block: false outside, and the false-inside points of each hull (a point inside several
  // hulls counts for each: it is excess volume of every one of them).
  std::vector<std::uint64_t> eFalseOut(eblocks, 0);
  std::vector<std::vector<std::uint64_t>> eByHull(eblocks);
  const std::uint64_t falseIn = overBlocks(arena, exactSamples, nullptr, [&](std::uint64_t i0, std::uint64_t i1) {
    const std::uint64_t b = i0 / kBlock;
    std::uint64_t fi = 0, fo = 0;
    for (std::uint64_t i = i0; i < i1; ++i) {
      const Vec3 p = points(i);
      const bool claimed = hullInside(p), truth = exact.inside(p);
      if (claimed && !truth) {
        ++fi;
        if (eByHull[b].empty()) eByHull[b].assign(nh, 0);
        for (int h = 0; h < nh; ++h) eByHull[b][h] += hulls.contains(h, p) ? 1 : 0;
      } else if (!claimed && truth) {
        ++fo;
      }
    }
    eFalseOut[b] = fo;
    return fi;
  });
  const std::uint64_t falseOut = std::accumulate(eFalseOut.begin(), eFalseOut.end(), std::uint64_t{0});
  std::vector<std::uint64_t> byHull(nh, 0);
  for (const auto& v : eByHull)
    for (std::size_t h = 0; h < v.size(); ++h) byHull[h] += v[h];
  std::vector<int> order(nh);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return byHull[a] > byHull[b]; });

  if (!dumpPath.empty()) {
    std::ofstream f(dumpPath);
    f << "x,y,z,hulls,direct,exact\n";
    char line[160];
    for (std::uint64_t i = 0; i < exactSamples && f; ++i) {
      const Vec3 p = points(i);
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%d,%d,%d\n", p.x(), p.y(), p.z(), hullInside(p) ? 1 : 0,
                    hulls.insideDirect(p) ? 1 : 0, exact.inside(p) ? 1 : 0);
      f << line;
    }
    if (!f) {
      return kConsole.failf(kOutputFailed, "cannot write %s", dumpPath.c_str());
    }
  }
  const double mainSeconds = since(t0);

  // ---- --compare: the same points against the model and its exact decomposition
  std::vector<Method> methods;
  pointloc::ExactPieces ecd;
  std::optional<HullLocator> ecdLocator;
  if (compare) {
    const std::uint64_t k = compareSamples;
    std::vector<std::uint8_t> truth(k), answer(k);
    overBlocks(arena, k, nullptr, [&](std::uint64_t i0, std::uint64_t i1) {
      for (std::uint64_t i = i0; i < i1; ++i) truth[i] = exact.inside(points(i)) ? 1 : 0;
      return std::uint64_t{0};
    });
    const auto disagreements = [&] {
      std::uint64_t d = 0;
      for (std::uint64_t i = 0; i < k; ++i) d += truth[i] != answer[i] ? 1 : 0;
      return d;
    };
    // Times `test` on the first k points in `arena`, keeping the answers for the check.
    const auto timeOn = [&](Method m, tbb::task_arena& a, const auto& test) {
      for (int r = 0; r < repeat; ++r) {
        const auto t = Clock::now();
        const bool alone = a.max_concurrency() == 1;
        const double cpu = cpuNow(alone);
        m.inside = overBlocks(a, k, nullptr, [&](std::uint64_t i0, std::uint64_t i1) {
          std::uint64_t in = 0;
          for (std::uint64_t i = i0; i < i1; ++i) {
            answer[i] = test(points(i)) ? 1 : 0;
            in += answer[i];
          }
          return in;
        });
        m.runs.push_back(since(t));
        m.cpuRuns.push_back(cpuNow(alone) - cpu);
      }
      m.seconds = median(m.runs);
      m.points = k;
      m.threads = a.max_concurrency();
      m.disagreements = disagreements();
      return m;
    };
    tbb::task_arena single = acd::workerArena(1);

    Method acdAll{"ACD hulls (grid)", false, decomposeSeconds + indexSeconds, usedThreads, samples, locateSeconds,
                  inside};
    acdAll.runs = locateRuns;
    acdAll.cpuRuns = locateCpuRuns;
    methods.push_back(acdAll);
    methods.push_back(timeOn({"ACD hulls (grid)", false, decomposeSeconds + indexSeconds}, single, hullInside));

    if (progress) std::fprintf(stderr, "compare: CGAL Side_of_triangle_mesh\n");
    const pointloc::CgalSideOfMesh cgal(read.mesh);
    const std::string cgalName = "model: CGAL Side_of_triangle_mesh";
    if (cgal.ok()) {
      const auto test = [&](const Vec3& p) { return cgal.inside(p); };
      methods.push_back(timeOn({cgalName, true, cgal.buildSeconds()}, single, test));
      methods.push_back(timeOn({cgalName, true, cgal.buildSeconds()}, arena, test));
    } else {
      methods.push_back({cgalName, true, 0, 1, 0, 0, 0, std::nullopt, cgal.error()});
    }
    methods.push_back(timeOn({"model: acd::InsideTest", true, exactBuildSeconds}, single,
                             [&](const Vec3& p) { return exact.inside(p); }));
    methods.push_back(timeOn({"model: acd::InsideTest", true, exactBuildSeconds}, arena,
                             [&](const Vec3& p) { return exact.inside(p); }));

    if (progress) std::fprintf(stderr, "compare: exact convex decomposition (limit %g s)\n", ecdTimeLimit);
    ecd = pointloc::exactPieces(read.mesh, ecdTimeLimit);
    const std::string ecdName = "ECD pieces (grid)";
    if (ecd.finished) {
      ecdLocator.emplace(slack);
      for (const acd::TriMesh& piece : ecd.pieces) ecdLocator->add(piece);
      const auto tIndex = Clock::now();
      ecdLocator->buildIndex(box, gridCells, arena);
      const double ecdIndexSeconds = since(tIndex);
      const auto test = [&](const Vec3& p) { return ecdLocator->inside(p); };
      methods.push_back(timeOn({ecdName, true, ecd.seconds + ecdIndexSeconds}, single, test));
      Method all{ecdName, true, ecd.seconds + ecdIndexSeconds, usedThreads, samples};
      for (int r = 0; r < repeat; ++r) {
        const auto t = Clock::now();
        const double cpu = cpuNow(false);
        all.inside =
            overBlocks(arena, samples, progress ? "locating in the ECD" : nullptr,
                       [&](std::uint64_t i0, std::uint64_t i1) { return ecdLocator->countInside(points, i0, i1); });
        all.runs.push_back(since(t));
        all.cpuRuns.push_back(cpuNow(false) - cpu);
      }
      all.seconds = median(all.runs);
      methods.push_back(all);
    } else {
      methods.push_back({ecdName, true, ecd.seconds, 0, 0, 0, 0, std::nullopt,
                         !ecd.available ? ecd.note : (ecd.refused ? "refused: " : "unfinished: ") + ecd.note});
    }
  }
  const double totalSeconds = since(t0);

  // ---- report
  const double pps = locateSeconds > 0 ? static_cast<double>(samples) / locateSeconds : 0.0;
  const double exactPps = exactRunSeconds > 0 ? static_cast<double>(exactSamples) / exactRunSeconds : 0.0;
  const double m = static_cast<double>(std::max<std::uint64_t>(exactSamples, 1));
  const pointloc::Interval ciIn = pointloc::wilson95(falseIn, exactSamples),
                           ciOut = pointloc::wilson95(falseOut, exactSamples),
                           ciAll = pointloc::wilson95(falseIn + falseOut, exactSamples);

  std::printf("pointloc  %s\n", modelPath.c_str());
  std::printf("  tau                    %g\n", tau);
  std::printf("  components             %zu (%d unresolved), %zu half-spaces (6 of them the box, per hull)\n",
              dec.components.size(), unresolved, hulls.planeCount());
  std::printf("  threads                %d\n", usedThreads);
  std::printf("  seed                   %llu\n", static_cast<unsigned long long>(seed));
  std::printf("  decomposition time     %.3f s\n", decomposeSeconds);
  if (!noIndex)
    std::printf("  hull grid              %dx%dx%d, %.3f s, %.1f%% cells inside, %.1f%% boundary (%.1f planes each), %.1f MB\n",
                hulls.gridX(), hulls.gridY(), hulls.gridZ(), indexSeconds,
                100.0 * static_cast<double>(hulls.insideCells()) / static_cast<double>(hulls.cellCount()),
                100.0 * static_cast<double>(hulls.boundaryCells()) / static_cast<double>(hulls.cellCount()),
                hulls.planesPerBoundaryCell(), static_cast<double>(hulls.indexBytes()) / 1e6);
  std::printf("  points                 %llu\n", static_cast<unsigned long long>(samples));
  std::printf("  location time          %.3f s wall, %.3f s CPU%s\n", locateSeconds, locateCpuSeconds,
              repeat > 1 ? (" (median of " + std::to_string(repeat) + " runs, wall " +
                            std::to_string(*std::min_element(locateRuns.begin(), locateRuns.end())).substr(0, 5) + " to " +
                            std::to_string(*std::max_element(locateRuns.begin(), locateRuns.end())).substr(0, 5) + " s)")
                                   .c_str()
                           : "");
  std::printf("  points per second      %s\n", human(pps).c_str());
  std::printf("  points inside          %llu (%.4f%% of the box)\n", static_cast<unsigned long long>(inside),
              100.0 * static_cast<double>(inside) / static_cast<double>(samples));
  std::printf("  exact test alone       %llu points, %.3f s (+%.3f s index), %s points/s\n",
              static_cast<unsigned long long>(exactSamples), exactRunSeconds, exactBuildSeconds,
              human(exactPps).c_str());
  std::printf("  false inside           %llu  rate %.3e  95%% CI [%.3e, %.3e]\n",
              static_cast<unsigned long long>(falseIn), falseIn / m, ciIn.lo, ciIn.hi);
  std::printf("  false outside          %llu  rate %.3e  95%% CI [%.3e, %.3e]\n",
              static_cast<unsigned long long>(falseOut), falseOut / m, ciOut.lo, ciOut.hi);
  std::printf("  error rate             %.3e  95%% CI [%.3e, %.3e]  (of all points; %.3e of the points truly inside)\n",
              (falseIn + falseOut) / m, ciAll.lo, ciAll.hi,
              exactInside ? static_cast<double>(falseIn + falseOut) / static_cast<double>(exactInside) : 0.0);
  std::printf("  top components by false-inside volume (points in their hull, volume estimate, share):\n");
  json top = json::array();
  for (int t = 0; t < std::min(nh, 5); ++t) {
    const int h = order[t];
    if (byHull[h] == 0) break;
    const double volume = static_cast<double>(byHull[h]) / m * boxVolume;
    const double share = static_cast<double>(byHull[h]) / static_cast<double>(std::max<std::uint64_t>(falseIn, 1));
    std::printf("    component %-5d %8llu  %.4g  %.1f%%\n", hullComponent[h], static_cast<unsigned long long>(byHull[h]),
                volume, 100.0 * share);
    top.push_back({{"component", hullComponent[h]}, {"false_inside", byHull[h]}, {"volume", volume}, {"share", share}});
  }
  std::printf("  total time             %.3f s%s\n", mainSeconds, compare ? " (without --compare)" : "");

  json compareJson = json::array();
  double vsCgal1 = 0.0, vsCgalAll = 0.0, cgalPerCpu = 0.0;
  if (compare) {
    std::printf("\ncompare (same points; %llu for the exact methods; time for N extrapolated where fewer were timed;"
                " median of %d runs)\n",
                static_cast<unsigned long long>(compareSamples), repeat);
    std::printf("  %-36s %7s %9s %7s %11s %11s %12s %11s %10s %10s\n", "method", "threads", "prepare s", "points",
                "points/s", "per CPU s", "N points s", "total s", "inside", "wrong");
    for (const Method& r : methods) {
      if (!r.measured()) {
        std::printf("  %-36s %s\n", r.name.c_str(), r.note.c_str());
        compareJson.push_back({{"method", r.name}, {"exact", r.exact}, {"available", false}, {"note", r.note}});
        continue;
      }
      const double forN = r.secondsFor(samples);
      const double perCpu = r.cpuSeconds() > 0 ? static_cast<double>(r.points) / r.cpuSeconds() : 0.0;
      std::printf("  %-36s %7d %9.3f %7s %11s %11s %11.3f%s %11.3f %10llu %10s\n", r.name.c_str(), r.threads,
                  r.prepareSeconds, human(static_cast<double>(r.points)).c_str(), human(r.rate()).c_str(),
                  human(perCpu).c_str(), forN,
                  r.points < samples ? "*" : " ", r.prepareSeconds + forN, static_cast<unsigned long long>(r.inside),
                  r.disagreements ? std::to_string(*r.disagreements).c_str() : "-");
      compareJson.push_back({{"method", r.name},
                             {"exact", r.exact},
                             {"available", true},
                             {"threads", r.threads},
                             {"prepare_seconds", r.prepareSeconds},
                             {"points", r.points},
                             {"seconds", r.seconds},
                             {"seconds_runs", r.runs},
                             {"cpu_seconds", r.cpuSeconds()},
                             {"cpu_seconds_runs", r.cpuRuns},
                             {"points_per_cpu_second", r.cpuSeconds() > 0 ? r.points / r.cpuSeconds() : 0.0},
                             {"points_per_second", r.rate()},
                             {"seconds_for_all_points", forN},
                             {"extrapolated", r.points < samples},
                             {"total_seconds", r.prepareSeconds + forN},
                             {"points_inside", r.inside},
                             {"disagreements_with_exact", r.disagreements ? json(*r.disagreements) : json(nullptr)}});
      if (r.name.rfind("model: CGAL", 0) == 0) {
        (r.threads == 1 ? vsCgal1 : vsCgalAll) = pps / r.rate();
        if (r.threads == 1 && perCpu > 0) cgalPerCpu = perCpu;
      }
    }
    std::printf("  (* extrapolated from the points timed; 'wrong' = answers that differ from acd::InsideTest on the\n"
                "   first %llu points; 'prepare' = decomposition or AABB tree, and the grid)\n",
                static_cast<unsigned long long>(compareSamples));
    if (vsCgal1 > 0)
      std::printf("  ACD hulls, %d threads, are %.1fx the rate of CGAL on 1 thread and %.1fx CGAL on %d threads\n",
                  usedThreads, vsCgal1, vsCgalAll, usedThreads);
    // Per CPU second the ratio does not depend on how much of the machine this process got.
    if (cgalPerCpu > 0 && locateCpuSeconds > 0)
      std::printf("  per CPU second: ACD hulls %s points, CGAL %s points (%.1fx)\n",
                  human(static_cast<double>(samples) / locateCpuSeconds).c_str(), human(cgalPerCpu).c_str(),
                  static_cast<double>(samples) / locateCpuSeconds / cgalPerCpu);
    if (ecd.available)
      std::printf("  exact convex decomposition: %zu pieces, %.3f s, %s%s%s\n", ecd.pieceCount, ecd.seconds,
                  ecd.refused ? "refused" : ecd.finished ? "finished" : "unfinished", ecd.note.empty() ? "" : ": ",
                  ecd.note.c_str());
  }

  if (!jsonPath.empty()) {
    json j;
    j["model"] = modelPath;
    j["tau"] = tau;
    j["seed"] = seed;
    j["threads"] = usedThreads;
    j["components"] = dec.components.size();
    j["unresolved_components"] = unresolved;
    j["half_spaces"] = hulls.planeCount();
    j["samples"] = samples;
    j["points_inside"] = inside;
    j["box_volume"] = boxVolume;
    j["decomposition_seconds"] = decomposeSeconds;
    j["location_seconds"] = locateSeconds;
    j["location_cpu_seconds"] = locateCpuSeconds;
    j["repeat"] = repeat;
    j["location_seconds_runs"] = locateRuns;
    j["location_cpu_seconds_runs"] = locateCpuRuns;
    j["index"] = noIndex ? json(nullptr)
                         : json{{"cells", {hulls.gridX(), hulls.gridY(), hulls.gridZ()}},
                                {"seconds", indexSeconds},
                                {"inside_cells", hulls.insideCells()},
                                {"boundary_cells", hulls.boundaryCells()},
                                {"planes_per_boundary_cell", hulls.planesPerBoundaryCell()},
                                {"bytes", hulls.indexBytes()}};
    j["total_seconds"] = mainSeconds;
    j["points_per_second"] = pps;
    j["exact"] = {{"method", "acd::InsideTest"},
                  {"samples", exactSamples},
                  {"points_inside", exactInside},
                  {"seconds", exactRunSeconds},
                  {"index_seconds", exactBuildSeconds},
                  {"points_per_second", exactPps},
                  {"false_inside", falseIn},
                  {"false_outside", falseOut},
                  {"false_inside_rate", falseIn / m},
                  {"false_outside_rate", falseOut / m},
                  {"false_inside_ci95", {ciIn.lo, ciIn.hi}},
                  {"false_outside_ci95", {ciOut.lo, ciOut.hi}},
                  {"error_rate", (falseIn + falseOut) / m},
                  {"error_rate_ci95", {ciAll.lo, ciAll.hi}},
                  {"error_rate_of_inside",
                   exactInside ? static_cast<double>(falseIn + falseOut) / static_cast<double>(exactInside) : 0.0},
                  {"top_false_inside", top}};
    if (compare) {
      j["compare"] = {{"samples", compareSamples},
                      {"methods", compareJson},
                      {"speedup_vs_cgal_1_thread", vsCgal1},
                      {"speedup_vs_cgal_same_threads", vsCgalAll},
                      {"speedup_vs_cgal_per_cpu_second",
                       cgalPerCpu > 0 && locateCpuSeconds > 0
                           ? static_cast<double>(samples) / locateCpuSeconds / cgalPerCpu
                           : 0.0},
                      {"ecd",
                       {{"available", ecd.available},
                        {"refused", ecd.refused},
                        {"finished", ecd.finished},
                        {"pieces", ecd.pieceCount},
                        {"seconds", ecd.seconds},
                        {"time_limit_seconds", ecdTimeLimit},
                        {"note", ecd.note}}}};
      j["compare_seconds"] = totalSeconds - mainSeconds;
    }
    std::ofstream f(jsonPath);
    f << j.dump(2) << "\n";
    if (!f) {
      return kConsole.failf(kOutputFailed, "cannot write %s", jsonPath.c_str());
    }
  }
  return kOk;
}
