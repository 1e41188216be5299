// TriMesh's basic measures and operations (libacd/src/mesh/mesh.cpp) on solids with known answers:
// boxes (volume, area, bounds), a right triangle's normal, connected parts, concatenation,
// compaction, and what makes a mesh closed and consistently oriented.
#include <acd/diagnosis.hpp>
#include <acd/mesh.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <set>

using namespace acd;

namespace {

TriMesh moved(TriMesh m, const Vec3& t) {
  for (Vec3& v : m.vertices) v += t;
  return m;
}

TriMesh joined(const TriMesh& a, const TriMesh& b) {
  TriMesh out = a;
  const int base = static_cast<int>(a.vertices.size());
  out.vertices.insert(out.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const Face& f : b.faces) out.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  return out;
}

}  // namespace

TEST(Mesh, BoxVolumeAreaAndBounds) {
  const TriMesh box = shapes::box(Vec3(1, 2, 3), Vec3(2, 4, 6));  // 1 x 2 x 3
  EXPECT_NEAR(signedVolume(box), 6.0, 1e-12);
  EXPECT_NEAR(surfaceArea(box), 2 * (1 * 2 + 2 * 3 + 1 * 3), 1e-12);
  const Box3 b = boundingBox(box);
  EXPECT_EQ(b.lo, Vec3(1, 2, 3));
  EXPECT_EQ(b.hi, Vec3(2, 4, 6));
  EXPECT_EQ(b.size(), Vec3(1, 2, 3));
  EXPECT_EQ(b.center(), Vec3(1.5, 3, 4.5));
  // Inside out: the same volume, negative; the volume does not depend on where the box is.
  TriMesh inverted = box;
  for (Face& f : inverted.faces) std::swap(f[1], f[2]);
  EXPECT_NEAR(signedVolume(inverted), -6.0, 1e-12);
  EXPECT_NEAR(signedVolume(moved(box, Vec3(-100, 50, 7))), 6.0, 1e-9);
}

TEST(Mesh, FaceNormalIsTwiceTheAreaAlongTheRightHandNormal) {
  TriMesh t;
  t.vertices = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 3, 0)};
  t.faces = {{0, 1, 2}};
  EXPECT_EQ(faceNormal(t, 0), Vec3(0, 0, 6));
  t.faces = {{0, 2, 1}};
  EXPECT_EQ(faceNormal(t, 0), Vec3(0, 0, -6));
  EXPECT_NEAR(surfaceArea(t), 3.0, 1e-15);
}

TEST(Mesh, EdgeKeyIgnoresDirectionAndTellsEdgesApart) {
  EXPECT_EQ(edgeKey(3, 7), edgeKey(7, 3));
  std::set<std::uint64_t> keys;
  for (int a = 0; a < 30; ++a)
    for (int b = a + 1; b < 30; ++b) keys.insert(edgeKey(a, b));
  EXPECT_EQ(keys.size(), 30u * 29u / 2u);
  EXPECT_NE(edgeKey(0, 1 << 20), edgeKey(1 << 20, 1 << 21));
}

// Two boxes apart are two parts; two boxes sharing one corner vertex are two edge-connected parts too.
TEST(Mesh, SplitEdgeConnectedGivesEachPartCompacted) {
  const TriMesh a = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  for (const TriMesh& two : {joined(a, moved(a, Vec3(3, 0, 0))), joined(a, moved(a, Vec3(1, 1, 1)))}) {
    const std::vector<TriMesh> parts = splitEdgeConnected(two);
    ASSERT_EQ(parts.size(), 2u);
    for (const TriMesh& p : parts) {
      EXPECT_EQ(p.faces.size(), a.faces.size());
      EXPECT_EQ(p.vertices.size(), a.vertices.size());
      EXPECT_NEAR(signedVolume(p), 1.0, 1e-12);
      EXPECT_TRUE(isClosedOriented(p));
    }
  }
  EXPECT_EQ(splitEdgeConnected(a).size(), 1u);
}

TEST(Mesh, ConcatenateAndCompact) {
  const TriMesh a = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), b = shapes::lShape();
  const TriMesh c = concatenate({a, b});
  EXPECT_EQ(c.vertices.size(), a.vertices.size() + b.vertices.size());
  EXPECT_EQ(c.faces.size(), a.faces.size() + b.faces.size());
  EXPECT_NEAR(signedVolume(c), signedVolume(a) + signedVolume(b), 1e-12);
  // A stray vertex in front and one in the middle: compact drops both and keeps the geometry.
  TriMesh loose;
  loose.vertices.push_back(Vec3(9, 9, 9));
  for (const Vec3& v : a.vertices) {
    loose.vertices.push_back(v);
    if (loose.vertices.size() == 4) loose.vertices.push_back(Vec3(-9, -9, -9));
  }
  for (const Face& f : a.faces) {
    Face g;
    for (int k = 0; k < 3; ++k) g[k] = f[k] + 1 + (f[k] + 1 >= 4 ? 1 : 0);
    loose.faces.push_back(g);
  }
  EXPECT_NEAR(signedVolume(loose), 1.0, 1e-12);
  const TriMesh tight = compact(loose);
  EXPECT_EQ(tight.vertices.size(), a.vertices.size());
  EXPECT_EQ(tight.faces.size(), a.faces.size());
  EXPECT_NEAR(signedVolume(tight), 1.0, 1e-12);
  for (const Face& f : tight.faces)
    for (int v : f) EXPECT_LT(v, static_cast<int>(tight.vertices.size()));
}

TEST(Mesh, ClosedAndOrientedOrNot) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_TRUE(isClosedOriented(box));
  EXPECT_TRUE(isClosedOriented(shapes::torus(2.0, 0.5, 12, 6)));
  TriMesh open = box;
  open.faces.pop_back();
  EXPECT_FALSE(isClosedOriented(open));
  TriMesh flipped = box;
  std::swap(flipped.faces[0][1], flipped.faces[0][2]);
  EXPECT_FALSE(isClosedOriented(flipped));
}

// pinchedVertices walks the fans around each vertex; diagnose's count joins corners across the
// numbered edges with a union-find. On oriented surfaces, closed or open, they must agree.
TEST(Mesh, PinchedVerticesAsTheDiagnosisCountsThem) {
  auto diagnosed = [](const std::vector<Face>& faces) {
    int nv = 0;
    for (const Face& f : faces) nv = std::max({nv, f[0] + 1, f[1] + 1, f[2] + 1});
    return countNonManifoldVertices(faces, nv);
  };
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_EQ(pinchedVertices(box.faces), 0);
  // Two boxes corner to corner, the corner shared: one pinch.
  TriMesh two = concatenate({box, shapes::box(Vec3(1, 1, 1), Vec3(2, 2, 2))});
  const int n = static_cast<int>(box.vertices.size());
  int corner = -1, other = -1;
  for (int v = 0; v < static_cast<int>(two.vertices.size()); ++v)
    if (two.vertices[v] == Vec3(1, 1, 1)) (v < n ? corner : other) = v;
  ASSERT_GE(corner, 0);
  ASSERT_GE(other, 0);
  for (Face& f : two.faces)
    for (int& v : f)
      if (v == other) v = corner;
  EXPECT_EQ(pinchedVertices(two.faces), 1);
  // Two triangles meeting at one vertex (open fans): one pinch; an open box: none.
  EXPECT_EQ(pinchedVertices({{0, 1, 2}, {0, 3, 4}}), 1);
  TriMesh open = box;
  open.faces.pop_back();
  EXPECT_EQ(pinchedVertices(open.faces), 0);
  // Not an oriented edge-manifold: -1.
  TriMesh flipped = box;
  std::swap(flipped.faces[0][1], flipped.faces[0][2]);
  EXPECT_EQ(pinchedVertices(flipped.faces), -1);
  EXPECT_EQ(pinchedVertices({{0, 0, 1}}), -1);
  // Spheres with random faces taken away: open fans, pinches where the faces left around a vertex
  // fall apart; vertices renumbered at random.
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  std::mt19937 rng(5);
  int withPinches = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<int> rename(sphere.vertices.size());
    std::iota(rename.begin(), rename.end(), 0);
    std::shuffle(rename.begin(), rename.end(), rng);
    const double keep = 0.5 + 0.5 * (trial % 10) / 10.0;
    std::vector<Face> faces;
    for (const Face& f : sphere.faces)
      if (std::uniform_real_distribution<double>(0, 1)(rng) < keep) faces.push_back({rename[f[0]], rename[f[1]], rename[f[2]]});
    if (faces.empty()) continue;
    const int expected = diagnosed(faces);
    ASSERT_EQ(pinchedVertices(faces), expected) << "trial " << trial;
    withPinches += expected > 0 ? 1 : 0;
  }
  EXPECT_GT(withPinches, 50);  // the comparison saw pinches, not only clean fans
}
