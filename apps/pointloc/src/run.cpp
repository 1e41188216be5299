#include "run.hpp"

#include <appcli/exit_codes.hpp>

#include <acd/diagnosis.hpp>
#include <acd/io.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace pointloc {

namespace fs = std::filesystem;
using appcli::kInternal;
using appcli::kOk;
using appcli::kOutputFailed;
constexpr int kBadModel = appcli::kBadInput;

int readModel(Run& run) {
  run.modelPath = run.p.model;
  if (run.p.model == "data/meshes/elephant.off" && !fs::exists(run.p.model)) run.modelPath = POINTLOC_DEFAULT_MODEL;
  const std::string& path = run.modelPath;
  run.t0 = Clock::now();
  acd::ReadResult read = acd::readMesh(path);
  if (!read.status.ok()) {
    // The reader's message usually names the file already.
    if (read.status.message.find(path) != std::string::npos) return kConsole.fail(kBadModel, read.status.message);
    return kConsole.failf(kBadModel, "model %s: %s", path.c_str(), read.status.message.c_str());
  }
  // The exact answer ("inside the model") is defined only for a closed surface; a decomposition
  // of a repaired copy would be compared with a question that has no answer.
  const acd::MeshDiagnosis diagnosis = acd::diagnose(read.mesh);
  if (diagnosis.boundaryEdges > 0 || diagnosis.nonManifoldEdges > 0) {
    return kConsole.failf(kBadModel, "model %s is not a closed surface (%d boundary, %d non-manifold edges): %s",
                          path.c_str(), diagnosis.boundaryEdges, diagnosis.nonManifoldEdges,
                          "inside and outside are undefined");
  }
  run.mesh = std::move(read.mesh);
  run.progress = isatty(STDERR_FILENO) != 0;
  return kOk;
}

int decomposeAndIndex(Run& run) {
  acd::DecomposeOptions options;
  options.tau = run.p.tau;
  // The errors measured are those of the hulls against their own components: the paper's promise
  // for every component (a merge held to the model lets a component be more concave than tau),
  // and the input's coordinates bit for bit, in which the points are drawn.
  options.mergeScope = acd::MergeScope::Component;
  options.invariant = false;
  options.threads = run.p.threads;
  if (run.progress)
    options.progress = [](int done, int pending) {
      std::fprintf(stderr, "\rdecomposing: %d done, %d pending   ", done, pending);
    };
  const auto tDec = Clock::now();
  run.dec = acd::decompose(run.mesh, options);
  run.decomposeSeconds = secondsSince(tDec);
  if (run.progress) std::fprintf(stderr, "\n");
  if (!run.dec.status.ok()) {
    kConsole.sayf("model %s: %s", run.modelPath.c_str(), run.dec.status.message.c_str());
    return appcli::exitFor(run.dec.status);
  }

  run.box = acd::boundingBox(run.mesh);
  run.boxVolume = run.box.size().prod();
  run.slack = 1e-10 * std::max(run.box.size().norm(), 1e-300);
  run.hulls = acd::HullSet(run.slack);
  for (std::size_t c = 0; c < run.dec.components.size(); ++c) {
    run.unresolved += run.dec.components[c].unresolved ? 1 : 0;
    if (run.hulls.add(run.dec.components[c].hull)) run.hullComponent.push_back(static_cast<int>(c));
  }

  run.points.emplace(run.p.seed, run.box);
  run.arena.emplace(acd::workerArena(run.p.threads));
  run.usedThreads = run.arena->max_concurrency();
  const auto tGrid = Clock::now();
  if (!run.p.noIndex) run.hulls.buildIndex(run.box, run.p.gridCells, *run.arena);
  run.indexSeconds = secondsSince(tGrid);
  return kOk;
}

int locateAll(Run& run) {
  const acd::BoxPointStream& points = *run.points;
  for (int r = 0; r < run.p.repeat; ++r) {
    const auto tLoc = Clock::now();
    const double cpuLoc = cpuNow(run.usedThreads == 1);
    const std::uint64_t in =
        overBlocks(*run.arena, run.p.samples, run.progress ? "locating" : nullptr,
                   [&](std::uint64_t i0, std::uint64_t i1) { return run.hulls.countInside(points, i0, i1); });
    run.locateRuns.push_back(secondsSince(tLoc));
    // CPU seconds of all threads: on a busy machine the better guide to what location costs.
    run.locateCpuRuns.push_back(cpuNow(run.usedThreads == 1) - cpuLoc);
    if (r > 0 && in != run.inside) {
      return kConsole.failf(kInternal, "internal error: repeated location counted %llu, then %llu",
                            static_cast<unsigned long long>(run.inside), static_cast<unsigned long long>(in));
    }
    run.inside = in;
  }
  run.locateSeconds = median(run.locateRuns);
  run.locateCpuSeconds = median(run.locateCpuRuns);
  return kOk;
}

void measureErrors(Run& run) {
  const acd::BoxPointStream& points = *run.points;
  const std::uint64_t samples = run.p.exactSamples;
  const auto tExact = Clock::now();
  const acd::InsideTest& exact = run.exact.emplace(run.mesh);
  run.exactBuildSeconds = secondsSince(tExact);
  const auto tExactRun = Clock::now();
  run.exactInside = overBlocks(*run.arena, samples, nullptr, [&](std::uint64_t i0, std::uint64_t i1) {
    std::uint64_t in = 0;
    for (std::uint64_t i = i0; i < i1; ++i) in += exact.inside(points(i)) ? 1 : 0;
    return in;
  });
  run.exactRunSeconds = secondsSince(tExactRun);
  const int nh = run.hulls.size();
  const std::uint64_t eblocks = (samples + kBlock - 1) / kBlock;
  // Per block: false outside, and the false-inside points of each hull (a point inside several
  // hulls counts for each: it is excess volume of every one of them).
  std::vector<std::uint64_t> eFalseOut(eblocks, 0);
  std::vector<std::vector<std::uint64_t>> eByHull(eblocks);
  run.falseIn = overBlocks(*run.arena, samples, nullptr, [&](std::uint64_t i0, std::uint64_t i1) {
    const std::uint64_t b = i0 / kBlock;
    std::uint64_t fi = 0, fo = 0;
    for (std::uint64_t i = i0; i < i1; ++i) {
      const acd::Vec3 q = points(i);
      const bool claimed = run.hullInside(q), truth = exact.inside(q);
      if (claimed && !truth) {
        ++fi;
        if (eByHull[b].empty()) eByHull[b].assign(nh, 0);
        for (int h = 0; h < nh; ++h) eByHull[b][h] += run.hulls.contains(h, q) ? 1 : 0;
      } else if (!claimed && truth) {
        ++fo;
      }
    }
    eFalseOut[b] = fo;
    return fi;
  });
  run.falseOut = std::accumulate(eFalseOut.begin(), eFalseOut.end(), std::uint64_t{0});
  run.byHull.assign(nh, 0);
  for (const auto& v : eByHull)
    for (std::size_t h = 0; h < v.size(); ++h) run.byHull[h] += v[h];
  run.order.resize(nh);
  std::iota(run.order.begin(), run.order.end(), 0);
  std::stable_sort(run.order.begin(), run.order.end(), [&](int a, int b) { return run.byHull[a] > run.byHull[b]; });
}

int dumpPoints(const Run& run) {
  if (run.p.dumpPath.empty()) return kOk;
  const acd::BoxPointStream& points = *run.points;
  std::ofstream f(run.p.dumpPath);
  f << "x,y,z,hulls,direct,exact\n";
  char line[160];
  for (std::uint64_t i = 0; i < run.p.exactSamples && f; ++i) {
    const acd::Vec3 q = points(i);
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%d,%d,%d\n", q.x(), q.y(), q.z(), run.hullInside(q) ? 1 : 0,
                  run.hulls.insideDirect(q) ? 1 : 0, run.exact->inside(q) ? 1 : 0);
    f << line;
  }
  if (!f) {
    return kConsole.failf(kOutputFailed, "cannot write %s", run.p.dumpPath.c_str());
  }
  return kOk;
}

}  // namespace pointloc
