// tetmesh: a tetrahedral mesh of the convex hulls of the solid ACD components, with TetGen
// (Lien & Amato 2007, Section 7, "Mesh generation", Figure 4).
//   tetmesh MODEL [--tau 0.2] [--simplify K] [--quality Q] [--max-volume V] [-o OUT]
//           [--format vtk|mesh|tetgen] [--compare] [--json FILE]
//
// main.cpp is the command line; the steps are in src/ (command_line, hull_mesher, report, ...).
#include "command_line.hpp"
#include "deformation_files.hpp"
#include "hull_mesher.hpp"
#include "report.hpp"
#include "tet_files.hpp"

#include <appcli/exit_codes.hpp>

#include <acd/io.hpp>

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

using namespace tetmesh;
using appcli::kBadInput;
using appcli::kOk;
using appcli::kOutputFailed;

const char* exitCodes() {
  return "Exit codes: 0 success; 1 bad command line; 2 unreadable or invalid model; 3 invalid parameter;\n"
         "5 cannot write output; 6 meshing failed (TetGen refused or crashed on the hull complex).";
}

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

/// Writes --poly and --regions: written even when TetGen fails on the complex, when they are most useful.
int writeComplexFiles(const Args& a, const HullMeshResult& r) {
  if (!a.poly.empty() && !r.complex.plc.facets.empty()) {
    const acd::Status s = writePoly(a.poly, r.complex.plc);
    if (!s.ok()) {
      return kConsole.fail(kOutputFailed, s.message);
    }
  }
  // The regions as meshed, one OBJ object per component: a picture before the numbers.
  if (!a.regions.empty() && !r.regions.empty()) {
    std::vector<acd::TriMesh> meshes;
    std::vector<std::string> names;
    for (std::size_t i = 0; i < r.regions.size(); ++i)
      if (!r.regions[i].empty())
        meshes.push_back(r.regions[i]), names.push_back("component_" + std::to_string(i + 1));
    const acd::Status s = acd::writeObjObjects(a.regions, meshes, names);
    if (!s.ok()) {
      return kConsole.fail(kOutputFailed, s.message);
    }
  }
  return kOk;
}

int run(Args& a) {
  const bool progress = !a.quiet && ::isatty(STDERR_FILENO);
  TetFormat format = TetFormat::Vtk;
  if (const int code = checkArgs(a, format); code != kOk) return code;

  DeformationOptions deformOpts;
  if (!a.deform.dir.empty())
    if (const int code = deformOptions(a.deform, deformOpts); code != kOk) return code;
  deformOpts.arap.threads = a.options.threads;

  const acd::ReadResult read = acd::readMesh(a.model);
  if (!read.status.ok()) {
    return kConsole.fail(kBadInput, read.status.message);
  }
  if (progress) kConsole.sayf("decomposing at tau %g, hulls, tets ...", a.options.tau);
  const HullMeshResult r = meshHulls(read.mesh, a.options);
  if (const int code = writeComplexFiles(a, r); code != kOk) return code;
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
    const int code = runDeformation(a.deform, deformOpts, r.mesh, read.mesh, deformed);
    if (progress) std::fprintf(stderr, "\n");
    if (code != kOk) return code;
  }

  if (!a.out.empty()) {
    const acd::Status s = writeTetMesh(a.out, format, r.mesh);
    if (!s.ok()) {
      return kConsole.fail(kOutputFailed, s.message);
    }
  }

  printReport(a, format, r, direct, deformed);
  if (!a.json.empty()) return writeJsonReport(a, r, direct, deformed);
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  CLI::App app{"Tetrahedral mesh of the convex hulls of the solid ACD components (TetGen)."};
  app.footer(exitCodes());
  app.add_option("MODEL", a.model, "Closed mesh (OFF, OBJ, PLY, STL)")->required();
  app.add_option("-t,--tau", a.options.tau, "Concavity tolerance, normalised units")->capture_default_str();
  app.add_option("--mesher", a.mesher,
                 "refine: Delaunay refinement of the hull regions, sizes tied to tau, no slivers; "
                 "complex: the regions' exact faces given to TetGen (the paper's Figure 4); "
                 "auto: the complex where every hull has at most 24 faces and its mesh no sliver, else refine")
      ->capture_default_str();
  app.add_option("--simplify", a.options.simplify,
                 "Hulls with at most K vertices that still contain their component (K >= 4; 0: the exact hulls; "
                 "default: 0 with refine, 24 with complex)");
  app.add_flag("--clip", a.options.clip, "Mesh the components themselves: the hull regions clipped to the model (refine)");
  app.add_option("--sharp", a.options.sharpAngle,
                 "Keep the hull regions' edges whose faces turn by more than DEG degrees exactly (refine; CAD parts); "
                 "0: all edges are followed within the facet distance")
      ->capture_default_str();
  app.add_flag("--no-coarsen", [&a](std::int64_t) { a.options.coarsen = false; },
               "Coarse refinement: keep the refinement's mesh as it is (no edge collapses that coarsen it)");
  app.add_flag("--keep-volume", a.options.keepVolume,
               "Coarse refinement: no collapse takes a component's tets below the component's own volume");
  app.add_option("--surface-distance", a.options.surfaceDistance,
                 "Refinement: its surface follows the hull regions within S tau (default 0.5 when coarsened, "
                 "else 0.25); the collapses may take it the rest of tau from them");
  app.add_option("--quality", a.options.tetgen.radiusEdge,
                 "Radius-edge bound of the tets (e.g. 1.5); 0: the coarse mesh (refine: bound 2, then coarsened; complex: TetGen's "
                 "constrained Delaunay mesh, no refinement)")
      ->capture_default_str();
  app.add_option("--max-volume", a.options.tetgen.maxVolume, "Largest tet volume, input units; 0: none");
  app.add_option("-o,--output", a.out, "Mesh file (.vtk, .mesh) or base name for .node/.ele/.face");
  app.add_option("--format", a.format, "vtk, mesh or tetgen (default: from the -o extension, else vtk)");
  app.add_flag("--compare", a.compare, "Also mesh the model itself with TetGen and print both side by side");
  app.add_flag("--merge", a.options.merge, "Use the decomposition's merge pass (hulls then overlap and are clipped)");
  app.add_option("--threads", a.options.threads, "Decomposition threads, 0 = all cores")->capture_default_str();
  app.add_option("--snap", a.options.tolerance,
                 "Complex: features closer than this (relative to the half-diagonal) are one: welding, contacts")
      ->capture_default_str();
  app.add_option("--timeout", a.options.tetgen.timeoutSeconds, "Seconds TetGen may take per call before it is stopped")
      ->capture_default_str();
  app.add_option("--json", a.json, "Write the report as JSON to this file");
  app.add_option("--poly", a.poly, "Complex: write the hull complex given to TetGen as a .poly file");
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
