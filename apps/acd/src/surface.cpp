// acd decompose --surface: the surface split along global cuts into patches whose concavity is
// at most tau (Section 4.3). Writes patches.obj, hulls.obj and report.json.
#include "exit_codes.hpp"
#include "scene_reader.hpp"
#include "surface.hpp"

#include <acd/diagnosis.hpp>
#include <acd/io.hpp>
#include <acd/report.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace acdcli {

namespace {

std::uintmax_t fileSize(const fs::path& p) {
  std::error_code ec;
  const auto n = fs::file_size(p, ec);
  return ec ? 0 : n;
}

void printSummary(const SurfaceArgs& a, const acd::SurfaceDecomposition& d, std::uintmax_t bytes) {
  const auto& ps = d.patches;
  double maxConcavity = 0;
  for (const auto& p : ps) maxConcavity = std::max(maxConcavity, p.concavity);
  std::printf("\n  %-5s %9s %9s %10s %10s\n", "patch", "faces", "vertices", "area %", "concavity");
  const std::size_t shown = std::min<std::size_t>(ps.size(), 40);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto& p = ps[i];
    std::printf("  %-5zu %9zu %9zu %10.3f %10.4f%s\n", i, p.faces.size(), p.mesh.vertices.size(),
                100.0 * p.area / d.stats.inputArea, p.concavity, p.unresolved ? "  (unresolved)" : "");
  }
  if (shown < ps.size()) std::printf("  ... %zu more in report.json\n", ps.size() - shown);
  const auto& o = d.options;
  std::printf("\n  model          %s\n", a.model.c_str());
  std::printf("  method         surface ACD (split along global cuts)\n");
  std::printf("  tau            %g   (epsilon %g, delta %g, feature grouping %s)\n", o.tau, o.epsilon, o.delta,
              o.featureGrouping ? "on" : "off");
  std::printf("  components     %zu\n", ps.size());
  std::printf("  max concavity  %.4f\n", maxConcavity);
  std::printf("  input          %d edges, %d boundary edges, %d concave hull vertices\n", d.stats.inputEdges,
              d.stats.boundaryEdges, d.stats.concaveHullVertices);
  std::printf("  splits         %d (%d along global cuts, %d along planes, %d geodesic), %d merged back\n",
              d.stats.splits, d.stats.globalCutSplits, d.stats.planeSplits, d.stats.geodesicSplits, d.stats.merges);
  std::printf("  time           %.3f s (prepare %.3f, merge %.3f, hulls %.3f; CPU: concavity %.3f, splitting %.3f)\n",
              d.times.total, d.times.prepare, d.times.merging, d.times.hulls, d.times.concavity, d.times.splitting);
  std::printf("  output         %s (patches.obj %ju bytes)\n", a.out.c_str(), bytes);
  for (const auto& line : d.repairs) std::printf("  repaired       %s\n", line.c_str());
  std::fflush(stdout);  // before the warnings on stderr: with both sent to one file, no line is cut
}

}  // namespace

int runSurfaceDecompose(SurfaceArgs& a) {
  const acd::Status valid = acd::validate(a.options);
  if (!valid.ok()) return fail("invalid parameter", valid);
  acd::ReadResult r = readModel(a.model);
  if (!r.status.ok()) return fail(a.model, r.status);
  const bool showProgress = !a.quiet && isatty(fileno(stderr));
  if (showProgress)
    a.options.progress = [](int done, int pending) {
      std::fprintf(stderr, "\r  splitting the surface: %d final, %d pending   ", done, pending);
      std::fflush(stderr);
    };
  const acd::SurfaceDecomposition d = acd::decomposeSurface(r.mesh, a.options);
  if (showProgress) std::fprintf(stderr, "\r%60s\r", "");
  if (!d.status.ok()) return fail(a.model, d.status);
  // Splitting never cuts through the surface, so a surface that passes through itself is split
  // like any other; the patches then pass through each other where the input did.
  const acd::ReportInput input = acd::describeInput(a.model, r.mesh, a.options.threads);
  const int selfIntersections = input.selfIntersections;
  if (selfIntersections > 0)
    std::fprintf(stderr, "acd: warning: %s intersects itself (%d face pairs); the patches intersect where it does\n",
                 a.model.c_str(), selfIntersections);

  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec) return outputFailed(a.out + " (" + ec.message() + ")");
  std::vector<acd::TriMesh> patches, hulls;
  std::vector<std::string> patchNames, hullNames;
  for (std::size_t i = 0; i < d.patches.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "patch_%05zu", i);
    patches.push_back(d.patches[i].mesh);
    patchNames.emplace_back(name);
    if (d.patches[i].hull.empty()) continue;  // a flat patch has no solid hull
    std::snprintf(name, sizeof name, "hull_%05zu", i);
    hulls.push_back(d.patches[i].hull);
    hullNames.emplace_back(name);
  }
  const fs::path patchPath = fs::path(a.out) / "patches.obj", hullPath = fs::path(a.out) / "hulls.obj";
  if (!acd::writeObjObjects(patchPath.string(), patches, patchNames).ok()) return outputFailed(patchPath.string());
  if (!acd::writeObjObjects(hullPath.string(), hulls, hullNames).ok()) return outputFailed(hullPath.string());
  const std::uintmax_t bytes = fileSize(patchPath);
  std::ofstream report(fs::path(a.out) / "report.json");
  report << acd::reportJson(input, d, bytes);
  if (!report) return outputFailed((fs::path(a.out) / "report.json").string());
  if (!a.quiet) printSummary(a, d, bytes);
  const bool anyUnresolved = std::any_of(d.patches.begin(), d.patches.end(), [](const auto& p) { return p.unresolved; });
  if (anyUnresolved) {
    std::fprintf(stderr, "acd: warning: some patches still exceed tau (marked unresolved in report.json)\n");
    return kUnresolved;
  }
  return kOk;
}

}  // namespace acdcli
