// fitCutPlane and bisectorPlane against planes known from the construction of each case.
#include <acd/algo/cut_plane.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>

using namespace acd;

namespace {

const double kPi = std::acos(-1.0);

/// A cut through mesh vertices 0..n-1 with the given weights.
GlobalCut cutThrough(int n, const std::vector<double>& weight) {
  GlobalCut cut;
  for (int i = 0; i < n; ++i) cut.vertices.push_back(i);
  cut.weight = weight;
  return cut;
}

double maxDistance(const TriMesh& mesh, const GlobalCut& cut, const Plane& plane, double minWeight) {
  double worst = 0.0;
  for (std::size_t i = 0; i < cut.vertices.size(); ++i)
    if (cut.weight[i] >= minWeight)
      worst = std::max(worst, std::abs(plane.signedDistance(mesh.vertices[cut.vertices[i]])) / plane.normal.norm());
  return worst;
}

TEST(FitCutPlane, ARingOnATiltedPlaneGivesThatPlane) {
  const Vec3 n0 = Vec3(1, 2, 2) / 3.0, centre(0.3, -0.2, 0.5);
  const Vec3 u = Vec3(2, -1, 0).normalized(), w = n0.cross(u);
  TriMesh mesh;
  std::vector<double> weight;
  for (int i = 0; i < 12; ++i) {
    const double a = 2 * kPi * i / 12;
    mesh.vertices.push_back(centre + 0.4 * std::cos(a) * u + 0.25 * std::sin(a) * w);
    weight.push_back(0.01 * (1 + i % 5));
  }
  const Plane p = fitCutPlane(mesh, cutThrough(12, weight), Vec3(0, 0, 1), 1e-3);
  EXPECT_NEAR(std::abs(p.normal.normalized().dot(n0)), 1.0, 1e-12);
  EXPECT_LT(maxDistance(mesh, cutThrough(12, weight), p, 0.0), 1e-12);
}

TEST(FitCutPlane, AStraightCutContainsTheBridgeNormal) {
  // Collinear cut vertices along x: the plane contains the line and cuts down along the bridge normal.
  TriMesh mesh;
  for (int i = 0; i < 6; ++i) mesh.vertices.emplace_back(0.1 * i, 0.5, 0.2);
  const GlobalCut cut = cutThrough(6, std::vector<double>(6, 0.05));
  const Plane p = fitCutPlane(mesh, cut, Vec3(0, 0, 1), 1e-3);
  const Vec3 n = p.normal.normalized();
  EXPECT_NEAR(std::abs(n.y()), 1.0, 1e-9);
  EXPECT_LT(maxDistance(mesh, cut, p, 0.0), 1e-12);
}

TEST(FitCutPlane, IsPushedTowardTheConcaveVerticesItMisses) {
  // Ten flat vertices of little concavity and two deep ones off their plane. Plain weighted PCA
  // (computed here) leaves the deep ones farther than the tolerance; the fit must get closer.
  TriMesh mesh;
  std::vector<double> weight;
  for (int i = 0; i < 10; ++i) {
    const double a = 2 * kPi * i / 10;
    mesh.vertices.emplace_back(std::cos(a), std::sin(a), 0.0);
    weight.push_back(0.005);  // below a tenth of the peak: not counted as missed
  }
  mesh.vertices.emplace_back(0.5, 0.0, 0.3);
  mesh.vertices.emplace_back(-0.5, 0.0, 0.3);
  weight.push_back(0.1);
  weight.push_back(0.1);
  const GlobalCut cut = cutThrough(12, weight);
  Vec3 centroid = Vec3::Zero();
  double total = 0;
  for (int i = 0; i < 12; ++i) centroid += weight[i] * mesh.vertices[i], total += weight[i];
  centroid /= total;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 12; ++i) cov += weight[i] * (mesh.vertices[i] - centroid) * (mesh.vertices[i] - centroid).transpose();
  const Plane pca = Plane::through(centroid, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0));
  const double tolerance = 0.05;
  const double before = maxDistance(mesh, cut, pca, 0.1);
  ASSERT_GT(before, tolerance);  // the case is what it claims to be
  const Plane fitted = fitCutPlane(mesh, cut, Vec3(0, 0, 1), tolerance);
  EXPECT_LT(maxDistance(mesh, cut, fitted, 0.1), 0.5 * before);
}

TEST(BisectorPlane, HalvesTheReflexAngleOfAnL) {
  // Cells (0,0), (1,0), (0,1): the inner corner edge runs along z at (1, 1); its faces face +x and
  // +y, so the bisector contains z and (1, 1, 0): normal (1, -1, 0) / sqrt(2).
  const TriMesh l = shapes::lShape();
  int notch = -1;
  for (std::size_t v = 0; v < l.vertices.size(); ++v)
    if ((l.vertices[v] - Vec3(1, 1, 0)).norm() < 1e-12) notch = static_cast<int>(v);
  ASSERT_GE(notch, 0);
  const SurfaceGraph graph(l);
  const Plane p = bisectorPlane(l, graph, notch, Vec3(1, 1, 0).normalized());
  const Vec3 n = p.normal.normalized();
  EXPECT_NEAR(std::abs(n.dot(Vec3(1, -1, 0).normalized())), 1.0, 1e-12);
  EXPECT_NEAR(p.signedDistance(Vec3(1, 1, 0.5)), 0.0, 1e-12);
  // It splits the L into two congruent halves: the corner cells' far corners lie on opposite sides.
  EXPECT_LT(p.signedDistance(Vec3(2, 0, 0)) * p.signedDistance(Vec3(0, 2, 0)), 0.0);
}

}  // namespace
