// Bridge estimation (Appendix A, Algorithm 2) and concavity (Section 4.1, Observation 4.1).
#include <acd/algo/concavity.hpp>
#include <acd/algo/surface_graph.hpp>
#include <acd/algo/hull.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <string>

using namespace acd;
using acdtest::randomPoints;
using acdtest::corpus;
using acdtest::normalised;
using acdtest::measure;

namespace {



}  // namespace

// ------------------------------------------------------------------ Algorithm 2

TEST(BridgeCount, BoxHullHasSixBridgesUntilEpsilonExceedsItsSide) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const TriMesh hull = hullMesh(box.vertices);
  for (double eps : {1e-9, 0.01, 0.5, 0.999}) {
    std::vector<int> seeds;
    EXPECT_EQ(estimateBridgeCount(hull, eps, &seeds), 6) << eps;
    EXPECT_EQ(seeds.size(), 6u);
    std::set<std::pair<int, int>> normals;  // one seed per box side
    for (int s : seeds) {
      const Vec3 n = faceNormal(hull, s).normalized();
      int axis = 0;
      n.cwiseAbs().maxCoeff(&axis);
      normals.insert({axis, n[axis] > 0 ? 1 : -1});
    }
    EXPECT_EQ(normals.size(), 6u) << eps;
  }
  // Every facet of a unit cube lies within 1 of every facet plane: one bridge covers it all.
  EXPECT_EQ(estimateBridgeCount(hull, 1.01), 1);
  // epsilon <= 0: nothing is within epsilon, one bridge per facet.
  EXPECT_EQ(estimateBridgeCount(hull, 0.0), static_cast<int>(hull.faces.size()));
}

TEST(BridgeCount, FlatBoxSeedsLargestFacesFirst) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(4, 3, 0.5));
  const TriMesh hull = hullMesh(box.vertices);
  std::vector<int> seeds;
  EXPECT_EQ(estimateBridgeCount(hull, 0.1, &seeds), 6);
  ASSERT_FALSE(seeds.empty());
  EXPECT_GT(std::abs(faceNormal(hull, seeds[0]).normalized().z()), 0.999);  // a 4x3 face
  // Every facet lies within 0.5 of the big faces' planes: above that one bridge covers the box.
  EXPECT_EQ(estimateBridgeCount(hull, 0.6), 1);
}

TEST(BridgeCount, MonotoneInEpsilonOnAnIcosphereHull) {
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  const TriMesh hull = hullMesh(sphere.vertices);
  int previous = std::numeric_limits<int>::max();
  std::vector<int> counts;
  for (double eps : {0.0, 1e-4, 1e-3, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.5, 0.8, 1.0, 1.5, 2.5}) {
    const int n = estimateBridgeCount(hull, eps);
    counts.push_back(n);
    EXPECT_LE(n, previous) << "epsilon " << eps;
    EXPECT_GE(n, 1);
    previous = n;
  }
  EXPECT_EQ(counts.front(), static_cast<int>(hull.faces.size()));
  EXPECT_EQ(counts.back(), 1);  // every facet is within the diameter 2 of every tangent plane
  EXPECT_LT(counts[6], counts[1] / 4);  // 0.05 clusters the 1280 facets substantially
}

// ------------------------------------------------------------------ concavity

TEST(Concavity, ConvexInputsAreWithinEpsilonOfZero) {
  const std::vector<std::pair<const char*, TriMesh>> cases = {
      {"box", shapes::box(Vec3(-1, 0, 2), Vec3(3, 1, 2.5))},
      {"icosphere", shapes::icosphere(Vec3(0.5, 0.5, 0.5), 3.0, 3)},
      {"hull", hullMesh(randomPoints(300, 11, true))}};
  for (const auto& [name, mesh] : cases) {
    for (double eps : {0.1, 0.025, 0.01}) {
      SCOPED_TRACE(std::string(name) + " eps " + std::to_string(eps));
      const TriMesh m = normalised(mesh);
      const ConcavityMap map = measure(m, eps);
      EXPECT_LT(map.concavity, eps);
      EXPECT_GE(map.concavity, 0.0);
      for (double c : map.facetConcavity) EXPECT_LE(c, 1e-12);  // every vertex is on the hull
    }
  }
}

TEST(Concavity, UShapeNotchIsAtTheSlotBottomAndItsDepthIsTheSlotDepth) {
  const TriMesh u = shapes::uShape();  // slot x in [1,2], y in [1,3]: 2 deep
  const Normalization n = minimumSphereNormalization(u);
  EXPECT_NEAR(n.scale, 2.0 / std::sqrt(19.0), 1e-9);  // sphere of the 3x3x1 box
  const TriMesh m = applyNormalization(u, n);
  const double depth = 2.0 * n.scale;
  for (double eps : {0.1, 0.025, 0.01}) {
    SCOPED_TRACE(eps);
    const ConcavityMap map = measure(m, eps);
    EXPECT_NEAR(map.concavity, depth, eps);
    EXPECT_GE(map.concavity, depth - 1e-12);  // the estimate never undershoots the true depth here
    ASSERT_GE(map.notch, 0);
    const Vec3 notch = u.vertices[map.notch];
    EXPECT_EQ(notch.y(), 1.0) << notch.transpose();
    EXPECT_TRUE(notch.x() == 1.0 || notch.x() == 2.0) << notch.transpose();
    EXPECT_EQ(map.vertexConcavity[map.notch], map.concavity);
    // The notch's bridge closes the slot: its plane is y = 3 (normal +y in input coordinates).
    const Bridge& b = map.bridges[map.vertexBridge[map.notch]];
    EXPECT_GT(b.normal.y(), 1 - 1e-9);
  }
}

// Vertices on the U's outer boundary lie on the convex hull (true concavity 0: the paper's pockets are
// the boundary minus the hull boundary). The Dijkstra projection of the hull edge (3,3,0)-(0,3,0)
// shortcuts over bottom-face diagonals, so bottom triangles of the arms border the y = 3 bridge's
// pocket too; they must still not inherit its depth.
TEST(Concavity, UShapeVerticesOnTheHullHaveConcavityBelowEpsilon) {
  const TriMesh u = shapes::uShape();
  const TriMesh m = normalised(u);
  for (double eps : {0.1, 0.025, 0.01}) {
    SCOPED_TRACE(eps);
    const ConcavityMap map = measure(m, eps);
    for (std::size_t v = 0; v < u.vertices.size(); ++v) {
      const Vec3& p = u.vertices[v];
      const bool inSlot = p.x() > 0.5 && p.x() < 2.5 && p.y() > 0.5;
      if (!inSlot) EXPECT_LT(map.vertexConcavity[v], eps) << p.transpose();
    }
  }
}

TEST(Concavity, LShapeConcavityIsTheInnerCornerDistance) {
  // The L's hull cuts the inner corner (1,1) by the plane x + y = 3; the corner is 1/sqrt(2) below it.
  const TriMesh l = shapes::lShape();
  const Normalization n = minimumSphereNormalization(l);
  const TriMesh m = applyNormalization(l, n);
  const double depth = n.scale / std::sqrt(2.0);
  for (double eps : {0.1, 0.025, 0.01}) {
    const ConcavityMap map = measure(m, eps);
    EXPECT_NEAR(map.concavity, depth, eps) << eps;
    ASSERT_GE(map.notch, 0);
    EXPECT_EQ(l.vertices[map.notch].x(), 1.0);
    EXPECT_EQ(l.vertices[map.notch].y(), 1.0);
  }
}

TEST(Concavity, DumbbellNotchIsOnTheBar) {
  const TriMesh m = normalised(shapes::dumbbell());
  const ConcavityMap map = measure(m, 0.025);
  ASSERT_GE(map.notch, 0);
  // Balls of radius 1 at z = +-2, normalised by 1/3: the bar (radius 0.15/3) lies 0.95/3 below the
  // tangent plane x = 1/3 of the hull's cylindrical part.
  EXPECT_NEAR(map.concavity, 0.85 / 3.0, 0.025);
  const Vec3 notch = m.vertices[map.notch];
  EXPECT_LE(std::abs(notch.z()), 1.0 / 3.0 + 1e-12) << notch.transpose();       // on the bar, ends included
  EXPECT_NEAR(std::hypot(notch.x(), notch.y()), 0.15 / 3.0, 1e-9) << notch.transpose();
}

// Observation 4.1: the bridge-patch estimate exceeds the per-facet concavity by less than epsilon.
class Observation41 : public ::testing::TestWithParam<std::string> {};

TEST_P(Observation41, VertexConcavityIsWithinEpsilonOfFacetConcavity) {
  const std::string name = GetParam();
  TriMesh mesh;
  if (name == "dumbbell") mesh = shapes::dumbbell();
  else if (name == "U") mesh = shapes::uShape();
  else if (name == "torus") mesh = shapes::torus(2.0, 0.5, 64, 32);
  else {
    const std::string path = corpus(name);
    if (!std::ifstream(path)) GTEST_SKIP() << path << " not present";
    ReadResult r = readMesh(path);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    mesh = std::move(r.mesh);
  }
  ASSERT_TRUE(isClosedOriented(mesh));
  const TriMesh m = normalised(mesh);
  SurfaceGraph graph(m);
  for (double eps : {0.1, 0.025, 0.01}) {
    SCOPED_TRACE("epsilon " + std::to_string(eps));
    ConcavityOptions o;
    o.epsilon = eps;
    const ConcavityMap map = measureConcavity(m, graph, o);
    ASSERT_EQ(map.vertexConcavity.size(), m.vertices.size());
    ASSERT_EQ(map.facetConcavity.size(), m.vertices.size());
    int below = 0, beyond = 0, worst = -1;
    double worstGap = 0;
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
      const double gap = map.vertexConcavity[v] - map.facetConcavity[v];
      below += gap < -1e-12;
      beyond += gap >= eps;
      if (gap > worstGap) worstGap = gap, worst = static_cast<int>(v);
    }
    RecordProperty("worst_gap_eps_" + std::to_string(eps), std::to_string(worstGap));
    EXPECT_EQ(below, 0) << "vertices whose estimate is below their facet concavity";
    EXPECT_EQ(beyond, 0) << "vertices with estimate - facet >= epsilon; worst gap " << worstGap << " at vertex "
                         << worst << " (bridges " << map.bridges.size() << ", refinements " << map.refinements << ")";
    EXPECT_GE(map.concavity, 0.0);
    EXPECT_EQ(map.concavity, *std::max_element(map.vertexConcavity.begin(), map.vertexConcavity.end()));
  }
  // epsilon <= 0: one bridge per hull facet, so the estimate is the facet concavity itself.
  const ConcavityMap exact = measure(m, 0.0);
  EXPECT_EQ(exact.bridges.size(), exact.hull.mesh.faces.size());
  int differ = 0;
  for (std::size_t v = 0; v < m.vertices.size(); ++v) differ += exact.vertexConcavity[v] != exact.facetConcavity[v];
  EXPECT_EQ(differ, 0);
}

INSTANTIATE_TEST_SUITE_P(Shapes, Observation41, ::testing::Values("dumbbell", "U", "torus"),
                         [](const auto& info) { return info.param; });

// DISABLED: fails with the current library. measureConcavity gives up refining after 16 patch
// splits, leaving vertices whose estimate exceeds the per-facet concavity by epsilon or more:
// elephant (eps 0.025: 5 vertices, worst gap 0.0280; eps 0.01: 56 vertices, worst 0.0152) and
// armadillo (eps 0.025: 219 vertices, worst 0.0363; eps 0.01: 2059 vertices, worst 0.0232).
INSTANTIATE_TEST_SUITE_P(Corpus, Observation41, ::testing::Values("elephant", "armadillo"),
                         [](const auto& info) { return info.param; });
