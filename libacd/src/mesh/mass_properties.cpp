// Mass properties by signed tetrahedra; see mass_properties.hpp.
//
// Each triangle (a, b, c) and a reference point r span a tetrahedron of signed volume
// v = a'.(b' x c') / 6 (primes: relative to r). Its second moment about r is
// v / 20 (a'a'^T + b'b'^T + c'c'^T + s s^T), s = a' + b' + c' (the covariance of a
// tetrahedron with one corner at the origin). Summed over a closed surface the tetrahedra
// outside cancel, leaving the solid's volume, first and second moments. The reference is the
// bounding-box centre, which keeps the sums free of cancellation for meshes far from the origin.
#include <acd/algo/mass_properties.hpp>

#include <Eigen/Eigenvalues>

namespace acd {

MassProperties massProperties(const std::vector<TriMesh>& solids, double density) {
  MassProperties mp;
  bool any = false;
  Box3 all;
  for (const TriMesh& m : solids) {
    if (m.vertices.empty()) continue;
    const Box3 b = boundingBox(m);
    all.lo = any ? all.lo.cwiseMin(b.lo) : b.lo;
    all.hi = any ? all.hi.cwiseMax(b.hi) : b.hi;
    any = true;
  }
  if (!any) return mp;
  const Vec3 r = all.center();
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // integral of x x^T about r
  for (const TriMesh& m : solids)
    for (const Face& f : m.faces) {
      const Vec3 a = m.vertices[f[0]] - r, b = m.vertices[f[1]] - r, c = m.vertices[f[2]] - r;
      const double v = a.dot(b.cross(c)) / 6.0;
      const Vec3 s = a + b + c;
      volume += v;
      first += v * s / 4.0;
      second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
  mp.volume = volume;
  mp.mass = density * volume;
  if (volume == 0.0) return mp;
  const Vec3 com = first / volume;  // relative to r
  mp.centerOfMass = r + com;
  const Eigen::Matrix3d central = second - volume * com * com.transpose();
  mp.inertia = density * (central.trace() * Eigen::Matrix3d::Identity() - central);
  mp.inertia = 0.5 * (mp.inertia + mp.inertia.transpose()).eval();
  mp.principalMoments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(mp.inertia, Eigen::EigenvaluesOnly).eigenvalues();
  return mp;
}

}  // namespace acd
