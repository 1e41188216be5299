// findGlobalCut (Section 4.2) on a shape whose right cut is known: the dumbbell's bar meets each
// ball in a circle at the notch, so a global cut grown from the notch must ring the bar there and
// fit a plane across the bar (normal along z, the bar's axis).
#include <acd/algo/concavity.hpp>
#include <acd/algo/cut_plane.hpp>
#include <acd/algo/features.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <cmath>

using namespace acd;

namespace {

TEST(FindGlobalCut, DumbbellCutsFromTheNotchRingTheBar) {
  const TriMesh m = acdtest::normalised(shapes::dumbbell());
  const SurfaceGraph graph(m);
  const ConcavityMap map = acdtest::measure(m, 0.025);
  ASSERT_GT(map.concavity, 0.1);
  const double z = m.vertices[map.notch].z();
  // With the notch taken as an end of the root pocket cut (variants 0 and 2). The other two
  // variants let a leg run along the bar on this shape: they are candidates the lookahead may
  // reject, not cuts that must be right on their own.
  for (int variant : {0, 2}) {
    SCOPED_TRACE(variant);
    FeatureOptions fo;
    fo.delta = 0.0025;
    fo.matchKnots = variant < 2;
    fo.notchAsEnd = variant % 2 == 0;
    const GlobalCut cut = findGlobalCut(m, graph, map, fo);
    ASSERT_GE(cut.vertices.size(), 3u);
    ASSERT_EQ(cut.weight.size(), cut.vertices.size());
    double radius = 0.0;
    for (int v : cut.vertices) {
      EXPECT_NEAR(m.vertices[v].z(), z, 0.05) << "cut vertex " << v;
      radius = std::max(radius, std::hypot(m.vertices[v].x(), m.vertices[v].y()));
    }
    // Near the bar (radius 0.15 before normalisation, which scales by about 1/3), not out on a ball.
    EXPECT_LT(radius, 0.15);
    const Plane p = fitCutPlane(m, cut, map.bridges[map.vertexBridge[map.notch]].normal, 0.025);
    EXPECT_GT(std::abs(p.normal.normalized().z()), 0.95);
  }
}

}  // namespace
