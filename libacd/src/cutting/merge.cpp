#include <acd/algo/merge.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <tuple>
#include <unordered_map>

namespace acd {

namespace {

using Corner = std::array<double, 3>;
using TriangleKey = std::array<Corner, 3>;  // corners sorted: the same for both orientations

Corner cornerOf(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

TriangleKey keyOf(const TriMesh& m, const Face& f) {
  TriangleKey k{cornerOf(m.vertices[f[0]]), cornerOf(m.vertices[f[1]]), cornerOf(m.vertices[f[2]])};
  std::sort(k.begin(), k.end());
  return k;
}

}  // namespace

bool glueAlongSharedFaces(const TriMesh& a, const TriMesh& b, TriMesh& out) {
  out = TriMesh{};
  std::map<Corner, int> index;
  auto vertex = [&](const Vec3& p) {
    auto [it, inserted] = index.emplace(cornerOf(p), static_cast<int>(out.vertices.size()));
    if (inserted) out.vertices.push_back(p);
    return it->second;
  };
  std::map<TriangleKey, int> fromA;  // shared candidates: key -> face of a
  for (int f = 0; f < static_cast<int>(a.faces.size()); ++f) fromA.emplace(keyOf(a, a.faces[f]), f);
  std::vector<char> dropA(a.faces.size(), 0), dropB(b.faces.size(), 0);
  int shared = 0;
  for (int f = 0; f < static_cast<int>(b.faces.size()); ++f) {
    auto it = fromA.find(keyOf(b, b.faces[f]));
    if (it == fromA.end() || dropA[it->second]) continue;
    dropA[it->second] = dropB[f] = 1;
    ++shared;
  }
  if (shared == 0) return false;
  for (int pass = 0; pass < 2; ++pass) {
    const TriMesh& m = pass == 0 ? a : b;
    const std::vector<char>& drop = pass == 0 ? dropA : dropB;
    for (int f = 0; f < static_cast<int>(m.faces.size()); ++f)
      if (!drop[f])
        out.faces.push_back({vertex(m.vertices[m.faces[f][0]]), vertex(m.vertices[m.faces[f][1]]),
                             vertex(m.vertices[m.faces[f][2]])});
  }
  // Only a shared region that is the whole contact makes a valid solid; anything else (a cap
  // later split on one side only) leaves open or doubled edges and is refused. Gluing must join
  // at least two shells into one (a piece joined apart by the merge pass has several).
  if (!isClosedOriented(out)) return false;
  const std::size_t shells = splitEdgeConnected(out).size();
  if (shells != 1 && shells + 1 > splitEdgeConnected(a).size() + splitEdgeConnected(b).size()) return false;
  out = compact(out);
  return true;
}

std::vector<SharedFaces> nearbyPairs(const std::vector<TriMesh>& meshes, double reach) {
  std::vector<Box3> boxes;
  for (const TriMesh& m : meshes) boxes.push_back(boundingBox(m));
  std::vector<int> byLow(meshes.size());
  for (int i = 0; i < static_cast<int>(meshes.size()); ++i) byLow[i] = i;
  std::stable_sort(byLow.begin(), byLow.end(), [&](int a, int b) { return boxes[a].lo.x() < boxes[b].lo.x(); });
  std::vector<SharedFaces> pairs;
  for (std::size_t s = 0; s < byLow.size(); ++s)
    for (std::size_t t = s + 1; t < byLow.size() && boxes[byLow[t]].lo.x() <= boxes[byLow[s]].hi.x() + reach; ++t) {
      const Box3 &p = boxes[byLow[s]], &q = boxes[byLow[t]];
      const Vec3 gap = (p.lo - q.hi).cwiseMax(q.lo - p.hi).cwiseMax(0.0);
      if (gap.norm() <= reach) pairs.push_back({std::min(byLow[s], byLow[t]), std::max(byLow[s], byLow[t]), 0.0});
    }
  std::sort(pairs.begin(), pairs.end(), [](const SharedFaces& x, const SharedFaces& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  return pairs;
}

std::vector<SharedFaces> sharedFacePairs(const std::vector<TriMesh>& meshes) {
  std::map<TriangleKey, std::vector<int>> owners;
  for (int i = 0; i < static_cast<int>(meshes.size()); ++i)
    for (const Face& f : meshes[i].faces) owners[keyOf(meshes[i], f)].push_back(i);
  std::map<std::pair<int, int>, double> area;
  for (const auto& [key, list] : owners) {
    if (list.size() != 2 || list[0] == list[1]) continue;
    const Vec3 p(key[0][0], key[0][1], key[0][2]), q(key[1][0], key[1][1], key[1][2]), r(key[2][0], key[2][1], key[2][2]);
    area[std::minmax(list[0], list[1])] += 0.5 * (q - p).cross(r - p).norm();
  }
  std::vector<SharedFaces> pairs;
  for (const auto& [ij, a] : area) pairs.push_back({ij.first, ij.second, a});
  std::stable_sort(pairs.begin(), pairs.end(), [](const SharedFaces& x, const SharedFaces& y) { return x.area > y.area; });
  return pairs;
}

}  // namespace acd
