#include <acd/mesh.hpp>

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace acd {

Box3 boundingBox(const TriMesh& mesh) {
  Box3 box;
  if (mesh.vertices.empty()) return box;
  box.lo = box.hi = mesh.vertices.front();
  for (const Vec3& p : mesh.vertices) {
    box.lo = box.lo.cwiseMin(p);
    box.hi = box.hi.cwiseMax(p);
  }
  return box;
}

double signedVolume(const TriMesh& mesh) {
  // Tetrahedra against the bounding-box centre keep the rounding error small far from the origin.
  const Vec3 o = boundingBox(mesh).center();
  double six = 0.0;
  for (const Face& f : mesh.faces) {
    const Vec3 a = mesh.vertices[f[0]] - o, b = mesh.vertices[f[1]] - o, c = mesh.vertices[f[2]] - o;
    six += a.dot(b.cross(c));
  }
  return six / 6.0;
}

double surfaceArea(const TriMesh& mesh) {
  double twice = 0.0;
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f) twice += faceNormal(mesh, f).norm();
  return 0.5 * twice;
}

Vec3 faceNormal(const TriMesh& mesh, int face) {
  const Face& f = mesh.faces[face];
  const Vec3& a = mesh.vertices[f[0]];
  return (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a);
}

TriMesh concatenate(const std::vector<TriMesh>& meshes) {
  TriMesh all;
  for (const TriMesh& m : meshes) {
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), m.vertices.begin(), m.vertices.end());
    for (const Face& f : m.faces) all.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  return all;
}

TriMesh compact(const TriMesh& mesh) {
  std::vector<int> remap(mesh.vertices.size(), -1);
  TriMesh out;
  out.faces.reserve(mesh.faces.size());
  for (const Face& f : mesh.faces) {
    Face g;
    for (int k = 0; k < 3; ++k) {
      int& r = remap[f[k]];
      if (r < 0) {
        r = static_cast<int>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[f[k]]);
      }
      g[k] = r;
    }
    out.faces.push_back(g);
  }
  // Keep the original vertex order so that output is stable: renumber by first original index.
  std::vector<int> order(out.vertices.size());
  std::vector<int> original(out.vertices.size());
  for (int v = 0; v < static_cast<int>(remap.size()); ++v)
    if (remap[v] >= 0) original[remap[v]] = v;
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return original[a] < original[b]; });
  std::vector<int> rank(order.size());
  TriMesh sorted;
  sorted.vertices.resize(order.size());
  for (int i = 0; i < static_cast<int>(order.size()); ++i) {
    rank[order[i]] = i;
    sorted.vertices[i] = out.vertices[order[i]];
  }
  sorted.faces = std::move(out.faces);
  for (Face& f : sorted.faces)
    for (int& v : f) v = rank[v];
  return sorted;
}

namespace {
int findRoot(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}
}  // namespace

std::vector<TriMesh> splitEdgeConnected(const TriMesh& mesh) {
  const int nf = static_cast<int>(mesh.faces.size());
  std::vector<int> parent(nf);
  std::iota(parent.begin(), parent.end(), 0);
  std::unordered_map<std::uint64_t, int> firstFace;
  firstFace.reserve(mesh.faces.size() * 2);
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      auto [it, inserted] = firstFace.emplace(edgeKey(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]), f);
      if (!inserted) parent[findRoot(parent, f)] = findRoot(parent, it->second);
    }
  }
  std::unordered_map<int, int> pieceOf;
  std::vector<TriMesh> pieces;
  for (int f = 0; f < nf; ++f) {
    const int r = findRoot(parent, f);
    auto [it, inserted] = pieceOf.emplace(r, static_cast<int>(pieces.size()));
    if (inserted) pieces.push_back(TriMesh{mesh.vertices, {}});
    pieces[it->second].faces.push_back(mesh.faces[f]);
  }
  for (TriMesh& p : pieces) p = compact(p);
  return pieces;
}

bool isClosedOriented(const TriMesh& mesh) {
  // Each directed edge once, and its reverse once.
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(mesh.faces.size() * 3);
  for (const Face& f : mesh.faces)
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::uint64_t>(f[k]), b = static_cast<std::uint64_t>(f[(k + 1) % 3]);
      if (a == b) return false;
      if (++directed[(a << 32) | b] > 1) return false;
    }
  for (const auto& [key, count] : directed) {
    const std::uint64_t reverse = (key << 32) | (key >> 32);
    if (directed.find(reverse) == directed.end()) return false;
  }
  return !mesh.faces.empty();
}

}  // namespace acd
