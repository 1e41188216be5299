// Tet quality measures; see mesh_quality.hpp.
#include "mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace tetmesh {

std::array<double, 6> dihedralAngles(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const std::array<Vec3, 4> p{a, b, c, d};
  // Outward normal of the face opposite each vertex.
  std::array<Vec3, 4> n;
  for (int k = 0; k < 4; ++k) {
    const Vec3& q0 = p[(k + 1) % 4];
    const Vec3& q1 = p[(k + 2) % 4];
    const Vec3& q2 = p[(k + 3) % 4];
    Vec3 m = (q1 - q0).cross(q2 - q0);
    if (m.dot(p[k] - q0) > 0) m = -m;
    const double len = m.norm();
    n[k] = len > 0 ? Vec3(m / len) : Vec3::Zero();
  }
  std::array<double, 6> out{};
  int i = 0;
  for (int k = 0; k < 4; ++k)
    for (int l = k + 1; l < 4; ++l) {
      const double cosine = std::clamp(-n[k].dot(n[l]), -1.0, 1.0);
      out[i++] = std::acos(cosine) * 180.0 / M_PI;
    }
  return out;
}

double radiusEdgeRatio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double det = 2.0 * u.dot(v.cross(w));
  const double shortest = std::min({u.norm(), v.norm(), w.norm(), (c - b).norm(), (d - b).norm(), (d - c).norm()});
  if (det == 0.0 || shortest == 0.0) return std::numeric_limits<double>::infinity();
  const Vec3 center = (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u) + w.squaredNorm() * u.cross(v)) / det;
  return center.norm() / shortest;
}

MeshQuality measureQuality(const TetMesh& mesh) {
  MeshQuality q;
  q.tets = static_cast<int>(mesh.tets.size());
  if (q.tets == 0) return q;
  std::vector<char> used(mesh.points.size(), 0);
  std::vector<double> ratios;
  ratios.reserve(mesh.tets.size());
  q.minDihedral = 180.0;
  q.maxDihedral = 0.0;
  q.minTetVolume = std::numeric_limits<double>::infinity();
  for (int t = 0; t < q.tets; ++t) {
    const auto& v = mesh.tets[t];
    for (int k : v) used[k] = 1;
    const double vol = tetVolume(mesh, t);
    q.volume += vol;
    q.minTetVolume = std::min(q.minTetVolume, vol);
    if (!(vol > 0)) ++q.nonPositiveTets;
    const Vec3 &a = mesh.points[v[0]], &b = mesh.points[v[1]], &c = mesh.points[v[2]], &d = mesh.points[v[3]];
    double smallest = 180.0;
    for (double angle : dihedralAngles(a, b, c, d)) {
      smallest = std::min(smallest, angle);
      q.maxDihedral = std::max(q.maxDihedral, angle);
    }
    q.minDihedral = std::min(q.minDihedral, smallest);
    if (smallest < kSliverDegrees) ++q.slivers;
    const double r = radiusEdgeRatio(a, b, c, d);
    ratios.push_back(r);
    std::size_t bin = 0;
    while (bin < kRadiusEdgeBins.size() && r > kRadiusEdgeBins[bin]) ++bin;
    ++q.radiusEdgeHistogram[bin];
  }
  q.points = static_cast<int>(std::count(used.begin(), used.end(), 1));
  std::sort(ratios.begin(), ratios.end());
  q.minRadiusEdge = ratios.front();
  q.maxRadiusEdge = ratios.back();
  q.medianRadiusEdge = ratios[ratios.size() / 2];
  return q;
}

}  // namespace tetmesh
