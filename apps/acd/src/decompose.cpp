// acd decompose MODEL: solid ACD of a model (or, with --per-mesh, of every mesh of a scene):
// components, hulls.obj, report.json, simulator files and a summary table. --surface and --exact
// are handed to surface.cpp and exact.cpp.
#include "decompose.hpp"

#include "exact.hpp"
#include "exit_codes.hpp"
#include "scene_reader.hpp"
#include "surface.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/diagnosis.hpp>
#include <acd/evaluate.hpp>
#include <acd/io.hpp>
#include <acd/report.hpp>
#include <acd/robust.hpp>
#include <acd/scene_io.hpp>

#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace acdcli {

namespace {

// The component whose hull stands off furthest (the figure that carries the promise), or -1.
int furthestHull(const acd::Decomposition& d) {
  int worst = -1;
  for (std::size_t i = 0; i < d.components.size(); ++i)
    if (worst < 0 || d.components[i].hullExcess > d.components[worst].hullExcess) worst = static_cast<int>(i);
  return worst;
}

void printSummary(const DecomposeArgs& a, const acd::Decomposition& d, double uncovered, const acd::HullsOffInput& off) {
  const auto& cs = d.components;
  double volume = 0, hullVolume = 0, maxConcavity = 0;
  for (const auto& c : cs) volume += c.volume, hullVolume += c.hullVolume, maxConcavity = std::max(maxConcavity, c.concavity);
  std::printf("\n  %-5s %9s %9s %10s %10s %11s %10s\n", "part", "vertices", "faces", "volume %", "hull/vol", "hull excess",
              "concavity");
  const std::size_t shown = std::min<std::size_t>(cs.size(), 40);
  // A hull's excess is the larger of its distances off the model decomposed and off the input as
  // read (they differ where a repair, a wrap or a union moved the surface).
  auto excessOf = [&](std::size_t i) { return std::max(cs[i].hullExcess, off.excess.empty() ? 0.0 : off.excess[i]); };
  for (std::size_t i = 0; i < shown; ++i) {
    const auto& c = cs[i];
    std::printf("  %-5zu %9zu %9zu %10.3f %10.3f %11.4f %10.4f%s\n", i, c.mesh.vertices.size(), c.mesh.faces.size(),
                100.0 * c.volume / d.stats.inputVolume, c.volume > 0 ? c.hullVolume / c.volume : 0.0, excessOf(i),
                c.concavity, c.unresolved ? "  (unresolved)" : excessOf(i) > d.options.tau ? "  (beyond tau)" : "");
  }
  if (shown < cs.size()) std::printf("  ... %zu more in report.json\n", cs.size() - shown);
  std::printf("\n  model          %s\n", a.model.c_str());
  std::printf("  tau            %g   (epsilon %g, delta %g, feature grouping %s)\n", d.options.tau, d.options.epsilon,
              d.options.delta, d.options.featureGrouping ? "on" : "off");
  std::printf("  components     %zu\n", cs.size());
  // The promise: every hull within tau of the model. A merged component's own concavity is not
  // promised (its pockets may lie in its neighbours), so it is shown after, as information.
  const int worst = furthestHull(d);
  const double modelExcess = worst < 0 ? 0.0 : cs[worst].hullExcess;
  const double maxExcess = std::max(modelExcess, off.max);
  std::printf("  hull excess    %.4f   (how far a hull stands off the model, at most: %s)\n", maxExcess,
              modelExcess <= d.options.tau && off.kept ? "within tau, as promised"
                                                       : "BEYOND tau, the promise is not kept");
  if (off.max > modelExcess)
    std::printf("                 (off the input as read; off the model decomposed, after its repairs: %.4f)\n",
                modelExcess);
  std::printf("  input outside  %.4f   (how far the input reaches outside every hull, at most: %s)\n", uncovered,
              uncovered == 0.0 ? "covered" : uncovered <= d.options.tau ? "within tau" : "BEYOND tau, the promise is not kept");
  std::printf("  max concavity  %.4f%s\n", maxConcavity,
              d.options.mergeScope == acd::MergeScope::Model && maxConcavity > d.options.tau
                  ? "   (not promised: a merged component's pockets lie in its neighbours)" : "");
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
  std::fflush(stdout);  // before the warnings on stderr: with both sent to one file, no line is cut
}

/// Lowers the calling thread's scheduling priority (Linux: a nice value per thread; elsewhere
/// nothing). The work it does is the same, it only runs when a core is free.
void giveWayToOtherThreads() {
#ifdef __linux__
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), 10);
#endif
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
  // The input's description (its diagnosis and self-intersection count, seconds on a dense scan)
  // does not depend on the decomposition: beside it when more than one thread is allowed, on a
  // thread that gives way to the decomposition's where they compete for the cores.
  const bool beside = a.options.threads != 1;
  std::future<acd::ReportInput> described =
      std::async(beside ? std::launch::async : std::launch::deferred, [&, beside] {
        if (beside) giveWayToOtherThreads();
        return acd::describeInput(a.model, mesh, a.options.threads);
      });
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
  // where a section crosses itself no clean cut exists, and such a shell is repaired around its
  // crossings or decomposed through its wrap (or, with --no-wrap, its components are flagged,
  // never hidden).
  acd::ReportInput input = described.get();
  input.mesh = a.mesh;
  const int selfIntersections = input.selfIntersections;
  if (selfIntersections > 0)
    std::fprintf(stderr, "acd: warning: %s intersects itself (%d face pairs); %s\n", a.model.c_str(), selfIntersections,
                 a.options.wrap ? "a shell left above tau there is repaired around the crossings, or decomposed through its wrap"
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
  // The other half of the promise: every point of the input as read inside a hull, or within tau
  // of one (a repair that cut off a fold, a shell dropped by mistake would show here).
  const auto checkStart = acd::Clock::now();
  const acd::Coverage cover = acd::inputOutsideHulls(mesh, d);
  const double uncovered = cover.max;
  input.inputOutside = uncovered;
  // And the first half on the input as read: no repair, wrap, union or dropped cavity may hide a
  // hull that stands off what the user gave.
  const acd::HullsOffInput off = acd::hullsOffInput(mesh, d, a.sim.maxHulls == 0 && a.sim.maxHullVertices == 0);
  input.hullOffInput = off.excess;
  input.promiseSeconds = acd::secondsSince(checkStart);
  std::ofstream report(fs::path(a.out) / "report.json");
  const bool anyUnresolved = std::any_of(d.components.begin(), d.components.end(), [](const auto& c) { return c.unresolved; });
  // The library's report with the post-passes' sections, plus the simulator files written.
  json j = json::parse(acd::reportJson(input, d, post));
  j.update(outputs);
  report << j.dump(2) << "\n";
  if (!report) return (void)fail("output", acd::Status::error(acd::StatusCode::FileUnreadable, "cannot write report.json")), kOutputFailed;
  if (!a.quiet) printSummary(a, d, uncovered, off);
  if (anyUnresolved) {
    std::fprintf(stderr, "acd: warning: some components still exceed tau (marked unresolved in report.json)%s\n",
                 selfIntersections > 0 ? "; the input self-intersects" : "");
    return kUnresolved;
  }
  // --max-hulls trades tau for a hull budget on the user's request (its note says so).
  if (const int worst = furthestHull(d); worst >= 0 && d.components[worst].hullExcess > d.options.tau && a.sim.maxHulls == 0) {
    std::fprintf(stderr, "acd: %s: tau not kept: the hull of component %d stands %.4g off the model (%.2f tau)\n",
                 a.model.c_str(), worst, d.components[worst].hullExcess, d.components[worst].hullExcess / d.options.tau);
    return kTauNotKept;
  }
  // --max-hull-vertices enlarges hulls on the user's request (its added volume is in report.json):
  // the measure says how far, the exit code does not fail it.
  if (!off.kept && (a.sim.maxHulls != 0 || a.sim.maxHullVertices != 0) && !a.quiet)
    std::fprintf(stderr, "acd: %s: note: with the hull budget or vertex cap asked for, the hull of component %d stands "
                 "%.4g off the input (%.2f tau)\n", a.model.c_str(), off.component, off.max, off.max / d.options.tau);
  if (!off.kept && a.sim.maxHulls == 0 && a.sim.maxHullVertices == 0) {
    std::fprintf(stderr, "acd: %s: tau not kept: the hull of component %d stands %.4g off the input as read (%.2f tau), "
                 "at (%.6g, %.6g, %.6g)%s\n", a.model.c_str(), off.component, off.max, off.max / d.options.tau,
                 off.worst.x(), off.worst.y(), off.worst.z(),
                 off.openShells > 0 ? "; the input is open (a hull over a hole is measured to the input's own faces; "
                                      "--surface decomposes the open surface as it is)" : "");
    return kTauNotKept;
  }
  if (uncovered > d.options.tau && a.sim.maxHulls == 0) {
    std::fprintf(stderr, "acd: %s: tau not kept: the input reaches %.4g outside every hull (%.2f tau), at (%.6g, %.6g, %.6g)\n",
                 a.model.c_str(), uncovered, uncovered / d.options.tau, cover.worst.x(), cover.worst.y(), cover.worst.z());
    return kTauNotKept;
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
    acd::ReadResult r = readModel(a.model);
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

int runSolidDecompose(DecomposeArgs& a) {
  a.options.featureGrouping = !a.noGrouping;
  a.options.cutAtNotchOnly = !a.cutEveryRegion;
  a.options.merge = !a.noMerge;
  a.options.invariant = !a.noInvariant;
  a.options.mergeScope = a.mergeScope == "component" ? acd::MergeScope::Component : acd::MergeScope::Model;
  a.options.fillHoles = !a.noFillHoles;
  a.options.wrap = !a.noWrap && !a.noRepair;
  a.options.uniteShells = !a.noUnion;
  a.options.repair = !a.noRepair;
  if (a.perMesh) return runPerMesh(a);
  acd::ReadResult r = readModel(a.model);
  if (!r.status.ok()) return fail(a.model, r.status);
  return decomposeMesh(a, r.mesh);
}

}  // namespace

CLI::App* addDecomposeCommand(CLI::App& app, DecomposeArgs& a) {
  auto* dec = app.add_subcommand("decompose", "Solid ACD of a closed mesh (OFF, OBJ, PLY, STL; glTF, GLB, COLLADA, 3MF, FBX)");
  dec->add_option("model", a.model, "Input mesh")->required();
  dec->add_option("-t,--tau", a.options.tau, "Concavity tolerance, in units of the model's enclosing-sphere radius. Promised: every hull stays within tau of the model "
                  "(exit 8 when one does not); every piece the recursion leaves has concavity <= tau (or, where cuts stall on a notch "
                  "the pocket estimate sees, its hull and its vertices' depth below the hull measured within tau), but a merged component's own "
                  "concavity is not bounded (its pockets may lie in its neighbours; --merge-scope component bounds it)")
      ->capture_default_str();
  dec->add_option("--epsilon", a.options.epsilon, "Bridge clustering tolerance (default tau/2)");
  dec->add_option("--delta", a.options.delta, "Douglas-Peucker knot tolerance (default tau/20)");
  dec->add_flag("--no-grouping", a.noGrouping,
                "Resolve the most concave notch with a plane bisecting its dihedral angle (no feature grouping)");
  dec->add_flag("--cut-every-region", a.cutEveryRegion,
                "Cut every region of the section a plane meets (by default only the one at the notch, and those with "
                "large pieces on both sides: a plane across a hand leaves the fingertips on)");
  dec->add_flag("--no-invariant", a.noInvariant,
                "Decompose in the model's own coordinates: the parts may change with the model's pose and order of faces, "
                "and every cut face is exactly planar (by default the shape's own frame is used: the same parts for any "
                "rotation, translation or face order; cuts are computed on coordinates rounded to 2.4e-7 of the radius)");
  dec->add_flag("--invariant", a.invariantFlag, "Decompose in the shape's own frame (the default)")->group("");
  dec->add_option("--merge-scope", a.mergeScope,
                  "What a merge of two pieces must keep: 'model' (the union's hull within tau of the model; touching pieces "
                  "that do not glue may share a hull; fewer parts) or 'component' (neighbours only, the union's own concavity within tau, "
                  "the paper's promise for every component)")
      ->check(CLI::IsMember({"model", "component"}))
      ->capture_default_str();
  dec->add_flag("--no-merge", a.noMerge,
                "Keep every piece the recursion made (by default neighbours are glued back while their union stays within tau)");
  dec->add_flag("--no-fill-holes", a.noFillHoles,
                "Refuse an open mesh instead of closing its holes before the solid decomposition");
  dec->add_flag("--no-wrap", a.noWrap,
                "Refuse a mesh that the repairs cannot make a clean solid instead of decomposing its watertight wrap; "
                "self-intersecting pieces left above tau stay unresolved (exit 4)");
  dec->add_flag("--no-union", a.noUnion,
                "Decompose each shell on its own only: by default, shells that pass through, touch or lie in another "
                "(an assembly exported from CAD) are also decomposed as the solid they bound together, and whichever "
                "gives fewer hulls is kept (slower where shells meet)");
  dec->add_flag("--union", a.unionFlag, "Shells that meet also decomposed as their union (the default)")->group("");
  dec->add_flag("--no-repair", a.noRepair,
                "Only the strict checks and safe repairs of earlier versions: no vertex merging, double-sided face, "
                "non-manifold, degenerate-face repairs, no cavity handling and no wrap");
  dec->add_option("--working-share", a.options.workingShare,
                  "A solid of --working-from-faces faces or more is decomposed as a simplified copy that stands at most "
                  "this share of tau off it, at tau less that share; the hulls are built from it and the input's own "
                  "vertices, merged and checked against the input, so a dense scan's cost follows tau, not its face "
                  "count (0: always the input's own triangles)")
      ->check(CLI::Range(0.0, 0.5))
      ->capture_default_str();
  dec->add_option("--working-from-faces", a.options.workingFromFaces,
                  "The face count from which a solid is decomposed as its working mesh (below it the input's own "
                  "triangles are about as fast and give fewer parts)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  dec->add_option("--threads", a.options.threads, "Worker threads, 0 = all cores; output is identical for any value")
      ->capture_default_str();
  dec->add_option("-o,--out", a.out, "Output folder: component_NNN.off, hulls.obj (one object per hull), report.json")
      ->capture_default_str();
  dec->add_flag("-q,--quiet", a.quiet, "No summary table and no progress");
  addSimulatorOptions(*dec, a.sim);
  dec->add_flag("--per-mesh", a.perMesh,
                "Decompose every mesh of a scene file (glTF, GLB, COLLADA, 3MF, FBX; or every object of an OBJ) on its "
                "own, into OUT/NNN_NAME/ (default: all meshes merged into one model)");
  dec->add_flag("--surface", a.surface,
                "Surface ACD: split the surface along global cuts into patches (patches.obj, hulls.obj); open meshes "
                "stay open. With --exact: convex surface patches");
  return dec;
}

int runDecompose(const CLI::App& dec, DecomposeArgs& a) {
  if (const int code = validateSimulatorArgs(a.sim, dec); code != kOk) return code;
  const bool exact = exactRequested(dec);
  if ((a.surface || exact) && simulatorRequested(a.sim)) {
    std::fprintf(stderr, "acd: --tau-abs, --max-hulls, --max-hull-vertices and --format apply to solid "
                         "decomposition only (not --surface or --exact)\n");
    return kUsage;
  }
  if (a.perMesh && (a.surface || exact)) {
    std::fprintf(stderr, "acd: --per-mesh applies to solid decomposition only (not --surface or --exact)\n");
    return kUsage;
  }
  if (exact) return runExact(dec, a.model, a.out, a.quiet);
  if (a.surface) {
    SurfaceArgs sa;
    sa.model = a.model;
    sa.out = a.out;
    sa.quiet = a.quiet;
    sa.options.tau = a.options.tau;
    sa.options.epsilon = a.options.epsilon;
    sa.options.delta = a.options.delta;
    sa.options.threads = a.options.threads;
    sa.options.featureGrouping = !a.noGrouping;
    sa.options.merge = !a.noMerge;
    return runSurfaceDecompose(sa);
  }
  return runSolidDecompose(a);
}

}  // namespace acdcli
