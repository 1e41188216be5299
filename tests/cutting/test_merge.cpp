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
