// skeleton: skeletons from the components of an approximate convex decomposition, and how
// much they change when the model is deformed (paper, Section 7, Figure 21).
//
//   skeleton MODEL [--tau 0.1] [--deformed MODEL2 ...] [--deform SPEC ...] [-o OUT]
//
// For the model and every deformed version: the ACD skeleton (a node per part — components
// grouped into limbs, trunk, head — a node per cut between parts, edges part-cut), the skeleton
// of the components themselves, and CGAL's mean-curvature-flow skeleton; for every deformed
// version: D = graph edit distance to the original's skeleton, and D2 = the same with degree-2
// nodes contracted. Exit codes are listed in --help.
//
// main.cpp is the command line; the steps are in src/skeleton_run.hpp, the files and the table
// in src/run_report.hpp.
#include <CLI/CLI.hpp>
#include <appcli/exit_codes.hpp>
#include <string>
#include <vector>

#include "run_report.hpp"
#include "skeleton_run.hpp"

using namespace skeleton;

namespace {

const char* exitCodes() {
  return "Exit codes: 0 success; 1 bad command line; 2 unreadable or invalid model, or a deformation failed;\n"
         "3 invalid parameter or deformation spec; 4 some component still exceeds tau; 5 cannot write output;\n"
         "6 internal error.";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Skeletons from approximate convex decomposition components, and graph edit distance under "
      "deformation (Lien & Amato 2007, Section 7)."};
  app.footer(exitCodes());
  RunParameters p;
  app.add_option("model", p.modelPath, "closed mesh (.off, .obj, .ply, .stl)")->required();
  app.add_option("-t,--tau", p.tau, "concavity tolerance of the decomposition (normalised units)");
  app.add_option("--deformed", p.deformedPaths, "deformed versions of the model (files)");
  app.add_option("--deform", p.deformSpecs,
                 "deformations to make: bend:DIR:AXIS:DEG[:HANDLE[:REGION]], twist:DIR:DEG[:HANDLE[:REGION]], "
                 "ids:FILE.json, affine:RX,RY,RZ:SX,SY,SZ[:TX,TY,TZ], or steps joined by ';' (see docs/SKELETON.md)");
  app.add_option("-o,--out", p.outDir, "output folder, created if missing");
  app.add_option(
      "--exact-max-nodes", p.exactMaxNodes,
      "exact graph edit distance when both graphs have at most this many nodes; bipartite approximation above");
  app.add_option("--max-expansions", p.maxExpansions, "search budget of the exact graph edit distance");
  app.add_option("--mip-max-columns", p.mipMaxColumns,
                 "above --exact-max-nodes, solve the edit distance as a binary program (GLPK) when it has at most "
                 "this many variables (n1*n2 + m1*m2); 0 = never");
  app.add_option("--mcf-runs", p.mcfRuns, "run CGAL's skeletonization this many times per model (node counts vary)");
  app.add_option("--tubes", p.tubeRadius,
                 "also write each skeleton as thin tubes (NAME.*_skeleton_tubes.off) of this radius, as a fraction "
                 "of the bounding-box diagonal, for renderers that do not draw lines (e.g. 0.004)");
  app.add_flag("--handle-cycles", p.handleCycles,
               "keep a cycle in the skeleton of parts for each handle of the solid that runs through the contacts "
               "of several parts (default: a tree; handles are counted in report.json)");
  app.add_flag("--no-mcf", p.noMcf, "skip CGAL's mean-curvature-flow skeleton");
  app.add_option("--threads", p.threads, "decomposition worker threads, 0 = all cores");
  app.add_flag("-q,--quiet", p.quiet, "no summary table");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return appcli::usageExit(app.exit(e));  // CLI11 prints help or the reason
  }

  if (const int code = checkParameters(p); code != appcli::kOk) return code;
  if (p.deformedPaths.empty() && p.deformSpecs.empty())
    kConsole.say("no --deformed or --deform given: only the model's skeletons are written");
  std::vector<Model> models;
  for (auto step : {loadModels, makeDeformations, decomposeModels})
    if (const int code = step(p, models); code != appcli::kOk) return code;
  compareSkeletons(p, models);
  bool unresolved = false;
  if (const int code = writeRunFiles(p, models, unresolved); code != appcli::kOk) return code;
  if (!p.quiet) printTable(models);
  return unresolved ? appcli::kUnresolved : appcli::kOk;
}
