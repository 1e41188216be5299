// The tetmesh pipeline; see hull_mesher.hpp.
#include "hull_mesher.hpp"

#include "hull_simplify.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/diagnosis.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/shell_inside.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

namespace tetmesh {

namespace {

/// Gaps between hulls narrower than this times tau (of the half-diagonal) are closed by the
/// complex: far below what tau resolves (hulls stand up to tau off the model), and a gap that
/// thin between two regions would give TetGen two faces a hair apart, or a mesh in two pieces
/// where the model is one.
constexpr double kClosedGapPerTau = 1e-3;

/// The refinement's surface follows the regions within this share of tau (normalised units, as
/// tau): the regions themselves stand up to tau off the model, so a quarter of tau more is of the
/// order of what the hulls already allow, and features below it are not resolved (and so cannot
/// force short edges). Gaps between regions narrower than it are closed.
constexpr double kFacetDistancePerTau = 0.25;
/// Radius-edge bound of the coarse refinement: the 2 from which Delaunay refinement is proven to
/// end; slivers, which a radius-edge bound does not see, are the sliver passes' work.
constexpr double kCoarseRadiusEdge = 2.0;
/// Coarse mode: edge collapses keep every tet's dihedral angles within [this, 180 - this]: the
/// angle CGAL's exudation works towards, twice the 5 degrees a sliver is counted below.
constexpr double kCoarseDihedral = 10.0;
/// Coarse mode: the refinement is only where the collapses start, and follows the regions within
/// this share of tau; the collapses may take the surface the rest of kCoarseSurfacePerTau from
/// the refinement's surface points: in all, as far as the hulls themselves may stand off the model.
constexpr double kCoarseFacetDistancePerTau = 0.5;
constexpr double kCoarseSurfacePerTau = 1.0;
/// With `--sharp`: the largest protecting ball along a kept edge, in tau (normalised units).
constexpr double kEdgeSizePerTau = 1.0;
/// The last slivers' corners may move by this share of the facet distance (the surface follows
/// the regions within the facet distance anyway).
constexpr double kSliverMoveShare = 0.5;
/// Smallest angle of a surface triangle (the largest bound CGAL proves its refinement ends with).
constexpr double kFacetAngle = 30.0;

/// The circumradius of a regular tet of volume v: the refinement's size bound for TetGen's `a`.
double regularCircumradius(double volume) {
  const double edge = std::cbrt(6.0 * std::sqrt(2.0) * volume);
  return edge * std::sqrt(6.0) / 4.0;
}

int defaultSimplify(Mesher mesher) { return mesher == Mesher::Complex ? 24 : 0; }

/// Mesher::Auto tries the complex of the exact hulls when none has more faces than this (CAD
/// parts: boxes, plates, prisms), where its unrefined mesh is a handful of tets with the faces
/// kept exactly; hulls of curved parts have hundreds, and their complex always has slivers.
constexpr int kComplexTrialFaces = 24;
/// Most seconds per TetGen call of that trial (it meshes a few boxes in milliseconds).
constexpr int kComplexTrialSeconds = 10;

/// The faces of a convex hull as planes (its triangles' planes, those within 1e-6 of the hull's
/// size one): an exported box has many triangles but six faces.
int hullFaces(const acd::TriMesh& hull) {
  double size = 0.0;
  for (const Vec3& v : hull.vertices) size = std::max(size, v.cwiseAbs().maxCoeff());
  std::vector<std::array<double, 4>> planes;
  for (const acd::Face& f : hull.faces) {
    const Vec3& a = hull.vertices[f[0]];
    const Vec3 n = (hull.vertices[f[1]] - a).cross(hull.vertices[f[2]] - a);
    if (!(n.norm() > 0)) continue;
    const Vec3 u = n.normalized();
    planes.push_back({u.x(), u.y(), u.z(), u.dot(a)});
  }
  std::sort(planes.begin(), planes.end());
  const double eps = 1e-6 * std::max(1.0, size);
  std::vector<std::array<double, 4>> kept;
  for (const auto& p : planes) {
    bool same = false;
    for (const auto& q : kept)
      same = same || (std::abs(p[0] - q[0]) < 1e-6 && std::abs(p[1] - q[1]) < 1e-6 && std::abs(p[2] - q[2]) < 1e-6 &&
                      std::abs(p[3] - q[3]) < eps);
    if (!same) kept.push_back(p);
    if (static_cast<int>(kept.size()) > kComplexTrialFaces) break;  // enough to say no
  }
  return static_cast<int>(kept.size());
}


/// The hulls simplified to at most `budget` corners each, with the figures the report gives.
std::vector<acd::TriMesh> simplifyInto(const std::vector<acd::TriMesh>& exact, int budget, HullMeshResult& r) {
  const auto t0 = acd::Clock::now();
  HullSimplifyOptions sopt;
  sopt.maxVertices = budget;
  SimplifiedHulls simplified = simplifyHulls(exact, sopt);
  r.times.hulls += acd::secondsSince(t0);
  r.simplifyUsed = budget;
  r.simplifyMissed = 0;
  for (bool reached : simplified.reached) r.simplifyMissed += reached ? 0 : 1;
  r.separatingPlanes = simplified.separatingPlanes;
  r.overlappingHulls = simplified.overlappingHulls;
  return std::move(simplified.regions);
}

/// Mesher::Complex: the complex of the regions (simplified to `simplify` corners when > 0) given
/// to TetGen, with larger snapping distances and smaller budgets when TetGen refuses.
void meshComplex(const std::vector<acd::TriMesh>& exact, int simplify, const HullMeshOptions& options, HullMeshResult& r) {
  // TetGen merges points closer than its own tolerance and then trips over the complex; when it
  // refuses one, the complex is rebuilt with a 10 times larger snapping distance (twice at most).
  auto attempt = [&](std::vector<acd::TriMesh> hulls) {
    r.hulls = std::move(hulls);
    for (int tries = 0; tries < 3 && !r.tetgen.ok; ++tries) {
      const double tolerance = options.tolerance * std::pow(10.0, tries);
      const auto t0 = acd::Clock::now();
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
  const int lowestBudget = std::min(simplify, std::max(8, simplify - 8));
  for (int budget = simplify; simplify > 0 && !r.tetgen.ok && budget >= lowestBudget; budget -= 4)
    attempt(simplifyInto(exact, budget, r));
  if (!r.tetgen.ok) {
    r.simplifyFallback = simplify > 0;
    attempt(exact);
  }
  if (!r.complex.status.ok()) {
    r.status = r.complex.status;
    return;
  }
  r.regions = r.complex.regions;
  if (!r.tetgen.ok) {
    // Say which facets were at fault: TetGen's own intersection check (`d`) on the same input.
    TetGenOptions check = options.tetgen;
    check.checkIntersections = true;
    const TetGenResult detect = runTetGen(r.complex.plc, check);
    std::string why = "meshing the hulls: " + r.tetgen.error;
    if (!detect.ok) why += " (intersection check: " + detect.error + ")";
    r.status = acd::Status::error(acd::StatusCode::InternalError, why);
    return;
  }
  r.mesh = std::move(r.tetgen.mesh);
  r.tetgen.mesh = {};
}

/// Mesher::Refine: Delaunay refinement of the regions, with sizes tied to tau.
void meshRefined(const acd::TriMesh& model, const std::vector<acd::TriMesh>& exact, int simplify,
                 const HullMeshOptions& options, HullMeshResult& r) {
  r.hulls = simplify > 0 ? simplifyInto(exact, simplify, r) : exact;
  r.regions = r.hulls;
  const double unit = 1.0 / r.decomposition.normalization.scale;  // tau's unit in input lengths
  RefineOptions& o = r.refineOptions;
  const bool quality = options.tetgen.radiusEdge > 0;
  // Clipped components are asked for their volume: the refinement's closer surface, not coarsened.
  const bool coarsen = !quality && options.coarsen && !options.clip;
  const double share = options.surfaceDistance > 0 ? options.surfaceDistance
                       : coarsen                   ? kCoarseFacetDistancePerTau
                                                   : kFacetDistancePerTau;
  o.facetDistance = share * options.tau * unit;
  o.closedGap = o.facetDistance;
  o.radiusEdge = quality ? options.tetgen.radiusEdge : kCoarseRadiusEdge;
  o.sliverMove = kSliverMoveShare * o.facetDistance;
  o.featureAngle = options.sharpAngle;
  o.edgeSize = kEdgeSizePerTau * options.tau * unit;
  o.facetAngle = kFacetAngle;
  if (options.tetgen.maxVolume > 0) o.cellSize = regularCircumradius(options.tetgen.maxVolume);
  std::unique_ptr<acd::ShellsInside> inside;
  std::function<bool(const Vec3&)> keep;
  if (options.clip) {
    inside = std::make_unique<acd::ShellsInside>(model);
    keep = [&inside](const Vec3& p) { return inside->inside(p); };
  }
  r.refine = refineRegions(r.regions, o, keep);
  r.times.refine = r.refine.seconds;
  if (!r.refine.ok) {
    r.status = acd::Status::error(acd::StatusCode::InternalError, "meshing the hulls: " + r.refine.error);
    return;
  }
  r.mesh = std::move(r.refine.mesh);
  r.refine.mesh = {};
  if (coarsen) {
    CoarsenOptions& c = r.coarsenOptions;
    c.minDihedral = kCoarseDihedral;
    c.maxDistance = std::max(0.0, kCoarseSurfacePerTau * options.tau * unit - o.facetDistance);
    // On request the coarse mesh keeps at least each component's own volume (the hulls hold it).
    if (options.keepVolume)
      for (const acd::Component& comp : r.decomposition.components) c.minVolume.push_back(acd::signedVolume(comp.mesh));
    const auto t0 = acd::Clock::now();
    r.coarsening = coarsenMesh(r.mesh, c);
    r.coarsened = true;
    r.times.coarsen = acd::secondsSince(t0);
  }
}

}  // namespace

HullMeshResult meshHulls(const acd::TriMesh& model, const HullMeshOptions& options) {
  HullMeshResult r;
  const int simplify = options.simplify >= 0 ? options.simplify : defaultSimplify(options.mesher);
  if (simplify != 0 && simplify < 4) {
    r.status = acd::Status::error(acd::StatusCode::InvalidParameter,
                                  "--simplify must be at least 4 (a tetrahedron), got " + std::to_string(simplify));
    return r;
  }
  if ((options.clip || options.sharpAngle != 0) && options.mesher == Mesher::Complex) {
    r.status = acd::Status::error(acd::StatusCode::InvalidParameter,
                                  "clipping the components to the model and keeping sharp edges need the refinement mesher");
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

  bool refine = options.mesher == Mesher::Refine;
  if (options.mesher == Mesher::Auto) {
    // The complex of the exact hulls where they have few corners, kept if it has no sliver;
    // otherwise (and with --clip or --sharp, which only the refinement does) the refinement.
    bool few = !options.clip && options.sharpAngle == 0;
    for (const acd::TriMesh& hull : exact) few = few && hullFaces(hull) <= kComplexTrialFaces;
    refine = true;
    if (few) {
      r.complexTried = true;
      HullMeshResult trial = r;
      HullMeshOptions quick = options;  // a trial: TetGen may loop on a near-degenerate complex
      quick.tetgen.timeoutSeconds = std::min(options.tetgen.timeoutSeconds, kComplexTrialSeconds);
      meshComplex(exact, options.simplify >= 0 ? options.simplify : 0, quick, trial);
      if (trial.status.ok()) trial.complexSlivers = measureQuality(trial.mesh).slivers;
      if (trial.status.ok() && trial.complexSlivers == 0) {
        r = std::move(trial);
        refine = false;
      } else {
        r.complexSlivers = trial.status.ok() ? trial.complexSlivers : -1;
        r.times.complex += trial.times.complex, r.times.tetgen += trial.times.tetgen;
      }
    }
  }
  r.used = refine ? Mesher::Refine : Mesher::Complex;
  if (options.mesher == Mesher::Complex)
    meshComplex(exact, simplify, options, r);
  else if (refine)
    meshRefined(model, exact, simplify, options, r);
  if (r.regions.empty() && !r.status.ok()) return r;

  const std::size_t n = r.decomposition.components.size();
  r.maxOutside = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    r.maxOutside = std::max(r.maxOutside, maxOutsideDistance(r.hulls[i], r.decomposition.components[i].mesh.vertices));
  r.hullsVolume = 0;
  for (const acd::TriMesh& region : r.regions)
    if (!region.empty()) r.hullsVolume += acd::signedVolume(region);
  // Containment where it matters: each component inside the region that was meshed for it.
  for (std::size_t i = 0; i < n; ++i)
    r.maxOutsideRegion = std::max(r.maxOutsideRegion, r.regions[i].empty() ? std::numeric_limits<double>::infinity()
                                                                           : maxOutsideDistance(r.regions[i], r.decomposition.components[i].mesh.vertices));
  if (!r.status.ok()) return r;
  r.meshedVolume.assign(n, 0.0);
  for (std::size_t t = 0; t < r.mesh.tets.size(); ++t)
    if (r.mesh.labels[t] >= 1 && r.mesh.labels[t] <= static_cast<int>(n))
      r.meshedVolume[r.mesh.labels[t] - 1] += tetVolume(r.mesh, static_cast<int>(t));
  t0 = acd::Clock::now();
  r.quality = measureQuality(r.mesh);
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
