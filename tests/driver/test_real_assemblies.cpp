// Multi-body files from the wide data set, decomposed with what the command uses
// (recommendedOptions()), and the promise checked by the tests' own geometry (tests/helpers.hpp:
// winding numbers by ray crossings, distances through a BVH; nothing from the library's
// measures): every point of every hull that lies outside the input within tau of its surface,
// and every point of the input inside a hull.
#include <acd/decompose.hpp>
#include <acd/io.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "helpers.hpp"

using namespace acd;

namespace {

struct Measured {
  double hullsOff = 0.0;     // furthest hull point outside the input, from its surface
  double inputOutside = 0.0; // furthest input point outside every hull (0: covered)
};

/// A hull's facet planes, each placed at the support of the hull's vertices along its normal: a
/// thin facet's normal may be off by rounding, and a plane through the facet itself could then
/// cut the hull.
std::vector<std::pair<Vec3, double>> planesOf(const TriMesh& hull) {
  std::vector<std::pair<Vec3, double>> planes;
  for (std::size_t f = 0; f < hull.faces.size(); ++f) {
    const Vec3 n = faceNormal(hull, static_cast<int>(f));
    if (!(n.norm() > 0)) continue;
    const Vec3 u = n.normalized();
    double support = -std::numeric_limits<double>::infinity();
    for (const Vec3& v : hull.vertices) support = std::max(support, u.dot(v));
    planes.emplace_back(u, support);
  }
  return planes;
}

/// How far p lies outside the planes (<= 0 inside).
double outside(const std::vector<std::pair<Vec3, double>>& planes, const Vec3& p) {
  double off = -std::numeric_limits<double>::infinity();
  for (const auto& [u, support] : planes) off = std::max(off, u.dot(p) - support);
  return off;
}

Measured measure(const TriMesh& input, const Decomposition& d) {
  Measured m;
  const acdtest::MeshIndex index(input);
  std::mt19937_64 rng(5);
  for (const Component& c : d.components)
    for (const Vec3& p : acdtest::sampleSurface(c.hull, 400, rng)) {
      if (index.inside(p)) continue;
      m.hullsOff = std::max(m.hullsOff, index.distance(p));
    }
  const double slack = 1e-9 * (index.hi() - index.lo()).norm();
  std::vector<std::vector<std::pair<Vec3, double>>> hullPlanes;
  for (const Component& c : d.components) hullPlanes.push_back(planesOf(c.hull));
  for (const Vec3& p : acdtest::sampleSurface(input, 4000, rng)) {
    // Outside every hull: how far from the nearest (the largest plane distance, a lower bound of
    // the true distance, is enough to fail on).
    double best = std::numeric_limits<double>::infinity();
    for (const auto& planes : hullPlanes) best = std::min(best, outside(planes, p));
    m.inputOutside = std::max(m.inputOutside, std::max(0.0, best - slack));
  }
  return m;
}

}  // namespace

TEST(RealAssemblies, EveryHullWithinTauOfTheInputAndTheInputCovered) {
  const std::string dir = std::string(ACD_WIDE_DATA_DIR) + "/develop/";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "wide data set not found: " << dir;
  const double tau = 0.05;
  // Shells that pass through and touch each other (box, chair, pole, two objects), apart (multibody),
  // and a scene of several meshes (Duck).
  for (const char* name : {"box.STL", "chair_model.obj", "simple_pole.glb", "two_objects.obj", "multibody.stl",
                           "Duck.glb"}) {
    const ReadResult read = readMesh(dir + name);
    ASSERT_TRUE(read.status.ok()) << name << ": " << read.status.message;
    DecomposeOptions o = recommendedOptions();
    o.tau = tau;
    const Decomposition d = decompose(read.mesh, o);
    ASSERT_TRUE(d.status.ok()) << name << ": " << d.status.message;
    const double radius = 1.0 / d.normalization.scale;
    const Measured m = measure(read.mesh, d);
    // The library samples its measure at a fraction of tau: a tenth more for what its samples miss.
    EXPECT_LE(m.hullsOff, 1.1 * tau * radius) << name << ": " << d.components.size() << " hulls";
    EXPECT_LE(m.inputOutside, 1e-6 * radius) << name;
  }
}

// A CAD export's ear-clipped faces are fans of slivers; cuts through them leave needles along the
// pocket's floor that once misled the pocket measure into nine cuts at one notch and then the
// whole plate through its wrap (56 hulls at tau 0.0175). The hull, measured directly after three
// such stalls, shows the true notch: the pocket's corners.
TEST(CadExports, ASliveredPlateIsDecomposedWithoutItsWrap) {
  const ReadResult read = readMesh(std::string(ACD_TEST_DATA_DIR) + "/pocketed_plate_earclipped.off");
  ASSERT_TRUE(read.status.ok()) << read.status.message;
  DecomposeOptions o = recommendedOptions();
  o.tau = 0.0175;
  const Decomposition d = decompose(read.mesh, o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_FALSE(d.wrap.used);
  for (const Component& c : d.components) EXPECT_FALSE(c.unresolved) << c.note;
  // A plate, one octagonal pocket and four bores: 22 hulls (the same plate as OpenSCAD
  // triangulates it: 22); the wrap took 56.
  EXPECT_LE(d.components.size(), 30u);
  const double radius = 1.0 / d.normalization.scale;
  const Measured m = measure(read.mesh, d);
  EXPECT_LE(m.hullsOff, 1.1 * o.tau * radius);
  EXPECT_LE(m.inputOutside, 1e-6 * radius);
}

