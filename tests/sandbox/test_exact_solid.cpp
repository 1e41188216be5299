// sandbox/exact_solid: the exact solid decomposition in a capped child. The same pieces as the
// library's steps in this process, the time and memory caps (a run stopped says where and how
// many reflex edges the input has), the pieces of finished solids kept, progress, and the
// input's refusals (which never start a child).
#include <acd/exact_decomposition.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/shapes.hpp>
#include <sandbox/exact_solid.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

using namespace acd;

namespace {

struct Collect : ExactListener {
  std::vector<std::vector<Vec3>> pieces;
  void stage(ExactStage, std::size_t) override {}
  void piece(const std::vector<Vec3>& vertices) override { pieces.push_back(vertices); }
  void solidDone(std::size_t, std::uint64_t) override {}
};

ExactDecomposition capped(const TriMesh& mesh, double limit = 60) {
  ExactOptions o;
  o.timeLimitSeconds = limit;
  return acdsandbox::exactSolidDecomposition(mesh, o);
}

}  // namespace

// The child's pieces are the library's, bit for bit (the doubles go through the pipe as they are).
TEST(ExactSolidCapped, SamePiecesAsInProcess) {
  const TriMesh u = shapes::uShape();
  const ExactDecomposition d = capped(u);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.finished) << d.note;
  EXPECT_EQ(d.pieceCount, 3u);
  EXPECT_EQ(d.unfinishedSolids, 0u);
  EXPECT_TRUE(d.note.empty()) << d.note;
  std::vector<TriMesh> solids;
  ExactDecomposition here = prepareExactSolids(u, {}, solids);
  Collect c;
  decomposeExactSolids(solids, 1000, c);
  addExactPieces(c.pieces, here);
  ASSERT_EQ(d.pieces.size(), here.pieces.size());
  for (std::size_t i = 0; i < d.pieces.size(); ++i) {
    EXPECT_EQ(d.pieces[i].faces, here.pieces[i].faces) << "piece " << i;
    ASSERT_EQ(d.pieces[i].vertices.size(), here.pieces[i].vertices.size());
    for (std::size_t v = 0; v < d.pieces[i].vertices.size(); ++v)
      EXPECT_EQ(d.pieces[i].vertices[v], here.pieces[i].vertices[v]) << "piece " << i << " vertex " << v;
  }
  EXPECT_EQ(d.reflexEdges, here.reflexEdges);
}

// The time cap stops the child and says where; the caller gets control back promptly.
TEST(ExactSolidCapped, TimeCapReportsUnfinished) {
  const TriMesh torus = shapes::torus(2.0, 0.5, 64, 32);
  const auto start = std::chrono::steady_clock::now();
  const ExactDecomposition d = capped(torus, 0.3);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_FALSE(d.finished);
  EXPECT_EQ(d.unfinishedSolids, 1u);
  EXPECT_TRUE(d.pieces.empty());
  EXPECT_GT(d.reflexEdges, 0);
  EXPECT_NE(d.note.find("not finished within 0.3 s: stopped while"), std::string::npos) << d.note;
  EXPECT_NE(d.note.find("solid 1 of 1 (" + std::to_string(d.reflexEdges) + " reflex edges in the input)"),
            std::string::npos)
      << d.note;
  EXPECT_LT(wall, 5.0);
}

// A solid finished before the cap keeps its pieces: an L next to a torus the cap stops.
TEST(ExactSolidCapped, FinishedSolidsKeepTheirPieces) {
  TriMesh torus = shapes::torus(2.0, 0.5, 64, 32);
  for (Vec3& v : torus.vertices) v += Vec3(10, 0, 0);
  std::vector<std::string> stages;
  ExactOptions o;
  o.timeLimitSeconds = 2.0;
  o.progress = [&](const std::string& stage, double) { stages.push_back(stage); };
  const ExactDecomposition d = acdsandbox::exactSolidDecomposition(concatenate({shapes::lShape(), torus}), o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  ASSERT_EQ(d.solids, 2u);
  EXPECT_FALSE(d.finished);
  EXPECT_EQ(d.unfinishedSolids, 1u);
  EXPECT_EQ(d.pieces.size(), 2u);  // the L's two
  EXPECT_NE(d.note.find("solid 2 of 2"), std::string::npos) << d.note;
  ASSERT_FALSE(stages.empty());
  EXPECT_NE(stages.back().find("solid 2 of 2"), std::string::npos) << stages.back();
}

// A memory cap the child cannot live with ends as "unfinished", never as a crash of the caller.
TEST(ExactSolidCapped, MemoryCapReportsUnfinished) {
  // The forked child inherits the caller's heap, whose free blocks a small model can finish in
  // without asking for memory (after other tests ran): the model must need far more than that.
  ExactOptions o;
  o.memoryLimitBytes = 1 << 20;
  o.timeLimitSeconds = 20.0;
  const ExactDecomposition d = acdsandbox::exactSolidDecomposition(shapes::torus(2.0, 0.5, 96, 48), o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_FALSE(d.finished);
  EXPECT_FALSE(d.note.empty());
}

// maxPieces: the rest are counted, and the note says so.
TEST(ExactSolidCapped, MaxPiecesNoted) {
  ExactOptions o;
  o.maxPieces = 1;
  const ExactDecomposition d = acdsandbox::exactSolidDecomposition(shapes::uShape(), o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.finished);
  EXPECT_EQ(d.pieceCount, 3u);
  EXPECT_EQ(d.pieces.size(), 1u);
  EXPECT_EQ(d.note, "only the first 1 of 3 pieces returned (maxPieces)");
}

TEST(ExactSolidCapped, RefusalsAndBadOptions) {
  TriMesh open = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  open.faces.pop_back();
  ExactOptions refuse;
  refuse.fillHoles = false;
  EXPECT_EQ(acdsandbox::exactSolidDecomposition(open, refuse).status.code, StatusCode::OpenMesh);
  ExactOptions nan;
  nan.timeLimitSeconds = std::nan("");
  EXPECT_EQ(acdsandbox::exactSolidDecomposition(shapes::lShape(), nan).status.code, StatusCode::InvalidParameter);
}
