// Hulls with a vertex budget: at most K vertices, every point of the hull (so of the component)
// still inside, convex, exact when the hull is within the budget, K < 4 refused.
#include <acd/algo/convex_polytope.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/hull_vertex_cap.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

using namespace acd;

namespace {

/// The test's own containment check: largest distance of a point beyond a face plane of the
/// convex mesh, each plane from the face's corners (no sliver skipping).
double beyondFaces(const TriMesh& convex, const std::vector<Vec3>& pts) {
  double worst = -std::numeric_limits<double>::infinity();
  for (const Face& f : convex.faces) {
    const Vec3 &a = convex.vertices[f[0]], &b = convex.vertices[f[1]], &c = convex.vertices[f[2]];
    const Vec3 n = (b - a).cross(c - a);
    if (!(n.norm() > 1e-14)) continue;
    const Vec3 u = n.normalized();
    for (const Vec3& p : pts) worst = std::max(worst, u.dot(p - a));
  }
  return worst;
}

}  // namespace

TEST(HullVertexCap, CubeWithEightVerticesStaysTheCube) {
  const TriMesh cube = hullMesh(shapes::box(Vec3(-1, 2, 0.5), Vec3(1.5, 3, 4)).vertices);
  HullCapOptions o;
  o.maxVertices = 8;
  const CappedHulls c = capHullVertices({cube}, o);
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  ASSERT_EQ(c.hulls.size(), 1u);
  EXPECT_EQ(c.unchanged, 1);
  EXPECT_EQ(c.vertices[0], 8);
  EXPECT_EQ(c.addedVolume[0], 0.0);
  // The very same corners.
  std::vector<Vec3> a = cube.vertices, b = c.hulls[0].vertices;
  auto lex = [](const Vec3& p, const Vec3& q) { return std::lexicographical_compare(p.data(), p.data() + 3, q.data(), q.data() + 3); };
  std::sort(a.begin(), a.end(), lex);
  std::sort(b.begin(), b.end(), lex);
  EXPECT_EQ(a, b);
}

TEST(HullVertexCap, BudgetBelowFourIsRefused) {
  const TriMesh cube = hullMesh(shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)).vertices);
  for (int k : {3, 0, -5}) {
    HullCapOptions o;
    o.maxVertices = k;
    const CappedHulls c = capHullVertices({cube}, o);
    EXPECT_EQ(c.status.code, StatusCode::InvalidParameter) << k;
    EXPECT_NE(c.status.message.find("at least 4"), std::string::npos) << c.status.message;
  }
}

TEST(HullVertexCap, SphereGetsEveryBudgetAndStaysInside) {
  const TriMesh sphere = shapes::icosphere(Vec3(0.3, -1, 2), 1.5, 3);  // 642 vertices
  const TriMesh hull = hullMesh(sphere.vertices);
  const double hullVolume = signedVolume(hull);
  double previous = std::numeric_limits<double>::infinity();
  for (int k : {4, 5, 6, 7, 8, 12, 24, 60, 100}) {
    HullCapOptions o;
    o.maxVertices = k;
    const CappedHulls c = capHullVertices({hull}, o);
    ASSERT_TRUE(c.status.ok());
    const TriMesh& r = c.hulls[0];
    EXPECT_LE(static_cast<int>(r.vertices.size()), k) << k;
    EXPECT_EQ(c.vertices[0], static_cast<int>(r.vertices.size()));
    EXPECT_EQ(c.reached, 1);
    EXPECT_TRUE(isClosedOriented(r)) << k;
    EXPECT_LE(beyondFaces(r, sphere.vertices), 1e-12) << k;  // contains the component
    EXPECT_LE(beyondFaces(r, r.vertices), 1e-9) << k;         // convex
    EXPECT_NEAR(c.addedVolume[0], signedVolume(r) - hullVolume, 1e-9);
    EXPECT_GE(c.addedVolume[0], 0.0);
    if (k >= 8) {
      EXPECT_LE(signedVolume(r), previous * (1 + 1e-9)) << "a larger budget is never looser, K = " << k;
      previous = signedVolume(r);
    }
  }
  // 60 corners around a ball: within 25 % of its hull (a cube around it is 91 % above).
  HullCapOptions o;
  o.maxVertices = 60;
  EXPECT_LT(signedVolume(capHullVertices({hull}, o).hulls[0]), 1.25 * hullVolume);
}

TEST(HullVertexCap, TheResultTurnsWithTheInput) {
  // A lumpy ellipsoid: three distinct principal moments, so its principal frame is defined.
  TriMesh blob = shapes::icosphere(Vec3::Zero(), 1.0, 3);
  for (Vec3& v : blob.vertices) v = Vec3(1.3 * v.x(), 0.8 * v.y(), 0.5 * v.z()) * (1.0 + 0.08 * std::sin(3 * v.x() + 2 * v.y()));
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  TriMesh turned = blob;
  for (Vec3& v : turned.vertices) v = rot * v + Vec3(5, -3, 2);
  HullCapOptions o;
  o.maxVertices = 16;
  const CappedHulls a = capHullVertices({hullMesh(blob.vertices)}, o);
  const CappedHulls b = capHullVertices({hullMesh(turned.vertices)}, o);
  for (const CappedHulls* c : {&a, &b}) {
    EXPECT_LE(c->vertices[0], 16);
    EXPECT_LT(c->addedVolume[0], 0.6 * c->hullVolume[0]);
  }
  EXPECT_LE(beyondFaces(a.hulls[0], blob.vertices), 1e-12);
  EXPECT_LE(beyondFaces(b.hulls[0], turned.vertices), 1e-12);
  EXPECT_EQ(a.vertices[0], b.vertices[0]);
  EXPECT_NEAR(b.addedVolume[0], a.addedVolume[0], 1e-6 * a.hullVolume[0]);
}

TEST(HullVertexCap, ConvexPolytopeCutsAndCounts) {
  ConvexPolytope p = ConvexPolytope::box(Vec3(0, 0, 0), Vec3(1, 1, 1), 1e-12);
  EXPECT_NEAR(p.volume(), 1.0, 1e-15);
  EXPECT_EQ(p.corners().size(), 8u);
  const HalfSpace corner{Vec3(1, 1, 1).normalized(), 2.5 / std::sqrt(3.0)};  // cuts one corner off
  ASSERT_TRUE(p.cutBy(corner));
  p = p.clipped(corner);
  EXPECT_EQ(p.corners().size(), 10u);
  EXPECT_NEAR(p.volume(), 1.0 - std::pow(0.5, 3) / 6.0, 1e-12);
  EXPECT_NEAR(maxOutsideDistance(p.mesh(), {Vec3(1, 1, 1)}), (3.0 - 2.5) / std::sqrt(3.0), 1e-12);
}
