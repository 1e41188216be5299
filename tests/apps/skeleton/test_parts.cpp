// Parts and their skeleton: tubes cut across are one part, a thin limb on a wide body is its own;
// a speck below tau's resolution goes into its neighbour; a ring's handle counted, and drawn as a cycle only when asked; a jointed stick figure of capsules, straight and bent at a joint by a
// known angle, whose right skeleton is known by construction; matching by shared vertices.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <acd/algo/cut.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/shapes.hpp>
#include <acd/algo/shell_union.hpp>
#include <acd/decompose.hpp>
#include <array>
#include <cmath>

#include "acd_skeleton.hpp"
#include "correspondence.hpp"
#include "ged.hpp"
#include "part_voxels.hpp"
#include "parts.hpp"

using namespace skeleton;

namespace {

/// Capsule of radius r from a to b (a cylinder with hemispherical ends), as a closed mesh.
acd::TriMesh capsule(const Vec3& a, const Vec3& b, double r) {
  const double h = 0.5 * (b - a).norm();
  acd::TriMesh m = acd::shapes::revolve(
      [h, r](double z) {
        const double over = std::max(0.0, std::abs(z) - h);
        return std::sqrt(std::max(r * r - over * over, 0.0)) + 1e-4 * r;
      },
      -h - r, h + r, 48, 20);
  const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), (b - a).normalized());
  for (Vec3& v : m.vertices) v = 0.5 * (a + b) + turn * v;
  return m;
}

/// A stick figure: a torso (z 0..2), a head ball, two arms of two segments (shoulder to elbow to
/// hand) and two legs of two segments; the right elbow bent by `elbowDegrees` in the xz plane.
/// The capsules overlap at the joints; their union is the figure.
acd::TriMesh stickFigure(double elbowDegrees) {
  std::vector<acd::TriMesh> shells;
  shells.push_back(capsule(Vec3(0, 0, 0), Vec3(0, 0, 2), 0.45));       // torso
  shells.push_back(acd::shapes::icosphere(Vec3(0, 0, 2.75), 0.4, 3));  // head
  const double k = elbowDegrees * M_PI / 180.0;
  for (int side : {-1, 1}) {
    const Vec3 shoulder(side * 0.35, 0, 1.9), elbow(side * 1.4, 0, 1.9);
    const Vec3 hand = side > 0 ? Vec3(elbow + Vec3(std::cos(k), 0, std::sin(k))) : Vec3(side * 2.4, 0, 1.9);
    shells.push_back(capsule(shoulder, elbow, 0.15));
    shells.push_back(capsule(elbow, hand, 0.13));
    const Vec3 hip(side * 0.25, 0, 0.1), knee(side * 0.45, 0, -1.1), foot(side * 0.5, 0, -2.2);
    shells.push_back(capsule(hip, knee, 0.17));
    shells.push_back(capsule(knee, foot, 0.15));
  }
  const acd::ShellUnion u = acd::uniteMeetingShells(shells, false);
  EXPECT_EQ(u.leftAlone, 0) << u.firstFailure;
  EXPECT_EQ(u.shells.size(), 1u);
  return u.shells.empty() ? acd::TriMesh{} : u.shells[0];
}

struct PartSkeleton {
  std::vector<acd::TriMesh> components;
  Parts parts;
  Graph graph;
};

PartSkeleton partSkeleton(const acd::TriMesh& mesh, double tau) {
  acd::DecomposeOptions options;
  options.tau = tau;
  options.invariant = true;
  options.mergeScope = acd::MergeScope::Component;
  const acd::Decomposition d = acd::decompose(mesh, options);
  EXPECT_TRUE(d.status.ok()) << d.status.message;
  PartSkeleton s;
  for (const acd::Component& c : d.components) s.components.push_back(c.mesh);
  s.parts = groupIntoParts(s.components, genusOf(mesh));
  s.graph = skeletonFromParts(s.parts);
  return s;
}

/// A star: one centre joined to `leaves` leaves.
Graph star(int leaves) {
  std::vector<std::pair<int, int>> e;
  for (int i = 1; i <= leaves; ++i) e.push_back({0, i});
  return makeGraph(leaves + 1, e);
}

}  // namespace

TEST(Parts, GenusCountsHandles) {
  EXPECT_EQ(genusOf(acd::shapes::icosphere(Vec3::Zero(), 1.0, 2)), 0);
  EXPECT_EQ(genusOf(acd::shapes::torus(2.0, 0.5, 32, 12)), 1);
  acd::TriMesh two = acd::shapes::torus(2.0, 0.5, 32, 12);
  acd::TriMesh other = acd::shapes::torus(2.0, 0.5, 24, 10);
  const int base = static_cast<int>(two.vertices.size());
  for (const Vec3& v : other.vertices) two.vertices.push_back(v + Vec3(10, 0, 0));
  for (const acd::Face& f : other.faces) two.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  EXPECT_EQ(genusOf(two), 2);  // two rings: one handle each
}

TEST(Parts, ATubeCutAcrossIsOnePart) {
  // A bar 1 x 1 x 6 cut square into three: every cut has the area of the bar's section, ratio 1.
  const acd::TriMesh bar = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 6));
  const acd::CutResult first = acd::cutByPlane(bar, acd::Plane::through(Vec3(0, 0, 2), Vec3(0, 0, 1)));
  ASSERT_TRUE(first.ok) << first.error;
  const acd::CutResult second = acd::cutByPlane(first.above[0], acd::Plane::through(Vec3(0, 0, 4), Vec3(0, 0, 1)));
  ASSERT_TRUE(second.ok) << second.error;
  const std::vector<acd::TriMesh> pieces{first.below[0], second.below[0], second.above[0]};
  const Parts parts = groupIntoParts(pieces, 0);
  EXPECT_EQ(parts.members.size(), 1u);
  EXPECT_EQ(parts.merges, 2);
  EXPECT_NEAR(parts.volume[0], 6.0, 1e-9);
  EXPECT_LT((parts.centroid[0] - Vec3(0.5, 0.5, 3)).norm(), 1e-9);
  EXPECT_TRUE(parts.joints.empty());
}

TEST(Parts, AThinLimbOnAWideBodyIsAPartOfItsOwn) {
  // A body of 3 x 3 x 3 unit cells with a limb of 1 x 1 x 3 cells on the middle of its top; cut
  // across the limb at z = 3.5 (where it meets the body) and at z = 5 (along it).
  std::vector<std::array<int, 3>> cells;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 3; ++z) cells.push_back({x, y, z});
  for (int z = 3; z < 6; ++z) cells.push_back({1, 1, z});
  const acd::TriMesh t = acd::shapes::voxels(cells);
  const acd::CutResult root = acd::cutByPlane(t, acd::Plane::through(Vec3(0, 0, 3.5), Vec3(0, 0, 1)));
  ASSERT_TRUE(root.ok) << root.error;
  const acd::CutResult along = acd::cutByPlane(root.above[0], acd::Plane::through(Vec3(0, 0, 5), Vec3(0, 0, 1)));
  ASSERT_TRUE(along.ok) << along.error;
  const std::vector<acd::TriMesh> pieces{root.below[0], along.below[0], along.above[0]};
  // Across the limb at z = 5: the section (1) against both sides' mean sections (1.5 / 1.5 and
  // 1 / 1): ratio 1, merged. At the root: 1 against the body's (27.5 / 3.5): 0.13, kept.
  const Parts parts = groupIntoParts(pieces, 0);
  ASSERT_EQ(parts.members.size(), 2u);
  EXPECT_EQ(parts.members[0], std::vector<int>{0});
  EXPECT_EQ(parts.members[1], (std::vector<int>{1, 2}));
  EXPECT_NEAR(parts.volume[0], 27.5, 1e-9);
  EXPECT_NEAR(parts.volume[1], 2.5, 1e-9);
  EXPECT_LT((parts.centroid[1] - Vec3(1.5, 1.5, 4.75)).norm(), 1e-9);
  ASSERT_EQ(parts.joints.size(), 1u);
  EXPECT_NEAR(parts.joints[0].area, 1.0, 1e-9);
  EXPECT_LT((parts.joints[0].centre - Vec3(1.5, 1.5, 3.5)).norm(), 1e-9);
  // A threshold above the root's ratio merges everything.
  EXPECT_EQ(groupIntoParts(pieces, 0, false, 0.1).members.size(), 1u);
  const Graph g = skeletonFromParts(parts);
  EXPECT_EQ(g.nodeCount(), 3);  // two parts and the cut between them
  EXPECT_EQ(g.edgeCount(), 2);
}

TEST(Parts, ASpeckBelowTausResolutionGoesIntoItsNeighbour) {
  // A body 10 x 10 x 10 (volume 1000), a limb 1 x 1 x 4 on its top (4: 0.4 %), and a thin tail of
  // two boxes 0.2 x 0.2 x 1 under it (0.04 each: 0.008 % together), all touching face to face.
  // The tail's two boxes are a tube cut across (ratio 1); neither the limb nor the tail meets the
  // body across a tube (ratios 0.01 and 0.0004) or is a stub (elongations 4 and 10): three parts.
  // At tau = 0.1 a speck holds less than tau^3 of the volume (1): the tail goes into the body,
  // the limb stays.
  const std::vector<acd::TriMesh> pieces{
      acd::shapes::box(Vec3(4.9, 4.9, -2), Vec3(5.1, 5.1, -1)),   // tail tip
      acd::shapes::box(Vec3(0, 0, 0), Vec3(10, 10, 10)),          // body
      acd::shapes::box(Vec3(4.9, 4.9, -1), Vec3(5.1, 5.1, 0)),    // tail root
      acd::shapes::box(Vec3(4.5, 4.5, 10), Vec3(5.5, 5.5, 14))};  // limb
  const Parts plain = groupIntoParts(pieces, 0);
  EXPECT_EQ(plain.members.size(), 3u);
  EXPECT_DOUBLE_EQ(leastPartShare(0.1), 1e-3);
  const Parts parts = groupIntoParts(pieces, 0, false, kTubeRatio, leastPartShare(0.1));
  ASSERT_EQ(parts.members.size(), 2u);
  EXPECT_EQ(parts.members[0], (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(parts.members[1], std::vector<int>{3});
  EXPECT_NEAR(parts.volume[0], 1000.08, 1e-9);
  ASSERT_EQ(parts.joints.size(), 1u);
  EXPECT_NEAR(parts.joints[0].area, 1.0, 1e-9);
  // The limb is no speck at a share below its own (0.4 %), and everything is one above it.
  EXPECT_EQ(groupIntoParts(pieces, 0, false, kTubeRatio, 3e-3).members.size(), 2u);
  EXPECT_EQ(groupIntoParts(pieces, 0, false, kTubeRatio, 5e-3).members.size(), 1u);
  // The same parts whatever order the pieces come in (the tail listed first or last).
  const std::vector<acd::TriMesh> reordered{pieces[1], pieces[3], pieces[2], pieces[0]};
  const Parts again = groupIntoParts(reordered, 0, false, kTubeRatio, leastPartShare(0.1));
  ASSERT_EQ(again.members.size(), 2u);
  EXPECT_EQ(again.members[0], (std::vector<int>{0, 2, 3}));
  EXPECT_EQ(again.members[1], std::vector<int>{1});
}

TEST(Parts, ARingsHandleIsCountedAndDrawnOnlyWhenAsked) {
  // A ring cut into four quarters, merging off (threshold out of reach): the quarters' adjacency
  // is a 4-cycle and the ring has one handle, which runs through every contact.
  const acd::TriMesh ring = acd::shapes::torus(2.0, 0.5, 64, 16);
  const acd::CutResult half = acd::cutByPlane(ring, acd::Plane::through(Vec3::Zero(), Vec3(1, 0.01, 0)));
  ASSERT_TRUE(half.ok) << half.error;
  std::vector<acd::TriMesh> quarters;
  for (const acd::TriMesh& h : {half.below[0], half.above[0]}) {
    const acd::CutResult q = acd::cutByPlane(h, acd::Plane::through(Vec3::Zero(), Vec3(0.01, 1, 0)));
    ASSERT_TRUE(q.ok) << q.error;
    quarters.push_back(q.below[0]);
    quarters.push_back(q.above[0]);
  }
  // By default a tree: the smallest adjacency goes; the handle is in the counts.
  const Parts tree = groupIntoParts(quarters, 1, false, 1e9);
  EXPECT_EQ(tree.members.size(), 4u);
  EXPECT_EQ(tree.joints.size(), 3u);
  EXPECT_EQ(tree.droppedAdjacencies, 1);
  EXPECT_EQ(tree.loopGrid, kPartGridSizes[0]);
  EXPECT_EQ(tree.handles, std::vector<int>(4, 0));
  EXPECT_EQ(tree.loopJoints.size(), 4u);
  // Asked for, the cycle stays.
  const Parts kept = groupIntoParts(quarters, 1, true, 1e9);
  EXPECT_EQ(kept.joints.size(), 4u);
  EXPECT_EQ(kept.droppedAdjacencies, 0);
  const Graph g = skeletonFromParts(kept);
  EXPECT_EQ(g.edgeCount() - g.nodeCount() + connectedComponents(g), 1);  // one independent cycle
  // Told the solid has no handle, no cycle and no counts.
  const Parts none = groupIntoParts(quarters, 0, true, 1e9);
  EXPECT_EQ(none.joints.size(), 3u);
  EXPECT_EQ(none.loopGrid, 0);
  // The whole ring one part (merging every tube-like cut): its handle is its own.
  const Parts one = groupIntoParts(quarters, 1, true);
  ASSERT_EQ(one.members.size(), 1u);
  EXPECT_EQ(one.handles, std::vector<int>{1});
  EXPECT_TRUE(one.joints.empty());
}

TEST(Parts, StickFigureHasTheSkeletonItWasBuiltWith) {
  // Torso, head, two arms, two legs: after contraction a star with five leaves, straight or with
  // the right elbow bent by 60 degrees; the ACD skeleton of parts must be that star both times.
  for (double elbow : {0.0, 60.0}) {
    SCOPED_TRACE("elbow " + std::to_string(elbow));
    const acd::TriMesh figure = stickFigure(elbow);
    ASSERT_FALSE(figure.faces.empty());
    EXPECT_EQ(genusOf(figure), 0);
    const PartSkeleton s = partSkeleton(figure, 0.05);
    EXPECT_GE(s.parts.members.size(), 6u);
    EXPECT_EQ(connectedComponents(s.graph), 1);
    EXPECT_EQ(s.graph.edgeCount(), 2 * (s.graph.nodeCount() - static_cast<int>(s.parts.members.size())));
    const Graph contracted = contractDegreeTwo(s.graph);
    const GedResult d = exactGed(contracted, star(5));
    EXPECT_TRUE(d.exact);
    EXPECT_EQ(d.distance, 0) << "contracted: " << contracted.nodeCount() << " nodes, " << contracted.edgeCount()
                             << " edges";
  }
}

TEST(Parts, MatchingBySharedVerticesIsTheIdentityOnTheSameMesh) {
  const acd::TriMesh figure = stickFigure(0.0);
  const PartSkeleton s = partSkeleton(figure, 0.05);
  std::vector<acd::TriMesh> hulls;
  for (const acd::TriMesh& c : s.components) hulls.push_back(acd::hullMesh(c.vertices));
  std::vector<int> vertexPart = componentOfVertices(figure, s.components, hulls);
  // Every vertex of the figure is a corner of some component (cutting keeps them).
  for (int c : vertexPart) ASSERT_GE(c, 0);
  for (int& v : vertexPart) v = s.parts.partOf[v];
  const std::vector<int> map = correspondenceMap(s.graph, vertexPart, s.graph, vertexPart);
  for (int i = 0; i < s.graph.nodeCount(); ++i) EXPECT_EQ(map[i], i);
  EXPECT_EQ(editPathCost(s.graph, s.graph, map), 0);
  // Parts renamed in the second graph: the map follows the vertices, not the names.
  std::vector<int> shifted = vertexPart;
  const int n = static_cast<int>(s.parts.members.size());
  for (int& v : shifted) v = (v + 1) % n;
  Graph renamed = s.graph;
  for (Node& node : renamed.nodes)
    if (node.kind == NodeKind::Component) node.source = (node.source + 1) % n;
  const std::vector<int> follow = correspondenceMap(s.graph, vertexPart, renamed, shifted);
  for (int i = 0; i < s.graph.nodeCount(); ++i) EXPECT_EQ(follow[i], i);
}
