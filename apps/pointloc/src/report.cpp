#include "report.hpp"

#include "statistics.hpp"

#include <appcli/exit_codes.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

namespace pointloc {

using json = nlohmann::json;
using appcli::kOutputFailed;

namespace {

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

// The figures are named as in the report, so each line reads as what it prints.
json printReport(const Run& run) {
  const Parameters& p = run.p;
  const std::uint64_t samples = p.samples;
  const std::uint64_t exactSamples = p.exactSamples;
  const double tau = p.tau;
  const std::uint64_t seed = p.seed;
  const int repeat = p.repeat;
  const int usedThreads = run.usedThreads;
  const int unresolved = run.unresolved;
  const bool noIndex = p.noIndex;
  const bool compare = p.compare;
  const std::string& modelPath = run.modelPath;
  const acd::Decomposition& dec = run.dec;
  const acd::HullSet& hulls = run.hulls;
  const std::uint64_t inside = run.inside;
  const std::uint64_t exactInside = run.exactInside;
  const std::uint64_t falseIn = run.falseIn;
  const std::uint64_t falseOut = run.falseOut;
  const double decomposeSeconds = run.decomposeSeconds;
  const double indexSeconds = run.indexSeconds;
  const double locateSeconds = run.locateSeconds;
  const double locateCpuSeconds = run.locateCpuSeconds;
  const double exactRunSeconds = run.exactRunSeconds;
  const double exactBuildSeconds = run.exactBuildSeconds;
  const double boxVolume = run.boxVolume;
  const double mainSeconds = run.mainSeconds;
  const std::vector<double>& locateRuns = run.locateRuns;
  const std::vector<std::uint64_t>& byHull = run.byHull;
  const std::vector<int>& order = run.order;
  const std::vector<int>& hullComponent = run.hullComponent;
  const int nh = hulls.size();
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

  return top;
}

CompareFigures printComparison(const Run& run, const Comparison& comparison) {
  const Parameters& p = run.p;
  const std::uint64_t samples = p.samples;
  const std::uint64_t compareSamples = p.compareSamples;
  const int repeat = p.repeat;
  const int usedThreads = run.usedThreads;
  const double locateSeconds = run.locateSeconds;
  const double locateCpuSeconds = run.locateCpuSeconds;
  const std::vector<Method>& methods = comparison.methods;
  const ExactPieces& ecd = comparison.ecd;
  const double pps = locateSeconds > 0 ? static_cast<double>(samples) / locateSeconds : 0.0;
  CompareFigures figures;
  json& compareJson = figures.methods;
  double& vsCgal1 = figures.vsCgal1;
  double& vsCgalAll = figures.vsCgalAll;
  double& cgalPerCpu = figures.cgalPerCpu;
  {
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

  return figures;
}

int writeJson(const Run& run, const json& top, const Comparison* comparison, const CompareFigures& figures,
              double totalSeconds) {
  const Parameters& p = run.p;
  const std::uint64_t samples = p.samples;
  const std::uint64_t exactSamples = p.exactSamples;
  const std::uint64_t compareSamples = p.compareSamples;
  const double tau = p.tau;
  const std::uint64_t seed = p.seed;
  const int repeat = p.repeat;
  const int usedThreads = run.usedThreads;
  const int unresolved = run.unresolved;
  const bool noIndex = p.noIndex;
  const bool compare = p.compare;
  const std::string& modelPath = run.modelPath;
  const acd::Decomposition& dec = run.dec;
  const acd::HullSet& hulls = run.hulls;
  const std::uint64_t inside = run.inside;
  const std::uint64_t exactInside = run.exactInside;
  const std::uint64_t falseIn = run.falseIn;
  const std::uint64_t falseOut = run.falseOut;
  const double decomposeSeconds = run.decomposeSeconds;
  const double indexSeconds = run.indexSeconds;
  const double locateSeconds = run.locateSeconds;
  const double locateCpuSeconds = run.locateCpuSeconds;
  const double exactRunSeconds = run.exactRunSeconds;
  const double exactBuildSeconds = run.exactBuildSeconds;
  const double boxVolume = run.boxVolume;
  const double mainSeconds = run.mainSeconds;
  const std::vector<double>& locateRuns = run.locateRuns;
  const std::vector<double>& locateCpuRuns = run.locateCpuRuns;
  const std::string& jsonPath = p.jsonPath;
  static const ExactPieces kNone;
  const ExactPieces& ecd = comparison ? comparison->ecd : kNone;
  const double ecdTimeLimit = p.ecdTimeLimit;
  const json& compareJson = figures.methods;
  const double vsCgal1 = figures.vsCgal1, vsCgalAll = figures.vsCgalAll, cgalPerCpu = figures.cgalPerCpu;
  const double pps = locateSeconds > 0 ? static_cast<double>(samples) / locateSeconds : 0.0;
  const double exactPps = exactRunSeconds > 0 ? static_cast<double>(exactSamples) / exactRunSeconds : 0.0;
  const double m = static_cast<double>(std::max<std::uint64_t>(exactSamples, 1));
  const Interval ciIn = wilson95(falseIn, exactSamples), ciOut = wilson95(falseOut, exactSamples),
                 ciAll = wilson95(falseIn + falseOut, exactSamples);
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
  return appcli::kOk;
}

}  // namespace pointloc
