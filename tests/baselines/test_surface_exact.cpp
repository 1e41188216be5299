// The exact surface decomposition (libacd/src/baselines/surface_exact.cpp, flood-and-retract):
// patches that partition the faces, are edge-connected and lie on their own hull's boundary
// (checked by the definition and, independently, by a hull).
#include <acd/decompose.hpp>
#include <acd/algo/hull.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>
#include <acd/surface_exact.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

using namespace acd;
using acdtest::corpus;

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
