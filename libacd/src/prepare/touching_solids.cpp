// Faces around a non-manifold edge sorted by angle, paired by the side their material is on.
#include <acd/algo/touching_solids.hpp>
#include <acd/algo/union_find.hpp>
#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace acd {

namespace {

struct Incidence {
  int face;
  bool forward;  // the face runs lo -> hi along the edge
  double angle;  // of its third vertex about the edge
};

int thirdVertex(const Face& f, int a, int b) {
  for (int v : f)
    if (v != a && v != b) return v;
  return f[0];
}

/// Pairs of faces around one edge lo -> hi, each face with the neighbour that closes its material
/// wedge; empty when the faces do not alternate that way.
std::vector<std::pair<int, int>> pairByMaterial(const TriMesh& m, int lo, int hi, std::vector<Incidence> around) {
  const Vec3 e = (m.vertices[hi] - m.vertices[lo]).normalized();
  Vec3 u = e.unitOrthogonal();
  const Vec3 v = e.cross(u);
  for (Incidence& in : around) {
    const Vec3 d = m.vertices[thirdVertex(m.faces[in.face], lo, hi)] - m.vertices[lo];
    in.angle = std::atan2(d.dot(v), d.dot(u));
  }
  // Faces that lie on each other (a lid on its box) meet at an angle that rounding in the pose
  // makes a hair positive or negative: angles this close are one, so that the rule below and not
  // the pose decides. (Directions a hair below pi are those a hair above -pi.)
  constexpr double kSameAngle = 1e-9;
  const double pi = std::acos(-1.0);
  for (Incidence& in : around)
    if (in.angle > pi - kSameAngle) in.angle -= 2 * pi;
  std::sort(around.begin(), around.end(), [](const Incidence& a, const Incidence& b) { return a.angle < b.angle; });
  for (std::size_t i = 1, start = 0; i < around.size(); ++i) {
    if (around[i].angle - around[start].angle > kSameAngle) start = i;
    around[i].angle = around[start].angle;
  }
  // A face running lo -> hi has its normal towards increasing angle (e x d), so its material lies
  // at decreasing angle; a face running hi -> lo the other way. At equal angles (faces that lie on
  // each other) the one closing a wedge comes before the one opening the next.
  std::sort(around.begin(), around.end(), [](const Incidence& a, const Incidence& b) {
    if (a.angle != b.angle) return a.angle < b.angle;
    if (a.forward != b.forward) return a.forward;
    return a.face < b.face;
  });
  const int n = static_cast<int>(around.size());
  // Rotate so that the sequence starts with a face that opens a wedge (runs hi -> lo).
  const auto first = std::find_if(around.begin(), around.end(), [](const Incidence& in) { return !in.forward; });
  if (first == around.end()) return {};
  std::rotate(around.begin(), first, around.end());
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < n; i += 2) {
    if (around[i].forward || !around[(i + 1) % n].forward) return {};
    pairs.emplace_back(around[i].face, around[(i + 1) % n].face);
  }
  return pairs;
}

/// True when some edge has four faces or more (or a face repeats a vertex): only then can
/// anything be split. One pass of edge numbers, where the ordered map below costs a node per edge.
bool mayTouch(const std::vector<Face>& faces) {
  const SideEdges numbered = numberEdges(faces);
  std::vector<unsigned char> uses(numbered.edges, 0);
  for (const int e : numbered.edgeOfSide) {
    if (e < 0 || ++uses[e] == 4) return true;
  }
  return false;
}

}  // namespace

TouchingSolidsSplit splitTouchingSolids(const TriMesh& mesh) {
  TouchingSolidsSplit out;
  out.mesh = mesh;
  if (!mayTouch(mesh.faces)) return out;
  std::map<std::pair<int, int>, std::vector<Incidence>> edges;  // ordered: the result follows the mesh, not a hash
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces[f][k], b = mesh.faces[f][(k + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back({f, a < b, 0.0});
    }
  // glued[{edge, face}] = the face it is glued to across that edge (pairs by material only; the
  // other edges glue all their faces together, as before).
  std::map<std::pair<std::pair<int, int>, int>, int> glued;
  for (const auto& [edge, around] : edges) {
    if (around.size() < 4) continue;
    const auto forward = std::count_if(around.begin(), around.end(), [](const Incidence& in) { return in.forward; });
    if (2 * forward != static_cast<long>(around.size())) continue;
    const auto pairs = pairByMaterial(mesh, edge.first, edge.second, around);
    if (pairs.empty()) continue;
    ++out.splitEdges;
    for (const auto& [f, g] : pairs) glued[{edge, f}] = g, glued[{edge, g}] = f;
  }
  if (out.splitEdges == 0) return out;

  // Fans: at each vertex, the faces around it joined across the edges through it.
  std::vector<std::vector<int>> facesAt(mesh.vertices.size());
  for (int f = 0; f < static_cast<int>(mesh.faces.size()); ++f)
    for (int v : mesh.faces[f]) facesAt[v].push_back(f);
  for (int v = 0; v < static_cast<int>(mesh.vertices.size()); ++v) {
    const std::vector<int>& fs = facesAt[v];
    if (fs.size() < 2) continue;
    UnionFind fans(static_cast<int>(fs.size()));
    auto slot = [&](int f) { return static_cast<int>(std::lower_bound(fs.begin(), fs.end(), f) - fs.begin()); };
    for (std::size_t i = 0; i < fs.size(); ++i)
      for (int w : mesh.faces[fs[i]]) {
        if (w == v) continue;
        const std::pair<int, int> edge{std::min(v, w), std::max(v, w)};
        const auto it = glued.find({edge, fs[i]});
        if (it != glued.end()) {
          fans.joinKeepingSmallest(static_cast<int>(i), slot(it->second));
        } else if (!glued.count({edge, edges[edge].front().face})) {
          for (const Incidence& in : edges[edge]) fans.joinKeepingSmallest(static_cast<int>(i), slot(in.face));
        }
      }
    // The fan of the lowest face keeps v; every other fan gets a copy, in the order of its lowest face.
    std::map<int, int> copyOf;
    for (std::size_t i = 0; i < fs.size(); ++i) {
      const int root = fans.find(static_cast<int>(i));
      if (root == 0) continue;
      auto [it, added] = copyOf.try_emplace(root, static_cast<int>(out.mesh.vertices.size()));
      if (added) {
        out.mesh.vertices.push_back(mesh.vertices[v]);
        ++out.copiedVertices;
      }
      for (int& corner : out.mesh.faces[fs[i]])
        if (corner == v) corner = it->second;
    }
  }
  return out;
}

}  // namespace acd
