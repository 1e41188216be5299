// The choice of a cut among candidate planes (cut_choice.cpp): the lookahead on shapes whose best
// cut is known, its ties and repeats, the hull points it scores with, and the candidates' shape.
#include <acd/algo/cut_choice.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>

using namespace acd;

namespace {

Plane plane(const Vec3& normal, double offset) { return {normal, offset}; }

std::vector<double> sortedVolumes(const std::vector<TriMesh>& pieces) {
  std::vector<double> v;
  for (const TriMesh& m : pieces) v.push_back(signedVolume(m));
  std::sort(v.begin(), v.end());
  return v;
}

CutChoice lookahead(const TriMesh& mesh, const std::vector<Plane>& candidates) {
  return cutByLookahead(mesh, candidates, CutSite{0, Vec3::UnitZ(), 0, false}, ConcavityOptions{}, 0.05);
}

}  // namespace

// The L of three unit cells: cut at x = 1 it falls into two boxes (hull volume beyond the pieces:
// 0); cut at x = 0.5 the larger side keeps the notch (hull excess 0.5, the notch's triangle).
TEST(CutByLookahead, PicksThePlaneWhoseChildrenAreConvex) {
  const TriMesh l = shapes::lShape();
  const CutChoice choice = lookahead(l, {plane(Vec3::UnitX(), 0.5), plane(Vec3::UnitX(), 1.0)});
  ASSERT_TRUE(choice.ok);
  EXPECT_EQ(choice.index, 1u);
  EXPECT_EQ(choice.failed, 0);
  const std::vector<double> v = sortedVolumes(choice.pieces);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_NEAR(v[0], 1.0, 1e-12);
  EXPECT_NEAR(v[1], 2.0, 1e-12);
  for (const TriMesh& piece : choice.pieces)
    EXPECT_NEAR(signedVolume(hullMesh(piece.vertices)), signedVolume(piece), 1e-12);
}

TEST(CutByLookahead, EqualScoresGoToTheEarlierCandidate) {
  // x = 1 and y = 1 both leave two boxes: a tie, whichever comes first wins.
  const TriMesh l = shapes::lShape();
  const Plane x = plane(Vec3::UnitX(), 1.0), y = plane(Vec3::UnitY(), 1.0);
  EXPECT_EQ(lookahead(l, {x, y}).index, 0u);
  EXPECT_EQ(lookahead(l, {y, x}).index, 0u);
}

// The plane across a pocket's floor (its normal the bridge's) wins only by a clear margin (1 % of
// the piece's volume): on a tie it gives way even when listed first (where every plane lies in a
// wall of a straight pocket, it would cut the pocket into rings); clearly better, it wins.
TEST(CutByLookahead, TheFloorPlaneWinsOnlyByAClearMargin) {
  const TriMesh l = shapes::lShape();
  const ConcavityOptions co;
  // With the bridge along z, z = 0.5 halves the L into two L's (hull excess 0.25 each): a tie
  // with x = 0.5, which leaves the notch's triangle prism (0.5).
  const Plane floorZ = plane(Vec3::UnitZ(), 0.5), acrossX = plane(Vec3::UnitX(), 0.5);
  const CutSite alongZ{0, Vec3::UnitZ(), 0, false};
  EXPECT_EQ(cutByLookahead(l, {floorZ, acrossX}, alongZ, co, 0.05).index, 1u);
  EXPECT_EQ(cutByLookahead(l, {acrossX, floorZ}, alongZ, co, 0.05).index, 0u);
  // Alone, it is taken.
  EXPECT_TRUE(cutByLookahead(l, {floorZ}, alongZ, co, 0.05).ok);
  // With the bridge along x, x = 1 leaves two boxes (0) against x = 0.5's 0.5: it wins, listed last.
  const CutSite alongX{0, Vec3::UnitX(), 0, false};
  EXPECT_EQ(cutByLookahead(l, {acrossX, plane(Vec3::UnitX(), 1.0)}, alongX, co, 0.05).index, 1u);
  // An ordinary plane with the same tie goes to the earlier candidate (the rule above).
  EXPECT_EQ(cutByLookahead(l, {floorZ, acrossX}, CutSite{0, Vec3::UnitY(), 0, false}, co, 0.05).index, 0u);
}

TEST(CutByLookahead, RepeatsAndPlanesThatMissCountAsBefore) {
  const TriMesh l = shapes::lShape();
  const Plane good = plane(Vec3::UnitX(), 1.0), poor = plane(Vec3::UnitX(), 0.5), miss = plane(Vec3::UnitX(), 5.0);
  const CutChoice repeated = lookahead(l, {poor, good, good, poor});
  ASSERT_TRUE(repeated.ok);
  EXPECT_EQ(repeated.index, 1u);
  EXPECT_EQ(repeated.failed, 0);
  const CutChoice missing = lookahead(l, {miss, miss, good});
  ASSERT_TRUE(missing.ok);
  EXPECT_EQ(missing.index, 2u);
  EXPECT_EQ(missing.failed, 2);  // a repeat of a plane that misses misses too
  EXPECT_FALSE(lookahead(l, {miss, miss}).ok);
}

// A fine sphere cut obliquely: the hull the lookahead scores is the child's own hull (CGAL's, from
// all its vertices) up to rounding, and its vertices are the child's, in place.
TEST(LookaheadHull, IsTheChildsHullWithTheChildsVertices) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 8; ++trial) {
    SCOPED_TRACE(trial);
    const TriMesh sphere = shapes::icosphere(acdtest::drawPoint([&] { return u(rng); }), 1.0, 4);
    const Vec3 n = acdtest::drawPoint([&] { return u(rng); }).normalized();
    const Plane p = Plane::through(boundingBox(sphere).center() + 0.4 * u(rng) * n, n);
    const CutResult cut = cutByPlane(sphere, p);
    ASSERT_TRUE(cut.ok);
    for (const auto* side : {&cut.below, &cut.above})
      for (const TriMesh& child : *side) {
        const TriMesh hull = lookaheadHull(child, p);
        std::set<std::array<double, 3>> vertices;
        for (const Vec3& v : child.vertices) vertices.insert({v.x(), v.y(), v.z()});
        for (const Vec3& q : hull.vertices) EXPECT_TRUE(vertices.count({q.x(), q.y(), q.z()}));
        EXPECT_TRUE(isClosedOriented(hull));
        const double full = signedVolume(hullMesh(child.vertices));
        EXPECT_GT(full, 0.0);
        EXPECT_NEAR(signedVolume(hull), full, 1e-12 * full);
        // Every child vertex is inside the scored hull (up to rounding).
        for (int f = 0; f < static_cast<int>(hull.faces.size()); ++f) {
          const Vec3 normal = faceNormal(hull, f).normalized();
          const double d = normal.dot(hull.vertices[hull.faces[f][0]]);
          for (const Vec3& v : child.vertices) ASSERT_LE(normal.dot(v) - d, 1e-9);  // thin facets: noisy normals
        }
      }
  }
}

TEST(LookaheadHull, KeepsOnlyTheCornersOfTheCapOutline) {
  // A box of 2 x 2 voxels cut halfway up: its side faces' edges cross the plane between the
  // corners, so the cap has points along its outline's sides. Only the four corners stay.
  const TriMesh box = shapes::voxels({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, 0.5);  // 1 x 1 x 0.5
  const Plane z = plane(Vec3::UnitZ(), 0.25);
  const CutResult cut = cutByPlane(box, z);
  ASSERT_TRUE(cut.ok);
  ASSERT_EQ(cut.below.size(), 1u);
  const TriMesh& child = cut.below[0];
  int onCap = 0;
  for (const Vec3& v : child.vertices) onCap += std::abs(v.z() - 0.25) < 1e-12;
  ASSERT_GT(onCap, 4);  // the voxel box has edge midpoints: the cap has more than its corners
  const TriMesh hull = lookaheadHull(child, z);
  int kept = 0;
  for (const Vec3& q : hull.vertices) kept += std::abs(q.z() - 0.25) < 1e-12;
  EXPECT_EQ(kept, 4);
  EXPECT_EQ(hull.vertices.size(), 8u);
  EXPECT_NEAR(signedVolume(hull), 0.25, 1e-14);
}

// Every candidate passes through the notch it is for (a plane off the notch would leave it as it was).
TEST(CandidatePlanes, AllPassThroughTheNotch) {
  const TriMesh l = shapes::lShape();
  SurfaceGraph graph(l);
  const ConcavityMap map = acdtest::measure(l, 0.025);
  ASSERT_GE(map.notch, 0);
  DecomposeOptions o;
  o.tau = 0.05;
  o.epsilon = 0.025;
  o.delta = 0.0025;
  for (int stalls : {0, 1, 2, 3}) {
    SCOPED_TRACE(stalls);
    const CutSite site{map.notch, map.bridges[map.vertexBridge[map.notch]].normal, stalls, false};
    double seconds = 0;
    const std::vector<Plane> candidates = candidatePlanes(l, graph, map, o, site, seconds);
    ASSERT_GE(candidates.size(), 2u);
    EXPECT_LE(candidates.size(), 10u);  // global cuts (5, or 6 with a cup) + bisector + bridge plane + fan of 2, or a fan of 8 + the bridge plane
    for (const Plane& c : candidates) EXPECT_NEAR(c.signedDistance(l.vertices[map.notch]), 0.0, 1e-12);
    // The plane parallel to the bridge (across the pocket's floor) competes before any stall and
    // after two; after one, the bisector and the turned fan do.
    const int parallel = static_cast<int>(std::count_if(candidates.begin(), candidates.end(), [&](const Plane& c) {
      return c.normal == site.bridgeNormal;
    }));
    EXPECT_EQ(parallel, stalls == 1 ? 0 : 1);
  }
}
