// The working model (libacd/src/driver/working_model.cpp): a dense input decomposed through its
// working mesh (acd/algo/working_mesh.hpp). The promise is about the input, so it is checked
// against the input here, with the tests' own distance and inside tests, never the library's figures.
#include <acd/algo/shapes.hpp>
#include <acd/decompose.hpp>
#include <acd/io.hpp>

#include <gtest/gtest.h>

#include <random>

#include "../helpers.hpp"

using namespace acdtest;

namespace {

using acd::TriMesh;
using acd::Vec3;

TEST(DenseInput, HalfAMillionFaceTorusKeepsTauAgainstTheInput) {
  const TriMesh torus = acd::shapes::torus(1.0, 0.35, 1000, 260);
  ASSERT_GE(torus.faces.size(), 500000u);
  acd::DecomposeOptions o;
  o.tau = 0.05;
  o.threads = 2;
  o.workingShare = 0.1;
  const acd::Decomposition d = acd::decompose(torus, o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  // The work was done on far fewer faces than the input has.
  EXPECT_GT(d.stats.workingFaces, 0);
  EXPECT_LT(d.stats.workingFaces, static_cast<int>(torus.faces.size()) / 20);
  // A ring of 1.35 outer radius at tau 0.05 (normalised: radius 1): a handful of segments, not
  // hundreds.
  EXPECT_GE(d.components.size(), 4u);
  EXPECT_LE(d.components.size(), 40u);

  const MeshIndex input(torus);
  const double scale = d.normalization.scale;  // input units -> normalised units
  std::mt19937_64 rng(11);
  double worst = 0.0;
  for (const acd::Component& c : d.components) {
    EXPECT_FALSE(c.unresolved) << c.note;
    std::vector<Vec3> points = sampleSurface(c.hull, 4000, rng);
    points.insert(points.end(), c.hull.vertices.begin(), c.hull.vertices.end());
    for (const Vec3& p : points)
      if (!input.inside(p)) worst = std::max(worst, input.distance(p) * scale);
  }
  EXPECT_LE(worst, o.tau) << "a hull stands off the input by more than tau";
  // The reported excess bounds what is measured here (to the sampling's resolution).
  double reported = 0.0;
  for (const acd::Component& c : d.components) reported = std::max(reported, c.hullExcess);
  EXPECT_GE(reported + 0.05 * o.tau, worst);

  // Every input vertex is in some hull: the hulls are built from the input's own vertices. Every
  // 13th vertex, each against the hulls whose box holds it (a hull of dense input has thousands of faces).
  struct Planes {
    std::vector<std::pair<Vec3, double>> planes;  // unit normal, offset
    Vec3 lo, hi;
  };
  std::vector<Planes> hulls;
  for (const acd::Component& c : d.components) {
    Planes h;
    h.lo = h.hi = c.hull.vertices.front();
    for (const Vec3& v : c.hull.vertices) h.lo = h.lo.cwiseMin(v), h.hi = h.hi.cwiseMax(v);
    for (const acd::Face& f : c.hull.faces) {
      const Vec3& a = c.hull.vertices[f[0]];
      const Vec3 n = (c.hull.vertices[f[1]] - a).cross(c.hull.vertices[f[2]] - a);
      if (n.norm() > 0) h.planes.push_back({n.normalized(), n.normalized().dot(a)});
    }
    hulls.push_back(std::move(h));
  }
  double uncovered = 0.0;
  for (std::size_t k = 0; k < torus.vertices.size(); k += 13) {
    const Vec3& v = torus.vertices[k];
    double best = std::numeric_limits<double>::infinity();
    for (const Planes& h : hulls) {
      if ((v.array() < h.lo.array() - 1e-9).any() || (v.array() > h.hi.array() + 1e-9).any()) continue;
      double out = 0.0;
      for (const auto& [n, offset] : h.planes) out = std::max(out, n.dot(v) - offset);
      best = std::min(best, out);
      if (best <= 0) break;
    }
    uncovered = std::max(uncovered, best * scale);
  }
  EXPECT_LE(uncovered, 1e-9);
}

TEST(DenseInput, SubdividedModelGivesAboutTheSameParts) {
  acd::ReadResult read = acd::readMesh(corpus("elephant"));
  if (!read.status.ok()) GTEST_SKIP() << "the corpus is not fetched (scripts/fetch_corpus.sh)";
  const TriMesh elephant = std::move(read.mesh);
  const TriMesh dense = midpointSubdivided(midpointSubdivided(elephant));  // 16 times the faces
  acd::DecomposeOptions o;
  o.tau = 0.05;
  o.threads = 2;
  const acd::Decomposition a = acd::decompose(elephant, o);  // the input's own triangles
  o.workingShare = 0.1;
  const acd::Decomposition b = acd::decompose(dense, o);
  ASSERT_TRUE(b.status.ok()) << b.status.message;
  EXPECT_GT(b.stats.workingFaces, 0);
  ASSERT_FALSE(a.components.empty());
  const double ratio = static_cast<double>(b.components.size()) / static_cast<double>(a.components.size());
  EXPECT_GE(ratio, 0.8);
  EXPECT_LE(ratio, 1.25);
  for (const acd::Component& c : b.components) EXPECT_LE(c.hullExcess, 0.05);
}

}  // namespace
