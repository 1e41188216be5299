// Delaunay refinement of the hull regions; see region_refiner.hpp. The only CGAL Mesh_3
// translation unit: its templates are slow to compile.
#include "region_refiner.hpp"

#include "mesh_quality.hpp"
#include "region_features.hpp"
#include "region_labels.hpp"

#include <acd/algo/stopwatch.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_domain_with_polyline_features_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/Random.h>

#include <atomic>
#include <map>
#include <utility>

namespace tetmesh {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using LabeledDomain = CGAL::Mesh_domain_with_polyline_features_3<CGAL::Labeled_mesh_domain_3<K>>;

/// The labelled domain, started from surface points of every region. CGAL's own start shoots
/// random rays from the middle of the box, and the refinement only finds a region whose surface
/// some Delaunay edge crosses: with coarse criteria, thin regions off those rays (half the knot
/// at tau 0.2) were never meshed. Six axis rays from each region's centre meet its surface.
class Domain : public LabeledDomain {
 public:
  Domain(const CGAL::Labeled_mesh_domain_3<K>& base, std::vector<Point> centres, double reach)
      : LabeledDomain(base), centres_(std::move(centres)), reach_(reach) {}

  struct Construct_initial_points {
    const Domain& domain;
    template <class OutputIterator>
    OutputIterator operator()(OutputIterator points, int n = 12) const {
      points = domain.LabeledDomain::construct_initial_points_object()(points, n);
      const auto intersect = domain.construct_intersection_object();
      for (const Point& c : domain.centres_)
        for (int axis = 0; axis < 3; ++axis)
          for (double sign : {-1.0, 1.0}) {
            K::Vector_3 d(axis == 0 ? sign : 0.0, axis == 1 ? sign : 0.0, axis == 2 ? sign : 0.0);
            const auto hit = intersect(K::Segment_3(c, c + domain.reach_ * d));
            if (std::get<2>(hit) != 0) *points++ = std::make_pair(std::get<0>(hit), std::get<1>(hit));
          }
      return points;
    }
  };
  Construct_initial_points construct_initial_points_object() const { return {*this}; }

 private:
  std::vector<Point> centres_;
  double reach_;  // longer than the box: every ray ends outside
};

using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

/// Where the refinement puts a surface point between two labels: within this part of the box.
constexpr double kRelativeErrorBound = 1e-6;
/// A region holding less than kFoundShare of its volume in tets, when what it lost is more than
/// kLostShare of all the regions' volume, or holding no tets at all, was missed (thinner than the
/// facet distance) and is meshed again with half its facet distance, at most kMoreRounds times.
/// Small regions lose a large share to the rounding of their edges alone; only a loss that
/// matters to the whole, or a missing component, is worth the finer mesh.
constexpr double kFoundShare = 0.5;
constexpr double kLostShare = 0.01;
constexpr int kMoreRounds = 3;

/// The facet distance around a point: the global one, less near a thin region (a share of its
/// width). On a surface point shared by regions, the smallest of theirs.
class FacetDistanceField {
 public:
  FacetDistanceField(const RegionLabels& labels, std::vector<double> perRegion, double global)
      : labels_(&labels), perRegion_(std::move(perRegion)), global_(global) {}
  template <class Index>
  double operator()(const Point& p, int, const Index&) const {
    const Vec3 q(p.x(), p.y(), p.z());
    double d = global_;
    // Only on or near the thin region itself (within twice its own distance).
    for (int i = 0; i < labels_->regions(); ++i)
      if (perRegion_[i] < d && labels_->nearBox(i, q) && labels_->excess(i, q) <= 2 * perRegion_[i]) d = perRegion_[i];
    return d;
  }

 private:
  const RegionLabels* labels_;
  std::vector<double> perRegion_;
  double global_;
};

/// The complex as a TetMesh: vertices numbered as the cells meet them, tets positive.
TetMesh toTetMesh(const Complex& c3t3) {
  TetMesh mesh;
  std::map<Triangulation::Vertex_handle, int> index;
  auto id = [&](Triangulation::Vertex_handle v) {
    const auto [it, added] = index.emplace(v, static_cast<int>(mesh.points.size()));
    if (added) {
      const Point& p = v->point().point();
      mesh.points.emplace_back(p.x(), p.y(), p.z());
    }
    return it->second;
  };
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<int, 4> t{id(c->vertex(0)), id(c->vertex(1)), id(c->vertex(2)), id(c->vertex(3))};
    mesh.tets.push_back(t);
    mesh.labels.push_back(c3t3.subdomain_index(c));
    if (tetVolume(mesh, static_cast<int>(mesh.tets.size()) - 1) < 0) std::swap(mesh.tets.back()[2], mesh.tets.back()[3]);
  }
  for (auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    std::array<int, 3> tri{};
    int k = 0;
    for (int i = 0; i < 4; ++i)
      if (i != f->second) tri[k++] = id(f->first->vertex(i));
    const auto patch = c3t3.surface_patch_index(*f);
    mesh.faces.push_back(tri);
    mesh.faceMarkers.push_back(patch.first == 0 || patch.second == 0 ? kBoundaryFacet : kInterfaceFacet);
  }
  return mesh;
}

}  // namespace

namespace {

/// One refinement with the given facet distance per region.
RefineResult refineOnce(const std::vector<acd::TriMesh>& regions, const RefineOptions& options,
                        const std::vector<double>& distance, const std::function<bool(const Vec3&)>& keep) {
  RefineResult r;
  std::vector<double> gaps(regions.size(), options.closedGap);
  for (std::size_t i = 0; i < regions.size(); ++i) gaps[i] = std::min(gaps[i], distance[i]);
  const RegionLabels labels(regions, gaps);
  const Vec3 size = labels.upper() - labels.lower();
  if (!(size.minCoeff() > 0)) {
    r.error = "the regions enclose no volume";
    return r;
  }
  std::atomic<long> queries{0};
  auto label = [&](const Point& p) {
    queries.fetch_add(1, std::memory_order_relaxed);
    const Vec3 q(p.x(), p.y(), p.z());
    const int l = labels(q);
    return l != 0 && keep && !keep(q) ? 0 : l;
  };
  // The box must hold the domain strictly: widened by a tenth of its size.
  const Vec3 lo = labels.lower() - 0.1 * size, hi = labels.upper() + 0.1 * size;
  // CGAL draws from its (thread-local) default generator too, e.g. in point location: reset it.
  CGAL::get_default_random() = CGAL::Random(0);
  CGAL::Random random(0);
  std::vector<Point> centres;
  for (const acd::TriMesh& region : regions)
    if (!region.vertices.empty()) {
      Vec3 c = Vec3::Zero();
      for (const Vec3& v : region.vertices) c += v;
      c /= static_cast<double>(region.vertices.size());
      centres.emplace_back(c.x(), c.y(), c.z());
    }
  Domain domain(CGAL::Labeled_mesh_domain_3<K>(std::function<int(const Point&)>(label),
                                               K::Iso_cuboid_3(lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()),
                                               kRelativeErrorBound, CGAL::Null_subdomain_index(), &random),
                std::move(centres), 2.0 * (hi - lo).norm());
  if (options.featureAngle > 0) {
    const RegionFeatures features = regionFeatures(regions, labels, options.featureAngle, options.facetDistance);
    std::vector<std::vector<Point>> polylines;
    for (const std::vector<Vec3>& line : chainSegments(features.segments)) {
      polylines.emplace_back();
      for (const Vec3& v : line) polylines.back().emplace_back(v.x(), v.y(), v.z());
    }
    domain.add_features(polylines.begin(), polylines.end());
    r.features = static_cast<int>(features.segments.size());
    r.featuresDropped = features.dropped;
  }
  namespace p = CGAL::parameters;
  const double edgeSize = options.edgeSize > 0 ? options.edgeSize : (hi - lo).norm();
  const FacetDistanceField facetDistance(labels, distance, options.facetDistance);
  const Criteria criteria(p::edge_size = edgeSize, p::facet_angle = options.facetAngle, p::facet_size = options.facetSize,
                          p::facet_distance = facetDistance, p::cell_radius_edge_ratio = options.radiusEdge,
                          p::cell_size = options.cellSize);
  try {
    // No time limits: they would make the mesh depend on the machine's speed. No perturbation:
    // CGAL's did not repeat itself within one process; the sliver repair below does its work.
    const Complex c3t3 = CGAL::make_mesh_3<Complex>(domain, criteria, p::features(domain),
                                                    p::no_perturb(),
                                                    p::exude(p::sliver_bound = options.sliverBound));
    r.mesh = toTetMesh(c3t3);
    r.slivers = repairSlivers(r.mesh, kSliverDegrees, options.sliverMove);
  } catch (const std::exception& e) {
    r.error = std::string("the refinement failed: ") + e.what();
    return r;
  }
  r.labelQueries = queries.load();
  r.ok = !r.mesh.tets.empty();
  if (!r.ok) r.error = "the refinement found no volume to mesh";
  return r;
}

}  // namespace

RefineResult refineRegions(const std::vector<acd::TriMesh>& regions, const RefineOptions& options,
                           const std::function<bool(const Vec3&)>& keep) {
  const auto t0 = acd::Clock::now();
  if (!(options.facetDistance > 0) || !(options.radiusEdge > 0) || !(options.facetAngle > 0)) {
    RefineResult r;
    r.error = "the refinement needs a positive facet distance, radius-edge bound and facet angle";
    return r;
  }
  // A region thinner than about the facet distance can fall between the refinement's samples
  // (the walls of a thin-walled part, 0.019 thick under a facet distance of 0.014, kept 28 % of
  // their volume): a missed region (above) is meshed again with half its facet distance, up to
  // kMoreRounds times. The others keep theirs, so only thin parts cost.
  std::vector<double> distance(regions.size(), options.facetDistance), volume(regions.size());
  double total = 0.0;
  for (std::size_t i = 0; i < regions.size(); ++i) total += volume[i] = regions[i].empty() ? 0.0 : acd::signedVolume(regions[i]);
  long queries = 0;
  int refined = 0;
  for (int round = 0;; ++round) {
    RefineResult r = refineOnce(regions, options, distance, keep);
    queries += r.labelQueries;
    r.labelQueries = queries;
    r.regionsRefined = refined;
    r.seconds = acd::secondsSince(t0);
    if (!r.ok || keep || round == kMoreRounds) return r;  // clipped regions may rightly hold little
    std::vector<double> meshed(regions.size(), 0.0);
    for (std::size_t t = 0; t < r.mesh.tets.size(); ++t)
      if (r.mesh.labels[t] >= 1 && r.mesh.labels[t] <= static_cast<int>(regions.size()))
        meshed[r.mesh.labels[t] - 1] += tetVolume(r.mesh, static_cast<int>(t));
    bool again = false;
    for (std::size_t i = 0; i < regions.size(); ++i) {
      const bool missed = volume[i] > 0 && (meshed[i] == 0 || (meshed[i] < kFoundShare * volume[i] &&
                                                               volume[i] - meshed[i] > kLostShare * total));
      if (missed) distance[i] *= 0.5, again = true, ++refined;
    }
    if (!again) return r;
  }
}

}  // namespace tetmesh
