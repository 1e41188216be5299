// acd: approximate convex decomposition from the command line.
//   acd decompose MODEL [-t TAU] ... -o OUTDIR   components, hulls.obj, report.json, summary table
//   acd info MODEL                              mesh diagnosis
//   acd evaluate MODEL HULLS.obj                how well any set of hulls approximates the model
//   acd decompose MODEL --surface [-t TAU] -o OUT surface ACD: patches.obj, hulls.obj, report.json (surface.cpp)
//   acd decompose MODEL --exact [--surface]     exact convex decomposition (exact.cpp)
//   acd batch INPUT... -o OUT                   many meshes in capped workers, cached (batch.cpp)
//   acd report OUT                              index.html over a batch, with a 3D view (report.cpp)
// Exit codes are listed in exitCodes() and in --help.
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/evaluate.hpp>
#include <acd/io.hpp>
#include <acd/robust.hpp>
#include <acd/scene_io.hpp>
#include <acd/report.hpp>
#include <acd/version.hpp>

#include <CLI/CLI.hpp>
#include "batch.hpp"
#include "exit_codes.hpp"
#include "exact.hpp"
#include "report.hpp"
#include "scene_reader.hpp"
#include "simulator.hpp"
#include "surface.hpp"
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace acdcli;  // exit codes and fail(), shared with the other subcommands

namespace {

const char* exitCodes() {
  return "Exit codes: 0 success; 1 bad command line; 2 unreadable or invalid model; 3 invalid parameter;\n"
         "4 some component still exceeds tau (--exact: a cap stopped it); 5 cannot write output; 6 internal error;\n"
         "7 batch: some meshes failed (see OUT/batch.jsonl).";
}

acd::ReadResult load(const std::string& path) { return readModel(path); }

// ---------------------------------------------------------------- info
int runInfo(const std::string& path) {
  acd::ReadResult r = load(path);
  if (!r.status.ok()) return fail(path, r.status);
  const acd::MeshDiagnosis d = acd::diagnose(r.mesh);
  auto yes = [](bool b) { return b ? "yes" : "no"; };
  std::printf("%s\n", path.c_str());
  std::printf("  vertices              %d\n", d.vertices);
  std::printf("  faces                 %d\n", d.faces);
  std::printf("  edges                 %d\n", d.edges);
  std::printf("  boundary edges        %d\n", d.boundaryEdges);
  std::printf("  non-manifold edges    %d\n", d.nonManifoldEdges);
  std::printf("  non-manifold vertices %d\n", d.nonManifoldVertices);
  std::printf("  components            %d\n", d.components);
  std::printf("  consistent orientation %s\n", yes(d.orientationConsistent));
  std::printf("  degenerate faces      %d\n", d.degenerateFaces);
  std::printf("  duplicate faces       %d\n", d.duplicateFaces);
  std::printf("  duplicate vertices    %d\n", d.duplicateVertices);
  std::printf("  non-finite vertices   %d\n", d.nonFiniteVertices);
  std::printf("  closed                %s\n", yes(d.closed));
  if (d.genus >= 0)
    std::printf("  genus                 %d\n", d.genus);
  else
    std::printf("  genus                 undefined (not closed)\n");
  std::printf("  volume                %.9g%s\n", d.volume, d.closed ? "" : " (not closed: meaningless)");
  std::printf("  area                  %.9g\n", d.area);
  std::printf("  bounding box          [%g %g %g] - [%g %g %g]\n", d.bbox.lo.x(), d.bbox.lo.y(), d.bbox.lo.z(),
              d.bbox.hi.x(), d.bbox.hi.y(), d.bbox.hi.z());
  if (!d.firstProblem.empty()) std::printf("  first problem         %s\n", d.firstProblem.c_str());
  const int pairs = d.closed && d.nonManifoldEdges == 0 ? acd::countSelfIntersections(r.mesh) : -1;
  if (pairs >= 0) std::printf("  self-intersections    %d face pairs\n", pairs);
  // What `acd decompose` would do, step by step (the same code, without building the wrap).
  const acd::PreparedModel p = acd::prepareModel(r.mesh, acd::DecomposeOptions{}, false);
  for (const auto& line : p.repairs) std::printf("  repair                %s\n", line.c_str());
  if (pairs > 0)
    std::printf("  repair                the surface passes through itself: a shell left above tau is decomposed "
                "through its wrap\n");
  if (!p.status.ok())
    std::printf("  solid decomposition   refused: %s\n", p.status.message.c_str());
  else if (!p.wrapReason.empty())
    std::printf("  solid decomposition   possible, through a watertight wrap (--no-wrap refuses it)\n");
  else
    std::printf("  solid decomposition   possible%s\n", p.repairs.empty() ? "" : " after the repairs above");
  return kOk;
}

// ---------------------------------------------------------------- decompose
struct DecomposeArgs {
  std::string model;
  std::string out = "acd-out";
  acd::DecomposeOptions options = acd::recommendedOptions();
  bool noGrouping = false;
  bool noMerge = false;
  bool noInvariant = false;          // --no-invariant
  bool invariantFlag = false;        // --invariant: the default since 2026-11-25, still accepted
  std::string mergeScope = "model";  // --merge-scope
  bool noFillHoles = false;
  bool noWrap = false;
  bool noRepair = false;
  bool surface = false;
  bool quiet = false;
  SimulatorArgs sim;  // --tau-abs, --max-hulls, --max-hull-vertices, --density, --format (simulator.cpp)
  bool perMesh = false;
  std::string mesh;  // with --per-mesh: the name of the scene mesh being decomposed
};

void printSummary(const DecomposeArgs& a, const acd::Decomposition& d) {
  const auto& cs = d.components;
  double volume = 0, hullVolume = 0, maxConcavity = 0, maxExcess = 0;
  for (const auto& c : cs) {
    volume += c.volume, hullVolume += c.hullVolume;
    maxConcavity = std::max(maxConcavity, c.concavity), maxExcess = std::max(maxExcess, c.hullExcess);
  }
  std::printf("\n  %-5s %9s %9s %10s %10s %10s\n", "part", "vertices", "faces", "volume %", "hull/vol", "concavity");
  const std::size_t shown = std::min<std::size_t>(cs.size(), 40);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto& c = cs[i];
    std::printf("  %-5zu %9zu %9zu %10.3f %10.3f %10.4f%s\n", i, c.mesh.vertices.size(), c.mesh.faces.size(),
                100.0 * c.volume / d.stats.inputVolume, c.volume > 0 ? c.hullVolume / c.volume : 0.0, c.concavity,
                c.unresolved ? "  (unresolved)" : "");
  }
  if (shown < cs.size()) std::printf("  ... %zu more in report.json\n", cs.size() - shown);
  std::printf("\n  model          %s\n", a.model.c_str());
  std::printf("  tau            %g   (epsilon %g, delta %g, feature grouping %s)\n", d.options.tau, d.options.epsilon,
              d.options.delta, d.options.featureGrouping ? "on" : "off");
  std::printf("  components     %zu\n", cs.size());
  std::printf("  max concavity  %.4f%s\n", maxConcavity,
              d.options.mergeScope == acd::MergeScope::Model && maxConcavity > d.options.tau
                  ? "   (merged components: their pockets lie in other components)" : "");
  std::printf("  hull excess    %.4f   (how far a hull stands off the model, at most)\n", maxExcess);
  std::printf("  volume         %.6g of %.6g (relative error %.2e)\n", volume, d.stats.inputVolume,
              std::abs(volume - d.stats.inputVolume) / d.stats.inputVolume);
  std::printf("  hulls / model  %.4f\n", hullVolume / d.stats.inputVolume);
  std::printf("  cuts           %d (%d not by the first candidate plane, %d planes rejected), %d merged back\n",
              d.stats.cuts, d.stats.fallbackCuts, d.stats.failedCuts, d.stats.merges);
  std::printf("  time           %.3f s (prepare %.3f, merge %.3f, hulls %.3f; CPU: concavity %.3f, grouping %.3f, cutting %.3f)\n",
              d.times.total, d.times.prepare, d.times.merging, d.times.hulls, d.times.concavity, d.times.grouping,
              d.times.cutting);
  std::printf("  output         %s\n", a.out.c_str());
  for (const auto& line : d.repairs) std::printf("  repaired       %s\n", line.c_str());
  if (d.wrap.used)
    std::printf("  wrap           %d pieces wrapped (alpha %g, offset %g); Hausdorff distance to the input %.4f\n",
                d.wrap.wrappedPieces, d.wrap.alpha, d.wrap.offset, d.wrap.hausdorff);
}

int decomposeMesh(DecomposeArgs& a, const acd::TriMesh& mesh) {
  if (const int code = resolveTauAbs(a.sim, mesh, a.options); code != kOk) return code;
  const acd::Status valid = acd::validate(a.options);
  if (!valid.ok()) return fail("invalid parameter", valid);
  const bool showProgress = !a.quiet && isatty(fileno(stderr));
  if (showProgress)
    a.options.progress = [](int done, int pending) {
      std::fprintf(stderr, "\r  decomposing: %d final, %d pending   ", done, pending);
      std::fflush(stderr);
    };
  acd::Decomposition d = acd::decompose(mesh, a.options);
  if (showProgress) std::fprintf(stderr, "\r%60s\r", "");
  for (const auto& line : d.repairs) std::fprintf(stderr, "acd: %s: repaired: %s\n", a.model.c_str(), line.c_str());
  if (!d.status.ok()) return fail(a.model, d.status);
  acd::PostPassResult post;  // --max-hulls, --max-hull-vertices, the mass properties (simulator.cpp)
  if (const int code = applyPostPasses(a.sim, d, a.quiet, post); code != kOk) return code;
  if (d.wrap.used)
    std::fprintf(stderr, "acd: %s: decomposed through a watertight wrap (%d pieces; alpha %g, offset %g; Hausdorff distance "
                 "to the input %.4g, wrap to input %.4g; normalised units)\n", a.model.c_str(), d.wrap.wrappedPieces,
                 d.wrap.alpha, d.wrap.offset, d.wrap.hausdorff, d.wrap.wrapToInput);
  // A self-intersecting solid is decomposed anyway: every cut that succeeds yields closed pieces;
  // where a section crosses itself no clean cut exists, and such a shell is decomposed through its
  // wrap (or, with --no-wrap, its components are flagged, never hidden).
  acd::ReportInput input = acd::describeInput(a.model, mesh);
  input.mesh = a.mesh;
  const int selfIntersections = input.selfIntersections;
  if (selfIntersections > 0)
    std::fprintf(stderr, "acd: warning: %s intersects itself (%d face pairs); %s\n", a.model.c_str(), selfIntersections,
                 a.options.wrap ? "a shell left above tau there is decomposed through its wrap"
                                : "pieces whose sections cross themselves may stay above tau and are marked unresolved");

  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec) return fail("output", acd::Status::error(acd::StatusCode::FileUnreadable, "cannot create " + a.out + ": " + ec.message())), kOutputFailed;
  std::vector<acd::TriMesh> hulls;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < d.components.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "component_%03zu", i);
    const acd::Status s = acd::writeMesh((fs::path(a.out) / (std::string(name) + ".off")).string(), d.components[i].mesh);
    if (!s.ok()) return (void)fail("output", s), kOutputFailed;
    hulls.push_back(d.components[i].hull);
    std::snprintf(name, sizeof name, "hull_%03zu", i);
    names.emplace_back(name);
  }
  acd::Status s = acd::writeObjObjects((fs::path(a.out) / "hulls.obj").string(), hulls, names);
  if (!s.ok()) return (void)fail("output", s), kOutputFailed;
  json outputs = json::object();  // --format: the files written
  if (const int code = writeSimulatorOutputs(a.sim, d, mesh, a.model, a.out, outputs); code != kOk) return code;
  std::ofstream report(fs::path(a.out) / "report.json");
  const bool anyUnresolved = std::any_of(d.components.begin(), d.components.end(), [](const auto& c) { return c.unresolved; });
  // The library's report with the post-passes' sections, plus the simulator files written.
  json j = json::parse(acd::reportJson(input, d, post));
  j.update(outputs);
  report << j.dump(2) << "\n";
  if (!report) return (void)fail("output", acd::Status::error(acd::StatusCode::FileUnreadable, "cannot write report.json")), kOutputFailed;
  if (!a.quiet) printSummary(a, d);
  if (anyUnresolved) {
    std::fprintf(stderr, "acd: warning: some components still exceed tau (marked unresolved in report.json)%s\n",
                 selfIntersections > 0 ? "; the input self-intersects" : "");
    return kUnresolved;
  }
  return kOk;
}

/// --per-mesh: every mesh placed in a scene file (or every object of an OBJ) is a model of its own,
/// decomposed into OUT/NNN_NAME/ with τ in its own normalised units. A refused mesh does not stop
/// the others; the exit code is the largest of the meshes' codes.
int runPerMesh(DecomposeArgs& a) {
  std::vector<acd::TriMesh> meshes;
  std::vector<std::string> names;
  if (acd::isSceneFormat(a.model)) {
    acd::SceneMeshes scene = readSceneIsolated(a.model);
    if (!scene.status.ok()) return fail(a.model, scene.status);
    meshes = std::move(scene.meshes);
    names = std::move(scene.names);
  } else if (fs::path(a.model).extension() == ".obj" || fs::path(a.model).extension() == ".OBJ") {
    acd::ObjObjects objects = acd::readObjObjects(a.model);
    if (!objects.status.ok()) return fail(a.model, objects.status);
    meshes = std::move(objects.objects);
    names = std::move(objects.names);
  } else {
    acd::ReadResult r = load(a.model);
    if (!r.status.ok()) return fail(a.model, r.status);
    meshes.push_back(std::move(r.mesh));
    names.push_back(fs::path(a.model).stem().string());
  }
  int worst = kOk;
  const std::string root = a.out;
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    DecomposeArgs one = a;
    one.mesh = names[k];
    std::string folder = names[k];  // a file name: keep letters, digits, '-', '_' and '.'
    for (char& c : folder)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
    char prefix[16];
    std::snprintf(prefix, sizeof prefix, "%03zu_", k);
    one.out = (fs::path(root) / (prefix + folder.substr(0, 64))).string();
    if (!a.quiet) std::printf("\n== mesh %zu of %zu: %s -> %s\n", k + 1, meshes.size(), names[k].c_str(), one.out.c_str());
    const int code = decomposeMesh(one, meshes[k]);
    if (code != kOk) std::fprintf(stderr, "acd: %s: mesh %s: exit %d\n", a.model.c_str(), names[k].c_str(), code);
    worst = std::max(worst, code);
  }
  return worst;
}

int runDecompose(DecomposeArgs& a) {
  a.options.featureGrouping = !a.noGrouping;
  a.options.merge = !a.noMerge;
  a.options.invariant = !a.noInvariant;
  a.options.mergeScope = a.mergeScope == "component" ? acd::MergeScope::Component : acd::MergeScope::Model;
  a.options.fillHoles = !a.noFillHoles;
  a.options.wrap = !a.noWrap && !a.noRepair;
  a.options.repair = !a.noRepair;
  if (a.perMesh) return runPerMesh(a);
  acd::ReadResult r = load(a.model);
  if (!r.status.ok()) return fail(a.model, r.status);
  return decomposeMesh(a, r.mesh);
}

// ---------------------------------------------------------------- evaluate
int runEvaluate(const std::string& modelPath, const std::string& hullPath, acd::EvaluateOptions options, bool asJson) {
  acd::ReadResult r = load(modelPath);
  if (!r.status.ok()) return fail(modelPath, r.status);
  acd::ObjObjects hulls = acd::readObjObjects(hullPath);
  if (!hulls.status.ok()) return fail(hullPath, hulls.status);
  const acd::Evaluation e = acd::evaluateModel(r.mesh, hulls.objects, options);
  if (!e.status.ok()) return fail("evaluate", e.status);
  if (asJson) {
    std::cout << acd::evaluationJson(modelPath, hullPath, e);
    return kOk;
  }
  std::printf("  model            %s\n  hulls            %s (%d hulls)\n", modelPath.c_str(), hullPath.c_str(), e.hulls);
  std::printf("  model volume     %.5f   (normalised units)\n", e.modelVolume);
  std::printf("  union volume     %.5f ± %.5f   (%.4f × model)\n", e.unionVolume, e.unionVolumeStdErr, e.unionToModelRatio);
  std::printf("  IoU              %.4f ± %.4f\n", e.iou, e.iouStdErr);
  std::printf("  misclassified    %.4f %% of sampled points\n", 100.0 * e.misclassifiedShare);
  std::printf("  hulls stick out  max %.4f, mean %.5f\n", e.hullOutsideMax, e.hullOutsideMean);
  std::printf("  model uncovered  max %.4f, mean %.5f\n", e.modelToHullsMax, e.modelToHullsMean);
  std::printf("  time             %.2f s\n", e.seconds);
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"acd: approximate convex decomposition of polyhedra (Lien & Amato, SPM 2007).\n"
               "Lengths (tau, epsilon, delta) are in normalised units: the model scaled so that its\n"
               "minimum enclosing sphere has radius 1. Output meshes are in the input's coordinates."};
  app.footer(exitCodes());
  app.set_version_flag("--version", std::string("acd ") + ACD_VERSION);
  app.require_subcommand(1);

  DecomposeArgs da;
  auto* dec = app.add_subcommand("decompose", "Solid ACD of a closed mesh (OFF, OBJ, PLY, STL; glTF, GLB, COLLADA, 3MF, FBX)");
  dec->add_option("model", da.model, "Input mesh")->required();
  dec->add_option("-t,--tau", da.options.tau, "Concavity tolerance: every piece the recursion leaves has concavity <= tau, every hull stays within tau of the model")
      ->capture_default_str();
  dec->add_option("--epsilon", da.options.epsilon, "Bridge clustering tolerance (default tau/2)");
  dec->add_option("--delta", da.options.delta, "Douglas-Peucker knot tolerance (default tau/20)");
  dec->add_flag("--no-grouping", da.noGrouping,
                "Resolve the most concave notch with a plane bisecting its dihedral angle (no feature grouping)");
  dec->add_flag("--no-invariant", da.noInvariant,
                "Decompose in the model's own coordinates: the parts may change with the model's pose and order of faces, "
                "and every cut face is exactly planar (by default the shape's own frame is used: the same parts for any "
                "rotation, translation or face order; cuts are computed on coordinates rounded to 2.4e-7 of the radius)");
  dec->add_flag("--invariant", da.invariantFlag, "Decompose in the shape's own frame (the default)")->group("");
  dec->add_option("--merge-scope", da.mergeScope,
                  "What a merge of two neighbours must keep: 'model' (the union's hull within tau of the model; "
                  "fewer parts) or 'component' (the union's own concavity within tau, the paper's promise for every component)")
      ->check(CLI::IsMember({"model", "component"}))
      ->capture_default_str();
  dec->add_flag("--no-merge", da.noMerge,
                "Keep every piece the recursion made (by default neighbours are glued back while their union stays within tau)");
  dec->add_flag("--no-fill-holes", da.noFillHoles,
                "Refuse an open mesh instead of closing its holes before the solid decomposition");
  dec->add_flag("--no-wrap", da.noWrap,
                "Refuse a mesh that the repairs cannot make a clean solid instead of decomposing its watertight wrap; "
                "self-intersecting pieces left above tau stay unresolved (exit 4)");
  dec->add_flag("--no-repair", da.noRepair,
                "Only the strict checks and safe repairs of earlier versions: no vertex merging, double-sided face, "
                "non-manifold, degenerate-face repairs, no cavity handling and no wrap");
  dec->add_option("--threads", da.options.threads, "Worker threads, 0 = all cores; output is identical for any value")
      ->capture_default_str();
  dec->add_option("-o,--out", da.out, "Output folder: component_NNN.off, hulls.obj (one object per hull), report.json")
      ->capture_default_str();
  dec->add_flag("-q,--quiet", da.quiet, "No summary table and no progress");
  addSimulatorOptions(*dec, da.sim);
  dec->add_flag("--per-mesh", da.perMesh,
                "Decompose every mesh of a scene file (glTF, GLB, COLLADA, 3MF, FBX; or every object of an OBJ) on its "
                "own, into OUT/NNN_NAME/ (default: all meshes merged into one model)");

  std::string infoModel;
  auto* info = app.add_subcommand("info", "Diagnose a mesh: counts, manifoldness, orientation, genus, volume");
  info->add_option("model", infoModel, "Input mesh")->required();

  std::string evalModel, evalHulls;
  acd::EvaluateOptions eo;
  bool evalJson = false;
  auto* eval = app.add_subcommand("evaluate", "Measure a set of convex hulls (one OBJ object each) against a model");
  eval->add_option("model", evalModel, "The closed model")->required();
  eval->add_option("hulls", evalHulls, "OBJ with one object per hull (acd, CoACD, V-HACD output)")->required();
  eval->add_option("--samples", eo.volumeSamples, "Monte-Carlo points for volumes and IoU")->capture_default_str();
  eval->add_option("--surface-samples", eo.surfaceSamples, "Surface points for the distance measures")->capture_default_str();
  eval->add_option("--seed", eo.seed, "Random seed")->capture_default_str();
  eval->add_option("--threads", eo.threads, "Worker threads, 0 = all cores")->capture_default_str();
  eval->add_flag("--json", evalJson, "Print JSON instead of a table");

  dec->add_flag("--surface", da.surface,
                "Surface ACD: split the surface along global cuts into patches (patches.obj, hulls.obj); open meshes "
                "stay open. With --exact: convex surface patches");
  // Keep after every other decompose option: --exact adds --surface if no one else has.
  acdcli::addExactOptions(*dec);
  CLI::App* batch = acdcli::addBatchCommand(app, *dec);  // after every decompose option: it takes them all
  CLI::App* report = acdcli::addReportCommand(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kOk : kUsage;
  }
  try {
    if (*dec) {
      if (const int code = validateSimulatorArgs(da.sim, *dec); code != kOk) return code;
      if ((da.surface || acdcli::exactRequested(*dec)) && simulatorRequested(da.sim)) {
        std::fprintf(stderr, "acd: --tau-abs, --max-hulls, --max-hull-vertices and --format apply to solid "
                             "decomposition only (not --surface or --exact)\n");
        return kUsage;
      }
    }
    if (*dec && da.perMesh && (da.surface || acdcli::exactRequested(*dec))) {
      std::fprintf(stderr, "acd: --per-mesh applies to solid decomposition only (not --surface or --exact)\n");
      return kUsage;
    }
    if (*dec && acdcli::exactRequested(*dec)) return acdcli::runExact(*dec, da.model, da.out, da.quiet);
    if (*dec && da.surface) {
      acdcli::SurfaceArgs sa;
      sa.model = da.model;
      sa.out = da.out;
      sa.quiet = da.quiet;
      sa.options.tau = da.options.tau;
      sa.options.epsilon = da.options.epsilon;
      sa.options.delta = da.options.delta;
      sa.options.threads = da.options.threads;
      sa.options.featureGrouping = !da.noGrouping;
      sa.options.merge = !da.noMerge;
      return acdcli::runSurfaceDecompose(sa);
    }
    if (*dec) return runDecompose(da);
    if (*batch) return acdcli::runBatch();
    if (*report) return acdcli::runReport();
    if (*info) return runInfo(infoModel);
    if (*eval) {
      if (eo.volumeSamples <= 0 || eo.surfaceSamples <= 0)
        return fail("invalid parameter", acd::Status::error(acd::StatusCode::InvalidParameter, "samples must be positive"));
      return runEvaluate(evalModel, evalHulls, eo, evalJson);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "acd: internal error: %s\n", e.what());
    return kInternal;
  }
  return kUsage;
}
