#include "skeleton_run.hpp"

#include <unistd.h>

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>
#include <appcli/exit_codes.hpp>
#include <filesystem>

#include "acd_skeleton.hpp"
#include "correspondence.hpp"
#include "deform.hpp"
#include "mcf_skeleton.hpp"
#include "parts.hpp"

namespace skeleton {

namespace fs = std::filesystem;
using namespace appcli;  // the shared exit codes: a failed deformation is kBadInput

namespace {

const bool kProgress = ::isatty(2) != 0;

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

}  // namespace

void progress(const std::string& line) {
  if (kProgress) kConsole.say(line);
}

int checkParameters(const RunParameters& p) {
  const double tau = p.tau, tubeRadius = p.tubeRadius;
  const int exactMaxNodes = p.exactMaxNodes, mcfRuns = p.mcfRuns, threads = p.threads;
  const long long maxExpansions = p.maxExpansions;
  if (!(tau >= 1e-4 && tau <= 2)) return fail(kBadParameter, "--tau must lie in [1e-4, 2], got " + std::to_string(tau));
  if (exactMaxNodes < 0 || exactMaxNodes > 40) return fail(kBadParameter, "--exact-max-nodes must lie in [0, 40]");
  if (maxExpansions < 1) return fail(kBadParameter, "--max-expansions must be positive");
  if (mcfRuns < 1 || mcfRuns > 100) return fail(kBadParameter, "--mcf-runs must lie in [1, 100]");
  if (threads < 0) return fail(kBadParameter, "--threads must be >= 0");
  if (!(tubeRadius >= 0 && tubeRadius <= 0.1)) return fail(kBadParameter, "--tubes must lie in [0, 0.1]");
  return kOk;
}

int loadModels(const RunParameters& p, std::vector<Model>& models) {
  const std::string& modelPath = p.modelPath;
  models.assign(1, Model{});
  {
    std::string error;
    if (!loadSolid(modelPath, models[0].mesh, models[0].repairs, error)) return fail(kBadInput, error);
    models[0].name = "original";
    models[0].source = modelPath;
  }
  for (const std::string& path : p.deformedPaths) {
    Model m;
    std::string error;
    if (!loadSolid(path, m.mesh, m.repairs, error)) return fail(kBadInput, error);
    m.name = "deformed_" + std::to_string(models.size());
    m.source = path;
    models.push_back(std::move(m));
  }
  // Check every spec before the slow work starts.
  for (const std::string& spec : p.deformSpecs) {
    std::size_t begin = 0;
    for (;;) {  // every step of a sequence
      const std::size_t end = spec.find(';', begin);
      const std::string step = spec.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
      const std::string kind = step.substr(0, step.find(':'));
      if (kind != "bend" && kind != "twist" && kind != "ids" && kind != "affine")
        return fail(kBadParameter,
                    "--deform: unknown deformation '" + kind + "' (expected bend, twist, ids or affine)");
      if (end == std::string::npos) break;
      begin = end + 1;
    }
  }
  return kOk;
}

int makeDeformations(const RunParameters& p, std::vector<Model>& models) {
  const std::string& outDir = p.outDir;
  std::error_code ec;
  fs::create_directories(outDir, ec);
  if (ec) return fail(kOutputFailed, outDir + ": cannot create the output folder: " + ec.message());
  {  // the model as prepared: the mesh whose vertices vertex_parts and the deformations refer to
    const std::string path = (fs::path(outDir) / "original.off").string();
    const acd::Status w = acd::writeMesh(path, models[0].mesh);
    if (!w.ok()) return fail(kOutputFailed, path + ": " + w.message);
  }

  for (const std::string& spec : p.deformSpecs) {
    progress("deforming: " + spec);
    DeformResult r = applyDeformation(models[0].mesh, spec);
    if (!r.ok) {
      const bool specError = r.error.find("needs") != std::string::npos || r.error.find("must") != std::string::npos ||
                             r.error.find("not a number") != std::string::npos ||
                             r.error.find("unknown") != std::string::npos;
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

  return kOk;
}

int decomposeModels(const RunParameters& p, std::vector<Model>& models) {
  const int mcfRuns = p.mcfRuns;
  const bool noMcf = p.noMcf;
  acd::DecomposeOptions options;
  options.tau = p.tau;
  options.threads = p.threads;
  // Skeletons are compared across poses: the decomposition must not change with them (the
  // rounding of input vertices on cut planes, 2.1e-7 of the radius, does not matter here).
  options.invariant = true;
  // One node per component at the centroid of the solid it bounds: a component must be one solid
  // (a merge held to the model may give one hull to touching pieces that do not glue into one).
  options.mergeScope = acd::MergeScope::Component;
  if (const acd::Status s = acd::validate(acd::resolvedOptions(options)); !s.ok())
    return fail(kBadParameter, s.message);

  for (Model& m : models) {
    progress(m.name + ": decomposing");
    const acd::Decomposition d = acd::decompose(m.mesh, options);
    if (!d.status.ok()) return fail(exitFor(d.status), m.source + ": " + d.status.message);
    m.decomposeSeconds = d.times.total;
    std::vector<acd::TriMesh> pieces, hulls;
    for (const acd::Component& c : d.components) {
      pieces.push_back(c.mesh);
      hulls.push_back(c.hull);
      m.unresolved += c.unresolved;
    }
    m.components = static_cast<int>(pieces.size());
    m.components_ = skeletonFromComponents(pieces);
    m.componentsContracted = contractDegreeTwo(m.components_);
    m.genus = genusOf(m.mesh);
    const Parts parts = groupIntoParts(pieces, m.genus, p.handleCycles, kTubeRatio, leastPartShare(p.tau));
    m.parts = static_cast<int>(parts.members.size());
    m.partMembers = parts.members;
    m.partMerges = parts.merges;
    m.droppedAdjacencies = parts.droppedAdjacencies;
    m.loopGrid = parts.loopGrid;
    m.partHandles = parts.handles;
    for (const Joint& j : parts.loopJoints) m.loopJoints.push_back({j.a, j.b});
    m.acd = skeletonFromParts(parts);
    m.acdContracted = contractDegreeTwo(m.acd);
    m.vertexPart = componentOfVertices(m.mesh, pieces, hulls);
    for (int& v : m.vertexPart)
      if (v >= 0) v = parts.partOf[v];
    if (!noMcf) {
      for (int run = 0; run < mcfRuns; ++run) {
        progress(m.name + ": CGAL skeleton, run " + std::to_string(run + 1));
        McfSkeleton s = meanCurvatureSkeleton(m.mesh);
        if (!s.ok) {
          m.mcfError = s.error;
          break;
        }
        m.mcfRunNodes.push_back(s.graph.nodeCount());
        m.mcfRunContracted.push_back(contractDegreeTwo(s.graph));
        m.mcfSeconds += s.seconds;
        if (run == 0) {
          m.mcfOk = true;
          m.mcf = std::move(s.graph);
          m.mcfContracted = m.mcfRunContracted.front();
        } else if (run == 1 && &m == &models[0]) {
          m.mcfSecond = std::move(s.graph);
          m.hasSecond = true;
        }
      }
    }
  }

  return kOk;
}

void compareSkeletons(const RunParameters& p, std::vector<Model>& models) {
  GedOptions ged;
  ged.exactMaxNodes = p.exactMaxNodes;
  ged.maxExpansions = p.maxExpansions;
  ged.mipMaxColumns = p.mipMaxColumns;
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
    m.componentsD = graphEditDistance(m.components_, original.components_, ged);
    m.componentsD2 = graphEditDistance(m.componentsContracted, original.componentsContracted, ged);
    m.sharesVertices = m.mesh.vertices.size() == original.mesh.vertices.size() && m.mesh.faces == original.mesh.faces;
    if (m.sharesVertices) {
      const std::vector<int> map = correspondenceMap(m.acd, m.vertexPart, original.acd, original.vertexPart);
      m.correspondenceD = editPathCost(m.acd, original.acd, map);
      m.partMatch.assign(m.parts, -1);
      for (int node = 0; node < m.acd.nodeCount(); ++node)
        if (m.acd.nodes[node].kind == NodeKind::Component && map[node] >= 0)
          m.partMatch[m.acd.nodes[node].source] = original.acd.nodes[map[node]].source;
      const Contraction ca = contractWithChains(m.acd), cb = contractWithChains(original.acd);
      m.correspondenceD2 = editPathCost(ca.graph, cb.graph, contractedMap(ca, cb, map, original.acd.nodeCount()));
    }
    if (m.mcfOk && original.mcfOk) {
      m.mcfD = graphEditDistance(m.mcf, original.mcf, ged);
      m.mcfD2 = graphEditDistance(m.mcfContracted, original.mcfContracted, ged);
      if (m.mcfRunContracted.size() > 1 || original.mcfRunContracted.size() > 1)
        for (std::size_t i = 0; i < original.mcfRunContracted.size(); ++i)
          for (std::size_t j = 0; j < m.mcfRunContracted.size(); ++j)  // run 1 against run 1 is mcfD2
            m.mcfRunPairsD2.push_back(i + j == 0 ? m.mcfD2
                                                 : graphEditDistance(m.mcfRunContracted[j], original.mcfRunContracted[i], ged));
    }
  }
}

}  // namespace skeleton
