// The exact baselines: solid ECD (CGAL convex_decomposition_3 in a capped worker) and surface ECD
// (flood-and-retract). Piece counts on shapes whose minimum decomposition is known, and the
// invariants of any convex decomposition: closed convex pieces whose volumes add up to the input
// and which cover it exactly once (sampled); patches that partition the faces, are edge-connected
// and lie on their own hull's boundary (checked by the definition and, independently, by a hull).
#include <acd/decompose.hpp>
#include <acd/exact_decomposition.hpp>
#include <acd/hull.hpp>
#include <acd/inside.hpp>
#include <acd/io.hpp>
#include <acd/normalize.hpp>
#include <acd/shapes.hpp>
#include <acd/surface_exact.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <unordered_map>

using namespace acd;
using acdtest::corpus;

namespace {

TriMesh joined(const std::vector<TriMesh>& parts) {
  TriMesh out;
  for (const TriMesh& p : parts) {
    const int base = static_cast<int>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), p.vertices.begin(), p.vertices.end());
    for (const Face& f : p.faces) out.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  return out;
}

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
    const Vec3 q = box.lo + box.size().cwiseProduct(Vec3(uni(rng), uni(rng), uni(rng)));
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

ExactDecomposition solidECD(const TriMesh& mesh, double limit = 60) {
  ExactOptions o;
  o.timeLimitSeconds = limit;
  return exactSolidDecomposition(mesh, o);
}

}  // namespace

// ---------------------------------------------------------------- solid ECD
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
  const TriMesh two = joined({shapes::lShape(), second});
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

// The time cap stops the worker and says where; the caller gets control back promptly.
TEST(ExactSolid, TimeCapReportsUnfinished) {
  const TriMesh torus = shapes::torus(2.0, 0.5, 64, 32);
  const auto start = std::chrono::steady_clock::now();
  const ExactDecomposition d = solidECD(torus, 0.3);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_FALSE(d.finished);
  EXPECT_EQ(d.unfinishedSolids, 1u);
  EXPECT_TRUE(d.pieces.empty());
  EXPECT_GT(d.reflexEdges, 0);
  EXPECT_NE(d.note.find("not finished within 0.3 s"), std::string::npos) << d.note;
  EXPECT_LT(wall, 5.0);
}

// A memory cap the worker cannot live with ends as "unfinished", never as a crash of the caller.
TEST(ExactSolid, MemoryCapReportsUnfinished) {
  // The forked worker inherits the caller's heap, whose free blocks a small model can finish in
  // without asking for memory (after other tests ran): the model must need far more than that.
  ExactOptions o;
  o.memoryLimitBytes = 1 << 20;
  o.timeLimitSeconds = 20.0;
  const ExactDecomposition d = exactSolidDecomposition(shapes::torus(2.0, 0.5, 96, 48), o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_FALSE(d.finished);
  EXPECT_FALSE(d.note.empty());
}

// An open mesh has its holes filled first, as for solid ACD, or is refused when asked to.
TEST(ExactSolid, OpenMeshFilledOrRefused) {
  TriMesh open = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  open.faces.pop_back();  // a triangular hole: filling it gives the box back
  ExactOptions refuse;
  refuse.fillHoles = false;
  const ExactDecomposition r = exactSolidDecomposition(open, refuse);
  EXPECT_EQ(r.status.code, StatusCode::OpenMesh) << r.status.message;
  EXPECT_TRUE(r.pieces.empty());
  const ExactDecomposition d = exactSolidDecomposition(open);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_EQ(d.holesFilled, 1);
  EXPECT_FALSE(d.repairs.empty());
  ASSERT_EQ(d.pieces.size(), 1u);
  EXPECT_NEAR(signedVolume(d.pieces[0]), 1.0, 1e-12);
}

TEST(ExactSolid, RefusesSelfIntersectingInput) {
  const TriMesh overlapping =
      joined({shapes::box(Vec3(0, 0, 0), Vec3(2, 2, 2)), shapes::box(Vec3(1, 1, 1), Vec3(3, 3, 3))});
  const ExactDecomposition d = solidECD(overlapping);
  EXPECT_FALSE(d.status.ok());
  EXPECT_NE(d.status.message.find("intersects itself"), std::string::npos) << d.status.message;
}

// ---------------------------------------------------------------- surface ECD
namespace {

/// Faces partitioned exactly, every patch edge-connected and convex by the definition.
void expectConvexPartition(const TriMesh& mesh, const SurfaceExactDecomposition& d, double tolerance) {
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  ASSERT_EQ(d.patchOfFace.size(), mesh.faces.size());
  std::vector<int> seen(mesh.faces.size(), 0);
  for (std::size_t p = 0; p < d.patches.size(); ++p) {
    ASSERT_FALSE(d.patches[p].empty()) << "patch " << p;
    for (int f : d.patches[p]) {
      ++seen[f];
      EXPECT_EQ(d.patchOfFace[f], static_cast<int>(p));
    }
    EXPECT_EQ(splitEdgeConnected(patchMesh(mesh, d.patches[p])).size(), 1u) << "patch " << p;
    EXPECT_TRUE(isConvexPatch(mesh, d.patches[p], tolerance)) << "patch " << p;
  }
  for (std::size_t f = 0; f < seen.size(); ++f) EXPECT_EQ(seen[f], 1) << "face " << f;
}

/// Independent of the face planes: every vertex of a (solid) patch lies on its hull's boundary.
double worstDepthBelowHull(const TriMesh& mesh, const std::vector<int>& faces) {
  const TriMesh patch = patchMesh(mesh, faces);
  const ConvexHull hull = convexHull(patch.vertices);
  if (hull.degenerate || hull.mesh.faces.empty()) return 0.0;  // flat patch: lies in its hull
  double worst = 0;
  for (const Vec3& v : patch.vertices) {
    double depth = std::numeric_limits<double>::infinity();
    for (int f = 0; f < static_cast<int>(hull.mesh.faces.size()); ++f) {
      const Vec3 n = faceNormal(hull.mesh, f).normalized();
      depth = std::min(depth, -n.dot(v - hull.mesh.vertices[hull.mesh.faces[f][0]]));
    }
    worst = std::max(worst, depth);
  }
  return worst;
}

double absoluteTolerance(const TriMesh& mesh) {
  // The library's tolerance is in normalised units; 1 % slack for the coplanar-plane shortcut.
  return 1.01 * SurfaceExactOptions{}.tolerance / minimumSphereNormalization(compact(mesh)).scale;
}

}  // namespace

TEST(ExactSurface, ConvexShapesAreOnePatch) {
  for (const TriMesh& m : {shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3)), shapes::icosphere(Vec3(1, 2, 3), 2.0, 3)}) {
    const SurfaceExactDecomposition d = exactSurfaceDecomposition(m);
    expectConvexPartition(m, d, absoluteTolerance(m));
    EXPECT_EQ(d.patches.size(), 1u);
  }
}

// The L's one reflex edge separates two convex patches. The U needs only two as well: the slot's
// walls and floor together lie on the boundary of the slot's box (seen from inside), and the rest
// lies on the boundary of the U's hull. The definition does not care which side faces out.
TEST(ExactSurface, LAndUShapes) {
  const TriMesh l = shapes::lShape();
  const SurfaceExactDecomposition dl = exactSurfaceDecomposition(l);
  expectConvexPartition(l, dl, absoluteTolerance(l));
  EXPECT_EQ(dl.patches.size(), 2u);
  const TriMesh u = shapes::uShape();
  const SurfaceExactDecomposition du = exactSurfaceDecomposition(u);
  expectConvexPartition(u, du, absoluteTolerance(u));
  EXPECT_EQ(du.patches.size(), 2u);
}

// The checker can fail: a whole L or U surface is not convex, a box surface is; and a patch made of
// a reflex step and the face beyond it is not convex either.
TEST(ExactSurface, CheckerRejectsNonConvexPatches) {
  auto all = [](const TriMesh& m) {
    std::vector<int> faces(m.faces.size());
    for (std::size_t f = 0; f < faces.size(); ++f) faces[f] = static_cast<int>(f);
    return faces;
  };
  const TriMesh l = shapes::lShape(), u = shapes::uShape(), box = shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  EXPECT_FALSE(isConvexPatch(l, all(l), 1e-9));
  EXPECT_FALSE(isConvexPatch(u, all(u), 1e-9));
  EXPECT_TRUE(isConvexPatch(box, all(box), 1e-9));
  // Any two faces of the L that meet at an edge form a convex patch (a ridge or a valley)...
  std::unordered_map<std::uint64_t, std::vector<int>> edgeFaces;
  for (int f = 0; f < static_cast<int>(l.faces.size()); ++f)
    for (int k = 0; k < 3; ++k) edgeFaces[edgeKey(l.faces[f][k], l.faces[f][(k + 1) % 3])].push_back(f);
  for (const auto& [key, faces] : edgeFaces) EXPECT_TRUE(isConvexPatch(l, faces, 1e-9));
  // ...but the surface decomposition of the L needs two patches, so no single patch is all of it.
  EXPECT_EQ(countNotches(l), static_cast<int>(exactSurfaceDecomposition(l).patches.size()) - 1);
}

TEST(ExactSurface, TorusAndCorpus) {
  std::vector<std::pair<std::string, TriMesh>> models{{"torus", shapes::torus(2.0, 0.5, 48, 24)}};
  for (const char* name : {"elephant", "mushroom", "ChineseDragon-10kv"}) {
    const ReadResult r = readMesh(corpus(name));
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    models.emplace_back(name, r.mesh);
  }
  for (const auto& [name, mesh] : models) {
    SCOPED_TRACE(name);
    const SurfaceExactDecomposition d = exactSurfaceDecomposition(mesh);
    const double tol = absoluteTolerance(mesh);
    expectConvexPartition(mesh, d, tol);
    EXPECT_GT(d.patches.size(), 1u);
    double worst = 0;
    for (const auto& p : d.patches) worst = std::max(worst, worstDepthBelowHull(mesh, p));
    EXPECT_LE(worst, 10 * tol);
  }
}

TEST(ExactSurface, BadInput) {
  EXPECT_EQ(exactSurfaceDecomposition(TriMesh{}).status.code, StatusCode::EmptyMesh);
  TriMesh nan = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  nan.vertices[3].x() = std::nan("");
  EXPECT_EQ(exactSurfaceDecomposition(nan).status.code, StatusCode::NonFiniteVertex);
  TriMesh bad = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  bad.faces[0][1] = 99;
  EXPECT_EQ(exactSurfaceDecomposition(bad).status.code, StatusCode::IndexOutOfRange);
  SurfaceExactOptions o;
  o.tolerance = -1;
  EXPECT_EQ(exactSurfaceDecomposition(shapes::lShape(), o).status.code, StatusCode::InvalidParameter);
}
