// The working model (libacd/src/driver/working_model.cpp): a dense input decomposed through its
// working mesh (acd/algo/working_mesh.hpp). The promise is about the input, so it is checked
// against the input here, with the tests' own distance and inside tests, never the library's figures.
#include <acd/algo/shapes.hpp>
#include <acd/algo/surface_mesh_copy.hpp>
#include <acd/decompose.hpp>
#include <acd/io.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../helpers.hpp"

using namespace acdtest;

namespace {

using acd::TriMesh;
using acd::Vec3;

/// tau 0.05 on two threads, through a working mesh within a tenth of tau whatever the face count.
acd::DecomposeOptions throughWorkingMesh() {
  acd::DecomposeOptions o;
  o.tau = 0.05;
  o.threads = 2;
  o.workingShare = 0.1;
  o.workingFromFaces = 0;
  return o;
}

/// How far the hulls stand off the input at most, in normalised units: 4000 points sampled on
/// each hull and its corners, by the tests' own distance and inside code.
double worstStandOff(const acd::Decomposition& d, const TriMesh& input) {
  const MeshIndex index(input);
  std::mt19937_64 rng(11);
  double worst = 0.0;
  for (const acd::Component& c : d.components) {
    std::vector<Vec3> points = sampleSurface(c.hull, 4000, rng);
    points.insert(points.end(), c.hull.vertices.begin(), c.hull.vertices.end());
    for (const Vec3& p : points)
      if (!index.inside(p)) worst = std::max(worst, index.distance(p) * d.normalization.scale);
  }
  return worst;
}

/// How far outside every hull an input vertex lies at most, in normalised units: every
/// `stride`-th vertex, each against the half-spaces of the hulls whose box holds it (a hull of
/// dense input has thousands of faces).
double worstUncovered(const acd::Decomposition& d, const TriMesh& input, std::size_t stride) {
  struct Planes {
    std::vector<std::pair<Vec3, double>> planes;  // unit normal, offset
    Vec3 lo, hi;
  };
  std::vector<Planes> hulls;
  for (const acd::Component& c : d.components) {
    Planes h;
    h.lo = h.hi = c.hull.vertices.front();
    for (const Vec3& v : c.hull.vertices) h.lo = h.lo.cwiseMin(v), h.hi = h.hi.cwiseMax(v);
    // A sliver (three hull vertices almost on a line, where a facet's corner lies nearly on an
    // edge) has no reliable normal; its neighbours bound the hull there.
    const double sliver = 1e-9 * (h.hi - h.lo).squaredNorm();
    for (const acd::Face& f : c.hull.faces) {
      const Vec3& a = c.hull.vertices[f[0]];
      const Vec3 n = (c.hull.vertices[f[1]] - a).cross(c.hull.vertices[f[2]] - a);
      if (n.norm() > sliver) h.planes.push_back({n.normalized(), n.normalized().dot(a)});
    }
    hulls.push_back(std::move(h));
  }
  double uncovered = 0.0;
  for (std::size_t k = 0; k < input.vertices.size(); k += stride) {
    const Vec3& v = input.vertices[k];
    double best = std::numeric_limits<double>::infinity();
    for (const Planes& h : hulls) {
      if ((v.array() < h.lo.array() - 1e-9).any() || (v.array() > h.hi.array() + 1e-9).any()) continue;
      double out = 0.0;
      for (const auto& [n, offset] : h.planes) out = std::max(out, n.dot(v) - offset);
      best = std::min(best, out);
      if (best <= 0) break;
    }
    uncovered = std::max(uncovered, best * d.normalization.scale);
  }
  return uncovered;
}

TEST(DenseInput, HalfAMillionFaceTorusKeepsTauAgainstTheInput) {
  const TriMesh torus = acd::shapes::torus(1.0, 0.35, 1000, 260);
  ASSERT_GE(torus.faces.size(), 500000u);
  const acd::DecomposeOptions o = throughWorkingMesh();
  const acd::Decomposition d = acd::decompose(torus, o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  // The work was done on far fewer faces than the input has.
  EXPECT_GT(d.stats.workingFaces, 0);
  EXPECT_LT(d.stats.workingFaces, static_cast<int>(torus.faces.size()) / 20);
  // A ring of 1.35 outer radius at tau 0.05 (normalised: radius 1): a handful of segments, not
  // hundreds.
  EXPECT_GE(d.components.size(), 4u);
  EXPECT_LE(d.components.size(), 40u);

  for (const acd::Component& c : d.components) EXPECT_FALSE(c.unresolved) << c.note;
  const double worst = worstStandOff(d, torus);
  EXPECT_LE(worst, o.tau) << "a hull stands off the input by more than tau";
  // The reported excess bounds what is measured here (to the sampling's resolution).
  double reported = 0.0;
  for (const acd::Component& c : d.components) reported = std::max(reported, c.hullExcess);
  EXPECT_GE(reported + 0.05 * o.tau, worst);

  // Every input vertex is in some hull: the hulls are built from the input's own vertices.
  EXPECT_LE(worstUncovered(d, torus, 13), 1e-9);
}

TEST(DenseInput, WorkingMeshFromTheFaceCountOn) {
  const TriMesh torus = acd::shapes::torus(1.0, 0.35, 120, 40);  // 9600 faces
  const int faces = static_cast<int>(torus.faces.size());
  acd::DecomposeOptions o = throughWorkingMesh();
  o.workingFromFaces = faces + 1;
  const acd::Decomposition below = acd::decompose(torus, o);
  ASSERT_TRUE(below.status.ok()) << below.status.message;
  EXPECT_EQ(below.stats.workingFaces, 0);
  o.workingFromFaces = faces;
  const acd::Decomposition from = acd::decompose(torus, o);
  ASSERT_TRUE(from.status.ok()) << from.status.message;
  EXPECT_GT(from.stats.workingFaces, 0);
  EXPECT_LT(from.stats.workingFaces, faces);
  // By default a working share applies from 20k faces.
  EXPECT_EQ(acd::DecomposeOptions{}.workingFromFaces, 20000);
}

TEST(DenseInput, SubdividedModelGivesAboutTheSameParts) {
  acd::ReadResult read = acd::readMesh(corpus("elephant"));
  if (!read.status.ok()) GTEST_SKIP() << "the corpus is not fetched (scripts/fetch_corpus.sh)";
  const TriMesh elephant = std::move(read.mesh);
  const TriMesh dense = midpointSubdivided(midpointSubdivided(elephant));  // 16 times the faces
  acd::DecomposeOptions o;
  o.tau = 0.05;
  o.threads = 2;
  o.workingShare = 0.1;  // from 20k faces, the default of workingFromFaces
  const acd::Decomposition a = acd::decompose(elephant, o);  // 5.6k faces: the input's own triangles
  EXPECT_EQ(a.stats.workingFaces, 0);
  const acd::Decomposition b = acd::decompose(dense, o);
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  EXPECT_GT(b.stats.workingFaces, 0);
  ASSERT_FALSE(a.components.empty());
  // Within a tenth (the merge is held to the full tau against the input: 25 parts against 26).
  const double ratio = static_cast<double>(b.components.size()) / static_cast<double>(a.components.size());
  EXPECT_GE(ratio, 0.9);
  EXPECT_LE(ratio, 1.1);
  for (const acd::Component& c : b.components) EXPECT_LE(c.hullExcess, 0.05);
  // Unions taken at the full tau, judged against the input: their hulls are within it, measured
  // here independently (to the sampling's resolution).
  EXPECT_GT(b.stats.merges, 0);
  EXPECT_LE(worstStandOff(b, dense), 0.05);
}

// The corpus models of at least 20k faces go through the working mesh by default. What the
// default promises is checked against the input here, as the acd command decomposes them
// (the partition invariants of the mesh decomposed: test_decompose.cpp, at full resolution).
struct WorkingCase {
  const char* model;
  double tau;
};
void PrintTo(const WorkingCase& c, std::ostream* os) { *os << c.model << " tau " << c.tau; }
class WorkingMeshCorpus : public ::testing::TestWithParam<WorkingCase> {};

TEST_P(WorkingMeshCorpus, KeepsTheDefaultPromiseAgainstTheInput) {
  const WorkingCase c = GetParam();
  acd::ReadResult read = acd::readMesh(corpus(c.model));
  if (!read.status.ok()) GTEST_SKIP() << "the corpus is not fetched (scripts/fetch_corpus.sh)";
  const TriMesh& input = read.mesh;
  acd::DecomposeOptions o = acd::recommendedOptions();
  o.tau = c.tau;
  o.wrap = false;
  const acd::Decomposition d = acd::decompose(input, o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  ASSERT_GT(d.stats.workingFaces, 0) << "the default no longer simplifies a model of "
                                     << input.faces.size() << " faces";
  double volume = 0.0;
  for (const acd::Component& k : d.components) {
    EXPECT_FALSE(k.unresolved) << k.note;
    EXPECT_TRUE(acd::isClosedOriented(k.mesh));
    EXPECT_LE(k.hullExcess, c.tau);
    volume += k.volume;
  }
  EXPECT_LE(worstStandOff(d, input), c.tau) << "a hull stands off the input by more than tau";
  const double uncovered = worstUncovered(d, input, 3);
  EXPECT_LE(uncovered, 1e-9) << "an input vertex lies outside every hull";
  // The components fill the working model, whose surface stands within w of the input's: their
  // volume differs from the input's by at most about w times its area.
  const TriMesh model = acd::applyNormalization(input, d.normalization);
  const double w = o.workingShare * c.tau;
  EXPECT_NEAR(volume, d.stats.inputVolume, w * acd::surfaceArea(model));
}

INSTANTIATE_TEST_SUITE_P(Models, WorkingMeshCorpus,
                         ::testing::Values(WorkingCase{"armadillo", 0.05}, WorkingCase{"armadillo", 0.02},
                                           WorkingCase{"bunny00", 0.05}, WorkingCase{"bunny00", 0.02}),
                         [](const auto& info) {
                           return std::string(info.param.model) + (info.param.tau == 0.05 ? "_tau0_05" : "_tau0_02");
                         });

/// A plate bent along an arc: radius 1, `thickness` thick, 2 radians wide, 1 long, closed by its
/// ends and sides; 400 segments along the arc, 40 along its length.
TriMesh bentPlate(double thickness) {
  const int arc = 400, length = 40;
  std::vector<Vec3> ring;  // the outer arc, then the inner one back
  for (int i = 0; i <= arc; ++i) ring.emplace_back(std::cos(-1.0 + 2.0 * i / arc), std::sin(-1.0 + 2.0 * i / arc), 0.0);
  for (int i = arc; i >= 0; --i) ring.push_back(Vec3(ring[i].x(), ring[i].y(), 0.0) * (1.0 - thickness));
  const int n = static_cast<int>(ring.size());
  TriMesh m;
  for (int j = 0; j <= length; ++j)
    for (const Vec3& p : ring) m.vertices.push_back(p + Vec3(0, 0, static_cast<double>(j) / length));
  auto at = [&](int j, int i) { return j * n + (i % n); };
  for (int j = 0; j < length; ++j)
    for (int i = 0; i < n; ++i) {
      m.faces.push_back({at(j, i), at(j, i + 1), at(j + 1, i + 1)});
      m.faces.push_back({at(j, i), at(j + 1, i + 1), at(j + 1, i)});
    }
  for (const int j : {0, length})  // the two ends: strips between the arcs
    for (int i = 0; i < arc; ++i) {
      const int o0 = at(j, i), o1 = at(j, i + 1), i0 = at(j, n - 1 - i), i1 = at(j, n - 2 - i);
      if (j == 0) {
        m.faces.push_back({o0, i1, o1});
        m.faces.push_back({o0, i0, i1});
      } else {
        m.faces.push_back({o0, o1, i1});
        m.faces.push_back({o0, i1, i0});
      }
    }
  return m;
}

// Two sheets closer than the working tolerance, curved so that a chord of one passes through the
// other within it: collapses alone would give a working mesh that crosses itself (and components
// that do). Each component is checked by CGAL's own self-intersection test.
TEST(DenseInput, ThinBentPlateGivesComponentsThatDoNotCrossThemselves) {
  const TriMesh plate = bentPlate(0.002);
  const acd::DecomposeOptions o = throughWorkingMesh();
  const acd::Decomposition d = acd::decompose(plate, o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_GT(d.stats.workingFaces, 0);
  using SM = CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3>;
  for (const acd::Component& c : d.components) {
    SM sm;
    ASSERT_LT(acd::copyToSurfaceMesh(c.mesh, sm), 0) << "a component is no polygon mesh";
    EXPECT_FALSE(CGAL::Polygon_mesh_processing::does_self_intersect(sm));
  }
}

}  // namespace
