// Mass properties against closed forms: boxes (any pose), unions of unit cubes summed with the
// parallel-axis theorem, and a fine sphere against the ball's.
#include <acd/algo/mass_properties.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace acd;

namespace {

/// Inertia tensor of a solid box of these side lengths about its centre, axis-aligned.
Eigen::Matrix3d boxInertia(double mass, const Vec3& s) {
  return (mass / 12.0) * Vec3(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(), s.x() * s.x() + s.y() * s.y())
                             .asDiagonal()
                             .toDenseMatrix();
}

}  // namespace

TEST(MassProperties, BoxAtAnyPose) {
  const Vec3 lo(-1, 2, 0.5), hi(2, 2.5, 4.5), size = hi - lo;
  const double density = 7.5, mass = density * size.prod();
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(1.1, Vec3(0.3, -1, 2).normalized()).toRotationMatrix();
  const Vec3 shift(100, -40, 7);
  TriMesh box = shapes::box(lo, hi);
  const MassProperties a = massProperties(box, density);
  EXPECT_NEAR(a.volume, size.prod(), 1e-12);
  EXPECT_NEAR(a.mass, mass, 1e-10);
  EXPECT_LT((a.centerOfMass - 0.5 * (lo + hi)).norm(), 1e-12);
  EXPECT_LT((a.inertia - boxInertia(mass, size)).norm(), 1e-9 * boxInertia(mass, size).norm());
  for (Vec3& v : box.vertices) v = rot * v + shift;
  const MassProperties b = massProperties(box, density);
  EXPECT_NEAR(b.volume, size.prod(), 1e-9);
  EXPECT_LT((b.centerOfMass - (rot * (0.5 * (lo + hi)) + shift)).norm(), 1e-9);
  const Eigen::Matrix3d expected = rot * boxInertia(mass, size) * rot.transpose();
  EXPECT_LT((b.inertia - expected).norm(), 1e-8 * expected.norm());
  EXPECT_LT((b.principalMoments - a.principalMoments).norm(), 1e-8 * expected.norm());
}

TEST(MassProperties, UnionOfCubesMatchesParallelAxisSum) {
  const std::vector<std::array<int, 3>> cells = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}, {2, 1, 1}};
  const double h = 0.5;
  const MassProperties mp = massProperties(shapes::voxels(cells, h), 2.0);
  // Oracle: each cell a cube of mass 2 h^3; centre of mass the mean of the cell centres;
  // inertia the sum of the cubes' own plus m (|d|^2 I - d d^T).
  const double m = 2.0 * h * h * h;
  Vec3 com = Vec3::Zero();
  for (const auto& c : cells) com += h * Vec3(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5);
  com /= static_cast<double>(cells.size());
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  for (const auto& c : cells) {
    const Vec3 d = h * Vec3(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5) - com;
    inertia += boxInertia(m, Vec3::Constant(h)) + m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
  }
  EXPECT_NEAR(mp.volume, cells.size() * h * h * h, 1e-12);
  EXPECT_NEAR(mp.mass, cells.size() * m, 1e-12);
  EXPECT_LT((mp.centerOfMass - com).norm(), 1e-12);
  EXPECT_LT((mp.inertia - inertia).norm(), 1e-12);
  EXPECT_NE(mp.inertia(0, 1), 0.0);  // the L is not symmetric: products of inertia are there
}

TEST(MassProperties, SeveralSolidsAddUp) {
  const TriMesh a = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), b = shapes::box(Vec3(3, 0, 0), Vec3(4, 2, 1));
  const MassProperties both = massProperties({a, b}, 1.0);
  EXPECT_NEAR(both.volume, 3.0, 1e-12);
  EXPECT_LT((both.centerOfMass - (Vec3(0.5, 0.5, 0.5) + 2.0 * Vec3(3.5, 1, 0.5)) / 3.0).norm(), 1e-12);
}

TEST(MassProperties, FineSphereApproachesTheBall) {
  const double r = 2.0;
  const MassProperties mp = massProperties(shapes::icosphere(Vec3(1, 2, 3), r, 5), 1.0);
  const double volume = 4.0 / 3.0 * M_PI * r * r * r;
  EXPECT_NEAR(mp.volume / volume, 1.0, 2e-3);
  EXPECT_LT((mp.centerOfMass - Vec3(1, 2, 3)).norm(), 1e-9);
  const double moment = 0.4 * volume * r * r;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(mp.principalMoments[k] / moment, 1.0, 5e-3);
}
