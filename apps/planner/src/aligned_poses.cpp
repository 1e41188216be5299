#include "aligned_poses.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>

namespace planner {

namespace {

/// Smallest and largest of d . (R p) over the robot's corners.
std::pair<double, double> extentAlong(const std::vector<acd::Vec3>& corners, const Eigen::Matrix3d& R, const acd::Vec3& d) {
  const acd::Vec3 back = R.transpose() * d;  // project in the robot's frame: one rotation, not one per corner
  double lo = INFINITY, hi = -INFINITY;
  for (const acd::Vec3& p : corners) {
    const double s = back.dot(p);
    lo = std::min(lo, s), hi = std::max(hi, s);
  }
  return {lo, hi};
}

/// An eigenvector's sign made canonical: its largest component positive (ties: the first).
acd::Vec3 canonicalSign(acd::Vec3 v) {
  int big = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(v[i]) > std::abs(v[big]) + 1e-12) big = i;
  return v[big] < 0 ? acd::Vec3(-v) : v;
}

}  // namespace

Eigen::Matrix3d robotPrincipalAxes(const acd::TriMesh& robot, bool planar) {
  // Exact second moment of each triangle: area / 12 (a a^T + b b^T + c c^T + s s^T), s = a + b + c.
  double area = 0.0;
  acd::Vec3 first = acd::Vec3::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (int f = 0; f < static_cast<int>(robot.faces.size()); ++f) {
    const acd::Vec3& a = robot.vertices[robot.faces[f][0]];
    const acd::Vec3& b = robot.vertices[robot.faces[f][1]];
    const acd::Vec3& c = robot.vertices[robot.faces[f][2]];
    const double A = 0.5 * (b - a).cross(c - a).norm();
    const acd::Vec3 s = a + b + c;
    area += A;
    first += A / 3.0 * s;
    second += A / 12.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  if (area <= 0) return axes;
  const acd::Vec3 mean = first / area;
  Eigen::Matrix3d covariance = second / area - mean * mean.transpose();
  if (planar) {
    // Turning about z only: the long axis is sought in the xy-plane.
    covariance.row(2).setZero(), covariance.col(2).setZero();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  std::array<acd::Vec3, 3> v;
  std::array<double, 3> extent;
  for (int i = 0; i < 3; ++i) {
    v[i] = canonicalSign(eigen.eigenvectors().col(2 - i));  // largest variance first
    const auto [lo, hi] = extentAlong(robot.vertices, Eigen::Matrix3d::Identity(), v[i]);
    extent[i] = hi - lo;
  }
  if (planar) {
    // The z axis is the turning axis; the long axis is the longer of the two horizontal ones.
    std::array<int, 3> order{0, 1, 2};
    int zAxis = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(v[i].z()) > std::abs(v[zAxis].z())) zAxis = i;
    int h0 = zAxis == 0 ? 1 : 0, h1 = 3 - zAxis - h0;
    if (extent[h1] > extent[h0] * (1 + 1e-9)) std::swap(h0, h1);
    order = {h0, h1, zAxis};
    axes.col(0) = acd::Vec3(v[order[0]].x(), v[order[0]].y(), 0).normalized();
    axes.col(2) = acd::Vec3::UnitZ();
    axes.col(1) = axes.col(2).cross(axes.col(0));
    return axes;
  }
  // Longest extent first; equal extents keep the order of the variances.
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int i, int j) { return extent[i] > extent[j] * (1 + 1e-9); });
  axes.col(0) = v[order[0]];
  axes.col(1) = v[order[1]];
  axes.col(2) = axes.col(0).cross(axes.col(1));
  return axes;
}

OpeningAlignment::OpeningAlignment(const Robot& robot, const std::vector<Opening>& openings, bool planar)
    : vertices_(robot.mesh.vertices), planar_(planar), axes_(robotPrincipalAxes(robot.mesh, planar)) {
  for (const Opening& o : openings) frames_.push_back(openingFrame(o));
}

Eigen::Matrix3d OpeningAlignment::alignedRotation(int opening, int longSign, int crossSign) const {
  const OpeningFrame& f = frames_[opening];
  if (planar_) {
    // The long axis along the normal's horizontal part (a horizontal opening, which a planar
    // robot cannot pass anyway: along its long side's).
    acd::Vec3 target(f.normal.x(), f.normal.y(), 0);
    if (target.norm() < 1e-6) target = acd::Vec3(f.longSide.x(), f.longSide.y(), 0);
    target = longSign * target.normalized();
    const double yaw = std::atan2(target.y(), target.x()) - std::atan2(axes_(1, 0), axes_(0, 0));
    return Eigen::AngleAxisd(yaw, acd::Vec3::UnitZ()).toRotationMatrix();
  }
  Eigen::Matrix3d target;
  target.col(0) = longSign * f.normal;
  target.col(1) = crossSign * f.longSide;
  target.col(2) = target.col(0).cross(target.col(1));
  return target * axes_.transpose();  // maps the robot's axes onto the target's columns
}

Pose OpeningAlignment::sample(int opening, ompl::RNG& rng, double tilt, double spread) const {
  const OpeningFrame& f = frames_[opening];
  const int longSign = rng.uniformBool() ? 1 : -1;
  const int crossSign = rng.uniformBool() ? 1 : -1;
  Eigen::Matrix3d R = alignedRotation(opening, longSign, crossSign);
  if (planar_) {
    R = Eigen::AngleAxisd(rng.gaussian(0.0, tilt), acd::Vec3::UnitZ()).toRotationMatrix() * R;
  } else {
    const acd::Vec3 w(rng.gaussian(0.0, tilt), rng.gaussian(0.0, tilt), rng.gaussian(0.0, tilt));
    if (w.norm() > 0) R = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix() * R;
  }
  // Across the opening: the reference point where the robot's extent fits the rectangle.
  auto across = [&](const acd::Vec3& d, double half) {
    const auto [lo, hi] = extentAlong(vertices_, R, d);
    const double from = -half - lo, to = half - hi;  // reference offsets that keep [lo, hi] inside [-half, half]
    return from <= to ? rng.uniformReal(from, to) : 0.5 * (from + to);
  };
  const double u = across(f.longSide, f.halfLong);
  const double v = across(f.shortSide, f.halfShort);
  const auto [lo, hi] = extentAlong(vertices_, R, f.normal);
  const double n = rng.gaussian(0.0, spread) - 0.5 * (lo + hi);
  Pose pose;
  pose.position = f.center + u * f.longSide + v * f.shortSide + n * f.normal;
  pose.orientation = Eigen::Quaterniond(R).normalized();
  return pose;
}

}  // namespace planner
