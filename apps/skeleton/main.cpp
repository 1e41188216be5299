// skeleton: skeletons from the components of an approximate convex decomposition, and how
// much they change when the model is deformed (paper, Section 7, Figure 21).
//
//   skeleton MODEL [--tau 0.1] [--deformed MODEL2 ...] [--deform SPEC ...] [-o OUT]
//
// For the model and every deformed version: the ACD skeleton (a node per component, a node per
// cut, edges component-cut) and CGAL's mean-curvature-flow skeleton; for every deformed
// version: D = graph edit distance to the original's skeleton, and D2 = the same with degree-2
// nodes contracted. Exit codes are listed in --help.
#include "acd_skeleton.hpp"
#include "deform.hpp"
#include "ged.hpp"
#include "mcf_skeleton.hpp"
#include "skeleton_io.hpp"

#include <appcli/console.hpp>
#include <appcli/exit_codes.hpp>

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace skeleton;

namespace {

using namespace appcli;  // the shared exit codes: a failed deformation is kBadInput

const appcli::Console kConsole("skeleton");

const char* exitCodes() {
  return "Exit codes: 0 success; 1 bad command line; 2 unreadable or invalid model, or a deformation failed;\n"
         "3 invalid parameter or deformation spec; 4 some component still exceeds tau; 5 cannot write output;\n"
         "6 internal error.";
}

const bool kProgress = ::isatty(2) != 0;

void progress(const std::string& line) {
  if (kProgress) kConsole.say(line);
}

int fail(int code, const std::string& message) { return kConsole.fail(code, message); }

/// A closed, outward mesh ready for decomposition, deformation and CGAL: prepareSolid's
/// repairs applied and its pieces put back into one mesh.
bool loadSolid(const std::string& path, acd::TriMesh& mesh, std::vector<std::string>& repairs, std::string& error) {
  const acd::ReadResult read = acd::readMesh(path);
  if (!read.status.ok()) {
    error = read.status.message;
    return false;
  }
  const acd::PreparedSolid solid = acd::prepareSolid(read.mesh);
  if (!solid.status.ok()) {
    error = path + ": " + solid.status.message;
    return false;
  }
  repairs = solid.repairs;
  mesh = acd::TriMesh{};
  for (const acd::TriMesh& piece : solid.components) {
    const int base = static_cast<int>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (const acd::Face& f : piece.faces) mesh.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  return true;
}

struct Model {
  std::vector<std::string> repairs;  // what prepareSolid changed
  std::string name;    // file stem in OUT
  std::string source;  // the file, or the deformation spec
  std::string summary; // what the deformation did
  acd::TriMesh mesh;
  Graph acd, acdContracted, mcf, mcfContracted;
  int components = 0, unresolved = 0;
  bool mcfOk = false;
  std::string mcfError;
  std::vector<int> mcfRunNodes;  // node counts of repeated MCF runs
  double decomposeSeconds = 0, mcfSeconds = 0;
  GedResult d, d2, mcfD, mcfD2;
  Graph mcfSecond;               // second CGAL run of the same mesh, for the run-to-run distance
  bool hasSecond = false;
  GedResult runD, runD2;         // CGAL skeleton, run 1 against run 2 of the same mesh
};

json graphSummary(const Graph& g, const Graph& contracted) {
  return {{"nodes", g.nodeCount()},           {"edges", g.edgeCount()},
          {"nodes_d2", contracted.nodeCount()}, {"edges_d2", contracted.edgeCount()},
          {"connected_components", connectedComponents(g)}};
}

std::string distanceCell(const GedResult& r) {
  if (r.exact) return std::to_string(r.distance);
  return std::to_string(r.distance) + " [>=" + std::to_string(r.lowerBound) + "]";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Skeletons from approximate convex decomposition components, and graph edit distance under "
               "deformation (Lien & Amato 2007, Section 7)."};
  app.footer(exitCodes());
  std::string modelPath, outDir = "skeleton-out";
  std::vector<std::string> deformedPaths, deformSpecs;
  double tau = 0.1;
  int exactMaxNodes = 12, mcfRuns = 1, threads = 0;
  double tubeRadius = 0.0;
  long long maxExpansions = 20000000;
  bool noMcf = false, quiet = false;
  app.add_option("model", modelPath, "closed mesh (.off, .obj, .ply, .stl)")->required();
  app.add_option("-t,--tau", tau, "concavity tolerance of the decomposition (normalised units)");
  app.add_option("--deformed", deformedPaths, "deformed versions of the model (files)");
  app.add_option("--deform", deformSpecs,
                 "deformations to make: bend:DIR:AXIS:DEG[:HANDLE[:REGION]], ids:FILE.json, "
                 "affine:RX,RY,RZ:SX,SY,SZ[:TX,TY,TZ] (see docs/SKELETON.md)");
  app.add_option("-o,--out", outDir, "output folder, created if missing");
  app.add_option("--exact-max-nodes", exactMaxNodes, "exact graph edit distance when both graphs have at most this many nodes; bipartite approximation above");
  app.add_option("--max-expansions", maxExpansions, "search budget of the exact graph edit distance");
  app.add_option("--mcf-runs", mcfRuns, "run CGAL's skeletonization this many times per model (node counts vary)");
  app.add_option("--tubes", tubeRadius,
                 "also write each skeleton as thin tubes (NAME.*_skeleton_tubes.off) of this radius, as a fraction "
                 "of the bounding-box diagonal, for renderers that do not draw lines (e.g. 0.004)");
  app.add_flag("--no-mcf", noMcf, "skip CGAL's mean-curvature-flow skeleton");
  app.add_option("--threads", threads, "decomposition worker threads, 0 = all cores");
  app.add_flag("-q,--quiet", quiet, "no summary table");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return usageExit(app.exit(e));  // CLI11 prints help or the reason
  }

  if (!(tau >= 1e-4 && tau <= 2)) return fail(kBadParameter, "--tau must lie in [1e-4, 2], got " + std::to_string(tau));
  if (exactMaxNodes < 0 || exactMaxNodes > 40) return fail(kBadParameter, "--exact-max-nodes must lie in [0, 40]");
  if (maxExpansions < 1) return fail(kBadParameter, "--max-expansions must be positive");
  if (mcfRuns < 1 || mcfRuns > 100) return fail(kBadParameter, "--mcf-runs must lie in [1, 100]");
  if (threads < 0) return fail(kBadParameter, "--threads must be >= 0");
  if (!(tubeRadius >= 0 && tubeRadius <= 0.1)) return fail(kBadParameter, "--tubes must lie in [0, 0.1]");
  if (deformedPaths.empty() && deformSpecs.empty())
    kConsole.say("no --deformed or --deform given: only the model's skeletons are written");

  std::vector<Model> models(1);
  {
    std::string error;
    if (!loadSolid(modelPath, models[0].mesh, models[0].repairs, error)) return fail(kBadInput, error);
    models[0].name = "original";
    models[0].source = modelPath;
  }
  for (const std::string& path : deformedPaths) {
    Model m;
    std::string error;
    if (!loadSolid(path, m.mesh, m.repairs, error)) return fail(kBadInput, error);
    m.name = "deformed_" + std::to_string(models.size());
    m.source = path;
    models.push_back(std::move(m));
  }
  // Check every spec before the slow work starts.
  for (const std::string& spec : deformSpecs) {
    const std::string kind = spec.substr(0, spec.find(':'));
    if (kind != "bend" && kind != "ids" && kind != "affine")
      return fail(kBadParameter, "--deform: unknown deformation '" + kind + "' (expected bend, ids or affine)");
  }

  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) return fail(kOutputFailed, outDir + ": cannot create the output folder: " + ec.message());

  for (const std::string& spec : deformSpecs) {
    progress("deforming: " + spec);
    DeformResult r = applyDeformation(models[0].mesh, spec);
    if (!r.ok) {
      const bool specError = r.error.find("needs") != std::string::npos || r.error.find("must") != std::string::npos ||
                             r.error.find("not a number") != std::string::npos || r.error.find("unknown") != std::string::npos;
      return fail(specError ? kBadParameter : kBadInput, "--deform " + spec + ": " + r.error);
    }
    Model m;
    m.name = "deformed_" + std::to_string(models.size());
    m.source = spec;
    m.summary = r.summary;
    m.mesh = std::move(r.mesh);
    const std::string path = (fs::path(outDir) / (m.name + ".off")).string();
    const acd::Status w = acd::writeMesh(path, m.mesh);
    if (!w.ok()) return fail(kOutputFailed, path + ": " + w.message);
    models.push_back(std::move(m));
  }

  acd::DecomposeOptions options;
  options.tau = tau;
  options.threads = threads;
  // Skeletons are compared across poses: the decomposition must not change with them (the
  // rounding of input vertices on cut planes, 2.1e-7 of the radius, does not matter here).
  options.invariant = true;
  if (const acd::Status s = acd::validate(acd::resolvedOptions(options)); !s.ok()) return fail(kBadParameter, s.message);

  for (Model& m : models) {
    progress(m.name + ": decomposing");
    const acd::Decomposition d = acd::decompose(m.mesh, options);
    if (!d.status.ok()) return fail(exitFor(d.status), m.source + ": " + d.status.message);
    m.decomposeSeconds = d.times.total;
    std::vector<acd::TriMesh> parts;
    for (const acd::Component& c : d.components) {
      parts.push_back(c.mesh);
      m.unresolved += c.unresolved;
    }
    m.components = static_cast<int>(parts.size());
    m.acd = skeletonFromComponents(parts);
    m.acdContracted = contractDegreeTwo(m.acd);
    if (!noMcf) {
      for (int run = 0; run < mcfRuns; ++run) {
        progress(m.name + ": CGAL skeleton, run " + std::to_string(run + 1));
        McfSkeleton s = meanCurvatureSkeleton(m.mesh);
        if (!s.ok) {
          m.mcfError = s.error;
          break;
        }
        m.mcfRunNodes.push_back(s.graph.nodeCount());
        m.mcfSeconds += s.seconds;
        if (run == 0) {
          m.mcfOk = true;
          m.mcf = std::move(s.graph);
          m.mcfContracted = contractDegreeTwo(m.mcf);
        } else if (run == 1 && &m == &models[0]) {
          m.mcfSecond = std::move(s.graph);
          m.hasSecond = true;
        }
      }
    }
  }

  GedOptions ged;
  ged.exactMaxNodes = exactMaxNodes;
  ged.maxExpansions = maxExpansions;
  Model& first = models[0];
  if (first.hasSecond) {
    // The noise floor of the CGAL skeleton: the same mesh, skeletonized twice.
    progress("original: CGAL skeleton run 1 against run 2");
    first.runD = graphEditDistance(first.mcfSecond, first.mcf, ged);
    first.runD2 = graphEditDistance(contractDegreeTwo(first.mcfSecond), first.mcfContracted, ged);
  }
  const Model& original = models[0];
  for (std::size_t i = 1; i < models.size(); ++i) {
    Model& m = models[i];
    progress(m.name + ": graph edit distances");
    m.d = graphEditDistance(m.acd, original.acd, ged);
    m.d2 = graphEditDistance(m.acdContracted, original.acdContracted, ged);
    if (m.mcfOk && original.mcfOk) {
      m.mcfD = graphEditDistance(m.mcf, original.mcf, ged);
      m.mcfD2 = graphEditDistance(m.mcfContracted, original.mcfContracted, ged);
    }
  }

  // Files: per model the two skeletons as JSON and OBJ; report.json for the whole run.
  json report;
  report["model"] = modelPath;
  report["parameters"] = {{"tau", tau},
                          {"exact_max_nodes", exactMaxNodes},
                          {"max_expansions", maxExpansions},
                          {"mcf_runs", noMcf ? 0 : mcfRuns},
                          {"cost_model", "node insertion/deletion 1, edge insertion/deletion 1, substitution 0"}};
  report["models"] = json::array();
  bool unresolved = false;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const Model& m = models[i];
    unresolved = unresolved || m.unresolved > 0;
    const fs::path base = fs::path(outDir) / m.name;
    std::vector<std::pair<std::string, const Graph*>> files{{".acd_skeleton", &m.acd}};
    if (m.mcfOk) files.push_back({".mcf_skeleton", &m.mcf});
    for (const auto& [suffix, graph] : files) {
      std::ofstream js(base.string() + suffix + ".json");
      js << toJson(*graph).dump(1) << '\n';
      if (!js || !writeSkeletonObj(base.string() + suffix + ".obj", *graph))
        return fail(kOutputFailed, base.string() + suffix + ": cannot write the skeleton");
      if (tubeRadius > 0) {
        const double radius = tubeRadius * acd::boundingBox(m.mesh).size().norm();
        const std::string path = base.string() + suffix + "_tubes.off";
        if (!acd::writeMesh(path, tubeMesh(*graph, radius)).ok()) return fail(kOutputFailed, path + ": cannot write");
      }
    }
    json entry = {{"name", m.name},
                  {"source", m.source},
                  {"vertices", m.mesh.vertices.size()},
                  {"faces", m.mesh.faces.size()},
                  {"components", m.components},
                  {"unresolved_components", m.unresolved},
                  {"repairs", m.repairs},
                  {"decompose_seconds", m.decomposeSeconds},
                  {"acd", graphSummary(m.acd, m.acdContracted)}};
    if (!m.summary.empty()) entry["deformation"] = m.summary;
    if (i > 0) entry["mesh_file"] = m.source.find(':') != std::string::npos ? base.string() + ".off" : m.source;
    if (!noMcf) {
      if (m.mcfOk) {
        entry["mcf"] = graphSummary(m.mcf, m.mcfContracted);
        entry["mcf"]["seconds_per_run"] = m.mcfSeconds / std::max<std::size_t>(1, m.mcfRunNodes.size());
        entry["mcf"]["run_node_counts"] = m.mcfRunNodes;
        if (m.hasSecond) {
          entry["mcf"]["run2_vs_run1_D"] = toJson(m.runD);
          entry["mcf"]["run2_vs_run1_D2"] = toJson(m.runD2);
        }
      } else {
        entry["mcf"] = {{"error", m.mcfError}};
      }
    }
    if (i > 0) {
      entry["acd"]["D"] = toJson(m.d);
      entry["acd"]["D2"] = toJson(m.d2);
      if (m.mcfOk && original.mcfOk) {
        entry["mcf"]["D"] = toJson(m.mcfD);
        entry["mcf"]["D2"] = toJson(m.mcfD2);
      }
    }
    report["models"].push_back(entry);
  }
  {
    const std::string path = (fs::path(outDir) / "report.json").string();
    std::ofstream out(path);
    out << report.dump(2) << '\n';
    if (!out) return fail(kOutputFailed, path + ": cannot write the report");
  }

  if (!quiet) {
    std::printf("%-12s %5s %9s %9s %14s %14s %9s %9s %14s %14s\n", "model", "comp", "ACD nodes", "ACD n(D2)", "ACD D",
                "ACD D2", "MCF nodes", "MCF n(D2)", "MCF D", "MCF D2");
    for (std::size_t i = 0; i < models.size(); ++i) {
      const Model& m = models[i];
      const bool mcf = m.mcfOk && original.mcfOk;
      std::printf("%-12s %5d %9d %9d %14s %14s %9s %9s %14s %14s\n", m.name.c_str(), m.components, m.acd.nodeCount(),
                  m.acdContracted.nodeCount(), i ? distanceCell(m.d).c_str() : "-", i ? distanceCell(m.d2).c_str() : "-",
                  m.mcfOk ? std::to_string(m.mcf.nodeCount()).c_str() : "-",
                  m.mcfOk ? std::to_string(m.mcfContracted.nodeCount()).c_str() : "-",
                  i && mcf ? distanceCell(m.mcfD).c_str() : "-", i && mcf ? distanceCell(m.mcfD2).c_str() : "-");
    }
    if (original.hasSecond)
      std::printf("%-12s %5s %9s %9s %14s %14s %9d %9s %14s %14s\n", "orig. run 2", "", "", "", "", "",
                  original.mcfSecond.nodeCount(), "", distanceCell(original.runD).c_str(),
                  distanceCell(original.runD2).c_str());
    std::printf("D: graph edit distance to the original's skeleton (unit costs); D2: degree-2 nodes contracted.\n"
                "A value with [>=L] is the bipartite upper bound with lower bound L; others are exact.\n");
  }
  return unresolved ? kUnresolved : kOk;
}
