#include <acd/report.hpp>
#include <acd/version.hpp>
#include <acd/algo/parallel.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace acd {

using json = nlohmann::json;

namespace {

const char* const kUnits = "normalised: minimum enclosing sphere radius 1";

json vec(const Vec3& v) { return json::array({v.x(), v.y(), v.z()}); }

json matrix(const Eigen::Matrix3d& m) {
  json rows = json::array();
  for (int r = 0; r < 3; ++r) rows.push_back(json::array({m(r, 0), m(r, 1), m(r, 2)}));
  return rows;
}

json normalizationJson(const Normalization& n) {
  return {{"center", {n.center.x(), n.center.y(), n.center.z()}}, {"scale", n.scale}, {"rotation", matrix(n.rotation)}};
}

/// The "input" section of the exact baselines' reports; notches < 0: not counted (open mesh).
json exactInputJson(const MeshDiagnosis& d, int notches) {
  return {{"vertices", d.vertices},
          {"faces", d.faces},
          {"edges", d.edges},
          {"boundary_edges", d.boundaryEdges},
          {"reflex_edges", notches},
          {"notch_fraction", notches >= 0 && d.edges > 0 ? double(notches) / d.edges : 0.0},
          {"genus", d.genus},
          {"volume", d.closed ? d.volume : 0.0}};
}

std::string text(const json& j) { return j.dump(2) + "\n"; }

}  // namespace

ReportInput describeInput(const std::string& model, const TriMesh& mesh, int threads) {
  ReportInput in;
  in.model = model;
  in.diagnosis = diagnose(mesh);
  workerArena(threads).execute([&] { in.selfIntersections = countSelfIntersections(mesh); });
  return in;
}

namespace {

json solidReport(const ReportInput& in, const Decomposition& d) {
  json j;
  j["model"] = in.model;
  if (!in.mesh.empty()) j["mesh"] = in.mesh;
  j["version"] = ACD_VERSION;
  j["parameters"] = {{"tau", d.options.tau},
                     {"epsilon", d.options.epsilon},
                     {"delta", d.options.delta},
                     {"feature_grouping", d.options.featureGrouping},
                     {"cut_at_notch_only", d.options.cutAtNotchOnly},
                     {"merge", d.options.merge},
                     {"merge_scope", d.options.mergeScope == MergeScope::Model ? "model" : "component"},
                     {"invariant", d.options.invariant},
                     {"working_share", d.options.workingShare},
                     {"working_from_faces", d.options.workingFromFaces},
                     {"threads", d.options.threads},
                     {"units", kUnits}};
  const int edges = d.stats.inputEdges;
  j["input"] = {{"vertices", in.diagnosis.vertices},
                {"faces", in.diagnosis.faces},
                {"edges", edges},
                {"notches", d.stats.inputNotches},
                {"notch_fraction", edges > 0 ? double(d.stats.inputNotches) / edges : 0.0},
                {"volume", d.stats.inputVolume},
                {"genus", in.diagnosis.genus},
                {"self_intersecting_face_pairs", in.selfIntersections},
                {"normalization", normalizationJson(d.normalization)},
                {"repairs", d.repairs},
                {"holes_filled", d.stats.holesFilled},
                {"working_mesh", {{"faces", d.stats.workingFaces}, {"distance", d.stats.workingDistance}}},
                {"wrap", {{"used", d.wrap.used},
                          {"reason", d.wrap.reason},
                          {"wrapped_pieces", d.wrap.wrappedPieces},
                          {"alpha", d.wrap.alpha},
                          {"offset", d.wrap.offset},
                          {"hausdorff", d.wrap.hausdorff},
                          {"wrap_to_input", d.wrap.wrapToInput},
                          {"input_to_wrap", d.wrap.inputToWrap},
                          {"faces", d.wrap.faces}}}};
  json comps = json::array();
  double volume = 0, hullVolume = 0, maxConcavity = 0, maxExcess = 0;
  int unresolved = 0;
  for (std::size_t i = 0; i < d.components.size(); ++i) {
    const auto& c = d.components[i];
    comps.push_back({{"id", i},
                     {"volume", c.volume},
                     {"hull_volume", c.hullVolume},
                     {"concavity", c.concavity},
                     {"hull_excess", c.hullExcess},
                     {"vertices", c.mesh.vertices.size()},
                     {"faces", c.mesh.faces.size()},
                     {"hull_vertices", c.hull.vertices.size()},
                     {"hull_faces", c.hull.faces.size()},
                     {"depth", c.depth},
                     {"source_piece", c.source},
                     {"unresolved", c.unresolved},
                     {"of", c.ofWrap ? "wrap" : "input"}});
    if (c.unresolved) comps.back()["note"] = c.note;
    volume += c.volume;
    hullVolume += c.hullVolume;
    maxConcavity = std::max(maxConcavity, c.concavity);
    maxExcess = std::max(maxExcess, c.hullExcess);
    unresolved += c.unresolved;
  }
  j["components"] = comps;
  j["totals"] = {{"components", d.components.size()},
                 {"volume", volume},
                 {"hull_volume", hullVolume},
                 {"volume_relative_error", d.stats.inputVolume > 0 ? std::abs(volume - d.stats.inputVolume) / d.stats.inputVolume : 0.0},
                 {"max_concavity", maxConcavity},
                 {"max_hull_excess", maxExcess},
                 {"unresolved", unresolved},
                 {"cuts", d.stats.cuts},
                 {"fallback_cuts", d.stats.fallbackCuts},
                 {"rejected_planes", d.stats.failedCuts},
                 {"bridges_measured", d.stats.bridges},
                 {"bridge_refinements", d.stats.refinements},
                 {"merges", d.stats.merges}};
  if (in.inputOutside >= 0.0) j["totals"]["input_outside_hulls"] = in.inputOutside;
  if (in.hullOffInput.size() == d.components.size() && !d.components.empty()) {
    for (std::size_t i = 0; i < d.components.size(); ++i) j["components"][i]["hull_excess_input"] = in.hullOffInput[i];
    j["totals"]["max_hull_excess_input"] = *std::max_element(in.hullOffInput.begin(), in.hullOffInput.end());
  }
  j["timing"] = {{"prepare_seconds", d.times.prepare},
                 {"repair_seconds", d.repairSeconds},
                 {"wrap_seconds", d.wrap.seconds},
                 {"concavity_cpu_seconds", d.times.concavity},
                 {"grouping_cpu_seconds", d.times.grouping},
                 {"cutting_cpu_seconds", d.times.cutting},
                 {"merging_seconds", d.times.merging},
                 {"hulls_seconds", d.times.hulls},
                 {"total_seconds", d.times.total}};
  if (in.promiseSeconds >= 0.0) j["timing"]["promise_check_seconds"] = in.promiseSeconds;
  return j;
}

/// The sections of the post-passes, and their fields of each component, added to `j`.
void addPostPasses(json& j, const Decomposition& d, const PostPassResult& p) {
  const double radius = 1.0 / d.normalization.scale;  // one normalised unit in input units
  if (p.tauAbs)
    j["tau_abs"] = {{"given", *p.tauAbs}, {"tau", d.options.tau}, {"tau_input_units", d.options.tau * radius},
                    {"normalised_unit_in_input_units", radius}};
  if (p.budget) {
    const HullBudgetSummary& b = *p.budget;
    j["hull_budget"] = {{"max_hulls", b.maxHulls},
                        {"components_before", b.before},
                        {"components_after", b.after},
                        {"glued_merges", b.gluedMerges},
                        {"joined_merges", b.joinedMerges},
                        {"max_concavity", b.maxConcavity},
                        {"max_concavity_input_units", b.maxConcavity * radius},
                        {"tau", b.tau},
                        {"exceeds_tau", b.exceedsTau},
                        {"seconds", b.seconds}};
  }
  if (p.cap) {
    const HullVertexCapSummary& c = *p.cap;
    j["hull_vertex_cap"] = {{"max_hull_vertices", c.maxHullVertices},
                            {"hulls", c.hulls},
                            {"within_cap", c.withinCap},
                            {"unchanged", c.unchanged},
                            {"most_vertices", c.mostVertices},
                            {"uncapped_hull_volume", c.uncappedHullVolume},
                            {"added_volume", c.addedVolume},
                            {"added_volume_input_units", c.addedVolume * std::pow(radius, 3)},
                            {"added_relative", c.uncappedHullVolume > 0 ? c.addedVolume / c.uncappedHullVolume : 0.0},
                            {"units", "normalised (volumes); see normalization"}};
  }
  j["mass_properties"] = {{"units", "input units; mass = density x volume"},
                          {"density", p.density},
                          {"volume", p.mass.volume},
                          {"mass", p.mass.mass},
                          {"center_of_mass", vec(p.mass.centerOfMass)},
                          {"inertia_about_center_of_mass", matrix(p.mass.inertia)},
                          {"principal_moments", vec(p.mass.principalMoments)}};
  json& components = j["components"];
  for (std::size_t i = 0; i < p.components.size() && i < components.size(); ++i) {
    const ComponentPostPass& c = p.components[i];
    json& out = components[i];
    if (c.hullGapMeasure) {
      out["merged_from"] = c.mergedFrom;
      out["concavity_measure"] = *c.hullGapMeasure ? "hull_gap" : "concavity";
    }
    if (c.uncappedHullVertices) out["uncapped_hull_vertices"] = *c.uncappedHullVertices;
    if (c.uncappedHullVolume) out["uncapped_hull_volume"] = *c.uncappedHullVolume;
    if (c.addedVolume) out["added_volume"] = *c.addedVolume;
  }
}

}  // namespace

std::string reportJson(const ReportInput& in, const Decomposition& d) { return text(solidReport(in, d)); }

std::string reportJson(const ReportInput& in, const Decomposition& d, const PostPassResult& post) {
  json j = solidReport(in, d);
  addPostPasses(j, d, post);
  return text(j);
}

std::string reportJson(const ReportInput& in, const SurfaceDecomposition& d, std::uintmax_t outputBytes) {
  const auto& o = d.options;
  json j;
  j["model"] = in.model;
  j["version"] = ACD_VERSION;
  j["method"] = "surface ACD";
  j["parameters"] = {{"tau", o.tau},
                     {"epsilon", o.epsilon},
                     {"delta", o.delta},
                     {"feature_grouping", o.featureGrouping},
                     {"merge", o.merge},
                     {"threads", o.threads},
                     {"units", kUnits}};
  const int edges = d.stats.inputEdges;
  j["input"] = {{"vertices", in.diagnosis.vertices},
                {"faces", in.diagnosis.faces},
                {"edges", edges},
                {"boundary_edges", d.stats.boundaryEdges},
                {"notches", d.stats.inputNotches},
                {"notch_fraction", edges > 0 ? double(d.stats.inputNotches) / edges : 0.0},
                {"area", d.stats.inputArea},
                {"genus", in.diagnosis.genus},
                {"concave_hull_vertices", d.stats.concaveHullVertices},
                {"self_intersecting_face_pairs", in.selfIntersections},
                {"normalization", normalizationJson(d.normalization)},
                {"repairs", d.repairs}};
  json comps = json::array();
  double maxConcavity = 0, area = 0;
  int unresolved = 0;
  for (std::size_t i = 0; i < d.patches.size(); ++i) {
    const auto& p = d.patches[i];
    comps.push_back({{"id", i},
                     {"faces", p.faces.size()},
                     {"vertices", p.mesh.vertices.size()},
                     {"area", p.area},
                     {"concavity", p.concavity},
                     {"hull_vertices", p.hull.vertices.size()},
                     {"hull_faces", p.hull.faces.size()},
                     {"depth", p.depth},
                     {"source_piece", p.source},
                     {"unresolved", p.unresolved}});
    if (p.unresolved) comps.back()["note"] = p.note;
    maxConcavity = std::max(maxConcavity, p.concavity);
    area += p.area;
    unresolved += p.unresolved;
  }
  j["components"] = comps;
  j["totals"] = {{"finished", true},
                 {"components", d.patches.size()},
                 {"area", area},
                 {"max_concavity", maxConcavity},
                 {"unresolved", unresolved},
                 {"splits", d.stats.splits},
                 {"global_cut_splits", d.stats.globalCutSplits},
                 {"plane_splits", d.stats.planeSplits},
                 {"geodesic_splits", d.stats.geodesicSplits},
                 {"merges", d.stats.merges},
                 {"output_bytes", outputBytes}};
  j["timing"] = {{"prepare_seconds", d.times.prepare},
                 {"concavity_cpu_seconds", d.times.concavity},
                 {"splitting_cpu_seconds", d.times.splitting},
                 {"merging_seconds", d.times.merging},
                 {"hulls_seconds", d.times.hulls},
                 {"total_seconds", d.times.total}};
  return text(j);
}

std::string reportJson(const std::string& model, const MeshDiagnosis& diagnosis, const ExactDecomposition& d,
                       double timeLimitSeconds, double memoryGiB, std::uintmax_t outputBytes) {
  double volume = 0;
  json pieces = json::array();
  for (std::size_t i = 0; i < d.pieces.size(); ++i) {
    const double v = signedVolume(d.pieces[i]);
    volume += v;
    pieces.push_back({{"id", i}, {"vertices", d.pieces[i].vertices.size()}, {"faces", d.pieces[i].faces.size()}, {"volume", v}});
  }
  const double inputVolume = diagnosis.volume;
  json j;
  j["model"] = model;
  j["version"] = ACD_VERSION;
  j["method"] = "solid ECD (CGAL convex_decomposition_3 on an exact Nef polyhedron)";
  j["parameters"] = {{"time_limit_seconds", timeLimitSeconds}, {"memory_limit_gib", memoryGiB}};
  j["input"] = exactInputJson(diagnosis, d.reflexEdges);
  j["input"]["holes_filled"] = d.holesFilled;
  j["input"]["repairs"] = d.repairs;
  j["pieces"] = pieces;
  j["totals"] = {{"finished", d.finished},
                 {"components", d.pieceCount},
                 {"components_written", d.pieces.size()},
                 {"solids", d.solids},
                 {"unfinished_solids", d.unfinishedSolids},
                 {"volume", volume},
                 {"volume_relative_error", d.finished && inputVolume > 0 ? std::abs(volume - inputVolume) / inputVolume : 0.0},
                 {"output_bytes", outputBytes},
                 {"note", d.note}};
  j["timing"] = {{"total_seconds", d.seconds}};
  return text(j);
}

std::string reportJson(const std::string& model, const TriMesh& mesh, const MeshDiagnosis& diagnosis,
                       const SurfaceExactDecomposition& d, const std::vector<TriMesh>& patches, double tolerance,
                       std::uintmax_t outputBytes) {
  json list = json::array();
  std::size_t largest = 0, singles = 0;
  double area = 0;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    const double a = surfaceArea(patches[i]);
    area += a;
    largest = std::max(largest, d.patches[i].size());
    singles += d.patches[i].size() == 1;
    list.push_back({{"id", i}, {"faces", d.patches[i].size()}, {"vertices", patches[i].vertices.size()}, {"area", a}});
  }
  json j;
  j["model"] = model;
  j["version"] = ACD_VERSION;
  j["method"] = "surface ECD (flood-and-retract convex patches)";
  j["parameters"] = {{"tolerance", tolerance}, {"units", kUnits}};
  j["input"] = exactInputJson(diagnosis, diagnosis.closed ? countNotches(mesh) : -1);
  j["patches"] = list;
  j["totals"] = {{"finished", true},
                 {"components", d.patches.size()},
                 {"single_face_patches", singles},
                 {"largest_patch_faces", largest},
                 {"area", area},
                 {"input_area", diagnosis.area},
                 {"output_bytes", outputBytes}};
  j["timing"] = {{"total_seconds", d.seconds}};
  return text(j);
}

std::string evaluationJson(const std::string& model, const std::string& hullsFile, const Evaluation& e) {
  const json j = {{"model", model},
                  {"hulls_file", hullsFile},
                  {"hulls", e.hulls},
                  {"model_volume", e.modelVolume},
                  {"union_volume", e.unionVolume},
                  {"union_volume_stderr", e.unionVolumeStdErr},
                  {"union_to_model", e.unionToModelRatio},
                  {"misclassified_share", e.misclassifiedShare},
                  {"iou", e.iou},
                  {"iou_stderr", e.iouStdErr},
                  {"hull_outside_max", e.hullOutsideMax},
                  {"hull_outside_mean", e.hullOutsideMean},
                  {"model_to_hulls_max", e.modelToHullsMax},
                  {"model_to_hulls_mean", e.modelToHullsMean},
                  {"seconds", e.seconds}};
  return text(j);
}

}  // namespace acd
