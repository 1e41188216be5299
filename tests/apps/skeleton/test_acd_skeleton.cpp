// Skeletons from decompositions: the L-shape, a ring cut into two halves, and a corpus model.
#include "acd_skeleton.hpp"
#include "ged.hpp"

#include <acd/algo/cut.hpp>
#include <acd/decompose.hpp>
#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace skeleton;

namespace {

std::vector<acd::TriMesh> componentsOf(const acd::TriMesh& mesh, double tau) {
  acd::DecomposeOptions options;
  options.tau = tau;
  const acd::Decomposition d = acd::decompose(mesh, options);
  EXPECT_TRUE(d.status.ok()) << d.status.message;
  std::vector<acd::TriMesh> parts;
  for (const acd::Component& c : d.components) parts.push_back(c.mesh);
  return parts;
}

Graph pathGraph(int n) {
  std::vector<std::pair<int, int>> e;
  for (int i = 0; i + 1 < n; ++i) e.push_back({i, i + 1});
  return makeGraph(n, e);
}

}  // namespace

TEST(AcdSkeleton, CentroidOfKnownSolids) {
  const acd::TriMesh box = acd::shapes::box(Vec3(1, 2, 3), Vec3(3, 3, 7));
  EXPECT_LT((solidCentroid(box) - Vec3(2, 2.5, 5)).norm(), 1e-12);
  // An L of three unit cells: cells (0,0), (1,0), (0,1) -> centroid (5/6, 5/6) in xy.
  const acd::TriMesh l = acd::shapes::voxels({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  EXPECT_LT((solidCentroid(l) - Vec3(5.0 / 6, 5.0 / 6, 0.5)).norm(), 1e-12);
}

TEST(AcdSkeleton, LShapeIsOneCutBetweenTwoComponents) {
  const acd::TriMesh l = acd::shapes::lShape();
  const std::vector<acd::TriMesh> parts = componentsOf(l, 0.05);
  ASSERT_EQ(parts.size(), 2u);
  const Graph g = skeletonFromComponents(parts);
  ASSERT_EQ(g.nodeCount(), 3);
  ASSERT_EQ(g.edgeCount(), 2);
  EXPECT_EQ(g.nodes[0].kind, NodeKind::Component);
  EXPECT_EQ(g.nodes[1].kind, NodeKind::Component);
  EXPECT_EQ(g.nodes[2].kind, NodeKind::Cut);
  EXPECT_EQ(g.edges[0], std::make_pair(0, 2));
  EXPECT_EQ(g.edges[1], std::make_pair(1, 2));
  // Component nodes sit at the centroids of the pieces; the cut's centre lies on both pieces'
  // shared cap, i.e. on the boundary of both, between their centroids along the cut normal.
  for (int i = 0; i < 2; ++i) EXPECT_LT((g.nodes[i].position - solidCentroid(parts[i])).norm(), 1e-12);
  const std::vector<Cut> cuts = findCuts(parts);
  ASSERT_EQ(cuts.size(), 1u);
  EXPECT_GT(cuts[0].area, 0.0);
  const double volume = acd::signedVolume(parts[0]) + acd::signedVolume(parts[1]);
  EXPECT_NEAR(volume, acd::signedVolume(l), 1e-9);
  // The L (unit cells, depth 1 along z) is cut through its reflex edge x = y = 1: the section
  // is a rectangle of depth 1 and width between 1 (axis-parallel) and sqrt(2) (diagonal),
  // centred at mid-depth.
  EXPECT_GE(cuts[0].area, 1.0 - 1e-9);
  EXPECT_LE(cuts[0].area, std::sqrt(2.0) + 1e-9);
  EXPECT_NEAR(cuts[0].centre.z(), 0.5, 1e-9);
  EXPECT_GE(cuts[0].triangles, 2);
  // D2: the cut node has degree 2 and goes; one edge between the two components is left.
  const Graph c = contractDegreeTwo(g);
  EXPECT_EQ(c.nodeCount(), 2);
  EXPECT_EQ(c.edgeCount(), 1);
}

TEST(AcdSkeleton, CutsAreFoundWhereCapsDoNotShareTheirTriangles) {
  // A 3 x 2 x 1 block cut at x = 1.3, then its right piece at y = 0.7: the left piece's cap is
  // the whole 2 x 1 rectangle in two triangles, the right pieces' caps are its two parts. The
  // contacts, by construction: left-lower right 0.7 x 1, left-upper right 1.3 x 1, the two right
  // pieces 1.7 x 1, each one patch, centred on the rectangles.
  const acd::CutResult first =
      acd::cutByPlane(acd::shapes::box(Vec3::Zero(), Vec3(3, 2, 1)), acd::Plane::through(Vec3(1.3, 0, 0), Vec3::UnitX()));
  ASSERT_TRUE(first.ok) << first.error;
  const acd::CutResult second = acd::cutByPlane(first.above[0], acd::Plane::through(Vec3(0, 0.7, 0), Vec3::UnitY()));
  ASSERT_TRUE(second.ok) << second.error;
  const std::vector<acd::TriMesh> pieces{first.below[0], second.below[0], second.above[0]};
  const std::vector<Cut> cuts = findCuts(pieces);
  ASSERT_EQ(cuts.size(), 3u);
  const std::array<double, 3> area{0.7, 1.3, 1.7};
  const std::array<Vec3, 3> centre{Vec3(1.3, 0.35, 0.5), Vec3(1.3, 1.35, 0.5), Vec3(2.15, 0.7, 0.5)};
  const std::array<Vec3, 3> normal{Vec3::UnitX(), Vec3::UnitX(), Vec3::UnitY()};
  const std::array<std::pair<int, int>, 3> pair{std::pair{0, 1}, {0, 2}, {1, 2}};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(std::make_pair(cuts[k].a, cuts[k].b), pair[k]) << k;
    EXPECT_NEAR(cuts[k].area, area[k], 1e-9) << k;
    EXPECT_LT((cuts[k].centre - centre[k]).norm(), 1e-9) << k;
    EXPECT_LT((cuts[k].normal - normal[k]).norm(), 1e-9) << k;
  }
}

TEST(AcdSkeleton, ASmallFaceOnALargeOneIsFoundInEitherOrder) {
  // A 0.2 x 0.2 post under a 10 x 10 x 10 block: the block's bottom is two triangles of area 50,
  // whose splits (down to 1/256 of them) all miss the post; only the post's own side sees the
  // contact. Listed block first, it was missed until 2026-12-01.
  const acd::TriMesh block = acd::shapes::box(Vec3(0, 0, 0), Vec3(10, 10, 10));
  const acd::TriMesh post = acd::shapes::box(Vec3(4.9, 4.9, -1), Vec3(5.1, 5.1, 0));
  for (const bool blockFirst : {true, false}) {
    const std::vector<Cut> cuts = blockFirst ? findCuts({block, post}) : findCuts({post, block});
    ASSERT_EQ(cuts.size(), 1u) << blockFirst;
    EXPECT_NEAR(cuts[0].area, 0.04, 1e-12);
    EXPECT_LT((cuts[0].centre - Vec3(5, 5, 0)).norm(), 1e-12);
    // The normal points out of the first component: down out of the block, up out of the post.
    EXPECT_NEAR(cuts[0].normal.z(), blockFirst ? -1.0 : 1.0, 1e-12);
  }
}

TEST(AcdSkeleton, RingCutInTwoHasTwoCutsAndACycle) {
  const acd::TriMesh ring = acd::shapes::torus(2.0, 0.5, 48, 16);
  const acd::CutResult cut = acd::cutByPlane(ring, acd::Plane::through(Vec3::Zero(), Vec3(1, 0.1, 0)));
  ASSERT_TRUE(cut.ok) << cut.error;
  ASSERT_EQ(cut.below.size(), 1u);
  ASSERT_EQ(cut.above.size(), 1u);
  const std::vector<acd::TriMesh> halves{cut.below[0], cut.above[0]};
  const std::vector<Cut> cuts = findCuts(halves);
  ASSERT_EQ(cuts.size(), 2u);  // the two halves touch at two separate discs
  for (const Cut& c : cuts) {
    EXPECT_EQ(c.a, 0);
    EXPECT_EQ(c.b, 1);
    EXPECT_NEAR(c.area, 0.5 * 16 * 0.25 * std::sin(2 * M_PI / 16), 0.02);  // the tube's 16-gon section
    EXPECT_NEAR(Vec3(c.centre.x(), c.centre.y(), 0).norm(), 2.0, 0.02);  // on the tube's centre circle
    EXPECT_NEAR(c.centre.z(), 0.0, 1e-9);
  }
  EXPECT_GT((cuts[0].centre - cuts[1].centre).norm(), 3.9);  // opposite sides of the ring
  const Graph g = skeletonFromComponents(halves);
  EXPECT_EQ(g.nodeCount(), 4);
  EXPECT_EQ(g.edgeCount(), 4);  // a 4-cycle: the ring's hole survives in the skeleton
  const Graph c = contractDegreeTwo(g);
  EXPECT_EQ(c.edgeCount() - c.nodeCount(), 0);  // still one cycle
}

TEST(AcdSkeleton, DumbbellIsAPathOfComponents) {
  const acd::TriMesh dumbbell = acd::shapes::dumbbell(2.0, 0.15, 48, 24);
  const std::vector<acd::TriMesh> parts = componentsOf(dumbbell, 0.1);
  ASSERT_GE(parts.size(), 2u);
  const Graph g = skeletonFromComponents(parts);
  // Pieces follow the bar: the skeleton is a path, and contracting it leaves one edge.
  EXPECT_EQ(connectedComponents(g), 1);
  EXPECT_EQ(g.edgeCount(), g.nodeCount() - 1);
  const Graph c = contractDegreeTwo(g);
  EXPECT_EQ(exactGed(c, pathGraph(2)).distance, 0);
  // Every node lies on the axis of revolution (z).
  for (const Node& n : g.nodes) EXPECT_LT(Vec3(n.position.x(), n.position.y(), 0).norm(), 0.05);
}

TEST(AcdSkeleton, CorpusModelIsConnectedAndEveryCutJoinsTwoComponents) {
  const acd::ReadResult r = acd::readMesh(std::string(SKELETON_DATA_DIR) + "/meshes/elephant.off");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const std::vector<acd::TriMesh> parts = componentsOf(r.mesh, 0.1);
  ASSERT_GE(parts.size(), 5u);
  const Graph g = skeletonFromComponents(parts);
  EXPECT_EQ(connectedComponents(g), 1);  // the elephant is one solid, so its pieces all touch
  const std::vector<int> deg = degrees(g);
  int cuts = 0;
  for (int i = 0; i < g.nodeCount(); ++i) {
    if (g.nodes[i].kind == NodeKind::Cut) {
      ++cuts;
      EXPECT_EQ(deg[i], 2);
    } else {
      EXPECT_EQ(g.nodes[i].kind, NodeKind::Component);
      EXPECT_GE(deg[i], 1);
    }
  }
  EXPECT_EQ(g.nodeCount(), static_cast<int>(parts.size()) + cuts);
  EXPECT_EQ(g.edgeCount(), 2 * cuts);
  // A cut's centre is the centroid of a cap on both components' surfaces, so it lies inside the
  // bounding box of each of them.
  for (const auto& [a, b] : g.edges) {
    const int comp = g.nodes[a].kind == NodeKind::Component ? a : b;
    const int cut = comp == a ? b : a;
    const acd::Box3 box = acd::boundingBox(parts[g.nodes[comp].source]);
    const Vec3 p = g.nodes[cut].position;
    EXPECT_TRUE((p.array() >= box.lo.array() - 1e-9).all() && (p.array() <= box.hi.array() + 1e-9).all())
        << "cut node " << cut << " outside component " << g.nodes[comp].source;
  }
}
