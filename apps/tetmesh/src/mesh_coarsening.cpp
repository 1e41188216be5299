// Edge collapses that keep a labelled tet mesh well shaped; see mesh_coarsening.hpp.
#include "mesh_coarsening.hpp"

#include "mesh_quality.hpp"

#include <acd/algo/closest_point.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

namespace tetmesh {

namespace {

using Patch = std::pair<int, int>;  // the labels on either side, lower first; 0: outside
using Triangle = std::array<int, 3>;

constexpr int kOutside = -1;  // the outside as a vertex of links (next to every boundary vertex)
constexpr double kPi = 3.14159265358979323846;
constexpr int kPasses = 4;

/// A triangle of a surface patch, oriented so that its normal points to the lower label's side.
struct PatchFace {
  Triangle corners;
  Patch patch;
};

/// Triangle f of tet t, ordered so that its normal points away from t's fourth corner.
Triangle outward(const TetMesh& m, int t, Triangle f) {
  int apex = -1;
  for (int x : m.tets[t])
    if (std::find(f.begin(), f.end(), x) == f.end()) apex = x;
  const Vec3 n = (m.points[f[1]] - m.points[f[0]]).cross(m.points[f[2]] - m.points[f[0]]);
  if (n.dot(m.points[apex] - m.points[f[0]]) > 0) std::swap(f[1], f[2]);
  return f;
}

class Coarsener {
 public:
  Coarsener(TetMesh& mesh, const CoarsenOptions& options) : m_(mesh), o_(options) {
    const int n = static_cast<int>(m_.points.size());
    alive_.assign(m_.tets.size(), 1);
    for (int t = 0; t < static_cast<int>(m_.tets.size()); ++t) {
      const int l = m_.labels[t];
      if (l >= static_cast<int>(labelVolume_.size())) labelVolume_.resize(l + 1, 0.0);
      labelVolume_[l] += tetVolume(m_, t);
    }
    stars_.resize(n);
    for (int t = 0; t < static_cast<int>(m_.tets.size()); ++t)
      for (int v : m_.tets[t]) stars_[v].push_back(t);
    // Patches through each vertex, once: collapses move a vertex only within its own patch, so
    // no vertex gains or loses a patch.
    kind_.assign(n, Kind::Inner);
    patches_.resize(n);
    kept_.resize(n);
    for (int v = 0; v < n; ++v) {
      const std::vector<PatchFace> faces = facesAround(v);
      if (faces.empty()) continue;
      std::set<Patch> patches;
      for (const PatchFace& f : faces) patches.insert(f.patch);
      patches_[v].assign(patches.begin(), patches.end());
      for (const Patch& p : patches) kept_[v].push_back({m_.points[v], p});
      if (patches.size() == 1) {
        kind_[v] = oneFan(v, faces) ? Kind::OnPatch : Kind::Fixed;
      } else {
        // On a rim: exactly two rim edges (else a corner, or a tangle the collapses leave alone).
        const std::vector<int> rim = rimNeighbours(v, faces);
        kind_[v] = rim.size() == 2 ? Kind::OnRim : Kind::Fixed;
      }
    }
  }

  CoarsenResult run() {
    CoarsenResult r;
    r.tetsBefore = static_cast<int>(m_.tets.size());
    r.pointsBefore = static_cast<int>(m_.points.size());
    std::vector<char> gone(m_.points.size(), 0);
    // An edge refused now may pass once its neighbours have gone: a few sweeps over all edges.
    for (int pass = 0; pass < kPasses; ++pass) {
      const int collapses = sweep(gone);
      r.collapses += collapses;
      if (collapses == 0) break;
    }
    compact();
    r.tetsAfter = static_cast<int>(m_.tets.size());
    r.pointsAfter = static_cast<int>(m_.points.size());
    r.farthest = farthest_;
    return r;
  }

 private:
  enum class Kind { Inner, OnPatch, OnRim, Fixed };  // the order of ties to the surface

  int rank(int v) const { return static_cast<int>(kind_[v]); }

  /// Every edge once, shortest first (then by its ends' numbers); the edges around a kept vertex
  /// join the queue again. Returns the collapses made.
  int sweep(std::vector<char>& gone) {
    using Entry = std::tuple<double, int, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    auto push = [&](int v) {
      for (int w : neighbours(v)) queue.emplace((m_.points[v] - m_.points[w]).norm(), std::min(v, w), std::max(v, w));
    };
    for (int v = 0; v < static_cast<int>(m_.points.size()); ++v)
      if (!gone[v]) push(v);
    int collapses = 0;
    while (!queue.empty()) {
      const auto [length, u, w] = queue.top();
      queue.pop();
      if (gone[u] || gone[w] || !adjacent(u, w)) continue;
      // The vertex with fewer ties to the surface goes; on equal terms the higher number.
      const bool uFirst = rank(u) < rank(w) || (rank(u) == rank(w) && u > w);
      const int a = uFirst ? u : w, b = uFirst ? w : u;
      if (!collapse(a, b) && !(rank(a) == rank(b) && collapse(b, a))) continue;
      const int removed = stars_[a].empty() ? a : b;
      gone[removed] = 1;
      ++collapses;
      push(removed == a ? b : a);
    }
    return collapses;
  }

  std::vector<int> aliveStar(int v) const {
    std::vector<int> s;
    for (int t : stars_[v])
      if (alive_[t]) s.push_back(t);
    return s;
  }

  std::set<int> neighbours(int v) const {
    std::set<int> n;
    for (int t : stars_[v])
      if (alive_[t])
        for (int x : m_.tets[t])
          if (x != v) n.insert(x);
    return n;
  }

  bool adjacent(int a, int b) const {
    for (int t : stars_[a])
      if (alive_[t] && std::find(m_.tets[t].begin(), m_.tets[t].end(), b) != m_.tets[t].end()) return true;
    return false;
  }

  /// The patch triangles through v, from the tets around it (a triangle's other tet, if any,
  /// also has v).
  std::vector<PatchFace> facesAround(int v) const {
    std::map<Triangle, std::vector<int>> sides;  // sorted corners -> tets
    for (int t : stars_[v]) {
      if (!alive_[t]) continue;
      const auto& q = m_.tets[t];
      for (int k = 0; k < 4; ++k) {
        if (q[k] == v) continue;
        Triangle f{q[(k + 1) % 4], q[(k + 2) % 4], q[(k + 3) % 4]};
        std::sort(f.begin(), f.end());
        sides[f].push_back(t);
      }
    }
    std::vector<PatchFace> faces;
    for (const auto& [f, tets] : sides) {
      const int l0 = m_.labels[tets[0]], l1 = tets.size() > 1 ? m_.labels[tets[1]] : 0;
      if (tets.size() > 1 && l0 == l1) continue;
      // Oriented out of the tet with the higher label (towards the lower label's side).
      const int owner = tets.size() == 1 || l0 > l1 ? tets[0] : tets[1];
      faces.push_back({outward(m_, owner, f), {std::min(l0, l1), std::max(l0, l1)}});
    }
    return faces;
  }

  Vec3 normal(const Triangle& f) const {
    return (m_.points[f[1]] - m_.points[f[0]]).cross(m_.points[f[2]] - m_.points[f[0]]);
  }

  /// v's triangles of one patch form one fan around it (closed: the patch is a surface there).
  static bool oneFan(int v, const std::vector<PatchFace>& faces) {
    std::map<int, int> next;  // around v: corner after v -> corner before v
    for (const PatchFace& f : faces) {
      const auto& c = f.corners;
      const int at = static_cast<int>(std::find(c.begin(), c.end(), v) - c.begin());
      if (!next.emplace(c[(at + 1) % 3], c[(at + 2) % 3]).second) return false;
    }
    int x = next.begin()->first;
    for (std::size_t steps = 0; steps < next.size(); ++steps) {
      const auto it = next.find(x);
      if (it == next.end()) return false;
      x = it->second;
    }
    return x == next.begin()->first && faces.size() == next.size() && faces.size() >= 3;
  }

  bool onPatch(int v, const Patch& p) const {
    return std::find(patches_[v].begin(), patches_[v].end(), p) != patches_[v].end();
  }

  bool onBoundary(int v) const { return !patches_[v].empty() && patches_[v].front().first == 0; }

  /// The neighbours of v across whose edge the patch changes (the edge's triangles belong to
  /// more than one patch, or one patch has other than two of them).
  static std::vector<int> rimNeighbours(int v, const std::vector<PatchFace>& faces) {
    std::map<int, std::map<Patch, int>> edges;  // other end -> triangles per patch
    for (const PatchFace& f : faces)
      for (int x : f.corners)
        if (x != v) ++edges[x][f.patch];
    std::vector<int> rim;
    for (const auto& [x, count] : edges)
      if (count.size() > 1 || count.begin()->second != 2) rim.push_back(x);
    return rim;
  }

  /// The link condition on vertices: the vertices next to both a and b are exactly the third
  /// corners of the triangles on ab; the outside is next to every boundary vertex, and on ab's
  /// link when ab is a boundary edge. The same on a's patch, for its triangles.
  bool linkHolds(int a, int b, const std::vector<PatchFace>& facesA, const std::vector<PatchFace>& facesB) const {
    std::set<int> na = neighbours(a), nb = neighbours(b), common, link;
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::inserter(common, common.end()));
    for (int t : stars_[a])
      if (alive_[t] && std::find(m_.tets[t].begin(), m_.tets[t].end(), b) != m_.tets[t].end())
        for (int x : m_.tets[t])
          if (x != a && x != b) link.insert(x);
    bool boundaryEdge = false;
    for (const PatchFace& f : facesA)
      if (f.patch.first == 0 && std::find(f.corners.begin(), f.corners.end(), b) != f.corners.end()) boundaryEdge = true;
    if (onBoundary(a) && onBoundary(b)) common.insert(kOutside);
    if (boundaryEdge) link.insert(kOutside);
    if (common != link) return false;
    // On every patch of a: ab's triangles there (two inside a patch, one on a rim) are the only
    // ones whose third corner is next to both.
    for (const Patch& patch : patches_[a]) {
      std::set<int> patchA, patchB, patchLink;
      for (const PatchFace& f : facesA) {
        if (f.patch != patch) continue;
        const bool withB = std::find(f.corners.begin(), f.corners.end(), b) != f.corners.end();
        for (int x : f.corners)
          if (x != a && x != b) (withB ? patchLink : patchA).insert(x);
      }
      for (const PatchFace& f : facesB)
        if (f.patch == patch)
          for (int x : f.corners)
            if (x != a && x != b) patchB.insert(x);
      for (int x : patchLink) patchA.erase(x);
      for (int x : patchA)
        if (patchB.count(x)) return false;
      if (patchLink.size() != (kind_[a] == Kind::OnPatch ? 2u : 1u)) return false;
    }
    return true;
  }

  double volumeOf(const std::array<int, 4>& q) const {
    const Vec3 &p0 = m_.points[q[0]], &p1 = m_.points[q[1]], &p2 = m_.points[q[2]], &p3 = m_.points[q[3]];
    return (p1 - p0).cross(p2 - p0).dot(p3 - p0) / 6.0;
  }

  bool wellShaped(const std::array<int, 4>& q) const {
    const Vec3 &p0 = m_.points[q[0]], &p1 = m_.points[q[1]], &p2 = m_.points[q[2]], &p3 = m_.points[q[3]];
    if (!((p1 - p0).cross(p2 - p0).dot(p3 - p0) > 0)) return false;
    for (double angle : dihedralAngles(p0, p1, p2, p3))
      if (angle < o_.minDihedral || angle > 180.0 - o_.minDihedral) return false;
    return true;
  }

  /// Moves a onto b when every condition of the header holds; false leaves the mesh as it was.
  bool collapse(int a, int b) {
    if (kind_[a] == Kind::Fixed) return false;
    for (const Patch& patch : patches_[a])
      if (!onPatch(b, patch)) return false;  // b on all of a's patches
    // The tets first: most refusals are theirs, and they cost least to check.
    const std::vector<int> star = aliveStar(a);
    std::vector<int> moved, removed;
    std::map<int, double> change;  // label -> volume change
    for (int t : star) {
      const auto& q = m_.tets[t];
      change[m_.labels[t]] -= tetVolume(m_, t);
      if (std::find(q.begin(), q.end(), b) != q.end()) {
        removed.push_back(t);
        continue;
      }
      std::array<int, 4> made = q;
      *std::find(made.begin(), made.end(), a) = b;
      if (!wellShaped(made)) return false;
      change[m_.labels[t]] += volumeOf(made);
      moved.push_back(t);
    }
    for (const auto& [label, delta] : change) {
      const double floor = label >= 1 && label <= static_cast<int>(o_.minVolume.size()) ? o_.minVolume[label - 1] : 0.0;
      if (delta < 0 && labelVolume_[label] + delta < floor) return false;
    }
    const bool inner = kind_[a] == Kind::Inner;
    const std::vector<PatchFace> facesA = inner ? std::vector<PatchFace>{} : facesAround(a);
    const std::vector<PatchFace> facesB = inner ? std::vector<PatchFace>{} : facesAround(b);
    if (!inner) {
      // Along a patch edge of a's patch, or along the rim a lies on.
      if (kind_[a] == Kind::OnRim) {
        const std::vector<int> rim = rimNeighbours(a, facesA);
        if (std::find(rim.begin(), rim.end(), b) == rim.end()) return false;
      } else {
        bool alongPatch = false;
        for (const PatchFace& f : facesA)
          alongPatch = alongPatch || std::find(f.corners.begin(), f.corners.end(), b) != f.corners.end();
        if (!alongPatch) return false;
      }
    }
    if (!linkHolds(a, b, facesA, facesB)) return false;
    // The surface: new triangles turn little, and every starting surface point near the change
    // stays within maxDistance of its patch.
    std::vector<int> ring;
    if (!inner) {
      for (const PatchFace& f : facesA) {
        if (std::find(f.corners.begin(), f.corners.end(), b) != f.corners.end()) continue;
        Triangle g = f.corners;
        *std::find(g.begin(), g.end(), a) = b;
        const Vec3 before = normal(f.corners), after = normal(g);
        if (!(after.norm() > 0) || after.dot(before) < std::cos(o_.maxTurnDegrees * kPi / 180.0) * after.norm() * before.norm())
          return false;
        for (int x : f.corners)
          if (x != a) ring.push_back(x);
      }
      std::sort(ring.begin(), ring.end());
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    }
    for (int t : removed) alive_[t] = 0;
    for (int t : moved) *std::find(m_.tets[t].begin(), m_.tets[t].end(), a) = b;
    double far = 0.0;
    if (!inner) far = surfaceDeviation(a, b, ring);
    if (!(far <= o_.maxDistance)) {
      for (int t : removed) alive_[t] = 1;
      for (int t : moved) *std::find(m_.tets[t].begin(), m_.tets[t].end(), b) = a;
      return false;
    }
    farthest_ = std::max(farthest_, far);
    for (const auto& [label, delta] : change) labelVolume_[label] += delta;
    for (int t : moved) stars_[b].push_back(t);
    stars_[a].clear();
    for (const Kept& k : kept_[a]) kept_[b].push_back(k);
    kept_[a].clear();
    return true;
  }

  /// After a moved onto b: the farthest starting surface point of a, b and a's ring from the
  /// patch triangles now around b and the ring.
  double surfaceDeviation(int a, int b, const std::vector<int>& ring) const {
    std::vector<int> around = ring;
    around.push_back(b);
    std::map<Patch, std::set<Triangle>> faces;
    for (int v : around)
      for (const PatchFace& f : facesAround(v)) faces[f.patch].insert(f.corners);
    double worst = 0.0;
    std::vector<const std::vector<Kept>*> points{&kept_[a], &kept_[b]};
    for (int v : ring) points.push_back(&kept_[v]);
    for (const std::vector<Kept>* list : points)
      for (const auto& [p, on] : *list) {
        if (!onPatch(a, on)) continue;
        double best = std::numeric_limits<double>::infinity();
        for (const Triangle& f : faces[on])
          best = std::min(best, (p - acd::closestPointOnTriangle(p, m_.points[f[0]], m_.points[f[1]], m_.points[f[2]])).norm());
        worst = std::max(worst, best);
        if (worst > o_.maxDistance) return worst;
      }
    return worst;
  }

  void compact() {
    std::vector<int> index(m_.points.size(), -1);
    std::vector<Vec3> points;
    std::vector<std::array<int, 4>> tets;
    std::vector<int> labels;
    for (int t = 0; t < static_cast<int>(m_.tets.size()); ++t) {
      if (!alive_[t]) continue;
      std::array<int, 4> q = m_.tets[t];
      for (int& v : q) {
        if (index[v] < 0) index[v] = static_cast<int>(points.size()), points.push_back(m_.points[v]);
        v = index[v];
      }
      tets.push_back(q);
      labels.push_back(m_.labels[t]);
    }
    m_.points = std::move(points);
    m_.tets = std::move(tets);
    m_.labels = std::move(labels);
    rebuildFaces(m_);
  }

  TetMesh& m_;
  const CoarsenOptions& o_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> stars_;  // tets around each vertex (dead ones skipped)
  std::vector<Kind> kind_;
  std::vector<std::vector<Patch>> patches_;  // the patches each vertex lies on, sorted
  using Kept = std::pair<Vec3, Patch>;
  std::vector<std::vector<Kept>> kept_;  // starting surface points each vertex stands for, by patch
  double farthest_ = 0.0;
  std::vector<double> labelVolume_;  // by label
};

}  // namespace

void rebuildFaces(TetMesh& mesh) {
  std::map<Triangle, std::vector<int>> sides;
  for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t)
    for (int k = 0; k < 4; ++k) {
      const auto& q = mesh.tets[t];
      Triangle f{q[(k + 1) % 4], q[(k + 2) % 4], q[(k + 3) % 4]};
      std::sort(f.begin(), f.end());
      sides[f].push_back(t);
    }
  mesh.faces.clear();
  mesh.faceMarkers.clear();
  for (const auto& [f, tets] : sides) {
    const bool boundary = tets.size() == 1;
    if (!boundary && (mesh.labels.empty() || mesh.labels[tets[0]] == mesh.labels[tets[1]])) continue;
    int owner = tets[0];
    if (!boundary && mesh.labels[tets[1]] < mesh.labels[tets[0]]) owner = tets[1];
    mesh.faces.push_back(outward(mesh, owner, f));
    mesh.faceMarkers.push_back(boundary ? kBoundaryFacet : kInterfaceFacet);
  }
}

CoarsenResult coarsenMesh(TetMesh& mesh, const CoarsenOptions& options) {
  if (mesh.tets.empty()) return {};
  if (mesh.labels.size() != mesh.tets.size()) mesh.labels.assign(mesh.tets.size(), 1);
  return Coarsener(mesh, options).run();
}

}  // namespace tetmesh
