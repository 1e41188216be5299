#include "run_report.hpp"

#include <acd/io.hpp>
#include <algorithm>
#include <appcli/exit_codes.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "skeleton_io.hpp"

namespace skeleton {

namespace fs = std::filesystem;
using json = nlohmann::json;
using appcli::kOk;
using appcli::kOutputFailed;

namespace {

int fail(int code, const std::string& message) { return kConsole.fail(code, message); }

json graphSummary(const Graph& g, const Graph& contracted) {
  return {{"nodes", g.nodeCount()},
          {"edges", g.edgeCount()},
          {"nodes_d2", contracted.nodeCount()},
          {"edges_d2", contracted.edgeCount()},
          {"connected_components", connectedComponents(g)}};
}

std::string distanceCell(const GedResult& r) {
  if (r.exact) return std::to_string(r.distance);
  return std::to_string(r.distance) + " [>=" + std::to_string(r.lowerBound) + "]";
}

}  // namespace

int writeRunFiles(const RunParameters& p, const std::vector<Model>& models, bool& unresolved) {
  const std::string& modelPath = p.modelPath;
  const std::string& outDir = p.outDir;
  const double tau = p.tau, tubeRadius = p.tubeRadius;
  const int exactMaxNodes = p.exactMaxNodes, mcfRuns = p.mcfRuns, threads = p.threads;
  const long long maxExpansions = p.maxExpansions, mipMaxColumns = p.mipMaxColumns;
  const bool noMcf = p.noMcf;
  const Model& original = models[0];
  // Files: per model the two skeletons as JSON and OBJ; report.json for the whole run.
  json report;
  report["model"] = modelPath;
  report["parameters"] = {{"tau", tau},
                          {"exact_max_nodes", exactMaxNodes},
                          {"max_expansions", maxExpansions},
                          {"mip_max_columns", mipMaxColumns},
                          {"mcf_runs", noMcf ? 0 : mcfRuns},
                          {"handle_cycles", p.handleCycles},
                          {"cost_model", "node insertion/deletion 1, edge insertion/deletion 1, substitution 0"}};
  report["models"] = json::array();
  unresolved = false;
  for (std::size_t i = 0; i < models.size(); ++i) {
    const Model& m = models[i];
    unresolved = unresolved || m.unresolved > 0;
    const fs::path base = fs::path(outDir) / m.name;
    std::vector<std::pair<std::string, const Graph*>> files{{".acd_skeleton", &m.acd}};
    if (m.mcfOk) files.push_back({".mcf_skeleton", &m.mcf});
    for (const auto& [suffix, graph] : files) {
      std::ofstream js(base.string() + suffix + ".json");
      json j = toJson(*graph);
      if (graph == &m.acd) {  // which components make each part, which part each mesh vertex is in
        j["part_components"] = m.partMembers;
        j["vertex_parts"] = m.vertexPart;
        if (i > 0 && m.sharesVertices) j["original_part"] = m.partMatch;
      }
      js << j.dump(1) << '\n';
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
                  {"parts", m.parts},
                  {"part_merges", m.partMerges},
                  {"genus", m.genus},
                  {"dropped_adjacencies", m.droppedAdjacencies},
                  {"loop_grid", m.loopGrid},
                  {"part_handles", m.partHandles},
                  {"loop_adjacencies", m.loopJoints},
                  {"acd", graphSummary(m.acd, m.acdContracted)},
                  {"acd_components", graphSummary(m.components_, m.componentsContracted)}};
    if (!m.summary.empty()) entry["deformation"] = m.summary;
    if (i > 0) entry["mesh_file"] = m.source.find(':') != std::string::npos ? base.string() + ".off" : m.source;
    if (!noMcf) {
      if (m.mcfOk) {
        entry["mcf"] = graphSummary(m.mcf, m.mcfContracted);
        entry["mcf"]["seconds_per_run"] = m.mcfSeconds / std::max<std::size_t>(1, m.mcfRunNodes.size());
        entry["mcf"]["run_node_counts"] = m.mcfRunNodes;
        if (!m.mcfRunPairsD2.empty()) {
          entry["mcf"]["run_pairs_D2"] = json::array();  // original run i against this mesh's run j, i major
          for (const GedResult& r : m.mcfRunPairsD2) entry["mcf"]["run_pairs_D2"].push_back(toJson(r));
        }
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
      if (m.sharesVertices) {
        entry["acd"]["correspondence_D"] = m.correspondenceD;
        entry["acd"]["correspondence_D2"] = m.correspondenceD2;
      }
      entry["acd_components"]["D"] = toJson(m.componentsD);
      entry["acd_components"]["D2"] = toJson(m.componentsD2);
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

  return kOk;
}

void printTable(const std::vector<Model>& models) {
  const Model& original = models[0];
  std::printf("%-12s %5s %5s %9s %9s %14s %14s %9s %9s %9s %14s %14s\n", "model", "comp", "parts", "ACD nodes",
              "ACD n(D2)", "ACD D", "ACD D2", "by verts", "MCF nodes", "MCF n(D2)", "MCF D", "MCF D2");
  for (std::size_t i = 0; i < models.size(); ++i) {
    const Model& m = models[i];
    const bool mcf = m.mcfOk && original.mcfOk;
    const std::string byVertices =
        i && m.sharesVertices ? std::to_string(m.correspondenceD) + "/" + std::to_string(m.correspondenceD2) : "-";
    std::printf("%-12s %5d %5d %9d %9d %14s %14s %9s %9s %9s %14s %14s\n", m.name.c_str(), m.components, m.parts,
                m.acd.nodeCount(), m.acdContracted.nodeCount(), i ? distanceCell(m.d).c_str() : "-",
                i ? distanceCell(m.d2).c_str() : "-", byVertices.c_str(),
                m.mcfOk ? std::to_string(m.mcf.nodeCount()).c_str() : "-",
                m.mcfOk ? std::to_string(m.mcfContracted.nodeCount()).c_str() : "-",
                i && mcf ? distanceCell(m.mcfD).c_str() : "-", i && mcf ? distanceCell(m.mcfD2).c_str() : "-");
  }
  if (original.hasSecond)
    std::printf("%-12s %5s %5s %9s %9s %14s %14s %9s %9d %9s %14s %14s\n", "orig. run 2", "", "", "", "", "", "", "",
                original.mcfSecond.nodeCount(), "", distanceCell(original.runD).c_str(),
                distanceCell(original.runD2).c_str());
  std::printf(
      "ACD: the skeleton of parts (components merged across cuts through tubes). D: graph edit distance to\n"
      "the original's skeleton (unit costs); D2: degree-2 nodes contracted; by verts: D/D2 of the edit path\n"
      "that matches parts by the mesh vertices they share (deformations keep them).\n"
      "A value with [>=L] is the bipartite upper bound with lower bound L; others are exact.\n");
}

}  // namespace skeleton
