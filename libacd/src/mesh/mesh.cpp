#include <acd/algo/union_find.hpp>
#include <acd/mesh.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>

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

TriMesh compactFaces(const std::vector<Vec3>& vertices, const std::vector<Face>& faces, std::vector<int>& remap) {
  std::vector<int> used;
  for (const Face& f : faces)
    for (int v : f)
      if (remap[v] < 0) remap[v] = 0, used.push_back(v);
  if (4 * used.size() >= vertices.size()) {  // most vertices used: listed in order without a sort
    used.clear();
    for (int v = 0; v < static_cast<int>(vertices.size()); ++v)
      if (remap[v] == 0) used.push_back(v);
  } else {
    std::sort(used.begin(), used.end());
  }
  TriMesh out;
  out.vertices.reserve(used.size());
  for (int v : used) {
    remap[v] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(vertices[v]);
  }
  out.faces.reserve(faces.size());
  for (const Face& f : faces) out.faces.push_back({remap[f[0]], remap[f[1]], remap[f[2]]});
  for (int v : used) remap[v] = -1;
  return out;
}

TriMesh compact(const TriMesh& mesh) {
  std::vector<int> remap(mesh.vertices.size(), -1);
  return compactFaces(mesh.vertices, mesh.faces, remap);
}

std::vector<TriMesh> splitEdgeConnected(const TriMesh& mesh) {
  const int nf = static_cast<int>(mesh.faces.size());
  const int nv = static_cast<int>(mesh.vertices.size());
  UnionFind sets(nf);
  // The faces at each edge, listed at the edge's lower vertex as (other end, face): faces that
  // share an edge are neighbours in their vertex's sorted list.
  std::vector<int> start(nv + 1, 0);
  for (const Face& f : mesh.faces)
    for (int k = 0; k < 3; ++k) ++start[std::min(f[k], f[(k + 1) % 3]) + 1];
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::pair<int, int>> around(start[nv]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      around[fill[std::min(a, b)]++] = {std::max(a, b), f};
    }
  for (int v = 0; v < nv; ++v) {
    const auto first = around.begin() + start[v], last = around.begin() + start[v + 1];
    std::sort(first, last);
    for (auto it = first; it != last && it + 1 != last; ++it)
      if (it->first == (it + 1)->first) sets.join((it + 1)->second, it->second);
  }
  // Pieces in the order of their first face, faces in input order.
  std::vector<int> pieceOf(nf, -1);
  std::vector<std::vector<Face>> faces;
  for (int f = 0; f < nf; ++f) {
    int& piece = pieceOf[sets.find(f)];
    if (piece < 0) piece = static_cast<int>(faces.size()), faces.emplace_back();
    faces[piece].push_back(mesh.faces[f]);
  }
  std::vector<int> remap(nv, -1);
  std::vector<TriMesh> pieces;
  pieces.reserve(faces.size());
  for (const auto& pieceFaces : faces) pieces.push_back(compactFaces(mesh.vertices, pieceFaces, remap));
  return pieces;
}

SideEdges numberEdges(const std::vector<Face>& faces) {
  SideEdges out;
  const int sides = 3 * static_cast<int>(faces.size());
  out.edgeOfSide.assign(sides, -1);
  int nv = 0;
  for (const Face& f : faces)
    for (int v : f) nv = std::max(nv, v + 1);
  // Sides by their lower vertex, then each vertex's sides by the higher one: edgeKey order.
  std::vector<int> start(nv + 1, 0);
  for (int s = 0; s < sides; ++s) {
    const int a = faces[s / 3][s % 3], b = faces[s / 3][(s % 3 + 1) % 3];
    if (a != b) ++start[std::min(a, b) + 1];
  }
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::pair<int, int>> byLow(start[nv]);  // (higher vertex, side)
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int s = 0; s < sides; ++s) {
    const int a = faces[s / 3][s % 3], b = faces[s / 3][(s % 3 + 1) % 3];
    if (a != b) byLow[fill[std::min(a, b)]++] = {std::max(a, b), s};
  }
  for (int v = 0; v < nv; ++v) {
    std::sort(byLow.begin() + start[v], byLow.begin() + start[v + 1]);
    for (int i = start[v]; i < start[v + 1]; ++i) {
      if (i == start[v] || byLow[i].first != byLow[i - 1].first) ++out.edges;
      out.edgeOfSide[byLow[i].second] = out.edges - 1;
    }
  }
  return out;
}

namespace {

/// Each face's sides by their first vertex: for vertex v, (w, u) for every face (v, w, u) in
/// rotation, w the end of the side leaving v and u the start of the one entering it.
struct SidesByVertex {
  std::vector<int> start;                   // by vertex, into sides
  std::vector<std::pair<int, int>> sides;   // (w, u), sorted by w within each vertex
  bool valid = false;                       // no negative index, no face repeating a vertex

  explicit SidesByVertex(const std::vector<Face>& faces) {
    int nv = 0;
    for (const Face& f : faces)
      for (int k = 0; k < 3; ++k) {
        if (f[k] < 0 || f[k] == f[(k + 1) % 3]) return;
        nv = std::max(nv, f[k] + 1);
      }
    start.assign(nv + 1, 0);
    for (const Face& f : faces)
      for (int v : f) ++start[v + 1];
    for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
    sides.resize(start[nv]);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const Face& f : faces)
      for (int k = 0; k < 3; ++k) sides[fill[f[k]]++] = {f[(k + 1) % 3], f[(k + 2) % 3]};
    for (int v = 0; v < nv; ++v) std::sort(sides.begin() + start[v], sides.begin() + start[v + 1]);
    valid = true;
  }
  int vertices() const { return static_cast<int>(start.size()) - 1; }
  /// Each directed edge at most once.
  bool directedOnce() const {
    for (int v = 0; v < vertices(); ++v)
      for (int i = start[v] + 1; i < start[v + 1]; ++i)
        if (sides[i].first == sides[i - 1].first) return false;
    return true;
  }
  /// The side leaving v toward w, or -1.
  int leaving(int v, int w) const {
    const auto first = sides.begin() + start[v], last = sides.begin() + start[v + 1];
    const auto it = std::lower_bound(first, last, std::pair<int, int>(w, std::numeric_limits<int>::min()));
    return it != last && it->first == w ? static_cast<int>(it - sides.begin()) : -1;
  }
};

/// Each directed edge at most once, no face repeating a vertex, and (when `closed`) every edge's
/// reverse there too.
bool directedEdgesOnce(const std::vector<Face>& faces, bool closed) {
  if (faces.empty()) return !closed;
  const SidesByVertex by(faces);
  if (!by.valid || !by.directedOnce()) return false;
  if (!closed) return true;
  for (int a = 0; a < by.vertices(); ++a)
    for (int i = by.start[a]; i < by.start[a + 1]; ++i)
      if (by.leaving(by.sides[i].first, a) < 0) return false;
  return true;
}

}  // namespace

int pinchedVertices(const std::vector<Face>& faces) {
  const SidesByVertex by(faces);
  if (!by.valid || !by.directedOnce()) return -1;
  // Around v, face (v, w, u) and the face leaving v toward u share the edge vu: one fan goes on
  // from the first to the second. Each side leaves v once and enters it at most once, so the
  // faces around v form chains and cycles, one per fan; a vertex with more than one pinches.
  int pinched = 0;
  std::vector<char> seen;
  for (int v = 0; v < by.vertices(); ++v) {
    const int s0 = by.start[v], degree = by.start[v + 1] - s0;
    if (degree == 0) continue;
    seen.assign(degree, 0);
    auto walk = [&](int i) {  // marks the fan from face i on around v
      for (int j = s0 + i; j >= 0 && !seen[j - s0]; j = by.leaving(v, by.sides[j].second)) seen[j - s0] = 1;
    };
    int fans = 0;
    // The open fans first, from their first face (no face enters v along its side vw), then
    // the closed ones, from any face not yet seen.
    for (int i = 0; i < degree; ++i)
      if (by.leaving(by.sides[s0 + i].first, v) < 0) ++fans, walk(i);
    for (int i = 0; i < degree; ++i)
      if (!seen[i]) ++fans, walk(i);
    pinched += fans > 1 ? 1 : 0;
  }
  return pinched;
}

bool isClosedOriented(const TriMesh& mesh) { return directedEdgesOnce(mesh.faces, true); }

bool isOrientedEdgeManifold(const std::vector<Face>& faces) { return directedEdgesOnce(faces, false); }

/// For each vertex, the first vertex with exactly the same position, or itself (+0 and -0 are equal).
/// Sorting instead of hashing: no allocation per vertex, and meshes have millions of them.
std::vector<int> firstAtSamePosition(const std::vector<Vec3>& vertices) {
  auto bits = [](double x) {
    x += 0.0;  // turns -0 into +0
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  };
  struct Keyed {
    std::array<std::uint64_t, 3> key;
    int vertex;
    bool operator<(const Keyed& o) const { return key != o.key ? key < o.key : vertex < o.vertex; }
  };
  std::vector<Keyed> keyed;
  keyed.reserve(vertices.size());
  std::vector<int> first(vertices.size());
  for (int v = 0; v < static_cast<int>(vertices.size()); ++v) {
    first[v] = v;
    const Vec3& p = vertices[v];
    if (p.allFinite()) keyed.push_back({{bits(p.x()), bits(p.y()), bits(p.z())}, v});  // NaN equals nothing
  }
  std::sort(keyed.begin(), keyed.end());
  for (size_t i = 1; i < keyed.size(); ++i)
    if (keyed[i].key == keyed[i - 1].key) first[keyed[i].vertex] = first[keyed[i - 1].vertex];
  return first;
}

}  // namespace acd
