// The paper's units (libacd/src/mesh/normalize.cpp): the minimum enclosing sphere on point sets
// whose sphere is known (a box: its half diagonal; a regular tetrahedron: its circumradius; a
// long segment with points inside: half its length), and the normalisation's round trip.
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace acd;

namespace {

TriMesh pointsOnly(const std::vector<Vec3>& points) {
  TriMesh m;
  m.vertices = points;
  m.faces = {{0, 1, 2}};
  return m;
}

}  // namespace

TEST(MinimumSphereNormalization, BoxHasItsHalfDiagonal) {
  const TriMesh box = shapes::box(Vec3(1, 2, 3), Vec3(3, 6, 9));
  const Normalization n = minimumSphereNormalization(box);
  EXPECT_TRUE(n.center.isApprox(Vec3(2, 4, 6), 1e-12));
  EXPECT_NEAR(1.0 / n.scale, 0.5 * std::sqrt(4.0 + 16.0 + 36.0), 1e-12);
}

TEST(MinimumSphereNormalization, RegularTetrahedronHasItsCircumradius) {
  const std::vector<Vec3> tet{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  const Normalization n = minimumSphereNormalization(pointsOnly(tet));
  EXPECT_NEAR(n.center.norm(), 0.0, 1e-12);
  EXPECT_NEAR(1.0 / n.scale, std::sqrt(3.0), 1e-12);
}

// The two ends of a segment fix the sphere when every other point lies inside it.
TEST(MinimumSphereNormalization, SegmentEndsWithPointsInside) {
  std::vector<Vec3> pts{Vec3(-5, 1, 1), Vec3(5, 1, 1)};
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  while (pts.size() < 60) {
    const double x = 4 * u(rng), y = 1 + 2 * u(rng), z = 1 + 2 * u(rng);  // drawn in this order
    const Vec3 p(x, y, z);
    if ((p - Vec3(0, 1, 1)).norm() < 4.9) pts.push_back(p);
  }
  const Normalization n = minimumSphereNormalization(pointsOnly(pts));
  EXPECT_TRUE(n.center.isApprox(Vec3(0, 1, 1), 1e-12)) << n.center.transpose();
  EXPECT_NEAR(1.0 / n.scale, 5.0, 1e-12);
}

// Normalised, the model lies in the unit ball and touches its sphere; undoing gives it back.
TEST(MinimumSphereNormalization, ApplyAndUndo) {
  const TriMesh m = shapes::torus(3.0, 1.0, 16, 8);
  TriMesh placed = m;
  for (Vec3& v : placed.vertices) v = 7.0 * v + Vec3(100, -20, 3);
  const Normalization n = minimumSphereNormalization(placed);
  const TriMesh unit = applyNormalization(placed, n);
  double far = 0;
  for (const Vec3& v : unit.vertices) far = std::max(far, v.norm());
  EXPECT_NEAR(far, 1.0, 1e-12);
  EXPECT_EQ(unit.faces, placed.faces);
  const TriMesh back = undoNormalization(unit, n);
  for (std::size_t i = 0; i < back.vertices.size(); ++i)
    EXPECT_TRUE(back.vertices[i].isApprox(placed.vertices[i], 1e-12)) << i;
  EXPECT_TRUE(n.undo(n.apply(Vec3(1, 2, 3))).isApprox(Vec3(1, 2, 3), 1e-12));
}

// A triangle soup (every face with its own copies of its corners, as STL files and assemblies of
// shells give them) in any order has the sphere of its points taken once: exactly the same
// numbers. (On one such soup, a generated bearing block of 7 860 corner copies turned at
// random, CGAL's LP algorithm on the copies never returned.)
TEST(MinimumSphereNormalization, RepeatedPointsInAnyOrderGiveTheSameSphere) {
  TriMesh m = shapes::torus(3.0, 1.0, 24, 12);
  for (Vec3& v : m.vertices) v = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) * v + Vec3(10, -4, 2);
  TriMesh soup;
  for (const Face& f : m.faces)
    for (int k = 0; k < 3; ++k) soup.vertices.push_back(m.vertices[f[k]]);
  std::shuffle(soup.vertices.begin(), soup.vertices.end(), std::mt19937_64(3));
  soup.faces = {{0, 1, 2}};
  const Normalization a = minimumSphereNormalization(m), b = minimumSphereNormalization(soup);
  EXPECT_EQ(a.scale, b.scale);
  EXPECT_EQ(a.center, b.center);
  EXPECT_NEAR(1.0 / a.scale, 4.0, 1e-9);  // the torus's outer radius (its rings' vertices lie on it)
}

// The last vertex list's sphere is remembered: asked again on the same vertices it comes back
// as it was; a list that differs in one vertex's last bit, or in its length, gets its own.
TEST(MinimumSphereNormalization, AskedAgainOnlyTheSameVerticesGetTheSameSphere) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(2, 2, 2));
  const Normalization first = minimumSphereNormalization(box);
  EXPECT_TRUE(first.center.isApprox(Vec3(1, 1, 1), 1e-12));
  EXPECT_NEAR(1.0 / first.scale, std::sqrt(3.0), 1e-12);

  TriMesh moved = box;
  const auto corner = std::max_element(moved.vertices.begin(), moved.vertices.end(),
                                       [](const Vec3& a, const Vec3& b) { return a.sum() < b.sum(); });
  *corner = Vec3(4, 4, 4);  // the box's far corner pulled out along the diagonal: a larger sphere
  const Normalization pulled = minimumSphereNormalization(moved);
  EXPECT_NEAR(1.0 / pulled.scale, 2.0 * std::sqrt(3.0), 1e-12);  // half the diagonal from the origin to it
  EXPECT_TRUE(pulled.center.isApprox(Vec3(2, 2, 2), 1e-12));

  corner->x() = std::nextafter(4.0, 5.0);  // one bit apart: not the same vertices
  EXPECT_NE(minimumSphereNormalization(moved).center.x(), pulled.center.x());

  moved.vertices.push_back(Vec3(-4, -4, -4));  // one more vertex
  EXPECT_NEAR(1.0 / minimumSphereNormalization(moved).scale, 4.0 * std::sqrt(3.0), 1e-12);

  const Normalization again = minimumSphereNormalization(box);
  EXPECT_EQ(again.center, first.center);
  EXPECT_EQ(again.scale, first.scale);
}
