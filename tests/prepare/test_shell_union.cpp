// Shells that meet, united (libacd/src/prepare/shell_union.cpp, acd/algo/shell_union.hpp), and
// assemblies decomposed as one solid. The oracles are analytic: unions of axis-aligned boxes,
// whose volume and distance function the tests compute themselves.
#include <acd/algo/shell_union.hpp>
#include <acd/algo/canonical_frame.hpp>
#include <acd/decompose.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/robust.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace acd;

namespace {

struct Block {
  Vec3 lo, hi;
};

std::vector<TriMesh> meshesOf(const std::vector<Block>& blocks) {
  std::vector<TriMesh> out;
  for (const Block& b : blocks) out.push_back(shapes::box(b.lo, b.hi));
  return out;
}

/// Distance from p to the union of the blocks (0 inside).
double distanceToBlocks(const Vec3& p, const std::vector<Block>& blocks) {
  double best = 1e300;
  for (const Block& b : blocks) {
    const Vec3 d = (b.lo - p).cwiseMax(p - b.hi).cwiseMax(Vec3::Zero());
    best = std::min(best, d.norm());
  }
  return best;
}

/// The farthest any point of the hulls lies from the blocks, over a grid of points on every hull
/// face (the distance to a union of boxes is not convex: the vertices alone do not bound it).
double hullsToBlocks(const Decomposition& d, const std::vector<Block>& blocks) {
  double worst = 0.0;
  for (const Component& c : d.components)
    for (const Face& f : c.hull.faces) {
      const Vec3 &a = c.hull.vertices[f[0]], &b = c.hull.vertices[f[1]], &e = c.hull.vertices[f[2]];
      const int n = 12;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
          const Vec3 p = a + (b - a) * (double(i) / n) + (e - a) * (double(j) / n);
          worst = std::max(worst, distanceToBlocks(p, blocks));
        }
    }
  return worst;
}

/// Every corner of every block inside (or on) some hull: the input is covered.
bool blocksCovered(const Decomposition& d, const std::vector<Block>& blocks, double slack) {
  for (const Block& b : blocks)
    for (int k = 0; k < 8; ++k) {
      const Vec3 p((k & 1) ? b.hi.x() : b.lo.x(), (k & 2) ? b.hi.y() : b.lo.y(), (k & 4) ? b.hi.z() : b.lo.z());
      bool inside = false;
      for (const Component& c : d.components) {
        bool in = true;
        for (const Face& f : c.hull.faces) {
          const Vec3 n = faceNormal(c.hull, static_cast<int>(&f - c.hull.faces.data())).normalized();
          in = in && n.dot(p - c.hull.vertices[f[0]]) <= slack;
        }
        inside = inside || in;
      }
      if (!inside) return false;
    }
  return true;
}

Decomposition decomposeBlocks(const std::vector<Block>& blocks, double tau, bool unite = true) {
  DecomposeOptions o = recommendedOptions();
  o.tau = tau;
  o.uniteShells = unite;
  return decompose(concatenate(meshesOf(blocks)), o);
}

/// The model's radius (the unit tau is given in).
double radiusOf(const std::vector<Block>& blocks) {
  return 1.0 / minimumSphereNormalization(concatenate(meshesOf(blocks))).scale;
}

}  // namespace

TEST(ShellUnion, TwoOverlappingBoxesBecomeOneLShapedSolid) {
  const std::vector<Block> l = {{Vec3(0, 0, 0), Vec3(3, 1, 1)}, {Vec3(0, 0, 0), Vec3(1, 3, 1)}};
  for (bool invariant : {false, true}) {
    // Invariant, the crossings' points are found on the shells rounded to the canonical grid: a
    // grid step of the radius off at most.
    const double step = invariant ? kCanonicalGrid * radiusOf(l) : 1e-12;
    const ShellUnion u = uniteMeetingShells(meshesOf(l), invariant);
    EXPECT_EQ(u.united, 2);
    EXPECT_EQ(u.leftAlone, 0);
    ASSERT_EQ(u.shells.size(), 1u);
    EXPECT_TRUE(isClosedOriented(u.shells[0]));
    EXPECT_NEAR(signedVolume(u.shells[0]), 3.0 + 3.0 - 1.0, 10 * step);
    for (const Vec3& v : u.shells[0].vertices) EXPECT_LT(distanceToBlocks(v, l), step);
  }
}

TEST(ShellUnion, BoxesTouchingInAFaceBecomeOneBox) {
  const std::vector<Block> pair = {{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(1, 0, 0), Vec3(2, 1, 1)}};
  const ShellUnion u = uniteMeetingShells(meshesOf(pair), true);
  ASSERT_EQ(u.shells.size(), 1u);
  EXPECT_NEAR(signedVolume(u.shells[0]), 2.0, 1e-12);
}

TEST(ShellUnion, ShellsApartOrTouchingAlongAnEdgeStayAsTheyWere) {
  const std::vector<Block> apart = {{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(2, 0, 0), Vec3(3, 1, 1)}};
  const ShellUnion a = uniteMeetingShells(meshesOf(apart), true);
  EXPECT_EQ(a.united, 0);
  EXPECT_EQ(a.leftAlone, 0);
  EXPECT_EQ(a.shells.size(), 2u);
  // Along an edge the union is not a manifold: both are left alone, and counted.
  const std::vector<Block> edge = {{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(1, 1, 0), Vec3(2, 2, 1)}};
  const ShellUnion e = uniteMeetingShells(meshesOf(edge), true);
  EXPECT_EQ(e.united, 0);
  EXPECT_EQ(e.leftAlone, 2);
  EXPECT_FALSE(e.firstFailure.empty());
  EXPECT_EQ(e.shells.size(), 2u);
}

TEST(ShellUnion, TheOrderOfShellsAndFacesDoesNotChangeTheUnion) {
  const std::vector<Block> blocks = {{Vec3(0, 0, 0), Vec3(4, 1, 1)},
                                     {Vec3(0.5, -0.5, 0.5), Vec3(1.5, 2, 1.5)},
                                     {Vec3(3, 0.25, -1), Vec3(3.5, 0.75, 2)}};
  std::vector<TriMesh> meshes = meshesOf(blocks);
  const TriMesh first = uniteMeetingShells(meshes, true).shells.at(0);
  std::mt19937 rng(7);
  std::shuffle(meshes.begin(), meshes.end(), rng);
  for (TriMesh& m : meshes) std::shuffle(m.faces.begin(), m.faces.end(), rng);
  const TriMesh second = uniteMeetingShells(meshes, true).shells.at(0);
  auto sorted = [](std::vector<Vec3> v) {
    std::sort(v.begin(), v.end(), [](const Vec3& a, const Vec3& b) {
      return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    return v;
  };
  // The same points; those not of the input (where shells cross) come back through a frame that
  // sums the faces in their order, so up to an ulp.
  const std::vector<Vec3> a = sorted(first.vertices), b = sorted(second.vertices);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t v = 0; v < a.size(); ++v) EXPECT_LT((a[v] - b[v]).norm(), 1e-12) << "vertex " << v;
  EXPECT_EQ(first.faces.size(), second.faces.size());
  EXPECT_NEAR(signedVolume(first), signedVolume(second), 1e-12);
}

// The same shells give the same union on every call, bit for bit. CGAL's corefinement returns its
// surface in an order that follows memory addresses, so without putting it in a canonical order
// the union (and the decomposition after it) changed from call to call and with the thread count.
// Spheres crossing a box and one another, with the heap disturbed between calls.
TEST(ShellUnion, TheSameShellsGiveTheSameUnionOnEveryCall) {
  std::vector<TriMesh> shells = {shapes::box(Vec3(0, 0, 0), Vec3(3, 1, 1))};
  for (int k = 0; k < 3; ++k) shells.push_back(shapes::icosphere(Vec3(0.6 + 0.9 * k, 0.55, 0.9), 0.45 + 0.05 * k, 2));
  const ShellUnion first = uniteMeetingShells(shells, true);
  ASSERT_EQ(first.solids, 1);
  ASSERT_EQ(first.united, 4);
  std::vector<std::vector<double>> ballast;
  for (int call = 0; call < 6; ++call) {
    ballast.emplace_back(1000 * (call + 1) * 37);
    const ShellUnion again = uniteMeetingShells(shells, call % 2 == 0);
    if (call % 2 == 1) continue;
    ASSERT_EQ(again.shells.size(), first.shells.size());
    EXPECT_EQ(again.shells[0].vertices, first.shells[0].vertices) << "call " << call;
    EXPECT_EQ(again.shells[0].faces, first.shells[0].faces) << "call " << call;
  }
}

// CAD shells touching in planes, moved rigidly: in a turned pose their planes no longer meet
// exactly in doubles (they cross or part by an ulp), and a union computed there was full of
// slivers and refused. Worked in the frame turned onto their planes, it is the same solid in
// every pose: one closed shell of the blocks' volume, its corners on the blocks.
TEST(ShellUnion, ShellsTouchingInPlanesAreUnitedInEveryPose) {
  const std::vector<Block> blocks = {{Vec3(0, 0, 0), Vec3(4, 1, 1)},     // a bar
                                     {Vec3(0, 1, 0), Vec3(1, 3, 1)},     // an arm on its side face
                                     {Vec3(2, 0, 1), Vec3(3, 1, 1.5)}};  // a boss on its top
  const double volume = 4.0 + 2.0 + 0.5;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  std::size_t corners = 0;
  for (int trial = 0; trial < 8; ++trial) {
    SCOPED_TRACE("motion " + std::to_string(trial));
    const Eigen::Matrix3d r = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
    const Vec3 t(u(rng), u(rng), u(rng));
    std::vector<TriMesh> pose = meshesOf(blocks);
    for (TriMesh& m : pose)
      for (Vec3& p : m.vertices) p = r * p + t;
    const ShellUnion united = uniteMeetingShells(pose, true);
    EXPECT_EQ(united.united, 3);
    EXPECT_EQ(united.leftAlone, 0);
    ASSERT_EQ(united.shells.size(), 1u);
    EXPECT_TRUE(isClosedOriented(united.shells[0]));
    const double step = kCanonicalGrid * radiusOf(blocks);  // how far a crossing's point may move
    EXPECT_NEAR(signedVolume(united.shells[0]), volume, 10 * step);
    for (const Vec3& p : united.shells[0].vertices) EXPECT_LT(distanceToBlocks(r.transpose() * (p - t), blocks), step);
    if (trial == 0) corners = united.shells[0].vertices.size();
    EXPECT_EQ(united.shells[0].vertices.size(), corners);
  }
}

// The known answers: an L from two boxes is one or two hulls, not four; 20 bolts whose heads
// stand less than tau proud of a plate fall into the plate's hull; a box nested in a box is the
// outer box. Every hull within tau of the input, and the input covered, by the test's own measure.
TEST(Assemblies, TwoOverlappingBoxesGiveOneOrTwoHulls) {
  const std::vector<Block> l = {{Vec3(0, 0, 0), Vec3(3, 1, 1)}, {Vec3(0, 0, 0), Vec3(1, 3, 1)}};
  const double tau = 0.05;
  const Decomposition d = decomposeBlocks(l, tau);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_LE(d.components.size(), 2u);
  EXPECT_LE(hullsToBlocks(d, l), tau * radiusOf(l) + 1e-9);
  EXPECT_TRUE(blocksCovered(d, l, 1e-9));
}

TEST(Assemblies, BoltsOnAPlateFallIntoThePlatesHull) {
  std::vector<Block> parts = {{Vec3(0, 0, 0), Vec3(10, 10, 1)}};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) {
      const double x = 1.0 + 2.0 * i, y = 1.5 + 2.3 * j;
      parts.push_back({Vec3(x - 0.3, y - 0.3, 1.0), Vec3(x + 0.3, y + 0.3, 1.1)});  // head, on the top face
      parts.push_back({Vec3(x - 0.1, y - 0.1, 0.2), Vec3(x + 0.1, y + 0.1, 1.0)});  // shank, in the plate
    }
  const double tau = 0.05;  // 0.05 of the radius (7.1) is 0.35: the heads stand 0.1 proud
  const Decomposition united = decomposeBlocks(parts, tau);
  ASSERT_TRUE(united.status.ok()) << united.status.message;
  EXPECT_EQ(united.components.size(), 1u);
  EXPECT_LE(hullsToBlocks(united, parts), tau * radiusOf(parts) + 1e-9);
  EXPECT_TRUE(blocksCovered(united, parts, 1e-9));
  // Shell by shell, every head and shank has a hull of its own, until the merge across shells
  // joins them into the plate's.
  const Decomposition apart = decomposeBlocks(parts, tau, false);
  ASSERT_TRUE(apart.status.ok());
  EXPECT_EQ(apart.components.size(), 1u);
  EXPECT_EQ(apart.stats.merges, 40);
  EXPECT_LE(hullsToBlocks(apart, parts), tau * radiusOf(parts) + 1e-9);
  EXPECT_TRUE(blocksCovered(apart, parts, 1e-9));
}

TEST(Assemblies, ABoxNestedInABoxIsTheOuterBox) {
  const std::vector<Block> nested = {{Vec3(0, 0, 0), Vec3(4, 3, 2)}, {Vec3(1, 1, 0.5), Vec3(2, 2, 1.5)}};
  const Decomposition d = decomposeBlocks(nested, 0.05);
  ASSERT_TRUE(d.status.ok());
  ASSERT_EQ(d.components.size(), 1u);
  EXPECT_NEAR(signedVolume(d.components[0].hull), 24.0, 1e-9);
}
