// CGAL's mean-curvature-flow skeleton through our wrapper.
#include "mcf_skeleton.hpp"

#include <acd/algo/inside.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

using namespace skeleton;

TEST(McfSkeleton, DumbbellSkeletonIsAConnectedCurveInside) {
  const acd::TriMesh dumbbell = acd::shapes::dumbbell(2.0, 0.3, 48, 24);
  const McfSkeleton s = meanCurvatureSkeleton(dumbbell);
  ASSERT_TRUE(s.ok) << s.error;
  ASSERT_GE(s.graph.nodeCount(), 3);
  EXPECT_EQ(connectedComponents(s.graph), 1);
  EXPECT_EQ(s.graph.edgeCount(), s.graph.nodeCount() - 1);  // a tree (no handle)
  const acd::InsideTest inside(dumbbell);
  double zmin = 1e9, zmax = -1e9;
  for (const Node& n : s.graph.nodes) {
    EXPECT_TRUE(inside.inside(n.position));
    EXPECT_LT(Vec3(n.position.x(), n.position.y(), 0).norm(), 0.2);  // near the axis
    zmin = std::min(zmin, n.position.z());
    zmax = std::max(zmax, n.position.z());
  }
  EXPECT_GT(zmax - zmin, 2.0);  // spans the bar between the balls
}

TEST(McfSkeleton, TorusSkeletonHasOneCycle) {
  const McfSkeleton s = meanCurvatureSkeleton(acd::shapes::torus(2.0, 0.6, 48, 16));
  ASSERT_TRUE(s.ok) << s.error;
  EXPECT_EQ(connectedComponents(s.graph), 1);
  EXPECT_EQ(s.graph.edgeCount() - s.graph.nodeCount() + 1, 1);  // cycle rank = genus
}

TEST(McfSkeleton, OpenMeshIsRefused) {
  acd::TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  box.faces.pop_back();
  const McfSkeleton s = meanCurvatureSkeleton(box);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.error.find("not closed"), std::string::npos) << s.error;
}
