#include "acd_skeleton.hpp"

#include <acd/algo/union_find.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace skeleton {

namespace {

using Corner = std::array<double, 3>;
using TriangleKey = std::array<Corner, 3>;  // sorted corners: equal for both orientations

Corner cornerOf(const Vec3& p) { return {p.x(), p.y(), p.z()}; }
Vec3 pointOf(const Corner& c) { return {c[0], c[1], c[2]}; }

}  // namespace

std::vector<Cut> findCuts(const std::vector<acd::TriMesh>& components) {
  // Per triangle (corners sorted) its owners, each with its normal as that owner sees it.
  std::map<TriangleKey, std::vector<std::pair<int, Vec3>>> owners;
  for (int i = 0; i < static_cast<int>(components.size()); ++i) {
    const acd::TriMesh& m = components[i];
    for (const acd::Face& f : m.faces) {
      const Vec3 &p = m.vertices[f[0]], &q = m.vertices[f[1]], &r = m.vertices[f[2]];
      TriangleKey k{cornerOf(p), cornerOf(q), cornerOf(r)};
      std::sort(k.begin(), k.end());
      owners[k].push_back({i, (q - p).cross(r - p)});
    }
  }
  // Shared triangles per pair of components, with their normals out of the first of the pair.
  std::map<std::pair<int, int>, std::vector<std::pair<TriangleKey, Vec3>>> shared;
  for (const auto& [key, list] : owners) {
    if (list.size() != 2 || list[0].first == list[1].first) continue;
    const bool firstIsLow = list[0].first < list[1].first;
    shared[std::minmax(list[0].first, list[1].first)].push_back({key, list[firstIsLow ? 0 : 1].second});
  }

  std::vector<Cut> cuts;
  for (const auto& [pair, oriented] : shared) {
    std::vector<TriangleKey> triangles;
    for (const auto& [key, normal] : oriented) triangles.push_back(key);
    // Patches: triangles joined through common corners (union-find over triangles).
    const int n = static_cast<int>(triangles.size());
    acd::UnionFind sets(n);
    std::map<Corner, int> firstUser;
    for (int t = 0; t < n; ++t)
      for (const Corner& c : triangles[t]) {
        auto [it, inserted] = firstUser.emplace(c, t);
        if (!inserted) sets.join(t, it->second);
      }
    std::map<int, Cut> patches;
    for (int t = 0; t < n; ++t) {
      const Vec3 p = pointOf(triangles[t][0]), q = pointOf(triangles[t][1]), r = pointOf(triangles[t][2]);
      const double area = 0.5 * (q - p).cross(r - p).norm();
      Cut& cut = patches[sets.find(t)];
      cut.a = pair.first;
      cut.b = pair.second;
      cut.centre += area * (p + q + r) / 3.0;
      cut.area += area;
      cut.normal += oriented[t].second;  // twice the area along the normal
      ++cut.triangles;
    }
    std::vector<Cut> local;
    for (auto& [root, cut] : patches) {
      cut.centre /= cut.area > 0 ? cut.area : 1.0;
      if (cut.normal.norm() > 0) cut.normal.normalize();
      local.push_back(cut);
    }
    std::stable_sort(local.begin(), local.end(), [](const Cut& x, const Cut& y) { return x.area > y.area; });
    cuts.insert(cuts.end(), local.begin(), local.end());
  }
  return cuts;
}

Vec3 solidCentroid(const acd::TriMesh& mesh) {
  // Signed tetrahedra against a point near the mesh (its vertex mean) keep rounding small.
  Vec3 mean = Vec3::Zero();
  for (const Vec3& v : mesh.vertices) mean += v;
  if (!mesh.vertices.empty()) mean /= static_cast<double>(mesh.vertices.size());
  double volume = 0.0;
  Vec3 moment = Vec3::Zero();
  for (const acd::Face& f : mesh.faces) {
    const Vec3 a = mesh.vertices[f[0]] - mean, b = mesh.vertices[f[1]] - mean, c = mesh.vertices[f[2]] - mean;
    const double v = a.dot(b.cross(c)) / 6.0;
    volume += v;
    moment += v * (a + b + c) / 4.0;
  }
  if (!(std::abs(volume) > 0.0)) return mean;
  return mean + moment / volume;
}

Graph skeletonFromComponents(const std::vector<acd::TriMesh>& components) {
  Graph g;
  for (int i = 0; i < static_cast<int>(components.size()); ++i)
    g.addNode(solidCentroid(components[i]), NodeKind::Component, i);
  for (const Cut& cut : findCuts(components)) {
    const int node = g.addNode(cut.centre, NodeKind::Cut);
    g.addEdge(cut.a, node);
    g.addEdge(cut.b, node);
  }
  return g;
}

}  // namespace skeleton
