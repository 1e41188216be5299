#include <acd/algo/merge.hpp>

#include <acd/algo/random.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <tuple>
#include <unordered_map>

namespace acd {

namespace {

using Corner = std::array<double, 3>;
using TriangleKey = std::array<Corner, 3>;  // corners sorted: the same for both orientations

Corner cornerOf(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

std::vector<const TriMesh*> pointersTo(const std::vector<TriMesh>& meshes) {
  std::vector<const TriMesh*> pointers;
  for (const TriMesh& m : meshes) pointers.push_back(&m);
  return pointers;
}

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

std::vector<SharedFaces> touchingPairs(const std::vector<const TriMesh*>& meshes) {
  std::vector<std::pair<Corner, int>> corners;  // every corner of every mesh, with its mesh
  for (int i = 0; i < static_cast<int>(meshes.size()); ++i)
    for (const Vec3& v : meshes[i]->vertices) corners.emplace_back(cornerOf(v), i);
  std::sort(corners.begin(), corners.end());
  std::vector<std::pair<int, int>> touching;
  for (std::size_t s = 0, t = 0; s < corners.size(); s = t) {
    for (t = s; t < corners.size() && corners[t].first == corners[s].first; ++t) {}
    for (std::size_t x = s; x < t; ++x)
      for (std::size_t y = x + 1; y < t; ++y)
        if (corners[x].second != corners[y].second) touching.emplace_back(corners[x].second, corners[y].second);
  }
  std::sort(touching.begin(), touching.end());
  touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
  std::vector<SharedFaces> pairs;
  for (const auto& [i, j] : touching) pairs.push_back({i, j, 0.0});
  return pairs;
}

std::vector<SharedFaces> touchingPairs(const std::vector<TriMesh>& meshes) { return touchingPairs(pointersTo(meshes)); }

TriMesh joinPieces(const TriMesh& a, const TriMesh& b) {
  TriMesh out;
  if (!glueAlongSharedFaces(a, b, out)) out = concatenate({a, b});
  return out;
}

std::vector<SharedFaces> sharedFacePairs(const std::vector<const TriMesh*>& meshes) {
  // Every triangle as (hash of its key, mesh, face), sorted: equal keys come together (16 bytes a
  // triangle, where a map from keys took ten times as much on a million faces).
  struct Entry {
    std::uint64_t hash;
    int mesh, face;
  };
  auto hashOf = [](const TriangleKey& k) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const Corner& c : k)
      for (double x : c) {
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        h = mix64(h ^ bits);
      }
    return h;
  };
  std::vector<Entry> entries;
  for (int i = 0; i < static_cast<int>(meshes.size()); ++i)
    for (int f = 0; f < static_cast<int>(meshes[i]->faces.size()); ++f)
      entries.push_back({hashOf(keyOf(*meshes[i], meshes[i]->faces[f])), i, f});
  std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
    return std::tie(x.hash, x.mesh, x.face) < std::tie(y.hash, y.mesh, y.face);
  });
  std::vector<std::pair<TriangleKey, std::pair<int, int>>> shared;
  for (std::size_t s = 0, t = 0; s < entries.size(); s = t) {
    for (t = s; t < entries.size() && entries[t].hash == entries[s].hash; ++t) {}
    if (t - s < 2) continue;  // a triangle no other holds (most of them)
    // Within one hash, group by the key itself; a key held by exactly two meshes is shared.
    std::vector<std::pair<TriangleKey, int>> keys;
    for (std::size_t x = s; x < t; ++x)
      keys.emplace_back(keyOf(*meshes[entries[x].mesh], meshes[entries[x].mesh]->faces[entries[x].face]),
                        entries[x].mesh);
    std::sort(keys.begin(), keys.end());
    for (std::size_t u = 0, v = 0; u < keys.size(); u = v) {
      for (v = u; v < keys.size() && keys[v].first == keys[u].first; ++v) {}
      if (v - u == 2 && keys[u].second != keys[u + 1].second)
        shared.emplace_back(keys[u].first, std::minmax(keys[u].second, keys[u + 1].second));
    }
  }
  // Areas summed in key order, whatever order the hashes gave.
  std::sort(shared.begin(), shared.end());
  std::map<std::pair<int, int>, double> area;
  for (const auto& [key, pair] : shared) {
    const Vec3 p(key[0][0], key[0][1], key[0][2]), q(key[1][0], key[1][1], key[1][2]), r(key[2][0], key[2][1], key[2][2]);
    area[pair] += 0.5 * (q - p).cross(r - p).norm();
  }
  std::vector<SharedFaces> pairs;
  for (const auto& [ij, a] : area) pairs.push_back({ij.first, ij.second, a});
  std::stable_sort(pairs.begin(), pairs.end(), [](const SharedFaces& x, const SharedFaces& y) { return x.area > y.area; });
  return pairs;
}

std::vector<SharedFaces> sharedFacePairs(const std::vector<TriMesh>& meshes) {
  return sharedFacePairs(pointersTo(meshes));
}

}  // namespace acd
