// The tetmesh pipeline; see hull_mesher.hpp.
#include "hull_mesher.hpp"

#include "hull_simplify.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/diagnosis.hpp>
#include <acd/algo/hull.hpp>

#include <cmath>
#include <limits>

namespace tetmesh {

namespace {

/// Gaps between hulls narrower than this times tau (of the half-diagonal) are closed: far below
/// what tau resolves (hulls stand up to tau off the model), and a gap that thin between two
/// regions would give TetGen two faces a hair apart, or a mesh in two pieces where the model is one.
constexpr double kClosedGapPerTau = 1e-3;

}  // namespace

HullMeshResult meshHulls(const acd::TriMesh& model, const HullMeshOptions& options) {
  HullMeshResult r;
  if (options.simplify != 0 && options.simplify < 4) {
    r.status =
        acd::Status::error(acd::StatusCode::InvalidParameter,
                           "--simplify must be at least 4 (a tetrahedron), got " + std::to_string(options.simplify));
    return r;
  }
  auto t0 = acd::Clock::now();
  acd::DecomposeOptions dopt;
  dopt.tau = options.tau;
  dopt.merge = options.merge;
  // The complex needs leaves that lie on one side of every plane that cut their ancestors: their
  // hulls then meet only on those planes. A cut at the notch only leaves a finger whole across it.
  dopt.cutAtNotchOnly = false;
  // The same for merges: the union of two leaves must stay one solid within tau of itself, and
  // the cut planes must pass through the input's own vertices (hulls that meet on a plane).
  dopt.mergeScope = acd::MergeScope::Component;
  dopt.invariant = false;
  dopt.threads = options.threads;
  r.decomposition = acd::decompose(model, dopt);
  r.times.decompose = acd::secondsSince(t0);
  if (!r.decomposition.status.ok()) {
    r.status = r.decomposition.status;
    return r;
  }
  for (const acd::Component& c : r.decomposition.components) r.modelVolume += acd::signedVolume(c.mesh);

  t0 = acd::Clock::now();
  std::vector<acd::TriMesh> exact;
  for (const acd::Component& c : r.decomposition.components) {
    exact.push_back(c.hull.empty() ? acd::hullMesh(c.mesh.vertices) : c.hull);
    r.hullVertices.push_back(static_cast<int>(exact.back().vertices.size()));
  }
  r.times.hulls = acd::secondsSince(t0);

  // TetGen merges points closer than its own tolerance and then trips over the complex; when it
  // refuses one, the complex is rebuilt with a 10 times larger snapping distance (twice at most).
  auto meshComplex = [&](std::vector<acd::TriMesh> hulls) {
    r.hulls = std::move(hulls);
    r.maxOutside = 0.0;
    for (std::size_t i = 0; i < r.hulls.size(); ++i)
      r.maxOutside =
          std::max(r.maxOutside, maxOutsideDistance(r.hulls[i], r.decomposition.components[i].mesh.vertices));
    for (int attempt = 0; attempt < 3 && !r.tetgen.ok; ++attempt) {
      const double tolerance = options.tolerance * std::pow(10.0, attempt);
      t0 = acd::Clock::now();
      HullComplexOptions copt;
      copt.tolerance = tolerance;
      copt.closedGap = kClosedGapPerTau * options.tau;
      r.complex = buildHullComplex(r.hulls, copt);
      r.times.complex += acd::secondsSince(t0);
      r.toleranceUsed = tolerance;
      if (!r.complex.status.ok()) continue;
      r.tetgen = runTetGen(r.complex.plc, options.tetgen);
      r.times.tetgen += r.tetgen.seconds;
      if (!r.tetgen.ok) r.refusedComplexes.push_back(r.tetgen.error);
    }
  };
  // Simplified hulls: when TetGen refuses every complex, smaller budgets give other regions, and
  // one of them is often accepted; the exact hulls come last.
  const int lowestBudget = std::min(options.simplify, std::max(8, options.simplify - 8));
  for (int budget = options.simplify; options.simplify > 0 && !r.tetgen.ok && budget >= lowestBudget; budget -= 4) {
    t0 = acd::Clock::now();
    HullSimplifyOptions sopt;
    sopt.maxVertices = budget;
    const SimplifiedHulls simplified = simplifyHulls(exact, sopt);
    r.times.hulls += acd::secondsSince(t0);
    r.simplifyUsed = budget;
    r.simplifyMissed = 0;
    for (bool reached : simplified.reached) r.simplifyMissed += reached ? 0 : 1;
    r.separatingPlanes = simplified.separatingPlanes;
    r.overlappingHulls = simplified.overlappingHulls;
    meshComplex(simplified.regions);
  }
  if (!r.tetgen.ok) {
    r.simplifyFallback = options.simplify > 0;
    meshComplex(exact);
  }
  if (!r.complex.status.ok()) {
    r.status = r.complex.status;
    return r;
  }
  r.hullsVolume = 0;
  for (const acd::TriMesh& region : r.complex.regions)
    if (!region.empty()) r.hullsVolume += acd::signedVolume(region);
  // Containment where it matters: each component inside the region that was meshed for it.
  for (std::size_t i = 0; i < r.complex.regions.size(); ++i)
    r.maxOutsideRegion =
        std::max(r.maxOutsideRegion,
                 r.complex.regions[i].empty()
                     ? std::numeric_limits<double>::infinity()
                     : maxOutsideDistance(r.complex.regions[i], r.decomposition.components[i].mesh.vertices));
  if (!r.tetgen.ok) {
    // Say which facets were at fault: TetGen's own intersection check (`d`) on the same input.
    TetGenOptions check = options.tetgen;
    check.checkIntersections = true;
    const TetGenResult detect = runTetGen(r.complex.plc, check);
    std::string why = "meshing the hulls: " + r.tetgen.error;
    if (!detect.ok) why += " (intersection check: " + detect.error + ")";
    r.status = acd::Status::error(acd::StatusCode::InternalError, why);
    return r;
  }
  t0 = acd::Clock::now();
  r.quality = measureQuality(r.tetgen.mesh);
  r.times.quality = acd::secondsSince(t0);
  return r;
}

DirectMeshResult meshModelDirectly(const acd::TriMesh& model, const TetGenOptions& options) {
  DirectMeshResult r;
  const auto t0 = acd::Clock::now();
  const acd::PreparedSolid solid = acd::prepareSolid(model);
  if (!solid.status.ok()) {
    r.status = solid.status;
    r.seconds = acd::secondsSince(t0);
    return r;
  }
  Plc plc;
  for (const acd::TriMesh& piece : solid.components) {
    const int base = static_cast<int>(plc.points.size());
    plc.points.insert(plc.points.end(), piece.vertices.begin(), piece.vertices.end());
    for (const acd::Face& f : piece.faces)
      plc.facets.push_back({{base + f[0], base + f[1], base + f[2]}, kBoundaryFacet});
  }
  // TetGen cannot recover from intersecting facets; refuse them here, by name.
  acd::TriMesh all;
  for (const acd::TriMesh& piece : solid.components) {
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (const acd::Face& f : piece.faces) all.faces.push_back({base + f[0], base + f[1], base + f[2]});
  }
  r.selfIntersections = acd::countSelfIntersections(all);
  if (r.selfIntersections > 0) {
    r.status = acd::Status::error(acd::StatusCode::DegenerateFace,
                                  "the surface intersects itself (" + std::to_string(r.selfIntersections) +
                                      " pairs of faces); TetGen needs a surface without self-intersections");
    r.seconds = acd::secondsSince(t0);
    return r;
  }
  TetGenOptions o = options;
  o.regions = false;
  r.tetgen = runTetGen(plc, o);
  r.seconds = acd::secondsSince(t0);
  if (!r.tetgen.ok) {
    r.status = acd::Status::error(acd::StatusCode::InternalError, r.tetgen.error);
    return r;
  }
  r.quality = measureQuality(r.tetgen.mesh);
  return r;
}

}  // namespace tetmesh
