// The exact solid decomposition's steps in the calling process (libacd/src/baselines/
// exact_decomposition.cpp): piece counts on shapes whose minimum decomposition is known, and the
// invariants of any convex decomposition: closed convex pieces whose volumes add up to the input
// and which cover it exactly once (sampled); the input's checks; what the listener is told. The
// capped run in a child process is tested in tests/sandbox/test_exact_solid.cpp.
#include <acd/decompose.hpp>
#include <acd/exact_decomposition.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/inside.hpp>
#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace acd;
using acdtest::corpus;

namespace {

/// Largest distance of a piece vertex in front of one of the piece's face planes (<= 0: convex).
double convexityViolation(const TriMesh& piece) {
  double worst = -std::numeric_limits<double>::infinity();
  for (int f = 0; f < static_cast<int>(piece.faces.size()); ++f) {
    const Vec3 n = faceNormal(piece, f).normalized();
    const Vec3& a = piece.vertices[piece.faces[f][0]];
    for (const Vec3& v : piece.vertices) worst = std::max(worst, n.dot(v - a));
  }
  return worst;
}

/// Every piece closed, outward and convex; volumes add up to the input's.
void expectConvexPieces(const TriMesh& input, const ExactDecomposition& d) {
  const double scale = boundingBox(input).size().norm();
  double volume = 0;
  for (std::size_t i = 0; i < d.pieces.size(); ++i) {
    const TriMesh& p = d.pieces[i];
    EXPECT_TRUE(isClosedOriented(p)) << "piece " << i;
    EXPECT_GT(signedVolume(p), 0.0) << "piece " << i;
    EXPECT_LE(convexityViolation(p), 1e-9 * scale) << "piece " << i;
    volume += signedVolume(p);
  }
  EXPECT_NEAR(volume, signedVolume(input), 1e-9 * std::abs(signedVolume(input)));
}

/// Random points of the bounding box: inside the input exactly when inside exactly one piece.
/// Points within a hair of a piece's face plane are skipped (they lie on shared walls).
void expectExactCover(const TriMesh& input, const std::vector<TriMesh>& pieces, int samples) {
  const InsideTest model(input);
  const Box3 box = boundingBox(input);
  const double eps = 1e-9 * box.size().norm();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  int checked = 0, inside = 0;
  for (int s = 0; s < samples; ++s) {
    const Vec3 q = box.lo + box.size().cwiseProduct(acdtest::drawPoint([&] { return uni(rng); }));
    int containing = 0;
    bool onWall = false;
    for (const TriMesh& p : pieces) {
      double worst = -std::numeric_limits<double>::infinity();
      for (int f = 0; f < static_cast<int>(p.faces.size()); ++f) {
        const Vec3 n = faceNormal(p, f).normalized();
        worst = std::max(worst, n.dot(q - p.vertices[p.faces[f][0]]));
      }
      if (std::abs(worst) <= eps) onWall = true;
      containing += worst < -eps;
    }
    if (onWall) continue;
    ++checked;
    const bool in = model.inside(q);
    inside += in;
    EXPECT_EQ(containing, in ? 1 : 0) << "point " << q.transpose();
  }
  EXPECT_GT(checked, samples / 2);
  EXPECT_GT(inside, 0);
}

/// What the listener was told, in order.
struct Recorder : ExactListener {
  std::vector<std::string> events;
  std::vector<std::vector<Vec3>> pieces;
  void stage(ExactStage stage, std::size_t solid) override {
    events.push_back(std::string(1, static_cast<char>(stage)) + std::to_string(solid));
  }
  void piece(const std::vector<Vec3>& vertices) override {
    events.push_back("P");
    pieces.push_back(vertices);
  }
  void solidDone(std::size_t solid, std::uint64_t pieces) override {
    events.push_back("D" + std::to_string(solid) + ":" + std::to_string(pieces));
  }
};

/// The three steps in this process, as the capped run does them in a child.
ExactDecomposition solidECD(const TriMesh& mesh, const ExactOptions& o = {}) {
  std::vector<TriMesh> solids;
  ExactDecomposition d = prepareExactSolids(mesh, o, solids);
  if (!d.status.ok()) return d;
  Recorder r;
  decomposeExactSolids(solids, o.maxPieces, r);
  d.finished = true;
  for (const std::string& e : r.events)
    if (e[0] == 'D') d.pieceCount += std::stoull(e.substr(e.find(':') + 1));
  addExactPieces(r.pieces, d);
  return d;
}

}  // namespace

TEST(ExactSolid, BoxIsOnePiece) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const ExactDecomposition d = solidECD(box);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.finished);
  EXPECT_EQ(d.reflexEdges, 0);
  ASSERT_EQ(d.pieces.size(), 1u);
  EXPECT_EQ(d.pieceCount, 1u);
  expectConvexPieces(box, d);
}

// One reflex edge: two pieces, the minimum.
TEST(ExactSolid, LShapeIsTwoPieces) {
  const TriMesh l = shapes::lShape();
  const ExactDecomposition d = solidECD(l);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.finished) << d.note;
  EXPECT_GE(d.reflexEdges, 1);
  EXPECT_EQ(d.pieces.size(), 2u);
  expectConvexPieces(l, d);
  expectExactCover(l, d.pieces, 4000);
}

// Two reflex edges at the bottom of the slot: at least three pieces (two arms and the base).
TEST(ExactSolid, UShapeIsThreePieces) {
  const TriMesh u = shapes::uShape();
  const ExactDecomposition d = solidECD(u);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.finished) << d.note;
  EXPECT_EQ(d.pieces.size(), 3u);
  expectConvexPieces(u, d);
  expectExactCover(u, d.pieces, 4000);
}

// A plus sign of five cubes: four reflex edges, three pieces at least (a bar and two arms).
TEST(ExactSolid, PlusShapeCoveredOnce) {
  const TriMesh plus = shapes::voxels({{1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {1, 2, 0}});
  const ExactDecomposition d = solidECD(plus);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.finished) << d.note;
  EXPECT_GE(d.pieces.size(), 3u);
  EXPECT_LE(d.pieces.size(), 5u);  // never worse than the five cubes
  expectConvexPieces(plus, d);
  expectExactCover(plus, d.pieces, 4000);
}

// A box with a notch cut into one edge (a 3x2x2 block missing one corner cube).
TEST(ExactSolid, NotchedBoxCoveredOnce) {
  const TriMesh notched = shapes::voxels(
      {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {2, 1, 0}, {0, 0, 1}, {1, 0, 1}, {2, 0, 1}, {0, 1, 1}, {1, 1, 1}, {2, 1, 1}});
  const ExactDecomposition d = solidECD(notched);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.finished) << d.note;
  EXPECT_GE(d.pieces.size(), 3u);
  expectConvexPieces(notched, d);
  expectExactCover(notched, d.pieces, 4000);
}

TEST(ExactSolid, SeparateSolidsDecomposedEach) {
  TriMesh second = shapes::lShape();
  for (Vec3& v : second.vertices) v += Vec3(10, 0, 0);
  const TriMesh two = concatenate({shapes::lShape(), second});
  const ExactDecomposition d = solidECD(two);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.finished);
  EXPECT_EQ(d.solids, 2u);
  EXPECT_EQ(d.pieces.size(), 4u);
  expectConvexPieces(two, d);
}

TEST(ExactSolid, CorpusStar) {
  const ReadResult r = readMesh(corpus("star"));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const ExactDecomposition d = solidECD(r.mesh);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.finished) << d.note;
  EXPECT_GE(d.pieces.size(), 2u);
  EXPECT_EQ(d.pieceCount, d.pieces.size());
  expectConvexPieces(r.mesh, d);
  expectExactCover(r.mesh, d.pieces, 3000);
}

// An open mesh has its holes filled first, as for solid ACD, or is refused when asked to.
TEST(ExactSolid, OpenMeshFilledOrRefused) {
  TriMesh open = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  open.faces.pop_back();  // a triangular hole: filling it gives the box back
  ExactOptions refuse;
  refuse.fillHoles = false;
  const ExactDecomposition r = solidECD(open, refuse);
  EXPECT_EQ(r.status.code, StatusCode::OpenMesh) << r.status.message;
  EXPECT_TRUE(r.pieces.empty());
  const ExactDecomposition d = solidECD(open);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_EQ(d.holesFilled, 1);
  EXPECT_FALSE(d.repairs.empty());
  ASSERT_EQ(d.pieces.size(), 1u);
  EXPECT_NEAR(signedVolume(d.pieces[0]), 1.0, 1e-12);
}

TEST(ExactSolid, RefusesSelfIntersectingInput) {
  const TriMesh overlapping =
      concatenate({shapes::box(Vec3(0, 0, 0), Vec3(2, 2, 2)), shapes::box(Vec3(1, 1, 1), Vec3(3, 3, 3))});
  const ExactDecomposition d = solidECD(overlapping);
  EXPECT_FALSE(d.status.ok());
  EXPECT_NE(d.status.message.find("intersects itself"), std::string::npos) << d.status.message;
}

// The listener hears each solid's three stages, its pieces and its count, in order; pieces
// beyond maxPieces are counted, not sent.
TEST(ExactSolid, ListenerHearsStagesPiecesAndCounts) {
  TriMesh second = shapes::lShape();
  for (Vec3& v : second.vertices) v += Vec3(10, 0, 0);
  std::vector<TriMesh> solids;
  const ExactDecomposition prepared = prepareExactSolids(concatenate({shapes::lShape(), second}), {}, solids);
  ASSERT_TRUE(prepared.status.ok()) << prepared.status.message;
  ASSERT_EQ(solids.size(), 2u);
  Recorder all;
  decomposeExactSolids(solids, 1000, all);
  const std::vector<std::string> expected{"B0", "C0", "X0", "P", "P", "D0:2", "B1", "C1", "X1", "P", "P", "D1:2"};
  EXPECT_EQ(all.events, expected);
  Recorder capped;
  decomposeExactSolids(solids, 3, capped);
  const std::vector<std::string> cappedExpected{"B0", "C0", "X0", "P", "P", "D0:2", "B1", "C1", "X1", "P", "D1:2"};
  EXPECT_EQ(capped.events, cappedExpected);
  EXPECT_EQ(exactStageText(ExactStage::Decomposing, 1, 2), "decomposing solid 2 of 2");
  EXPECT_EQ(exactStageText(ExactStage::Starting, 0, 1), "starting on solid 1 of 1");
}

// A flat vertex set (a sliver rounded to no volume) gives no piece, and the note says so.
TEST(ExactSolid, SliversAreLeftOutAndNoted) {
  ExactDecomposition d;
  const std::vector<std::vector<Vec3>> sets{
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)},
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}};
  EXPECT_EQ(addExactPieces(sets, d), 1u);
  ASSERT_EQ(d.pieces.size(), 1u);
  EXPECT_NEAR(signedVolume(d.pieces[0]), 1.0 / 6.0, 1e-15);
  EXPECT_NE(d.note.find("1 sliver pieces"), std::string::npos) << d.note;
}
