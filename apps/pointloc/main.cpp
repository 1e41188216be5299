// pointloc: point location against the convex hulls of an approximate convex decomposition
// (paper, Section 7, Figure 20), with error statistics against the exact answer.
//
//   pointloc [MODEL] [--samples 1e8] [--tau 0.02] [--threads N] [--seed S] [--exact-samples M] [--json FILE]
//
// Points are uniform in the model's bounding box; point i depends only on (seed, i) through a
// counter-based hash, and work runs over fixed blocks whose counts are combined in block order,
// so every count is identical for any number of threads.
#include "exact_inside.hpp"

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

inline std::uint64_t mix64(std::uint64_t z) {
  z += 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// Point i, uniform in [lo, hi]: depends only on (seed, i).
struct PointStream {
  std::uint64_t key;
  Vec3 lo, size;
  Vec3 operator()(std::uint64_t i) const {
    const std::uint64_t base = key ^ mix64(i);
    const double u = static_cast<double>(mix64(base + 0x632BE59BD9B4E019ull) >> 11) * 0x1p-53;
    const double v = static_cast<double>(mix64(base + 0x8CB92BA72F3D8DD7ull) >> 11) * 0x1p-53;
    const double w = static_cast<double>(mix64(base + 0xA0761D6478BD642Full) >> 11) * 0x1p-53;
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

  /// Index of the first hull that contains p, or -1.
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

  PointStream points{mix64(seed ^ 0x5EED5EED5EED5EEDull), box.lo, box.size()};

  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  const int usedThreads = arena.max_concurrency();

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
                for (std::uint64_t i = i0; i < i1; ++i) in += hulls.locate(points(i)) >= 0 ? 1 : 0;
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
  const pointloc::ExactInside exact(read.mesh);
  const double exactBuildSeconds = since(tExact);
  const std::uint64_t eblocks = (exactSamples + kBlock - 1) / kBlock;
  const int nh = hulls.size();
  // Per block: false inside, false outside, exact inside, and false inside per hull.
  std::vector<std::uint64_t> eFalseIn(eblocks, 0), eFalseOut(eblocks, 0), eInside(eblocks, 0);
  std::vector<std::vector<std::uint64_t>> eByHull(eblocks);
  const auto tExactRun = Clock::now();
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
              const int h = hulls.locate(p);
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
  const double exactRunSeconds = since(tExactRun);
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
  std::printf("  points                 %llu\n", static_cast<unsigned long long>(samples));
  std::printf("  location time          %.3f s\n", locateSeconds);
  std::printf("  points per second      %s\n", human(pps).c_str());
  std::printf("  points inside          %llu (%.4f%% of the box)\n", static_cast<unsigned long long>(inside),
              100.0 * static_cast<double>(inside) / static_cast<double>(samples));
  std::printf("  exact subsample        %llu points, %.3f s (+%.3f s index), %s points/s\n",
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
