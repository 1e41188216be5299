#include "report.hpp"

#include "deformation_files.hpp"
#include "mesh_quality.hpp"

#include <algorithm>
#include <appcli/exit_codes.hpp>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <string>

namespace tetmesh {

using json = nlohmann::json;
using appcli::kOutputFailed;

namespace {

json qualityJson(const MeshQuality& q) {
  json hist = json::array();
  for (std::size_t b = 0; b < q.radiusEdgeHistogram.size(); ++b)
    hist.push_back({{"upto", b < kRadiusEdgeBins.size() ? json(kRadiusEdgeBins[b]) : json(nullptr)},
                    {"tets", q.radiusEdgeHistogram[b]}});
  return {{"tets", q.tets},
          {"vertices", q.points},
          {"volume", q.volume},
          {"non_positive_tets", q.nonPositiveTets},
          {"min_dihedral_deg", q.minDihedral},
          {"tets_below_5_deg", q.slivers},
          {"max_dihedral_deg", q.maxDihedral},
          {"radius_edge", {{"min", q.minRadiusEdge}, {"median", q.medianRadiusEdge}, {"max", q.maxRadiusEdge}}},
          {"radius_edge_histogram", hist}};
}

std::string histogramLine(const MeshQuality& q) {
  std::string s;
  char buf[64];
  for (std::size_t b = 0; b < q.radiusEdgeHistogram.size(); ++b) {
    const double share = q.tets > 0 ? 100.0 * q.radiusEdgeHistogram[b] / q.tets : 0.0;
    if (b < kRadiusEdgeBins.size())
      std::snprintf(buf, sizeof buf, "%s<=%g: %.1f%%", b ? ", " : "", kRadiusEdgeBins[b], share);
    else
      std::snprintf(buf, sizeof buf, ", >%g: %.1f%%", kRadiusEdgeBins.back(), share);
    s += buf;
  }
  return s;
}

void printColumns(const char* name, const std::string& a, const std::string& b, bool two) {
  if (two)
    std::printf("  %-22s %-22s %s\n", name, a.c_str(), b.c_str());
  else
    std::printf("  %-22s %s\n", name, a.c_str());
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

/// The figures both the summary and the JSON give.
/// How much a component's meshed region holds beyond the component itself, relative to the
/// component (the hulls stand off the model by up to tau by design; simplification adds more).
double overshootOf(const HullMeshResult& r, int i) {
  const double component = acd::signedVolume(r.decomposition.components[i].mesh);
  const double region = i < static_cast<int>(r.meshedVolume.size()) ? r.meshedVolume[i] : 0.0;
  return component > 0 ? region / component - 1.0 : 0.0;
}

/// One line: the median and the largest overshoot over the components, and which is largest.
void printOvershoot(const HullMeshResult& r) {
  const int n = static_cast<int>(r.decomposition.components.size());
  if (n == 0 || static_cast<int>(r.meshedVolume.size()) < n) return;
  std::vector<double> all;
  int worst = 0;
  for (int i = 0; i < n; ++i) {
    all.push_back(overshootOf(r, i));
    if (all[i] > all[worst]) worst = i;
  }
  std::vector<double> sorted = all;
  std::sort(sorted.begin(), sorted.end());
  std::printf("  overshoot      tets beyond their component: median %+.1f%%, largest %+.1f%% (component %d); per component: --json\n",
              100 * sorted[n / 2], 100 * all[worst], worst + 1);
}

struct Figures {
  int unresolved = 0;
  int n = 0;  // components (hulls)
  int hullVerts = 0, simpleVerts = 0;
  double volErr = 0.0, directErr = 0.0;  // tet volume against the model's, relative
};

Figures figuresOf(const HullMeshResult& r, const DirectMeshResult& direct) {
  Figures f;
  for (const acd::Component& c : r.decomposition.components) f.unresolved += c.unresolved ? 1 : 0;
  f.n = static_cast<int>(r.hulls.size());
  for (int i = 0; i < f.n; ++i) f.hullVerts += r.hullVertices[i], f.simpleVerts += static_cast<int>(r.hulls[i].vertices.size());
  f.volErr = r.modelVolume > 0 ? (r.quality.volume - r.modelVolume) / r.modelVolume : 0.0;
  f.directErr = r.modelVolume > 0 && direct.status.ok() ? (direct.quality.volume - r.modelVolume) / r.modelVolume : 0.0;
  return f;
}

}  // namespace

void printReport(const Args& a, TetFormat format, const HullMeshResult& r, const DirectMeshResult& direct,
                 const DeformationResult& deformed) {
  const Figures figures = figuresOf(r, direct);
  const int unresolved = figures.unresolved, n = figures.n, hullVerts = figures.hullVerts,
            simpleVerts = figures.simpleVerts;
  const double volErr = figures.volErr, directErr = figures.directErr;

  std::printf("%s\n", a.model.c_str());
  std::printf("  decomposition  tau %g, %d components%s, %.3f s\n", a.options.tau, n,
              a.options.merge ? " (with merge pass)" : " (no merge pass)", r.times.decompose);
  if (unresolved > 0) std::printf("  warning        %d components still exceed tau (see acd decompose)\n", unresolved);
  if (r.simplifyFallback)
    std::printf("  hulls          %d vertices; TetGen refused every complex of the hulls simplified to at most %d\n"
                "                 vertices, so the exact hulls were meshed\n",
                hullVerts, a.options.simplify);
  else if (a.options.simplify > 0)
    std::printf("  hulls          %d vertices, simplified to %d (at most %d each%s; %d hulls could not get there)\n",
                hullVerts, simpleVerts, r.simplifyUsed,
                r.simplifyUsed < a.options.simplify ? ", TetGen refused the larger budgets" : "", r.simplifyMissed);
  else
    std::printf("  hulls          %d vertices\n", hullVerts);
  if (a.options.simplify > 0 && !r.simplifyFallback)
    std::printf("  separation     %d planes keep the simplified hulls apart; %d pairs of exact hulls overlap (cut there)\n",
                r.separatingPlanes, r.overlappingHulls);
  std::printf("  containment    farthest component vertex outside its hull: %.3g, outside its meshed region: %.3g\n",
              r.maxOutside, r.maxOutsideRegion);
  printOvershoot(r);
  if (a.options.mesher == Mesher::Auto) {
    if (r.used == Mesher::Complex)
      std::printf("  mesher         auto: the complex of the exact hulls (every hull has few faces, no tet below %g deg)\n",
                  kSliverDegrees);
    else if (r.complexTried && r.complexSlivers >= 0)
      std::printf("  mesher         auto: the refinement (the complex of the exact hulls had %d tets below %g deg)\n",
                  r.complexSlivers, kSliverDegrees);
    else if (r.complexTried)
      std::printf("  mesher         auto: the refinement (TetGen refused the complex of the exact hulls)\n");
    else
      std::printf("  mesher         auto: the refinement (hulls with many faces, or --clip / --sharp)\n");
  }
  if (r.used == Mesher::Complex) {
    std::printf("  complex        %d touching pairs (%d overlapping, deepest %.3g), %d contact planes, %d interface + %d boundary facets\n",
                r.complex.contactPairs, r.complex.overlappingPairs, r.complex.maxOverlapDepth, r.complex.contactPlanes,
                r.complex.interfaceFacets, r.complex.boundaryFacets);
    std::printf("  TetGen         -%s (complex snapped at %.0e of the half-diagonal", r.tetgen.switches.c_str(), r.toleranceUsed);
    if (!r.refusedComplexes.empty()) std::printf("; %zu complexes refused before", r.refusedComplexes.size());
    std::printf(")\n");
  } else {
    const RefineOptions& o = r.refineOptions;
    std::printf("  refinement     %s; surface within %.3g, facet angle >= %g deg, radius-edge <= %g, gaps below %.3g closed,\n"
                "                 slivers exuded towards %g deg (%ld label queries)\n",
                a.options.clip ? "the components (hull regions clipped to the model)" : "the hull regions", o.facetDistance,
                o.facetAngle, o.radiusEdge, o.closedGap, o.sliverBound, r.refine.labelQueries);
    std::printf("                 %d tets below %g deg after the exudation, %d after moving their corners; "
                "%d times a region missed was meshed again finer\n",
                r.refine.slivers.before, kSliverDegrees, r.refine.slivers.after, r.refine.regionsRefined);
    if (r.coarsened)
      std::printf("  coarsened      %d edge collapses: %d -> %d tets, %d -> %d vertices; dihedral angles kept in [%g, %g] deg,\n"
                  "                 surface points moved off by at most %.3g (allowed %.3g)\n",
                  r.coarsening.collapses, r.coarsening.tetsBefore, r.coarsening.tetsAfter, r.coarsening.pointsBefore,
                  r.coarsening.pointsAfter, r.coarsenOptions.minDihedral, 180.0 - r.coarsenOptions.minDihedral,
                  r.coarsening.farthest, r.coarsenOptions.maxDistance);
    if (o.featureAngle > 0)
      std::printf("                 sharp edges (turning > %g deg) kept: %d segments, %d dropped as too close to others\n",
                  o.featureAngle, r.refine.features, r.refine.featuresDropped);
  }
  const bool two = a.compare;
  if (two) printColumns("", "hulls", "original model", true);
  const std::string directNote = direct.status.ok() ? "" : "not meshed";
  auto col = [&](const std::string& v) { return direct.status.ok() ? v : directNote; };
  printColumns("tets", std::to_string(r.quality.tets), col(std::to_string(direct.quality.tets)), two);
  printColumns("vertices", std::to_string(r.quality.points), col(std::to_string(direct.quality.points)), two);
  printColumns("volume", fmt("%.6g", r.quality.volume), col(fmt("%.6g", direct.quality.volume)), two);
  printColumns("vs model volume", fmt("%+.2f%%", 100 * volErr), col(fmt("%+.2f%%", 100 * directErr)), two);
  printColumns("min dihedral (deg)", fmt("%.2f", r.quality.minDihedral), col(fmt("%.2f", direct.quality.minDihedral)), two);
  printColumns("max dihedral (deg)", fmt("%.2f", r.quality.maxDihedral), col(fmt("%.2f", direct.quality.maxDihedral)), two);
  printColumns("radius-edge median", fmt("%.3f", r.quality.medianRadiusEdge), col(fmt("%.3f", direct.quality.medianRadiusEdge)), two);
  printColumns("radius-edge max", fmt("%.3f", r.quality.maxRadiusEdge), col(fmt("%.3f", direct.quality.maxRadiusEdge)), two);
  printColumns("tets below 5 deg", std::to_string(r.quality.slivers), col(std::to_string(direct.quality.slivers)), two);
  printColumns("meshing time (s)", fmt("%.3f", r.times.tetgen + r.times.refine + r.times.coarsen), col(fmt("%.3f", direct.tetgen.seconds)), two);
  std::printf("  radius-edge    %s\n", histogramLine(r.quality).c_str());
  if (two && direct.status.ok()) std::printf("  (original)     %s\n", histogramLine(direct.quality).c_str());
  if (two && !direct.status.ok()) std::printf("  original model not meshed: %s\n", direct.status.message.c_str());
  std::printf("  time (s)       decompose %.3f, hulls %.3f, complex %.3f, TetGen %.3f, refinement %.3f, coarsening %.3f, quality %.3f\n",
              r.times.decompose, r.times.hulls, r.times.complex, r.times.tetgen, r.times.refine, r.times.coarsen, r.times.quality);
  if (!a.out.empty()) {
    std::printf("  wrote         ");
    for (const std::string& f : tetOutputFiles(a.out, format)) std::printf(" %s", f.c_str());
    std::printf("\n");
  }
  if (!a.deform.dir.empty())
    for (const std::string& line : deformationSummary(deformed)) std::printf("%s\n", line.c_str());
}

int writeJsonReport(const Args& a, const HullMeshResult& r, const DirectMeshResult& direct,
                    const DeformationResult& deformed) {
  const Figures figures = figuresOf(r, direct);
  const int n = figures.n;
  const double volErr = figures.volErr, directErr = figures.directErr;
  if (!a.json.empty()) {
    json comps = json::array();
    for (int i = 0; i < n; ++i)
      comps.push_back({{"label", i + 1},
                       {"hull_vertices", r.hullVertices[i]},
                       {"meshed_hull_vertices", r.hulls[i].vertices.size()},
                       {"component_volume", acd::signedVolume(r.decomposition.components[i].mesh)},
                       {"region_volume", r.regions[i].empty() ? 0.0 : acd::signedVolume(r.regions[i])},
                       {"meshed_volume", r.meshedVolume[i]},
                       {"overshoot", overshootOf(r, i)},
                       {"clipped_volume", i < static_cast<int>(r.complex.clippedVolume.size()) ? r.complex.clippedVolume[i] : 0.0},
                       {"unresolved", r.decomposition.components[i].unresolved}});
    json j = {{"model", a.model},
              {"tau", a.options.tau},
              {"mesher", r.used == Mesher::Refine ? "refine" : "complex"},
              {"mesher_asked", a.options.mesher == Mesher::Auto ? "auto" : a.options.mesher == Mesher::Refine ? "refine" : "complex"},
              {"complex_tried", r.complexTried},
              {"complex_slivers", r.complexSlivers},
              {"clip", a.options.clip},
              {"refinement",
               {{"facet_distance", r.refineOptions.facetDistance},
                {"facet_angle_deg", r.refineOptions.facetAngle},
                {"radius_edge", r.refineOptions.radiusEdge},
                {"closed_gap", r.refineOptions.closedGap},
                {"sliver_bound_deg", r.refineOptions.sliverBound},
                {"slivers_before_repair", r.refine.slivers.before},
                {"slivers_after_repair", r.refine.slivers.after},
                {"regions_refined_again", r.refine.regionsRefined},
                {"sharp_angle_deg", r.refineOptions.featureAngle},
                {"sharp_segments", r.refine.features},
                {"sharp_segments_dropped", r.refine.featuresDropped},
                {"label_queries", r.refine.labelQueries}}},
              {"coarsening",
               {{"done", r.coarsened},
                {"collapses", r.coarsening.collapses},
                {"tets_before", r.coarsening.tetsBefore},
                {"tets_after", r.coarsening.tetsAfter},
                {"vertices_before", r.coarsening.pointsBefore},
                {"vertices_after", r.coarsening.pointsAfter},
                {"min_dihedral_deg", r.coarsenOptions.minDihedral},
                {"max_distance", r.coarsenOptions.maxDistance},
                {"keep_volume", !r.coarsenOptions.minVolume.empty()},
                {"farthest", r.coarsening.farthest}}},
              {"merge", a.options.merge},
              {"simplify", a.options.simplify},
              {"simplify_used", r.simplifyUsed},
              {"separating_planes", r.separatingPlanes},
              {"overlapping_exact_hulls", r.overlappingHulls},
              {"simplify_fallback", r.simplifyFallback},
              {"tetgen_switches", r.tetgen.switches},
              {"snap_tolerance", r.toleranceUsed},
              {"refused_complexes", r.refusedComplexes},
              {"model_volume", r.modelVolume},
              {"components", comps},
              {"complex",
               {{"touching_pairs", r.complex.contactPairs},
                {"overlapping_pairs", r.complex.overlappingPairs},
                {"max_overlap_depth", r.complex.maxOverlapDepth},
                {"contact_planes", r.complex.contactPlanes},
                {"interface_facets", r.complex.interfaceFacets},
                {"boundary_facets", r.complex.boundaryFacets}}},
              {"max_outside", r.maxOutside},
              {"max_outside_region", r.maxOutsideRegion},
              {"hull_mesh", qualityJson(r.quality)},
              {"volume_error", volErr},
              {"seconds",
               {{"decompose", r.times.decompose},
                {"hulls", r.times.hulls},
                {"complex", r.times.complex},
                {"tetgen", r.times.tetgen},
                {"refine", r.times.refine},
                {"coarsen", r.times.coarsen},
                {"quality", r.times.quality}}}};
    if (a.compare) {
      if (direct.status.ok())
        j["original_mesh"] = qualityJson(direct.quality), j["original_mesh"]["seconds"] = direct.seconds,
        j["original_mesh"]["volume_error"] = directErr;
      else
        j["original_mesh"] = {{"error", direct.status.message}};
    }
    if (!a.deform.dir.empty()) j["deformation"] = deformationJson(a.deform, deformed);
    std::ofstream out(a.json);
    out << j.dump(2) << "\n";
    if (!out) {
      return kConsole.failf(kOutputFailed, "%s: cannot write", a.json.c_str());
    }
  }
  return appcli::kOk;
}

}  // namespace tetmesh
