#include <acd/algo/cut.hpp>
#include <acd/algo/merge.hpp>
#include <acd/decompose.hpp>
#include <acd/algo/shapes.hpp>

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

TEST(Merge, TouchingPairsShareACorner) {
  // A and B share a face, C touches A along an edge and B along a face, D is apart.
  const std::vector<TriMesh> boxes{shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1)),
                                   shapes::box(Vec3(1, 1, 0), Vec3(2, 2, 1)), shapes::box(Vec3(3, 0, 0), Vec3(4, 1, 1))};
  std::vector<std::pair<int, int>> pairs;
  for (const SharedFaces& p : touchingPairs(boxes)) pairs.emplace_back(p.a, p.b);
  EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{0, 1}, {0, 2}, {1, 2}}));
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

namespace {

/// The box with its face on the plane x = `x` split into four triangles around its centre: the
/// same solid, but no triangle of that face matches the plain box's.
TriMesh boxWithSplitFace(const Vec3& lo, const Vec3& hi, double x) {
  TriMesh box = shapes::box(lo, hi);
  const int centre = static_cast<int>(box.vertices.size());
  box.vertices.push_back(Vec3(x, (lo.y() + hi.y()) / 2, (lo.z() + hi.z()) / 2));
  std::vector<Face> kept, onFace;
  for (const Face& f : box.faces)
    (box.vertices[f[0]].x() == x && box.vertices[f[1]].x() == x && box.vertices[f[2]].x() == x ? onFace : kept).push_back(f);
  EXPECT_EQ(onFace.size(), 2u);
  // The quad's boundary edges are the edges that only one of its two triangles has.
  for (const Face& f : onFace)
    for (int k = 0; k < 3; ++k) {
      const int u = f[k], v = f[(k + 1) % 3];
      const Face& g = &f == &onFace[0] ? onFace[1] : onFace[0];
      const bool diagonal = std::count(g.begin(), g.end(), u) && std::count(g.begin(), g.end(), v);
      if (!diagonal) kept.push_back({u, v, centre});
    }
  box.faces = kept;
  return box;
}

}  // namespace

// Two unit cubes side by side whose common face is triangulated differently on each side: they
// share no triangle, so they do not glue into one solid; joined, they are two shells.
TEST(Merge, TouchingPiecesThatDoNotGlueAreJoinedAsTwoShells) {
  const TriMesh a = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), b = boxWithSplitFace(Vec3(1, 0, 0), Vec3(2, 1, 1), 1.0);
  ASSERT_TRUE(isClosedOriented(b));
  TriMesh glued;
  EXPECT_FALSE(glueAlongSharedFaces(a, b, glued));
  const TriMesh joined = joinPieces(a, b);
  EXPECT_TRUE(isClosedOriented(joined));
  EXPECT_EQ(splitEdgeConnected(joined).size(), 2u);
  EXPECT_NEAR(signedVolume(joined), 2.0, 1e-12);
  EXPECT_EQ(touchingPairs({a, b}).size(), 1u);
  EXPECT_TRUE(sharedFacePairs({a, b}).empty());
  // Where the two glue, joining is gluing: one shell.
  const TriMesh c = shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1));
  EXPECT_EQ(splitEdgeConnected(joinPieces(a, c)).size(), 1u);
  EXPECT_NEAR(signedVolume(joinPieces(a, c)), 2.0, 1e-12);
}
