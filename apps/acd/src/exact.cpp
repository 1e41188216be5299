// acd decompose --exact: the exact baselines of the paper's Table 1.
//   --exact            solid ECD (CGAL convex_decomposition_3, capped): pieces.obj, report.json
//   --exact --surface  surface ECD (flood-and-retract convex patches): patches.obj, report.json
#include "exit_codes.hpp"
#include "exact.hpp"
#include "scene_reader.hpp"

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/report.hpp>
#include <acd/surface_exact.hpp>
#include <sandbox/exact_solid.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace acdcli {

namespace {

// Same exit codes as the other subcommands (see exitCodes() in main.cpp).

struct ExactFlags {
  bool exact = false;
  double timeLimit = 600.0;
  double memoryGiB = 8.0;
  double tolerance = acd::SurfaceExactOptions{}.tolerance;
  bool fillHoles = true;  // off with decompose's --no-fill-holes
};
ExactFlags flags;
bool ownSurfaceFlag = false;  // --surface was added here: no surface ACD in this build

bool surfaceRequested(const CLI::App& decompose) {
  const CLI::Option* surface = decompose.get_option_no_throw("--surface");
  return surface != nullptr && surface->count() > 0;
}

std::uintmax_t fileSize(const fs::path& p) {
  std::error_code ec;
  const auto n = fs::file_size(p, ec);
  return ec ? 0 : n;
}

// ---------------------------------------------------------------- solid ECD
int runSolid(const std::string& model, const std::string& out, bool quiet) {
  acd::ReadResult r = readModel(model);
  if (!r.status.ok()) return fail(model, r.status);
  acd::ExactOptions options;
  options.timeLimitSeconds = flags.timeLimit;
  options.memoryLimitBytes = static_cast<std::size_t>(flags.memoryGiB * double(std::size_t(1) << 30));
  options.fillHoles = flags.fillHoles;
  const bool showProgress = !quiet && isatty(fileno(stderr));
  if (showProgress)
    options.progress = [](const std::string& stage, double seconds) {
      std::fprintf(stderr, "\r  exact decomposition: %s, %.0f s   ", stage.c_str(), seconds);
      std::fflush(stderr);
    };
  const acd::ExactDecomposition d = acdsandbox::exactSolidDecomposition(r.mesh, options);
  if (showProgress) std::fprintf(stderr, "\r%78s\r", "");
  if (!d.status.ok()) return fail(model, d.status);

  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) return outputFailed(out + " (" + ec.message() + ")");
  std::vector<std::string> names;
  for (std::size_t i = 0; i < d.pieces.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "piece_%05zu", i);
    names.emplace_back(name);
  }
  const fs::path objPath = fs::path(out) / "pieces.obj";
  if (!acd::writeObjObjects(objPath.string(), d.pieces, names).ok()) return outputFailed(objPath.string());

  const acd::MeshDiagnosis diagnosis = acd::diagnose(r.mesh);
  double volume = 0;
  for (const acd::TriMesh& piece : d.pieces) volume += acd::signedVolume(piece);
  const double inputVolume = diagnosis.volume;
  const std::string report =
      acd::reportJson(model, diagnosis, d, flags.timeLimit, flags.memoryGiB, fileSize(objPath));
  std::ofstream rep(fs::path(out) / "report.json");
  rep << report;
  if (!rep) return outputFailed((fs::path(out) / "report.json").string());

  if (!quiet) {
    std::printf("\n  %-6s %9s %9s %10s\n", "piece", "vertices", "faces", "volume %");
    const std::size_t shown = std::min<std::size_t>(d.pieces.size(), 40);
    for (std::size_t i = 0; i < shown; ++i)
      std::printf("  %-6zu %9zu %9zu %10.3f\n", i, d.pieces[i].vertices.size(), d.pieces[i].faces.size(),
                  100.0 * acd::signedVolume(d.pieces[i]) / inputVolume);
    if (shown < d.pieces.size()) std::printf("  ... %zu more in report.json\n", d.pieces.size() - shown);
    std::printf("\n  model          %s\n", model.c_str());
    std::printf("  method         solid ECD (exact convex decomposition)\n");
    std::printf("  reflex edges   %d of %d edges\n", d.reflexEdges, diagnosis.edges);
    std::printf("  finished       %s\n", d.finished ? "yes" : "no");
    std::printf("  components     %zu\n", d.pieceCount);
    if (inputVolume > 0)
      std::printf("  volume         %.9g of %.9g (relative error %.2e)\n", volume, inputVolume,
                  std::abs(volume - inputVolume) / inputVolume);
    std::printf("  time           %.3f s\n", d.seconds);
    std::printf("  output         %s (pieces.obj %ju bytes)\n", out.c_str(), fileSize(objPath));
    if (!d.note.empty()) std::printf("  note           %s\n", d.note.c_str());
    for (const auto& line : d.repairs) std::printf("  repaired       %s\n", line.c_str());
  }
  if (!d.finished) {
    std::fprintf(stderr, "acd: warning: exact decomposition not finished: %s\n", d.note.c_str());
    return kUnfinished;
  }
  return kOk;
}

// ---------------------------------------------------------------- surface ECD
int runSurface(const std::string& model, const std::string& out, bool quiet) {
  acd::ReadResult r = readModel(model);
  if (!r.status.ok()) return fail(model, r.status);
  acd::SurfaceExactOptions options;
  options.tolerance = flags.tolerance;
  const acd::SurfaceExactDecomposition d = acd::exactSurfaceDecomposition(r.mesh, options);
  if (!d.status.ok()) return fail(d.status.code == acd::StatusCode::InvalidParameter ? "invalid parameter" : model, d.status);

  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) return outputFailed(out + " (" + ec.message() + ")");
  std::vector<acd::TriMesh> patches;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < d.patches.size(); ++i) {
    patches.push_back(acd::patchMesh(r.mesh, d.patches[i]));
    char name[32];
    std::snprintf(name, sizeof name, "patch_%05zu", i);
    names.emplace_back(name);
  }
  const fs::path objPath = fs::path(out) / "patches.obj";
  if (!acd::writeObjObjects(objPath.string(), patches, names).ok()) return outputFailed(objPath.string());

  const acd::MeshDiagnosis diagnosis = acd::diagnose(r.mesh);
  std::size_t largest = 0, singles = 0;
  for (const std::vector<int>& patch : d.patches) {
    largest = std::max(largest, patch.size());
    singles += patch.size() == 1;
  }
  const std::string report =
      acd::reportJson(model, r.mesh, diagnosis, d, patches, flags.tolerance, fileSize(objPath));
  std::ofstream rep(fs::path(out) / "report.json");
  rep << report;
  if (!rep) return outputFailed((fs::path(out) / "report.json").string());

  if (!quiet) {
    std::printf("\n  %-6s %9s %9s %10s\n", "patch", "faces", "vertices", "area %");
    const std::size_t shown = std::min<std::size_t>(patches.size(), 40);
    for (std::size_t i = 0; i < shown; ++i)
      std::printf("  %-6zu %9zu %9zu %10.3f\n", i, d.patches[i].size(), patches[i].vertices.size(),
                  100.0 * acd::surfaceArea(patches[i]) / diagnosis.area);
    if (shown < patches.size()) std::printf("  ... %zu more in report.json\n", patches.size() - shown);
    std::printf("\n  model          %s\n", model.c_str());
    std::printf("  method         surface ECD (convex patches, flood-and-retract)\n");
    std::printf("  components     %zu (%zu of one face, largest %zu faces)\n", patches.size(), singles, largest);
    std::printf("  faces          %d\n", diagnosis.faces);
    std::printf("  time           %.3f s\n", d.seconds);
    std::printf("  output         %s (patches.obj %ju bytes)\n", out.c_str(), fileSize(objPath));
  }
  return kOk;
}

}  // namespace

void addExactOptions(CLI::App& decompose) {
  if (decompose.get_option_no_throw("--surface") == nullptr) {
    decompose.add_flag("--surface", "With --exact: convex surface patches instead of solid pieces");
    ownSurfaceFlag = true;
  }
  decompose.add_flag("--exact", flags.exact,
                     "Exact convex decomposition instead of ACD: convex solid pieces (pieces.obj); with --surface, "
                     "convex surface patches (patches.obj). Exit 4 when a cap stopped it");
  decompose.add_option("--exact-time-limit", flags.timeLimit, "--exact: wall-clock cap in seconds (0 = none)")
      ->capture_default_str();
  decompose.add_option("--exact-memory", flags.memoryGiB, "--exact: memory cap of the solid worker in GiB (0 = none)")
      ->capture_default_str();
  decompose.add_option("--exact-tolerance", flags.tolerance,
                       "--exact --surface: how far a vertex may lie beyond a patch face's plane (normalised units)")
      ->capture_default_str();
}

bool exactRequested(const CLI::App& decompose) {
  return flags.exact || (ownSurfaceFlag && surfaceRequested(decompose));
}

int runExact(const CLI::App& decompose, const std::string& model, const std::string& out, bool quiet) {
  if (!flags.exact) {
    std::fprintf(stderr, "acd: --surface without --exact (surface ACD) is not available in this build\n");
    return 1;
  }
  if (!(flags.timeLimit >= 0) || !(flags.memoryGiB >= 0) || !std::isfinite(flags.memoryGiB))
    return fail("invalid parameter", acd::Status::error(acd::StatusCode::InvalidParameter,
                                                         "--exact-time-limit and --exact-memory must be >= 0"));
  const CLI::Option* noFill = decompose.get_option_no_throw("--no-fill-holes");
  flags.fillHoles = noFill == nullptr || noFill->count() == 0;
  if (surfaceRequested(decompose)) return runSurface(model, out, quiet);
  return runSolid(model, out, quiet);
}

}  // namespace acdcli
