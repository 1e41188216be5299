// See separation.hpp.
#include "separation.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace tetmesh {

/// Least-squares plane through points; normal oriented like `hint`.
bool fitPlane(const std::vector<Vec3>& pts, const Vec3& hint, Vec3& normal) {
  if (pts.size() < 3) return false;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : pts) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  if (es.info() != Eigen::Success) return false;
  // A plane needs two clear directions of spread.
  if (!(es.eigenvalues()(1) > 1e-12 * es.eigenvalues()(2))) return false;
  normal = es.eigenvectors().col(0).normalized();
  if (normal.dot(hint) < 0) normal = -normal;
  return true;
}


Contact findContact(const std::vector<Vec3>& vi, const std::vector<Vec3>& vj, const std::vector<Vec3>& ni,
                    const std::vector<Vec3>& nj, double tol) {
  Contact ct;
  ct.gap = -std::numeric_limits<double>::infinity();
  auto consider = [&](const Vec3& nrm) {
    const double gap = minAlong(vj, nrm) - maxAlong(vi, nrm);
    if (gap > ct.gap) ct.gap = gap, ct.normal = nrm;
  };
  for (const Vec3& nrm : ni) consider(nrm);
  for (const Vec3& nrm : nj) consider(-nrm);
  if (ct.gap >= -tol && ct.gap <= tol) {
    const double hi = maxAlong(vi, ct.normal), lo = minAlong(vj, ct.normal);
    const double band = 1e3 * tol;
    std::vector<Vec3> near;
    for (const Vec3& p : vi)
      if (std::abs(ct.normal.dot(p) - hi) <= band) near.push_back(p);
    for (const Vec3& p : vj)
      if (std::abs(ct.normal.dot(p) - lo) <= band) near.push_back(p);
    Vec3 fitted = ct.normal;
    if (fitPlane(near, ct.normal, fitted)) {
      const double gap = minAlong(vj, fitted) - maxAlong(vi, fitted);
      if (gap >= ct.gap) ct.gap = gap, ct.normal = fitted;
    }
  }
  ct.offset = 0.5 * (maxAlong(vi, ct.normal) + minAlong(vj, ct.normal));
  return ct;
}

}  // namespace tetmesh
