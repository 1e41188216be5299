// Simulator-ready output of `acd decompose`; see simulator.hpp.
#include "simulator.hpp"

#include "exit_codes.hpp"

#include <acd/algo/mass_properties.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace acdcli {

using json = nlohmann::json;

namespace {

int bad(const std::string& message) {
  std::fprintf(stderr, "acd: invalid parameter: %s\n", message.c_str());
  return kBadParameter;
}

std::vector<acd::TriMesh> componentMeshes(const acd::Decomposition& d) {
  std::vector<acd::TriMesh> meshes;
  for (const acd::Component& c : d.components) meshes.push_back(c.mesh);
  return meshes;
}

}  // namespace

void addSimulatorOptions(CLI::App& dec, SimulatorArgs& a) {
  a.tauOption = dec.get_option("--tau");
  dec.add_option("--tau-abs", a.tauAbs,
                 "Concavity tolerance as a length in the input's units (instead of -t; the report shows both)");
  dec.add_option("--max-hulls", a.maxHulls,
                 "After decomposing, merge components (least added concavity first) until at most N remain");
  dec.add_option("--max-hull-vertices", a.maxHullVertices,
                 "Replace every hull by a convex polytope of at most K >= 4 vertices that contains its component");
  dec.add_option("--density", a.density, "Density for the mass properties (mass per input unit cubed)")
      ->capture_default_str();
  dec.add_option("--format", a.formats,
                 "Simulator files, several allowed: obj, stl (one file per hull), glb, gltf, urdf, mjcf, sdf")
      ->delimiter(',');
}

bool simulatorRequested(const SimulatorArgs& a) {
  return a.tauAbs >= 0 || a.maxHulls != 0 || a.maxHullVertices != 0 || !a.formats.empty();
}

int validateSimulatorArgs(SimulatorArgs& a, const CLI::App& dec) {
  if (dec.count("--tau-abs") > 0 && a.tauOption != nullptr && a.tauOption->count() > 0)
    return bad("give either -t/--tau or --tau-abs, not both");
  // Only the options given: --max-hulls 0 is refused, an absent --max-hulls is no budget.
  a.post = acd::PostPassOptions{};
  if (dec.count("--tau-abs") > 0) a.post.tauAbs = a.tauAbs;
  if (dec.count("--max-hulls") > 0) a.post.maxHulls = a.maxHulls;
  if (dec.count("--max-hull-vertices") > 0) a.post.maxHullVertices = a.maxHullVertices;
  a.post.density = a.density;
  if (const acd::Status s = acd::validate(a.post); !s.ok()) return bad(s.message);
  a.parsed.clear();
  for (const std::string& f : a.formats) {
    acd::SimFormat sf;
    if (!acd::parseSimFormat(f, sf))
      return bad("unknown --format '" + f + "' (expected obj, stl, glb, gltf, urdf, mjcf or sdf)");
    if (std::find(a.parsed.begin(), a.parsed.end(), sf) == a.parsed.end()) a.parsed.push_back(sf);
  }
  return kOk;
}

int resolveTauAbs(const SimulatorArgs& a, const acd::TriMesh& mesh, acd::DecomposeOptions& options) {
  const acd::Status s = acd::resolveTauAbs(mesh, a.post, options);
  return s.ok() ? kOk : bad(s.message);
}

int applyPostPasses(const SimulatorArgs& a, acd::Decomposition& d, bool quiet, acd::PostPassResult& r) {
  r = acd::applyPostPasses(d, a.post);
  if (!r.status.ok())  // the message names the option that failed
    return fail(r.status.code == acd::StatusCode::InternalError ? "internal error" : "", r.status);
  if (r.budget) {
    const acd::HullBudgetSummary& b = *r.budget;
    if (b.exceedsTau && b.after < b.before)
      std::fprintf(stderr,
                   "acd: note: --max-hulls %d: merging %d components into %d reached concavity %.4g, above tau = %g "
                   "(report.json, hull_budget)\n",
                   b.maxHulls, b.before, b.after, b.maxConcavity, b.tau);
    else if (!quiet && b.after < b.before)
      std::fprintf(stderr, "acd: --max-hulls %d: %d components merged into %d, concavity %.4g (tau %g)\n", b.maxHulls,
                   b.before, b.after, b.maxConcavity, b.tau);
  }
  return kOk;
}

int writeSimulatorOutputs(const SimulatorArgs& a, const acd::Decomposition& d, const acd::TriMesh& input,
                          const std::string& modelPath, const std::string& out, json& report) {
  if (a.parsed.empty()) return kOk;
  acd::SimulatorModel m;
  m.name = acd::simulatorName(std::filesystem::path(modelPath).stem().string());
  m.visual = input;  // as read: the components' union would carry every cut face twice
  for (const acd::Component& c : d.components) m.hulls.push_back(c.hull);
  m.mass = acd::massProperties(componentMeshes(d), a.density);
  std::vector<std::string> written;
  const acd::Status s = acd::writeSimulatorFiles(out, m, a.parsed, &written);
  if (!s.ok()) return (void)fail("output", s), kOutputFailed;
  json formats = json::array();
  for (acd::SimFormat f : a.parsed) formats.push_back(acd::toString(f));
  report["outputs"] = {{"formats", formats}, {"files", written}};
  return kOk;
}

}  // namespace acdcli
