// tetmesh: a tetrahedral mesh of the convex hulls of the solid ACD components, with TetGen
// (Lien & Amato 2007, Section 7, "Mesh generation", Figure 4).
//   tetmesh MODEL [--tau 0.2] [--simplify K] [--quality Q] [--max-volume V] [-o OUT]
//           [--format vtk|mesh|tetgen] [--compare] [--json FILE]
#include "deformation_demo.hpp"
#include "hull_mesher.hpp"
#include "tet_files.hpp"

#include <appcli/console.hpp>
#include <appcli/exit_codes.hpp>

#include <acd/io.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using json = nlohmann::json;
using namespace tetmesh;

using appcli::kBadInput;
using appcli::kBadParameter;
using appcli::kOk;
using appcli::kOutputFailed;
constexpr int kMeshFailed = appcli::kInternal;  // the hulls could not be meshed (TetGen refused or failed): a bug, please report

const appcli::Console kConsole("tetmesh");

const char* exitCodes() {
  return "Exit codes: 0 success; 1 bad command line; 2 unreadable or invalid model; 3 invalid parameter;\n"
         "5 cannot write output; 6 meshing failed (TetGen refused or crashed on the hull complex).";
}

// ---- Deformation demo (--deform): the model's surface embedded in the hull mesh and carried
// along by an as-rigid-as-possible deformation that moves one component (docs/TETMESH.md).
struct DeformArgs {
  std::string dir;              // empty: no deformation
  int handle = 0, anchor = 0;   // component labels; 0: automatic
  std::vector<double> move;     // dx, dy, dz
  double angle = NAN;           // degrees
  int iterations = ArapOptions{}.maxIterations;
  double minWeight = ArapOptions{}.minWeight;
};

void addDeformOptions(CLI::App& app, DeformArgs& d) {
  auto* dir = app.add_option("--deform", d.dir,
                             "Deform: write DIR/surface_before.off, surface_after.off, tets_before.vtk, tets_after.vtk, parts_before.obj, parts_after.obj");
  app.add_option("--deform-handle", d.handle, "Component moved (label; default: farthest from the centroid)")->needs(dir);
  app.add_option("--deform-anchor", d.anchor, "Component held (label; default: the largest other one)")->needs(dir);
  app.add_option("--deform-move", d.move, "Handle translation dx,dy,dz (default: 0.2 x half-diagonal across)")
      ->expected(3)->delimiter(',')->needs(dir);
  app.add_option("--deform-angle", d.angle, "Instead: turn the handle by DEG about an axis through the anchor")->needs(dir);
  app.add_option("--deform-iterations", d.iterations, "Most ARAP iterations")->capture_default_str()->needs(dir);
  app.add_option("--deform-min-weight", d.minWeight, "Floor on a tet's ARAP weight, fraction of the mean tet volume (0: none)")
      ->capture_default_str()->needs(dir);
}

/// Options as given; exit code kBadParameter with a message when they cannot work.
int deformOptions(const DeformArgs& d, DeformationOptions& o) {
  auto bad = [](const std::string& message) {
    return kConsole.fail(kBadParameter, message);
  };
  o.handle = d.handle, o.anchor = d.anchor;
  o.arap.maxIterations = d.iterations;
  o.arap.minWeight = d.minWeight;
  o.translate = !d.move.empty();
  if (o.translate) o.move = Vec3(d.move[0], d.move[1], d.move[2]);
  o.rotate = !std::isnan(d.angle);
  o.angleDegrees = d.angle;
  if (d.handle < 0 || d.anchor < 0) return bad("--deform-handle and --deform-anchor are component labels (1, 2, ...)");
  if (d.handle != 0 && d.handle == d.anchor)
    return bad("--deform-handle and --deform-anchor are the same component (" + std::to_string(d.handle) + ")");
  if (o.translate && o.rotate) return bad("--deform-move and --deform-angle cannot be used together");
  if ((o.translate && !o.move.allFinite()) || (o.rotate && !std::isfinite(d.angle)))
    return bad("--deform-move and --deform-angle must be finite numbers");
  if (d.iterations < 0) return bad("--deform-iterations must not be negative, got " + std::to_string(d.iterations));
  if (!(d.minWeight >= 0) || !std::isfinite(d.minWeight)) return bad("--deform-min-weight must be a number >= 0");
  return kOk;
}

/// Runs the deformation and writes its four files; the report lines and JSON come from the result.
int runDeformation(const DeformArgs& d, const DeformationOptions& o, const TetMesh& tets, const acd::TriMesh& surface,
                   DeformationResult& r) {
  r = deformSurface(tets, surface, o);
  if (!r.status.ok()) {
    kConsole.say(r.status.message);
    return r.status.code == acd::StatusCode::InvalidParameter ? kBadParameter : kMeshFailed;
  }
  std::error_code ec;
  std::filesystem::create_directories(d.dir, ec);
  TetMesh after = tets;
  after.points = r.tetPositionsAfter;
  const std::string base = (std::filesystem::path(d.dir) / "").string();
  std::vector<acd::TriMesh> before, moved;
  std::vector<std::string> names;
  splitByPart(surface, r.facePart, before, names);
  splitByPart(r.surfaceAfter, r.facePart, moved, names);
  for (const acd::Status& s : {acd::writeMesh(base + "surface_before.off", surface), acd::writeMesh(base + "surface_after.off", r.surfaceAfter),
                               writeVtk(base + "tets_before.vtk", tets), writeVtk(base + "tets_after.vtk", after),
                               acd::writeObjObjects(base + "parts_before.obj", before, names),
                               acd::writeObjObjects(base + "parts_after.obj", moved, names)})
    if (!s.ok()) {
      return kConsole.fail(kOutputFailed, s.message);
    }
  return kOk;
}

json deformationJson(const DeformArgs& d, const DeformationResult& r) {
  const ArapResult& a = r.arap;
  return {{"directory", d.dir},
          {"handle", r.handle},
          {"anchor", r.anchor},
          {"motion", r.motion},
          {"translation", {r.translation.x(), r.translation.y(), r.translation.z()}},
          {"angle_deg", r.angleDegrees},
          {"axis", {r.axis.x(), r.axis.y(), r.axis.z()}},
          {"pivot", {r.pivot.x(), r.pivot.y(), r.pivot.z()}},
          {"handle_vertices", r.handleVertices},
          {"anchor_vertices", r.anchorVertices},
          {"shared_vertices", r.sharedVertices},
          {"embedding",
           {{"vertices", r.embedding.tet.size()},
            {"outside", r.embedding.outside},
            {"max_outside_distance", r.embedding.maxOutsideDistance},
            {"seconds", r.embedding.seconds}}},
          {"arap",
           {{"iterations", a.iterations},
            {"min_weight", d.minWeight},
            {"converged", a.converged},
            {"energy", a.energy},
            {"free_vertices", a.freeVertices},
            {"pinned_vertices", a.pinnedVertices},
            {"inverted_tets", a.invertedTets},
            {"linear_inverted_tets", a.linearInvertedTets},
            {"inverted_rest_volume", a.invertedRestVolume},
            {"surface_vertices_in_inverted_tets", r.surfaceInInverted},
            {"surface_vertices_on_handle", r.surfaceOnHandle},
            {"surface_handle_error", r.surfaceHandleError},
            {"max_constraint_error", a.maxConstraintError},
            {"factor_seconds", a.factorSeconds},
            {"solve_seconds", a.solveSeconds}}},
          {"inverted_tets", a.invertedTets},
          {"tet_volume", {{"rest", a.restVolume}, {"after", a.volume}, {"linear", a.linearVolume}}},
          {"surface_volume", {{"rest", r.surfaceVolumeBefore}, {"after", r.surfaceVolumeAfter}, {"linear", r.surfaceVolumeLinear}}},
          {"max_surface_displacement", r.maxSurfaceDisplacement},
          {"self_intersections", {{"before", r.selfIntersectionsBefore}, {"after", r.selfIntersectionsAfter}}},
          {"seconds", r.seconds}};
}
// ---- end of the deformation demo

struct Args {
  std::string model;
  HullMeshOptions options;
  std::string out;
  std::string format;
  std::string json;
  std::string poly;
  std::string regions;
  bool compare = false;
  bool quiet = false;
  DeformArgs deform;
};

json qualityJson(const MeshQuality& q) {
  json hist = json::array();
  for (std::size_t b = 0; b < q.radiusEdgeHistogram.size(); ++b)
    hist.push_back({{"upto", b < kRadiusEdgeBins.size() ? json(kRadiusEdgeBins[b]) : json(nullptr)},
                    {"tets", q.radiusEdgeHistogram[b]}});
  return {{"tets", q.tets},
          {"vertices", q.points},
          {"volume", q.volume},
          {"non_positive_tets", q.nonPositiveTets},
          {"min_dihedral_deg", q.minDihedral},
          {"max_dihedral_deg", q.maxDihedral},
          {"radius_edge", {{"min", q.minRadiusEdge}, {"median", q.medianRadiusEdge}, {"max", q.maxRadiusEdge}}},
          {"radius_edge_histogram", hist}};
}

std::string histogramLine(const MeshQuality& q) {
  std::string s;
  char buf[64];
  for (std::size_t b = 0; b < q.radiusEdgeHistogram.size(); ++b) {
    const double share = q.tets > 0 ? 100.0 * q.radiusEdgeHistogram[b] / q.tets : 0.0;
    if (b < kRadiusEdgeBins.size())
      std::snprintf(buf, sizeof buf, "%s<=%g: %.1f%%", b ? ", " : "", kRadiusEdgeBins[b], share);
    else
      std::snprintf(buf, sizeof buf, ", >%g: %.1f%%", kRadiusEdgeBins.back(), share);
    s += buf;
  }
  return s;
}

void printColumns(const char* name, const std::string& a, const std::string& b, bool two) {
  if (two)
    std::printf("  %-22s %-22s %s\n", name, a.c_str(), b.c_str());
  else
    std::printf("  %-22s %s\n", name, a.c_str());
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

int run(const Args& a) {
  const bool progress = !a.quiet && ::isatty(STDERR_FILENO);
  TetFormat format = TetFormat::Vtk;
  std::string formatName = a.format;
  if (formatName.empty() && !a.out.empty()) {
    const auto dot = a.out.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : a.out.substr(dot + 1);
    formatName = ext == "mesh" ? "mesh" : ext == "vtk" ? "vtk" : "tetgen";
  }
  if (!formatName.empty() && !parseTetFormat(formatName, format)) {
    return kConsole.failf(kBadParameter, "unknown --format '%s' (vtk, mesh or tetgen)", formatName.c_str());
  }
  if (!(a.options.tau > 0) || !std::isfinite(a.options.tau)) {
    return kConsole.failf(kBadParameter, "--tau must be positive, got %g", a.options.tau);
  }
  if (a.options.simplify != 0 && a.options.simplify < 4) {
    return kConsole.failf(kBadParameter, "--simplify must be at least 4 (a tetrahedron), got %d", a.options.simplify);
  }
  if (a.options.tetgen.radiusEdge != 0 && !(a.options.tetgen.radiusEdge >= 1.0)) {
    return kConsole.failf(kBadParameter, "--quality must be at least 1 (TetGen does not terminate below), or 0 for none; got %g",
                          a.options.tetgen.radiusEdge);
  }
  if (a.options.tetgen.maxVolume < 0 || !std::isfinite(a.options.tetgen.maxVolume)) {
    return kConsole.failf(kBadParameter, "--max-volume must be positive (or 0 for no bound), got %g", a.options.tetgen.maxVolume);
  }

  DeformationOptions deformOpts;
  if (!a.deform.dir.empty())
    if (const int code = deformOptions(a.deform, deformOpts); code != kOk) return code;
  deformOpts.arap.threads = a.options.threads;

  const acd::ReadResult read = acd::readMesh(a.model);
  if (!read.status.ok()) {
    return kConsole.fail(kBadInput, read.status.message);
  }
  if (progress) kConsole.sayf("decomposing at tau %g, hulls, TetGen ...", a.options.tau);
  const HullMeshResult r = meshHulls(read.mesh, a.options);
  // Written even when TetGen fails on it: that is when it is most useful.
  if (!a.poly.empty() && !r.complex.plc.facets.empty()) {
    const acd::Status s = writePoly(a.poly, r.complex.plc);
    if (!s.ok()) {
      return kConsole.fail(kOutputFailed, s.message);
    }
  }
  // The regions as meshed, one OBJ object per component: a picture before the numbers.
  if (!a.regions.empty() && !r.complex.regions.empty()) {
    std::vector<acd::TriMesh> meshes;
    std::vector<std::string> names;
    for (std::size_t i = 0; i < r.complex.regions.size(); ++i)
      if (!r.complex.regions[i].empty())
        meshes.push_back(r.complex.regions[i]), names.push_back("component_" + std::to_string(i + 1));
    const acd::Status s = acd::writeObjObjects(a.regions, meshes, names);
    if (!s.ok()) {
      return kConsole.fail(kOutputFailed, s.message);
    }
  }
  if (!r.status.ok()) {
    kConsole.sayf("%s: %s", a.model.c_str(), r.status.message.c_str());
    return appcli::exitFor(r.status);  // an internal error is kMeshFailed
  }
  DirectMeshResult direct;
  if (a.compare) {
    if (progress) kConsole.say("TetGen on the model itself ...");
    direct = meshModelDirectly(read.mesh, a.options.tetgen);
  }

  DeformationResult deformed;
  if (!a.deform.dir.empty()) {
    if (progress) {
      kConsole.say("deformation ...");
      deformOpts.arap.progress = [](int iteration, double energy) {
        std::fprintf(stderr, "\r  ARAP iteration %d, energy %.6g   ", iteration, energy);
      };
    }
    const int code = runDeformation(a.deform, deformOpts, r.tetgen.mesh, read.mesh, deformed);
    if (progress) std::fprintf(stderr, "\n");
    if (code != kOk) return code;
  }

  if (!a.out.empty()) {
    const acd::Status s = writeTetMesh(a.out, format, r.tetgen.mesh);
    if (!s.ok()) {
      return kConsole.fail(kOutputFailed, s.message);
    }
  }

  int unresolved = 0;
  for (const acd::Component& c : r.decomposition.components) unresolved += c.unresolved ? 1 : 0;
  const int n = static_cast<int>(r.hulls.size());
  int hullVerts = 0, simpleVerts = 0;
  for (int i = 0; i < n; ++i) hullVerts += r.hullVertices[i], simpleVerts += static_cast<int>(r.hulls[i].vertices.size());
  const double volErr = r.modelVolume > 0 ? (r.quality.volume - r.modelVolume) / r.modelVolume : 0.0;
  const double directErr =
      r.modelVolume > 0 && direct.status.ok() ? (direct.quality.volume - r.modelVolume) / r.modelVolume : 0.0;

  std::printf("%s\n", a.model.c_str());
  std::printf("  decomposition  tau %g, %d components%s, %.3f s\n", a.options.tau, n,
              a.options.merge ? " (with merge pass)" : " (no merge pass)", r.times.decompose);
  if (unresolved > 0) std::printf("  warning        %d components still exceed tau (see acd decompose)\n", unresolved);
  if (r.simplifyFallback)
    std::printf("  hulls          %d vertices; TetGen refused every complex of the hulls simplified to at most %d\n"
                "                 vertices, so the exact hulls were meshed\n",
                hullVerts, a.options.simplify);
  else if (a.options.simplify > 0)
    std::printf("  hulls          %d vertices, simplified to %d (at most %d each%s; %d hulls could not get there)\n",
                hullVerts, simpleVerts, r.simplifyUsed,
                r.simplifyUsed < a.options.simplify ? ", TetGen refused the larger budgets" : "", r.simplifyMissed);
  else
    std::printf("  hulls          %d vertices\n", hullVerts);
  if (a.options.simplify > 0 && !r.simplifyFallback)
    std::printf("  separation     %d planes keep the simplified hulls apart; %d pairs of exact hulls overlap (cut there)\n",
                r.separatingPlanes, r.overlappingHulls);
  std::printf("  containment    farthest component vertex outside its hull: %.3g, outside its meshed region: %.3g\n",
              r.maxOutside, r.maxOutsideRegion);
  std::printf("  complex        %d touching pairs (%d overlapping, deepest %.3g), %d contact planes, %d interface + %d boundary facets\n",
              r.complex.contactPairs, r.complex.overlappingPairs, r.complex.maxOverlapDepth, r.complex.contactPlanes,
              r.complex.interfaceFacets, r.complex.boundaryFacets);
  std::printf("  TetGen         -%s (complex snapped at %.0e of the half-diagonal", r.tetgen.switches.c_str(), r.toleranceUsed);
  if (!r.refusedComplexes.empty()) std::printf("; %zu complexes refused before", r.refusedComplexes.size());
  std::printf(")\n");
  const bool two = a.compare;
  if (two) printColumns("", "hulls", "original model", true);
  const std::string directNote = direct.status.ok() ? "" : "not meshed";
  auto col = [&](const std::string& v) { return direct.status.ok() ? v : directNote; };
  printColumns("tets", std::to_string(r.quality.tets), col(std::to_string(direct.quality.tets)), two);
  printColumns("vertices", std::to_string(r.quality.points), col(std::to_string(direct.quality.points)), two);
  printColumns("volume", fmt("%.6g", r.quality.volume), col(fmt("%.6g", direct.quality.volume)), two);
  printColumns("vs model volume", fmt("%+.2f%%", 100 * volErr), col(fmt("%+.2f%%", 100 * directErr)), two);
  printColumns("min dihedral (deg)", fmt("%.2f", r.quality.minDihedral), col(fmt("%.2f", direct.quality.minDihedral)), two);
  printColumns("max dihedral (deg)", fmt("%.2f", r.quality.maxDihedral), col(fmt("%.2f", direct.quality.maxDihedral)), two);
  printColumns("radius-edge median", fmt("%.3f", r.quality.medianRadiusEdge), col(fmt("%.3f", direct.quality.medianRadiusEdge)), two);
  printColumns("radius-edge max", fmt("%.3f", r.quality.maxRadiusEdge), col(fmt("%.3f", direct.quality.maxRadiusEdge)), two);
  printColumns("TetGen time (s)", fmt("%.3f", r.times.tetgen), col(fmt("%.3f", direct.tetgen.seconds)), two);
  std::printf("  radius-edge    %s\n", histogramLine(r.quality).c_str());
  if (two && direct.status.ok()) std::printf("  (original)     %s\n", histogramLine(direct.quality).c_str());
  if (two && !direct.status.ok()) std::printf("  original model not meshed: %s\n", direct.status.message.c_str());
  std::printf("  time (s)       decompose %.3f, hulls %.3f, complex %.3f, TetGen %.3f, quality %.3f\n", r.times.decompose,
              r.times.hulls, r.times.complex, r.times.tetgen, r.times.quality);
  if (!a.out.empty()) {
    std::printf("  wrote         ");
    for (const std::string& f : tetOutputFiles(a.out, format)) std::printf(" %s", f.c_str());
    std::printf("\n");
  }
  if (!a.deform.dir.empty())
    for (const std::string& line : deformationSummary(deformed)) std::printf("%s\n", line.c_str());

  if (!a.json.empty()) {
    json comps = json::array();
    for (int i = 0; i < n; ++i)
      comps.push_back({{"label", i + 1},
                       {"hull_vertices", r.hullVertices[i]},
                       {"meshed_hull_vertices", r.hulls[i].vertices.size()},
                       {"region_volume", r.complex.regions[i].empty() ? 0.0 : acd::signedVolume(r.complex.regions[i])},
                       {"clipped_volume", r.complex.clippedVolume[i]},
                       {"unresolved", r.decomposition.components[i].unresolved}});
    json j = {{"model", a.model},
              {"tau", a.options.tau},
              {"merge", a.options.merge},
              {"simplify", a.options.simplify},
              {"simplify_used", r.simplifyUsed},
              {"separating_planes", r.separatingPlanes},
              {"overlapping_exact_hulls", r.overlappingHulls},
              {"simplify_fallback", r.simplifyFallback},
              {"tetgen_switches", r.tetgen.switches},
              {"snap_tolerance", r.toleranceUsed},
              {"refused_complexes", r.refusedComplexes},
              {"model_volume", r.modelVolume},
              {"components", comps},
              {"complex",
               {{"touching_pairs", r.complex.contactPairs},
                {"overlapping_pairs", r.complex.overlappingPairs},
                {"max_overlap_depth", r.complex.maxOverlapDepth},
                {"contact_planes", r.complex.contactPlanes},
                {"interface_facets", r.complex.interfaceFacets},
                {"boundary_facets", r.complex.boundaryFacets}}},
              {"max_outside", r.maxOutside},
              {"max_outside_region", r.maxOutsideRegion},
              {"hull_mesh", qualityJson(r.quality)},
              {"volume_error", volErr},
              {"seconds",
               {{"decompose", r.times.decompose},
                {"hulls", r.times.hulls},
                {"complex", r.times.complex},
                {"tetgen", r.times.tetgen},
                {"quality", r.times.quality}}}};
    if (a.compare) {
      if (direct.status.ok())
        j["original_mesh"] = qualityJson(direct.quality), j["original_mesh"]["seconds"] = direct.seconds,
        j["original_mesh"]["volume_error"] = directErr;
      else
        j["original_mesh"] = {{"error", direct.status.message}};
    }
    if (!a.deform.dir.empty()) j["deformation"] = deformationJson(a.deform, deformed);
    std::ofstream out(a.json);
    out << j.dump(2) << "\n";
    if (!out) {
      return kConsole.failf(kOutputFailed, "%s: cannot write", a.json.c_str());
    }
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  CLI::App app{"Tetrahedral mesh of the convex hulls of the solid ACD components (TetGen)."};
  app.footer(exitCodes());
  app.add_option("MODEL", a.model, "Closed mesh (OFF, OBJ, PLY, STL)")->required();
  app.add_option("-t,--tau", a.options.tau, "Concavity tolerance, normalised units")->capture_default_str();
  a.options.simplify = 24;  // the paper's coarse mesh; the exact hulls keep every vertex of the cut sections
  app.add_option("--simplify", a.options.simplify,
                 "Hulls with at most K vertices that still contain their component (K >= 4; 0: the exact hulls)")
      ->capture_default_str();
  app.add_option("--quality", a.options.tetgen.radiusEdge,
                 "TetGen radius-edge bound (q, e.g. 2); 0: no refinement, the coarse constrained Delaunay mesh")
      ->capture_default_str();
  app.add_option("--max-volume", a.options.tetgen.maxVolume, "TetGen maximum tet volume (a), input units; 0: none");
  app.add_option("-o,--output", a.out, "Mesh file (.vtk, .mesh) or base name for .node/.ele/.face");
  app.add_option("--format", a.format, "vtk, mesh or tetgen (default: from the -o extension, else vtk)");
  app.add_flag("--compare", a.compare, "Also mesh the model itself with TetGen and print both side by side");
  app.add_flag("--merge", a.options.merge, "Use the decomposition's merge pass (hulls then overlap and are clipped)");
  app.add_option("--threads", a.options.threads, "Decomposition threads, 0 = all cores")->capture_default_str();
  app.add_option("--snap", a.options.tolerance,
                 "Features closer than this (relative to the half-diagonal) are one: welding, contacts")
      ->capture_default_str();
  app.add_option("--timeout", a.options.tetgen.timeoutSeconds, "Seconds TetGen may take per call before it is stopped")
      ->capture_default_str();
  app.add_option("--json", a.json, "Write the report as JSON to this file");
  app.add_option("--poly", a.poly, "Write the hull complex given to TetGen as a .poly file");
  app.add_option("--regions", a.regions, "Write the meshed hull regions as an OBJ, one object per component");
  app.add_flag("-q,--quiet", a.quiet, "No progress on stderr");
  addDeformOptions(app, a.deform);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return appcli::usageExit(app.exit(e));
  }
  return run(a);
}
