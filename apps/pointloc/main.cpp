// pointloc: point location against the convex hulls of an approximate convex decomposition
// (paper, Section 7, Figure 20), with error statistics against the exact answer.
//
//   pointloc [MODEL] [--samples 1e8] [--tau 0.02] [--threads N] [--seed S] [--exact-samples M] [--json FILE]
//
// Points are uniform in the model's bounding box; point i depends only on (seed, i) through a
// counter-based hash, and work runs over fixed blocks whose counts are combined in block order,
// so every count is identical for any number of threads.
#include <acd/inside.hpp>
#include <acd/random.hpp>

#include <acd/decompose.hpp>
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
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using json = nlohmann::json;
using acd::Vec3;

namespace {

enum Exit : int { kOk = 0, kUsage = 1, kBadModel = 2, kBadParameter = 3, kOutputFailed = 5, kInternal = 6 };

constexpr std::uint64_t kBlock = 1u << 16;  // points per block (fixed: results never depend on threads)

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// ---------------------------------------------------------------- random points


/// Point i, uniform in [lo, hi]: depends only on (seed, i).
struct PointStream {
  std::uint64_t key;
  Vec3 lo, size;
  Vec3 operator()(std::uint64_t i) const {
    const std::uint64_t base = key ^ acd::mix64(i);
    const double u = acd::unitInterval(acd::mix64(base + 0x632BE59BD9B4E019ull));
    const double v = acd::unitInterval(acd::mix64(base + 0x8CB92BA72F3D8DD7ull));
    const double w = acd::unitInterval(acd::mix64(base + 0xA0761D6478BD642Full));
    return {lo.x() + u * size.x(), lo.y() + v * size.y(), lo.z() + w * size.z()};
  }
};

// ---------------------------------------------------------------- hulls as half-spaces

/// All hulls' planes in one flat array; hull h owns planes [first[h], first[h + 1]).
struct HullSet {
  struct Plane {
    double nx, ny, nz, d;  // inside iff n.x <= d + slack
  };
  std::vector<Plane> planes;
  std::vector<int> first{0};
  std::vector<Vec3> lo, hi;
  double slack = 0.0;

  int size() const { return static_cast<int>(lo.size()); }

  void add(const acd::TriMesh& hull) {
    if (hull.faces.empty()) return;
    Vec3 l = hull.vertices[hull.faces[0][0]], h = l;
    const std::size_t start = planes.size();
    for (const acd::Face& f : hull.faces) {
      const Vec3 &a = hull.vertices[f[0]], &b = hull.vertices[f[1]], &c = hull.vertices[f[2]];
      l = l.cwiseMin(a).cwiseMin(b).cwiseMin(c);
      h = h.cwiseMax(a).cwiseMax(b).cwiseMax(c);
      Vec3 n = (b - a).cross(c - a);
      const double len = n.norm();
      if (!(len > 0)) continue;
      n /= len;
      // Support value over all hull vertices, not the face's own plane: a sliver triangle's
      // rounded normal can point anywhere, and its plane must still keep the whole hull inside.
      double d = n.dot(a);
      for (const Vec3& v : hull.vertices) d = std::max(d, n.dot(v));
      bool duplicate = false;  // coplanar triangles of one facet give one plane
      for (std::size_t k = start; k < planes.size() && !duplicate; ++k) {
        const Plane& p = planes[k];
        duplicate = p.nx * n.x() + p.ny * n.y() + p.nz * n.z() > 1 - 1e-12 && std::abs(p.d - d) <= slack;
      }
      if (!duplicate) planes.push_back({n.x(), n.y(), n.z(), d});
    }
    lo.push_back(l);
    hi.push_back(h);
    first.push_back(static_cast<int>(planes.size()));
  }

  // ---- uniform grid over the box: per cell, either a hull that holds the whole cell, or the
  // hulls that may hold part of it (bounding boxes overlap and no half-space excludes the cell).
  Vec3 gridLo = Vec3::Zero(), gridScale = Vec3::Ones();
  int gx = 1, gy = 1, gz = 1;
  std::vector<int> cellFull;              // hull holding the whole cell, or -1
  std::vector<std::uint32_t> cellStart;   // CSR offsets into cellHulls
  std::vector<int> cellHulls;

  void buildGrid(const acd::Box3& box, std::size_t targetCells, tbb::task_arena& arena) {
    const Vec3 extent = box.size().cwiseMax(Vec3::Constant(1e-300));
    const double unit = std::cbrt(extent.prod() / static_cast<double>(targetCells));
    gx = std::clamp(static_cast<int>(std::ceil(extent.x() / unit)), 1, 1024);
    gy = std::clamp(static_cast<int>(std::ceil(extent.y() / unit)), 1, 1024);
    gz = std::clamp(static_cast<int>(std::ceil(extent.z() / unit)), 1, 1024);
    gridLo = box.lo;
    gridScale = Vec3(gx / extent.x(), gy / extent.y(), gz / extent.z());
    const Vec3 cell(extent.x() / gx, extent.y() / gy, extent.z() / gz);
    const double margin = 1e-9 * extent.norm();  // covers rounding of the cell index
    const std::size_t cells = static_cast<std::size_t>(gx) * gy * gz;
    cellFull.assign(cells, -1);
    std::vector<std::vector<int>> lists(cells);
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cells), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t c = r.begin(); c != r.end(); ++c) {
          const int ix = static_cast<int>(c % gx), iy = static_cast<int>((c / gx) % gy),
                    iz = static_cast<int>(c / (static_cast<std::size_t>(gx) * gy));
          const Vec3 clo = box.lo + Vec3(ix * cell.x(), iy * cell.y(), iz * cell.z()) - Vec3::Constant(margin);
          const Vec3 chi = box.lo + Vec3((ix + 1) * cell.x(), (iy + 1) * cell.y(), (iz + 1) * cell.z()) +
                           Vec3::Constant(margin);
          for (int h = 0; h < size(); ++h) {
            if ((chi.array() < lo[h].array()).any() || (clo.array() > hi[h].array()).any()) continue;
            bool excluded = false, full = true;
            for (int k = first[h]; k < first[h + 1] && !excluded; ++k) {
              const Plane& q = planes[k];
              const double mn = (q.nx > 0 ? q.nx * clo.x() : q.nx * chi.x()) + (q.ny > 0 ? q.ny * clo.y() : q.ny * chi.y()) +
                                (q.nz > 0 ? q.nz * clo.z() : q.nz * chi.z());
              const double mx = (q.nx > 0 ? q.nx * chi.x() : q.nx * clo.x()) + (q.ny > 0 ? q.ny * chi.y() : q.ny * clo.y()) +
                                (q.nz > 0 ? q.nz * chi.z() : q.nz * clo.z());
              excluded = mn > q.d + 2 * slack;
              full = full && mx <= q.d;
            }
            if (excluded) continue;
            if (full) {
              cellFull[c] = h;
              lists[c].clear();
              break;
            }
            lists[c].push_back(h);
          }
        }
      });
    });
    cellStart.assign(cells + 1, 0);
    for (std::size_t c = 0; c < cells; ++c) cellStart[c + 1] = cellStart[c] + static_cast<std::uint32_t>(lists[c].size());
    cellHulls.resize(cellStart[cells]);
    for (std::size_t c = 0; c < cells; ++c) std::copy(lists[c].begin(), lists[c].end(), cellHulls.begin() + cellStart[c]);
  }

  bool inHull(int h, const Vec3& p) const {
    for (int k = first[h], e = first[h + 1]; k < e; ++k) {
      const Plane& q = planes[k];
      if (q.nx * p.x() + q.ny * p.y() + q.nz * p.z() > q.d + slack) return false;
    }
    return true;
  }

  /// A hull that contains p, or -1, through the grid (points outside the grid's box: -1).
  int locateIndexed(const Vec3& p) const {
    const double fx = (p.x() - gridLo.x()) * gridScale.x(), fy = (p.y() - gridLo.y()) * gridScale.y(),
                 fz = (p.z() - gridLo.z()) * gridScale.z();
    if (!(fx >= 0 && fy >= 0 && fz >= 0 && fx <= gx && fy <= gy && fz <= gz)) return locate(p);
    const int ix = std::min(static_cast<int>(fx), gx - 1), iy = std::min(static_cast<int>(fy), gy - 1),
              iz = std::min(static_cast<int>(fz), gz - 1);
    const std::size_t c = (static_cast<std::size_t>(iz) * gy + iy) * gx + ix;
    if (cellFull[c] >= 0) return cellFull[c];
    for (std::uint32_t k = cellStart[c], e = cellStart[c + 1]; k < e; ++k) {
      const int h = cellHulls[k];
      if (p.x() < lo[h].x() || p.x() > hi[h].x() || p.y() < lo[h].y() || p.y() > hi[h].y() || p.z() < lo[h].z() ||
          p.z() > hi[h].z())
        continue;
      if (inHull(h, p)) return h;
    }
    return -1;
  }

  /// Index of the first hull that contains p, or -1 (every hull's box tested).
  int locate(const Vec3& p) const {
    const int n = size();
    for (int h = 0; h < n; ++h) {
      if (p.x() < lo[h].x() || p.x() > hi[h].x() || p.y() < lo[h].y() || p.y() > hi[h].y() || p.z() < lo[h].z() ||
          p.z() > hi[h].z())
        continue;
      bool in = true;
      for (int k = first[h], e = first[h + 1]; k < e; ++k) {
        const Plane& q = planes[k];
        if (q.nx * p.x() + q.ny * p.y() + q.nz * p.z() > q.d + slack) {
          in = false;
          break;
        }
      }
      if (in) return h;
    }
    return -1;
  }
};

// ---------------------------------------------------------------- parsing

/// Positive integer written as a double ("1e8" or "100000000"), at most `max`.
bool parseCount(const std::string& s, double max, bool allowZero, std::uint64_t& out) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == s.c_str() || *end != '\0' || !std::isfinite(v)) return false;
  if (v != std::floor(v) || v > max || v < 0 || (!allowZero && v == 0)) return false;
  out = static_cast<std::uint64_t>(v);
  return true;
}

struct Wilson {
  double lo, hi;
};
Wilson wilson(std::uint64_t k, std::uint64_t n) {
  if (n == 0) return {0.0, 1.0};
  const double z = 1.959963984540054, nn = static_cast<double>(n), p = static_cast<double>(k) / nn;
  const double denom = 1 + z * z / nn;
  const double center = (p + z * z / (2 * nn)) / denom;
  const double half = z * std::sqrt(p * (1 - p) / nn + z * z / (4 * nn * nn)) / denom;
  return {k == 0 ? 0.0 : std::max(0.0, center - half), k == n ? 1.0 : std::min(1.0, center + half)};
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "pointloc: locate random points in the union of the convex hulls of an approximate convex\n"
      "decomposition, and compare with the exact point-in-model answer on a subsample."};
  std::string model = "data/meshes/elephant.off";
  std::string samplesText = "1e8", tauText = "0.02", exactText;
  int threads = 0;
  std::uint64_t seed = 1;
  std::string jsonPath;
  bool noIndex = false;
  std::size_t gridCells = 1u << 17;
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
  app.add_option("--json", jsonPath, "write the report as JSON to FILE");
  app.add_flag("--no-index", noIndex, "test every hull's bounding box for every point (no grid; same counts)");
  app.add_option("--grid-cells", gridCells, "cells of the grid over the box (about)")->capture_default_str();
  app.footer(
      "Exit codes: 0 success; 1 bad command line; 2 unreadable or invalid model; 3 invalid parameter;\n"
      "5 cannot write output; 6 internal error.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kUsage;
  }

  // ---- parameters first: they need no model
  std::uint64_t samples = 0, exactSamples = 0;
  if (!parseCount(samplesText, 1e10, false, samples)) {
    std::fprintf(stderr, "pointloc: --samples '%s' is not a positive integer <= 1e10\n", samplesText.c_str());
    return kBadParameter;
  }
  char* end = nullptr;
  const double tau = std::strtod(tauText.c_str(), &end);
  if (tauText.empty() || *end != '\0' || !(tau > 0.0 && tau <= 2.0)) {
    std::fprintf(stderr, "pointloc: --tau '%s' must be a number in (0, 2]\n", tauText.c_str());
    return kBadParameter;
  }
  if (threads < 0) {
    std::fprintf(stderr, "pointloc: --threads %d must be >= 0\n", threads);
    return kBadParameter;
  }
  if (exactText.empty()) {
    exactSamples = std::min<std::uint64_t>(samples, 2000000);
  } else if (!parseCount(exactText, 1e10, true, exactSamples)) {
    std::fprintf(stderr, "pointloc: --exact-samples '%s' is not a non-negative integer\n", exactText.c_str());
    return kBadParameter;
  } else {
    exactSamples = std::min(exactSamples, samples);
  }

  // ---- model
  std::string modelPath = model;
  if (model == "data/meshes/elephant.off" && !fs::exists(model)) modelPath = POINTLOC_DEFAULT_MODEL;
  const auto t0 = Clock::now();
  const acd::ReadResult read = acd::readMesh(modelPath);
  if (!read.status.ok()) {
    std::fprintf(stderr, "pointloc: model %s: %s\n", modelPath.c_str(), read.status.message.c_str());
    return kBadModel;
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
    std::fprintf(stderr, "pointloc: model %s: %s\n", modelPath.c_str(), dec.status.message.c_str());
    return dec.status.code == acd::StatusCode::InvalidParameter ? kBadParameter
           : dec.status.code == acd::StatusCode::InternalError  ? kInternal
                                                                : kBadModel;
  }

  const acd::Box3 box = acd::boundingBox(read.mesh);
  HullSet hulls;
  hulls.slack = 1e-10 * std::max(box.size().norm(), 1e-300);
  std::vector<int> hullComponent;  // hull index -> component index
  int unresolved = 0;
  for (std::size_t c = 0; c < dec.components.size(); ++c) {
    unresolved += dec.components[c].unresolved ? 1 : 0;
    const int before = hulls.size();
    hulls.add(dec.components[c].hull);
    if (hulls.size() > before) hullComponent.push_back(static_cast<int>(c));
  }
  std::size_t totalPlanes = hulls.planes.size();

  PointStream points{acd::mix64(seed ^ 0x5EED5EED5EED5EEDull), box.lo, box.size()};

  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  const int usedThreads = arena.max_concurrency();
  const auto tGrid = Clock::now();
  if (!noIndex) hulls.buildGrid(box, std::clamp<std::size_t>(gridCells, 1, 1u << 24), arena);
  const double gridSeconds = since(tGrid);
  auto where = [&](const Vec3& p) { return noIndex ? hulls.locate(p) : hulls.locateIndexed(p); };

  // ---- fast location over all N points
  const std::uint64_t blocks = (samples + kBlock - 1) / kBlock;
  std::vector<std::uint64_t> blockInside(blocks, 0);
  const auto tLoc = Clock::now();
  {
    const std::uint64_t chunk = progress ? std::max<std::uint64_t>(1, blocks / 100) : blocks;
    for (std::uint64_t b0 = 0; b0 < blocks; b0 += chunk) {
      const std::uint64_t b1 = std::min(blocks, b0 + chunk);
      arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<std::uint64_t>(b0, b1, 1),
            [&](const tbb::blocked_range<std::uint64_t>& r) {
              for (std::uint64_t b = r.begin(); b != r.end(); ++b) {
                const std::uint64_t i0 = b * kBlock, i1 = std::min(samples, i0 + kBlock);
                std::uint64_t in = 0;
                for (std::uint64_t i = i0; i < i1; ++i) in += where(points(i)) >= 0 ? 1 : 0;
                blockInside[b] = in;
              }
            },
            tbb::simple_partitioner());
      });
      if (progress) std::fprintf(stderr, "\rlocating: %3.0f%%", 100.0 * static_cast<double>(b1) / blocks);
    }
    if (progress) std::fprintf(stderr, "\n");
  }
  const double locateSeconds = since(tLoc);
  const std::uint64_t inside = std::accumulate(blockInside.begin(), blockInside.end(), std::uint64_t{0});

  // ---- exact answer on the first M points
  const auto tExact = Clock::now();
  const acd::InsideTest exact(read.mesh);
  const double exactBuildSeconds = since(tExact);
  const std::uint64_t eblocks = (exactSamples + kBlock - 1) / kBlock;
  const int nh = hulls.size();
  // Per block: false inside, false outside, exact inside, and false inside per hull.
  std::vector<std::uint64_t> eFalseIn(eblocks, 0), eFalseOut(eblocks, 0), eInside(eblocks, 0);
  std::vector<std::vector<std::uint64_t>> eByHull(eblocks);
  // Exact test alone, timed, for the comparison of rates.
  std::vector<std::uint64_t> exactOnly(eblocks, 0);
  const auto tExactRun = Clock::now();
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::uint64_t>(0, eblocks, 1),
        [&](const tbb::blocked_range<std::uint64_t>& r) {
          for (std::uint64_t b = r.begin(); b != r.end(); ++b) {
            const std::uint64_t i0 = b * kBlock, i1 = std::min(exactSamples, i0 + kBlock);
            std::uint64_t in = 0;
            for (std::uint64_t i = i0; i < i1; ++i) in += exact.inside(points(i)) ? 1 : 0;
            exactOnly[b] = in;
          }
        },
        tbb::simple_partitioner());
  });
  const double exactRunSeconds = since(tExactRun);
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::uint64_t>(0, eblocks, 1),
        [&](const tbb::blocked_range<std::uint64_t>& r) {
          for (std::uint64_t b = r.begin(); b != r.end(); ++b) {
            const std::uint64_t i0 = b * kBlock, i1 = std::min(exactSamples, i0 + kBlock);
            std::vector<std::uint64_t> byHull(nh, 0);
            std::uint64_t fi = 0, fo = 0, ei = 0;
            for (std::uint64_t i = i0; i < i1; ++i) {
              const Vec3 p = points(i);
              const int h = where(p);
              const bool truth = exact.inside(p);
              ei += truth ? 1 : 0;
              if (h >= 0 && !truth) {
                ++fi;
                ++byHull[h];
              } else if (h < 0 && truth) {
                ++fo;
              }
            }
            eFalseIn[b] = fi;
            eFalseOut[b] = fo;
            eInside[b] = ei;
            eByHull[b] = std::move(byHull);
          }
        },
        tbb::simple_partitioner());
  });
  std::uint64_t falseIn = 0, falseOut = 0, exactInside = 0;
  std::vector<std::uint64_t> byHull(nh, 0);
  for (std::uint64_t b = 0; b < eblocks; ++b) {
    falseIn += eFalseIn[b];
    falseOut += eFalseOut[b];
    exactInside += eInside[b];
    for (int h = 0; h < nh; ++h) byHull[h] += eByHull[b][h];
  }
  std::vector<int> order(nh);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return byHull[a] > byHull[b]; });
  const double totalSeconds = since(t0);

  // ---- report
  const double pps = locateSeconds > 0 ? static_cast<double>(samples) / locateSeconds : 0.0;
  const double exactPps = exactRunSeconds > 0 ? static_cast<double>(exactSamples) / exactRunSeconds : 0.0;
  const double m = static_cast<double>(std::max<std::uint64_t>(exactSamples, 1));
  const Wilson ciIn = wilson(falseIn, exactSamples), ciOut = wilson(falseOut, exactSamples),
               ciAll = wilson(falseIn + falseOut, exactSamples);

  std::printf("pointloc  %s\n", modelPath.c_str());
  std::printf("  tau                    %g\n", tau);
  std::printf("  components             %zu (%d unresolved), %zu half-spaces\n", dec.components.size(), unresolved,
              totalPlanes);
  std::printf("  threads                %d\n", usedThreads);
  std::printf("  seed                   %llu\n", static_cast<unsigned long long>(seed));
  std::printf("  decomposition time     %.3f s\n", decomposeSeconds);
  if (!noIndex)
    std::printf("  hull grid              %dx%dx%d, %.3f s, %.2f hull candidates per cell\n", hulls.gx, hulls.gy, hulls.gz,
                gridSeconds, static_cast<double>(hulls.cellHulls.size()) /
                                 std::max<double>(1.0, static_cast<double>(std::count(hulls.cellFull.begin(), hulls.cellFull.end(), -1))));
  std::printf("  points                 %llu\n", static_cast<unsigned long long>(samples));
  std::printf("  location time          %.3f s\n", locateSeconds);
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
  std::printf("  error rate             %.3e  95%% CI [%.3e, %.3e]\n", (falseIn + falseOut) / m, ciAll.lo, ciAll.hi);
  std::printf("  top components by false inside:\n");
  json top = json::array();
  for (int k = 0; k < std::min(nh, 5); ++k) {
    const int h = order[k];
    if (byHull[h] == 0) break;
    std::printf("    component %-5d %llu\n", hullComponent[h], static_cast<unsigned long long>(byHull[h]));
    top.push_back({{"component", hullComponent[h]}, {"false_inside", byHull[h]}});
  }
  std::printf("  total time             %.3f s\n", totalSeconds);

  if (!jsonPath.empty()) {
    json j;
    j["model"] = modelPath;
    j["tau"] = tau;
    j["seed"] = seed;
    j["threads"] = usedThreads;
    j["components"] = dec.components.size();
    j["unresolved_components"] = unresolved;
    j["half_spaces"] = totalPlanes;
    j["samples"] = samples;
    j["points_inside"] = inside;
    j["decomposition_seconds"] = decomposeSeconds;
    j["location_seconds"] = locateSeconds;
    j["index"] = noIndex ? json(nullptr) : json{{"cells", {hulls.gx, hulls.gy, hulls.gz}}, {"seconds", gridSeconds}};
    j["total_seconds"] = totalSeconds;
    j["points_per_second"] = pps;
    j["exact"] = {{"samples", exactSamples},
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
                  {"top_false_inside", top}};
    std::ofstream f(jsonPath);
    f << j.dump(2) << "\n";
    if (!f) {
      std::fprintf(stderr, "pointloc: cannot write %s\n", jsonPath.c_str());
      return kOutputFailed;
    }
  }
  return kOk;
}
