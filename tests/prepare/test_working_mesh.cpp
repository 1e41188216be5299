// The working mesh: fewer faces, the same surface to within the tolerance, measured here by an
// independent distance (the tests' own bounding-volume hierarchy), the same topology.
#include <acd/algo/shapes.hpp>
#include <acd/algo/working_mesh.hpp>
#include <acd/mesh.hpp>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "../helpers.hpp"

using namespace acdtest;

namespace {

using acd::TriMesh;
using acd::Vec3;

int eulerCharacteristic(const TriMesh& m) {
  return static_cast<int>(m.vertices.size()) - static_cast<int>(m.faces.size()) * 3 / 2 +
         static_cast<int>(m.faces.size());
}

/// The largest distance from the points to the surface of `to`.
double farthest(const std::vector<Vec3>& points, const TriMesh& to) {
  const MeshIndex index(to);
  double worst = 0.0;
  for (const Vec3& p : points) worst = std::max(worst, index.distance(p));
  return worst;
}

std::vector<Vec3> surfacePoints(const TriMesh& m, int count) {
  std::mt19937_64 rng(7);
  return sampleSurface(m, count, rng);
}

TEST(WorkingMesh, DenseSphereBecomesFewFacesWithinTolerance) {
  const TriMesh sphere = acd::shapes::icosphere(Vec3::Zero(), 1.0, 6);  // 81920 faces
  const double tolerance = 0.005;
  const acd::WorkingMesh w = acd::simplifyWithin(sphere, tolerance);
  EXPECT_TRUE(acd::isClosedOriented(w.mesh));
  EXPECT_EQ(eulerCharacteristic(w.mesh), 2);
  // A triangle whose chord stands h off the sphere has circumradius sqrt(2 h): at least about 4 pi
  // / (1.3 * 2 h) faces are needed (an upper bound on what any simplifier can reach), and a good
  // one needs few times that.
  const double least = 4 * M_PI / (1.3 * 2 * tolerance);
  EXPECT_GE(static_cast<double>(w.mesh.faces.size()), 0.5 * least);
  EXPECT_LE(static_cast<double>(w.mesh.faces.size()), 8 * least);
  EXPECT_LE(farthest(sphere.vertices, w.mesh), tolerance);
  EXPECT_LE(farthest(w.mesh.vertices, sphere), tolerance);
  // Between the vertices the checks are not exhaustive: measured over the faces, with a tenth more.
  EXPECT_LE(farthest(surfacePoints(w.mesh, 20000), sphere), 1.1 * tolerance);
  EXPECT_LE(farthest(surfacePoints(sphere, 20000), w.mesh), 1.1 * tolerance);
  EXPECT_NEAR(acd::signedVolume(w.mesh), acd::signedVolume(sphere), acd::surfaceArea(sphere) * tolerance);
}

// Above 100k faces the collapses run slab by slab in parallel first: the result must not depend
// on the thread count, and the strips along the slab walls must be simplified as well as the rest.
TEST(WorkingMesh, SlabsGiveTheSameMeshOnAnyThreadCountAndKeepTheTolerance) {
  const TriMesh sphere = acd::shapes::icosphere(Vec3::Zero(), 1.0, 7);  // 327680 faces: 3 slabs
  const double tolerance = 0.005;
  acd::WorkingMesh serial, parallel;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    serial = acd::simplifyWithin(sphere, tolerance);
  }
  {
    tbb::global_control four(tbb::global_control::max_allowed_parallelism, 4);
    parallel = acd::simplifyWithin(sphere, tolerance);
  }
  EXPECT_EQ(serial.mesh.faces, parallel.mesh.faces);
  EXPECT_EQ(serial.mesh.vertices, parallel.mesh.vertices);
  EXPECT_EQ(serial.collapses, parallel.collapses);
  const TriMesh& w = parallel.mesh;
  EXPECT_TRUE(acd::isClosedOriented(w));
  EXPECT_EQ(eulerCharacteristic(w), 2);
  const double least = 4 * M_PI / (1.3 * 2 * tolerance);  // as in the test above
  EXPECT_LE(static_cast<double>(w.faces.size()), 8 * least);
  EXPECT_LE(farthest(sphere.vertices, w), tolerance);
  EXPECT_LE(farthest(w.vertices, sphere), tolerance);
  EXPECT_LE(farthest(surfacePoints(w, 20000), sphere), 1.1 * tolerance);
}

TEST(WorkingMesh, TorusKeepsItsHole) {
  const TriMesh torus = acd::shapes::torus(1.0, 0.3, 400, 120);
  const acd::WorkingMesh w = acd::simplifyWithin(torus, 0.004);
  EXPECT_TRUE(acd::isClosedOriented(w.mesh));
  EXPECT_EQ(eulerCharacteristic(w.mesh), 0);
  EXPECT_LT(w.mesh.faces.size(), torus.faces.size() / 10);
  EXPECT_LE(farthest(torus.vertices, w.mesh), 0.004);
  EXPECT_LE(farthest(w.mesh.vertices, torus), 0.004);
}

TEST(WorkingMesh, FlatFacesCollapseToTheirCorners) {
  // A box whose faces are finely split: the working mesh needs little more than its 8 corners.
  TriMesh box = acd::shapes::box(Vec3(-1, -0.5, -0.25), Vec3(1, 0.5, 0.25));
  for (int k = 0; k < 4; ++k) box = midpointSubdivided(box);
  const acd::WorkingMesh w = acd::simplifyWithin(box, 1e-3);
  EXPECT_TRUE(acd::isClosedOriented(w.mesh));
  EXPECT_LE(w.mesh.faces.size(), 40u);  // of the input's 3072
  EXPECT_NEAR(acd::signedVolume(w.mesh), 1.0, 1e-9);
}

// Each collapse is made only if every new face's centroid stays within the tolerance of the input
// (its corners are input vertices): what the result must show face by face, measured here on a
// midpoint-subdivided torus, whose many faces are much smaller than the tolerance (the shortcut
// near an input vertex) and whose coarse faces are not.
TEST(WorkingMesh, EveryFaceCentroidStaysWithinTheToleranceOfTheInput) {
  const TriMesh torus = midpointSubdivided(acd::shapes::torus(1.0, 0.3, 160, 48));  // 61440 faces
  const double tolerance = 0.004;
  const acd::WorkingMesh w = acd::simplifyWithin(torus, tolerance);
  ASSERT_LT(w.mesh.faces.size(), torus.faces.size() / 10);
  std::vector<Vec3> centroids;
  for (const acd::Face& t : w.mesh.faces)
    centroids.push_back((w.mesh.vertices[t[0]] + w.mesh.vertices[t[1]] + w.mesh.vertices[t[2]]) / 3.0);
  EXPECT_LE(farthest(centroids, torus), tolerance * (1 + 1e-9));
  EXPECT_LE(farthest(torus.vertices, w.mesh), tolerance);
  EXPECT_EQ(eulerCharacteristic(w.mesh), 0);
}

TEST(WorkingMesh, NothingBelowTheToleranceLeavesTheMeshAlone) {
  const TriMesh sphere = acd::shapes::icosphere(Vec3::Zero(), 1.0, 3);
  const acd::WorkingMesh w = acd::simplifyWithin(sphere, 1e-9);
  EXPECT_EQ(w.mesh.faces.size(), sphere.faces.size());
  EXPECT_EQ(w.collapses, 0);
}

}  // namespace
