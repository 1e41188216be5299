// The labelling the refinement meshes: boxes whose answers are known by construction.
#include "region_labels.hpp"

#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

using tetmesh::RegionLabels;
using tetmesh::Vec3;

TEST(RegionLabels, TouchingBoxesKeepTheirOwnSidesOfTheContact) {
  const RegionLabels labels({acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), acd::shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1))}, 0.01);
  EXPECT_EQ(labels(Vec3(0.5, 0.5, 0.5)), 1);
  EXPECT_EQ(labels(Vec3(1.5, 0.5, 0.5)), 2);
  EXPECT_EQ(labels(Vec3(0.999, 0.999, 0.999)), 1);
  EXPECT_EQ(labels(Vec3(1.001, 0.001, 0.5)), 2);
  EXPECT_EQ(labels(Vec3(1.0, 0.5, 0.5)), 1);  // on the contact: a tie, the lower label
  EXPECT_EQ(labels(Vec3(2.5, 0.5, 0.5)), 0);
  // Nothing grows where the boxes face the open, not even along the seam.
  EXPECT_EQ(labels(Vec3(1.0, 0.5, 1.005)), 0);
  EXPECT_EQ(labels(Vec3(0.5, 0.5, 1.005)), 0);
}

TEST(RegionLabels, AThinGapBetweenFacingRegionsIsFilledByTheNearer) {
  // Two boxes 1e-3 apart along x, a gap tolerance of 1e-2.
  const RegionLabels labels({acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), acd::shapes::box(Vec3(1.001, 0, 0), Vec3(2, 1, 1))}, 0.01);
  EXPECT_EQ(labels(Vec3(1.0002, 0.5, 0.5)), 1);
  EXPECT_EQ(labels(Vec3(1.0008, 0.5, 0.5)), 2);
  // Above the top face over the gap: the planes beyond are the tops (parallel, not facing).
  EXPECT_EQ(labels(Vec3(1.0005, 0.5, 1.004)), 0);
  // A gap wider than the tolerance stays open.
  const RegionLabels wide({acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), acd::shapes::box(Vec3(1.05, 0, 0), Vec3(2, 1, 1))}, 0.01);
  EXPECT_EQ(wide(Vec3(1.025, 0.5, 0.5)), 0);
  EXPECT_EQ(wide(Vec3(1.005, 0.5, 0.5)), 0);  // near one region only: nothing to close
}

TEST(RegionLabels, AnOverlapIsSplitWhereTheDepthsAreEqual) {
  // [0,1] and [0.8,2] along x overlap on [0.8,1]; depth along x decides at the middle, 0.9.
  const RegionLabels labels({acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), acd::shapes::box(Vec3(0.8, 0, 0), Vec3(2, 1, 1))}, 0.0);
  EXPECT_EQ(labels(Vec3(0.85, 0.5, 0.5)), 1);
  EXPECT_EQ(labels(Vec3(0.95, 0.5, 0.5)), 2);
  // Near the top face both are as deep (0.05): the tie goes to the lower label.
  EXPECT_EQ(labels(Vec3(0.95, 0.5, 0.95)), 1);
}

TEST(RegionLabels, TheOrderOfTheRegionsOnlyRenamesThem) {
  // Outside both, inside exactly one: known without the labelling; the two orders agree.
  const Vec3 alo(0, 0, 0), ahi(1, 1, 1), blo(0.5, 0.2, 0), bhi(2, 1, 1.3);
  const RegionLabels ab({acd::shapes::box(alo, ahi), acd::shapes::box(blo, bhi)}, 0.0);
  const RegionLabels ba({acd::shapes::box(blo, bhi), acd::shapes::box(alo, ahi)}, 0.0);
  auto in = [](const Vec3& p, const Vec3& lo, const Vec3& hi) {
    return (p.array() > lo.array()).all() && (p.array() < hi.array()).all();
  };
  int checked = 0;
  for (double x = -0.1; x < 2.1; x += 0.0731)
    for (double y = -0.1; y < 1.1; y += 0.0913)
      for (double z = -0.1; z < 1.4; z += 0.0877) {
        const Vec3 p(x, y, z);
        const bool inA = in(p, alo, ahi), inB = in(p, blo, bhi);
        if (!inA && !inB) EXPECT_TRUE(ab(p) == 0 && ba(p) == 0) << p.transpose();
        if (inA && !inB) EXPECT_TRUE(ab(p) == 1 && ba(p) == 2) << p.transpose();
        if (inB && !inA) EXPECT_TRUE(ab(p) == 2 && ba(p) == 1) << p.transpose();
        if (inA && inB) EXPECT_TRUE(ab(p) != 0 && ba(p) != 0) << p.transpose();
        ++checked;
      }
  EXPECT_GT(checked, 3000);
}

TEST(RegionLabels, AFaceOfNearlyCollinearCornersDoesNotCutTheRegion) {
  // A unit box whose hull mesh also carries a sliver face on the edge (0,0,0)-(1,0,0): its middle
  // corner lies 1e-13 off the edge, so its normal is rounding noise, here (0, 1, -1)/sqrt(2).
  // Taken as a plane it would cut the box along its diagonal y = z (fandisk's regions lost
  // whole components this way).
  acd::TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const int a = static_cast<int>(box.vertices.size());
  box.vertices.push_back(Vec3(0, 0, 0));
  box.vertices.push_back(Vec3(0.5, 1e-13, 1e-13));
  box.vertices.push_back(Vec3(1, 0, 0));
  for (const acd::Face& sliver : {acd::Face{a, a + 1, a + 2}, acd::Face{a, a + 2, a + 1}}) {
    acd::TriMesh region = box;
    region.faces.push_back(sliver);  // either orientation
    const RegionLabels labels({region}, 0.0);
    EXPECT_EQ(labels(Vec3(0.5, 0.2, 0.8)), 1);
    EXPECT_EQ(labels(Vec3(0.5, 0.8, 0.2)), 1);
    EXPECT_EQ(labels(Vec3(0.5, 0.5, 0.5)), 1);
    EXPECT_EQ(labels(Vec3(0.5, 0.5, 1.1)), 0);
    EXPECT_EQ(labels(Vec3(-0.1, 0.5, 0.5)), 0);
  }
}
