// Simulator-ready output of `acd decompose`; see simulator.hpp.
#include "simulator.hpp"

#include "exit_codes.hpp"

#include <acd/diagnosis.hpp>
#include <acd/hull_budget.hpp>
#include <acd/hull_vertex_cap.hpp>
#include <acd/mass_properties.hpp>
#include <acd/normalize.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace acdcli {

using json = nlohmann::json;

namespace {

json vec(const acd::Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

json matrix(const Eigen::Matrix3d& m) {
  json rows = json::array();
  for (int r = 0; r < 3; ++r) rows.push_back(json::array({m(r, 0), m(r, 1), m(r, 2)}));
  return rows;
}

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
  if (dec.count("--tau-abs") > 0) {
    if (a.tauOption != nullptr && a.tauOption->count() > 0) return bad("give either -t/--tau or --tau-abs, not both");
    if (!(a.tauAbs > 0) || !std::isfinite(a.tauAbs)) return bad("--tau-abs must be a positive length");
  }
  if (dec.count("--max-hulls") > 0 && a.maxHulls < 1)
    return bad("--max-hulls must be at least 1, got " + std::to_string(a.maxHulls));
  if (dec.count("--max-hull-vertices") > 0 && a.maxHullVertices < 4)
    return bad("--max-hull-vertices must be at least 4 (a solid needs 4 corners), got " +
               std::to_string(a.maxHullVertices));
  if (!(a.density > 0) || !std::isfinite(a.density)) return bad("--density must be positive");
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
  if (a.tauAbs < 0) return kOk;
  // Normalised as decompose() does it: the repaired pieces' minimum enclosing sphere.
  acd::PrepareOptions po;
  po.openMeshes = options.fillHoles ? acd::OpenMeshPolicy::FillHoles : acd::OpenMeshPolicy::Refuse;
  const acd::PreparedSolid p = acd::prepareSolid(mesh, po);
  if (!p.status.ok()) return kOk;  // decompose() reports it
  acd::TriMesh all;
  for (const acd::TriMesh& c : p.components) {
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), c.vertices.begin(), c.vertices.end());
    for (const acd::Face& f : c.faces) all.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  const double scale = acd::minimumSphereNormalization(all).scale;
  options.tau = a.tauAbs * scale;
  if (options.tau < 1e-4 || options.tau > 2.0) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "--tau-abs %g is tau = %g in normalised units (radius %g), outside [1e-4, 2]",
                  a.tauAbs, options.tau, 1.0 / scale);
    return bad(msg);
  }
  return kOk;
}

int applyPostPasses(const SimulatorArgs& a, acd::Decomposition& d, bool quiet, json& report,
                    std::vector<json>& perComponent) {
  const double radius = 1.0 / d.normalization.scale;  // one normalised unit in input units
  if (a.tauAbs >= 0)
    report["tau_abs"] = {{"given", a.tauAbs}, {"tau", d.options.tau}, {"tau_input_units", d.options.tau * radius},
                         {"normalised_unit_in_input_units", radius}};

  if (a.maxHulls > 0) {
    acd::HullBudgetOptions bo;
    bo.maxHulls = a.maxHulls;
    bo.threads = d.options.threads;
    const acd::HullBudgetReport b = acd::limitHullCount(d, bo);
    if (!b.status.ok()) return fail("--max-hulls", b.status);
    report["hull_budget"] = {{"max_hulls", a.maxHulls},
                             {"components_before", b.before},
                             {"components_after", b.after},
                             {"glued_merges", b.gluedMerges},
                             {"joined_merges", b.joinedMerges},
                             {"max_concavity", b.maxConcavity},
                             {"max_concavity_input_units", b.maxConcavity * radius},
                             {"tau", b.tau},
                             {"exceeds_tau", b.exceedsTau},
                             {"seconds", b.seconds}};
    perComponent.assign(d.components.size(), json::object());
    for (std::size_t i = 0; i < d.components.size(); ++i) {
      perComponent[i]["merged_from"] = b.members[i];
      perComponent[i]["concavity_measure"] = b.hullGapMeasure[i] ? "hull_gap" : "concavity";
    }
    if (b.exceedsTau && b.after < b.before)
      std::fprintf(stderr,
                   "acd: note: --max-hulls %d: merging %d components into %d reached concavity %.4g, above tau = %g "
                   "(report.json, hull_budget)\n",
                   a.maxHulls, b.before, b.after, b.maxConcavity, b.tau);
    else if (!quiet && b.after < b.before)
      std::fprintf(stderr, "acd: --max-hulls %d: %d components merged into %d, concavity %.4g (tau %g)\n", a.maxHulls,
                   b.before, b.after, b.maxConcavity, b.tau);
  }
  perComponent.resize(d.components.size(), json::object());

  if (a.maxHullVertices > 0) {
    std::vector<acd::TriMesh> hulls;
    for (const acd::Component& c : d.components) hulls.push_back(c.hull);
    acd::HullCapOptions co;
    co.maxVertices = a.maxHullVertices;
    const acd::CappedHulls capped = acd::capHullVertices(hulls, co);
    if (!capped.status.ok()) return fail("--max-hull-vertices", capped.status);
    const double cube = std::pow(d.normalization.scale, 3);  // input volume -> normalised volume
    double exact = 0, added = 0;
    int most = 0;
    for (std::size_t i = 0; i < d.components.size(); ++i) {
      acd::Component& c = d.components[i];
      perComponent[i]["uncapped_hull_vertices"] = c.hull.vertices.size();
      perComponent[i]["uncapped_hull_volume"] = c.hullVolume;
      perComponent[i]["added_volume"] = capped.addedVolume[i] * cube;
      exact += c.hullVolume;
      added += capped.addedVolume[i] * cube;
      c.hull = capped.hulls[i];
      c.hullVolume = capped.hulls[i].empty() ? 0.0 : acd::signedVolume(capped.hulls[i]) * cube;
      most = std::max(most, capped.vertices[i]);
    }
    report["hull_vertex_cap"] = {{"max_hull_vertices", a.maxHullVertices},
                                 {"hulls", d.components.size()},
                                 {"within_cap", capped.reached},
                                 {"unchanged", capped.unchanged},
                                 {"most_vertices", most},
                                 {"uncapped_hull_volume", exact},
                                 {"added_volume", added},
                                 {"added_volume_input_units", added * std::pow(radius, 3)},
                                 {"added_relative", exact > 0 ? added / exact : 0.0},
                                 {"units", "normalised (volumes); see normalization"}};
    if (capped.reached != static_cast<int>(d.components.size())) {
      std::fprintf(stderr, "acd: internal error: %d hulls above %d vertices after the cap\n",
                   static_cast<int>(d.components.size()) - capped.reached, a.maxHullVertices);
      return kInternal;
    }
  }

  const acd::MassProperties mp = acd::massProperties(componentMeshes(d), a.density);
  report["mass_properties"] = {{"units", "input units; mass = density x volume"},
                               {"density", a.density},
                               {"volume", mp.volume},
                               {"mass", mp.mass},
                               {"center_of_mass", vec(mp.centerOfMass)},
                               {"inertia_about_center_of_mass", matrix(mp.inertia)},
                               {"principal_moments", vec(mp.principalMoments)}};
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
