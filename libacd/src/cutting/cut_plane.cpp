#include <acd/algo/cut_plane.hpp>

#include <Eigen/Eigenvalues>

#include <cmath>

namespace acd {

namespace {
/// Signed dihedral turn across edge a->b: > 0 convex, < 0 concave, in radians.
double signedDihedral(const TriMesh& mesh, const SurfaceGraph& graph, int a, int b, Vec3* left, Vec3* right) {
  const int fl = graph.faceLeftOf(a, b), fr = graph.faceLeftOf(b, a);
  if (fl < 0 || fr < 0) return 0.0;
  const Vec3 nl = faceNormal(mesh, fl).normalized(), nr = faceNormal(mesh, fr).normalized();
  if (left) *left = nl;
  if (right) *right = nr;
  const Vec3 c = nl.cross(nr);
  const double angle = std::atan2(c.norm(), nl.dot(nr));
  return c.dot(mesh.vertices[b] - mesh.vertices[a]) >= 0 ? angle : -angle;
}
}  // namespace

Plane fitCutPlane(const TriMesh& mesh, const GlobalCut& cut, const Vec3& bridgeNormal, double tolerance) {
  const int n = static_cast<int>(cut.vertices.size());
  std::vector<double> w(n);
  double peak = 0.0;
  for (double c : cut.weight) peak = std::max(peak, c);
  // Eq. 5 weighs by concavity: parts of the cut with none carry no weight (all equal if the cut has none).
  for (int i = 0; i < n; ++i) w[i] = peak > 0 ? cut.weight[i] : 1.0;
  Plane plane;
  for (int round = 0; round < 5; ++round) {
    double total = 0.0;
    Vec3 centroid = Vec3::Zero();
    for (int i = 0; i < n; ++i) total += w[i], centroid += w[i] * mesh.vertices[cut.vertices[i]];
    centroid /= total;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int i = 0; i < n; ++i) {
      const Vec3 d = mesh.vertices[cut.vertices[i]] - centroid;
      cov += w[i] * d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
    Vec3 normal = eig.eigenvectors().col(0);
    if (lambda(1) <= 1e-6 * std::max(lambda(2), 1e-300)) {
      // The cut is (nearly) a straight line: cut down into the solid, containing the line and the bridge normal.
      const Vec3 line = eig.eigenvectors().col(2);
      normal = line.cross(bridgeNormal);
      if (normal.norm() < 1e-9) normal = line.unitOrthogonal();
      normal.normalize();
    }
    plane = Plane::through(centroid, normal);
    // Figure 15: push the plane toward the cut vertices it misses.
    // Only vertices with real concavity count as misrepresented; the rest of the cut carries no weight in Eq. 5.
    bool misses = false;
    for (int i = 0; i < n; ++i)
      if (cut.weight[i] > 0.1 * peak && std::abs(plane.signedDistance(mesh.vertices[cut.vertices[i]])) > tolerance) {
        w[i] *= 4.0;
        misses = true;
      }
    if (!misses) break;
  }
  return plane;
}

Plane bisectorPlane(const TriMesh& mesh, const SurfaceGraph& graph, int notch, const Vec3& bridgeNormal) {
  int bestOther = -1;
  double best = 0.0;
  Vec3 nl = Vec3::Zero(), nr = Vec3::Zero(), bestL = Vec3::Zero(), bestR = Vec3::Zero();  // unset on a boundary edge
  for (int slot = graph.begin(notch); slot < graph.end(notch); ++slot) {
    const int other = graph.neighbour(slot);
    const double turn = signedDihedral(mesh, graph, notch, other, &nl, &nr);
    if (bestOther < 0 || turn < best) best = turn, bestOther = other, bestL = nl, bestR = nr;
  }
  const Vec3& x = mesh.vertices[notch];
  if (bestOther < 0 || best >= 0.0) {
    // No concave edge at the notch (a saddle or flat vertex): cut across the pocket through it.
    Vec3 normal = bridgeNormal.unitOrthogonal();
    return Plane::through(x, normal);
  }
  // The plane through the edge with normal nl - nr bisects the reflex angle into the solid.
  Vec3 normal = bestL - bestR;
  if (normal.norm() < 1e-12) normal = (mesh.vertices[bestOther] - x).cross(bridgeNormal);
  return Plane::through(x, normal.normalized());
}

}  // namespace acd
