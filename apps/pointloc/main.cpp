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
//
// main.cpp is the command line; the steps are in src/ (run.hpp, compare.hpp, report.hpp).
#include "compare.hpp"
#include "parameters.hpp"
#include "report.hpp"
#include "run.hpp"

#include <appcli/exit_codes.hpp>

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{
      "pointloc: locate random points in the union of the convex hulls of an approximate convex\n"
      "decomposition, and compare with the exact point-in-model answer on a subsample."};
  pointloc::Parameters p;
  app.add_option("MODEL", p.model,
                 "closed mesh (OFF, OBJ, PLY, STL); default data/meshes/elephant.off (relative to the current\n"
                 "directory, else the one in the source tree)");
  app.add_option("--samples", p.samplesText, "points to locate, e.g. 1e8 or 100000000 (positive integer <= 1e10)")
      ->capture_default_str();
  app.add_option("--tau", p.tauText, "concavity tolerance, normalised units, in (0, 2]")->capture_default_str();
  app.add_option("--threads", p.threads, "worker threads, 0 = all cores (results never depend on it)")
      ->capture_default_str();
  app.add_option("--seed", p.seed, "seed of the point stream")->capture_default_str();
  app.add_option("--exact-samples", p.exactText, "points (the first M of the stream) checked exactly; default min(N, 2e6)");
  app.add_flag("--compare", p.compare,
               "also time the same points against the original model (CGAL Side_of_triangle_mesh, 1 and all\n"
               "threads; acd::InsideTest) and against the solid exact convex decomposition when libacd has one");
  app.add_option("--compare-samples", p.compareText,
                 "points (the first K) timed by the exact methods; default min(N, 1e6), at most 1e8");
  app.add_option("--ecd-time-limit", p.ecdTimeLimit, "seconds allowed for the exact convex decomposition")
      ->capture_default_str();
  app.add_option("--repeat", p.repeat, "time every location pass R times and report the median (1..100)")
      ->capture_default_str();
  app.add_option("--json", p.jsonPath, "write the report as JSON to FILE");
  app.add_option("--dump", p.dumpPath,
                 "write the exactly checked points as CSV: x,y,z,hulls,direct,exact (1 = inside; hulls through\n"
                 "the grid, direct by testing every hull)");
  app.add_flag("--no-index", p.noIndex, "test every hull for every point (no grid; same counts)");
  app.add_option("--grid-cells", p.gridCells, "cells of the grid over the box (about, <= 2^24)")->capture_default_str();
  app.footer(
      "Exit codes: 0 success; 1 bad command line; 2 unreadable or invalid model; 3 invalid parameter;\n"
      "5 cannot write output; 6 internal error.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return appcli::usageExit(app.exit(e));
  }

  if (const int code = pointloc::checkParameters(p); code != appcli::kOk) return code;

  pointloc::Run run(p);
  for (auto step : {pointloc::readModel, pointloc::decomposeAndIndex, pointloc::locateAll})
    if (const int code = step(run); code != appcli::kOk) return code;
  pointloc::measureErrors(run);
  if (const int code = pointloc::dumpPoints(run); code != appcli::kOk) return code;
  run.mainSeconds = pointloc::secondsSince(run.t0);

  std::optional<pointloc::Comparison> comparison;
  if (p.compare) comparison = pointloc::compareMethods(run);
  const double totalSeconds = pointloc::secondsSince(run.t0);

  const nlohmann::json top = pointloc::printReport(run);
  pointloc::CompareFigures figures;
  if (comparison) figures = pointloc::printComparison(run, *comparison);
  if (!p.jsonPath.empty()) return pointloc::writeJson(run, top, comparison ? &*comparison : nullptr, figures, totalSeconds);
  return appcli::kOk;
}
