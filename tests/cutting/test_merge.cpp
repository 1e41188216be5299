#include <acd/algo/cut.hpp>
#include <acd/algo/merge.hpp>
#include <acd/decompose.hpp>
#include <acd/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <random>

using namespace acd;

TEST(Merge, HalvesOfACutSphereGlueBackIntoTheSphere) {
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  const CutResult cut = cutByPlane(sphere, Plane{Vec3(0.3, 0.2, 1.0), 0.1});
  ASSERT_TRUE(cut.ok);
  ASSERT_EQ(cut.below.size(), 1u);
  ASSERT_EQ(cut.above.size(), 1u);
  TriMesh glued;
  ASSERT_TRUE(glueAlongSharedFaces(cut.below[0], cut.above[0], glued));
  EXPECT_TRUE(isClosedOriented(glued));
  EXPECT_NEAR(signedVolume(glued), signedVolume(sphere), 1e-12);
  const auto pairs = sharedFacePairs({cut.below[0], cut.above[0]});
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_GT(pairs[0].area, 0.5);  // the section through a unit sphere near its centre
}

TEST(Merge, MeshesThatDoNotTouchDoNotGlue) {
  TriMesh out;
  EXPECT_FALSE(glueAlongSharedFaces(shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), shapes::box(Vec3(2, 0, 0), Vec3(3, 1, 1)), out));
  EXPECT_TRUE(sharedFacePairs({shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), shapes::box(Vec3(2, 0, 0), Vec3(3, 1, 1))}).empty());
}

TEST(Merge, NeverMoreComponentsThanWithoutAndStillWithinTau) {
  const TriMesh db = shapes::dumbbell();
  const acdtest::MeshIndex model(db);
  for (MergeScope scope : {MergeScope::Component, MergeScope::Model})
  for (bool grouping : {true, false}) {
    SCOPED_TRACE(std::string(scope == MergeScope::Model ? "model" : "component") + (grouping ? ", grouping" : ""));
    DecomposeOptions o;
    o.tau = 0.05;
    o.mergeScope = scope;
    o.featureGrouping = grouping;
    o.merge = false;
    const Decomposition plain = decompose(db, o);
    o.merge = true;
    const Decomposition merged = decompose(db, o);
    ASSERT_TRUE(plain.status.ok() && merged.status.ok());
    EXPECT_LE(merged.components.size(), plain.components.size());
    EXPECT_EQ(static_cast<int>(plain.components.size()) - merged.stats.merges, static_cast<int>(merged.components.size()));
    double volume = 0;
    std::mt19937_64 rng(5);
    const double radius = 1.0 / merged.normalization.scale;  // tau is in units of the model's radius
    for (const Component& c : merged.components) {
      EXPECT_TRUE(isClosedOriented(c.mesh));
      if (scope == MergeScope::Component) EXPECT_LE(c.concavity, o.tau);
      EXPECT_LE(c.hullExcess, o.tau);
      // Independently: no point of the hull farther than tau outside the model.
      for (const Vec3& p : acdtest::sampleSurface(c.hull, 2000, rng))
        if (!model.inside(p)) EXPECT_LE(model.distance(p), o.tau * radius) << p.transpose();
      volume += c.volume;
    }
    // (1e-6: cuts are made on coordinates rounded to the canonical grid, 2.4e-7.)
    EXPECT_NEAR(volume, merged.stats.inputVolume, 1e-6 * merged.stats.inputVolume);
  }
}

TEST(Merge, NearbyPairsAreTheBoxesWithinReach) {
  // Gaps by hand: A-B 0.3 along x; A-C 0.6 along y; B-C (0.3, 0.6) apart, 0.671.
  const std::vector<TriMesh> boxes{shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), shapes::box(Vec3(1.3, 0, 0), Vec3(2.3, 1, 1)),
                                   shapes::box(Vec3(0, 1.6, 0), Vec3(1, 2.6, 1))};
  auto pairsWithin = [&](double reach) {
    std::vector<std::pair<int, int>> out;
    for (const SharedFaces& p : nearbyPairs(boxes, reach)) out.emplace_back(p.a, p.b);
    return out;
  };
  using Pairs = std::vector<std::pair<int, int>>;
  EXPECT_EQ(pairsWithin(0.2), Pairs{});
  EXPECT_EQ(pairsWithin(0.5), (Pairs{{0, 1}}));
  EXPECT_EQ(pairsWithin(0.65), (Pairs{{0, 1}, {0, 2}}));
  EXPECT_EQ(pairsWithin(0.7), (Pairs{{0, 1}, {0, 2}, {1, 2}}));
}

TEST(Merge, GluingOntoAPieceOfTwoShellsKeepsTheOtherShell) {
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  const CutResult cut = cutByPlane(sphere, Plane{Vec3(0.3, 0.2, 1.0), 0.1});
  ASSERT_TRUE(cut.ok);
  const TriMesh box = shapes::box(Vec3(3, 0, 0), Vec3(4, 1, 1));
  TriMesh glued;
  ASSERT_TRUE(glueAlongSharedFaces(concatenate({cut.below[0], box}), cut.above[0], glued));
  EXPECT_TRUE(isClosedOriented(glued));
  EXPECT_EQ(splitEdgeConnected(glued).size(), 2u);
  EXPECT_NEAR(signedVolume(glued), signedVolume(sphere) + 1.0, 1e-12);
}

// Two unit cubes side by side: held to the model, they share one hull when the gap between them is
// narrow enough that no point of that hull is farther than tau from a cube (half the gap, in units
// of the model's radius); never when the merge is held to each component. (Without repair: with
// it, each shell is decomposed on its own, docs/ALGORITHM.md section 11.)
TEST(Merge, HeldToTheModelPiecesApartShareAHullWhenTheGapIsWithinTau) {
  for (double gap : {0.05, 0.15}) {
    const TriMesh cubes = concatenate({shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), shapes::box(Vec3(1 + gap, 0, 0), Vec3(2 + gap, 1, 1))});
    const double radius = std::sqrt((2 + gap) * (2 + gap) + 2) / 2;  // the smallest sphere around both
    for (MergeScope scope : {MergeScope::Component, MergeScope::Model}) {
      SCOPED_TRACE("gap " + std::to_string(gap) + (scope == MergeScope::Model ? ", model" : ", component"));
      DecomposeOptions o;
      o.tau = 0.05;
      o.mergeScope = scope;
      o.repair = false;
      const Decomposition d = decompose(cubes, o);
      ASSERT_TRUE(d.status.ok()) << d.status.message;
      const bool within = gap / 2 / radius <= 0.96 * o.tau;
      EXPECT_EQ(d.components.size(), scope == MergeScope::Model && within ? 1u : 2u);
      double volume = 0;
      for (const Component& c : d.components) {
        EXPECT_TRUE(isClosedOriented(c.mesh));
        volume += c.volume;
      }
      EXPECT_NEAR(volume, d.stats.inputVolume, 1e-9);
      if (d.components.size() == 1) {
        EXPECT_EQ(splitEdgeConnected(d.components[0].mesh).size(), 2u);
        EXPECT_NEAR(d.components[0].hullExcess, gap / 2 / radius, 2e-3);  // found to the resolution, tau / 32
      }
    }
  }
}
