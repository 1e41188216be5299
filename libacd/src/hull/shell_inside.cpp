// The input's solid, shell by shell: InsideTest (exact) on every shell that bounds a solid.
#include <acd/algo/close_vertices.hpp>
#include <acd/algo/duplicate_faces.hpp>
#include <acd/algo/inside.hpp>
#include <acd/algo/shell_inside.hpp>
#include <acd/algo/union_find.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace acd {

namespace {

/// By edge number, how often the faces use the edge from its lower vertex to its higher less how
/// often the other way (sides along no edge, a face's repeated vertex, count nowhere).
std::vector<int> netUses(const std::vector<Face>& faces, const SideEdges& numbered) {
  std::vector<int> net(numbered.edges, 0);
  for (std::size_t s = 0; s < numbered.edgeOfSide.size(); ++s) {
    const int e = numbered.edgeOfSide[s];
    if (e >= 0) net[e] += faces[s / 3][s % 3] < faces[s / 3][(s % 3 + 1) % 3] ? 1 : -1;
  }
  return net;
}

/// Every undirected edge used as often a->b as b->a: a closed 2-cycle, whose winding number is
/// defined everywhere off the surface.
bool balanced(const TriMesh& shell) {
  const std::vector<int> net = netUses(shell.faces, numberEdges(shell.faces));
  return std::all_of(net.begin(), net.end(), [](int n) { return n == 0; });
}

/// A closed manifold shell with some faces flipped, oriented by a walk over its edges (each edge
/// must be used twice, in opposite directions). False when the shell is open, non-manifold or
/// not orientable.
bool orientConsistently(TriMesh& shell) {
  std::unordered_map<std::uint64_t, std::vector<int>> facesOf;
  for (int i = 0; i < static_cast<int>(shell.faces.size()); ++i)
    for (int k = 0; k < 3; ++k) facesOf[edgeKey(shell.faces[i][k], shell.faces[i][(k + 1) % 3])].push_back(i);
  for (const auto& e : facesOf)
    if (e.second.size() != 2) return false;
  // Whether face f runs a->b (true) or b->a.
  auto runs = [&](int f, int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (shell.faces[f][k] == a && shell.faces[f][(k + 1) % 3] == b) return true;
    return false;
  };
  std::vector<int> state(shell.faces.size(), 0);  // 0 unseen, 1 kept, -1 flipped
  std::vector<int> stack{0};
  state[0] = 1;
  while (!stack.empty()) {
    const int f = stack.back();
    stack.pop_back();
    for (int k = 0; k < 3; ++k) {
      int a = shell.faces[f][k], b = shell.faces[f][(k + 1) % 3];
      if (state[f] < 0) std::swap(a, b);  // as f runs once flipped
      const auto& pair = facesOf[edgeKey(a, b)];
      const int g = pair[0] == f ? pair[1] : pair[0];
      const int wanted = runs(g, b, a) ? 1 : -1;  // g must run b->a
      if (state[g] == 0) {
        state[g] = wanted;
        stack.push_back(g);
      } else if (state[g] != wanted) {
        return false;
      }
    }
  }
  for (std::size_t i = 0; i < shell.faces.size(); ++i)
    if (state[i] < 0) std::swap(shell.faces[i][1], shell.faces[i][2]);
  return true;
}

/// The shell without its loose flaps: faces with an edge no other face uses go, again and again
/// (a fin welded to a closed box goes; an open box goes entirely). A work list of the faces whose
/// edge just became loose, so that peeling a scan ring by ring from its holes costs its size once.
TriMesh peeled(const TriMesh& shell) {
  const int nf = static_cast<int>(shell.faces.size());
  std::vector<std::pair<std::uint64_t, int>> sides(3 * static_cast<std::size_t>(nf));  // (edge, 3 * face + k)
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) sides[3 * f + k] = {edgeKey(shell.faces[f][k], shell.faces[f][(k + 1) % 3]), 3 * f + k};
  std::sort(sides.begin(), sides.end());
  std::vector<int> edgeOfSide(sides.size()), start{0}, uses;  // sides[start[e]..start[e+1]) lie on edge e
  for (std::size_t i = 0; i < sides.size(); ++i) {
    if (i > 0 && sides[i].first != sides[i - 1].first) start.push_back(static_cast<int>(i));
    edgeOfSide[sides[i].second] = static_cast<int>(start.size()) - 1;
  }
  start.push_back(static_cast<int>(sides.size()));
  for (std::size_t e = 0; e + 1 < start.size(); ++e) uses.push_back(start[e + 1] - start[e]);
  std::vector<char> gone(nf, 0);
  std::vector<int> work;
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      if (uses[edgeOfSide[3 * f + k]] == 1) work.push_back(f);
  while (!work.empty()) {
    const int f = work.back();
    work.pop_back();
    if (gone[f]) continue;
    gone[f] = 1;
    for (int k = 0; k < 3; ++k) {
      const int e = edgeOfSide[3 * f + k];
      if (--uses[e] != 1) continue;
      for (int i = start[e]; i < start[e + 1]; ++i)
        if (!gone[sides[i].second / 3]) work.push_back(sides[i].second / 3);
    }
  }
  TriMesh out{shell.vertices, {}};
  for (int f = 0; f < nf; ++f)
    if (!gone[f]) out.faces.push_back(shell.faces[f]);
  return out;
}

/// The generalised winding number of an open shell around q (Jacobson et al. 2013): the sum of
/// its triangles' signed solid angles (Van Oosterom & Strackee) over 4 pi.
double windingNumber(const std::vector<std::array<Vec3, 3>>& triangles, const Vec3& q) {
  double sum = 0.0;
  for (const auto& t : triangles) {
    const Vec3 a = t[0] - q, b = t[1] - q, c = t[2] - q;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    sum += 2.0 * std::atan2(a.dot(b.cross(c)), la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb);
  }
  return sum / (4.0 * M_PI);
}

/// An open shell bounds where its winding number reaches 1/2, less a margin: on the plane of a
/// box's missing lid it is 1/2 exactly, and a hull there, a rounding off that plane, must not be
/// called outside (and then measured to the rim).
constexpr double kHalfWinding = 0.499;

/// Open shells whose rims have more edges than this (all together) count as surface only: the
/// cone closing them is summed face by face.
constexpr std::size_t kWindingRimEdges = 50000;

/// The cone that closes an open shell: for every rim edge a->b (an edge used more often a->b than
/// b->a, as many times as the difference), the triangle (b, a, apex), with one apex per connected
/// piece of the rim: at the mean of its vertices, moved out of the hole (against the rim's area
/// vector) by a quarter of the rim's radius, so that the cone does not lie where hulls do (across
/// a flat hole, where the difference below would be taken on the cone itself). Shell and cone together use every edge
/// as often in each direction (the rim is a cycle), so their winding number is an integer that a ray counts exactly,
/// and the shell's own is that less the cone's (Jacobson et al. 2013, closing the shell up): the cost of a query
/// follows the rim, not the shell.
std::vector<std::array<Vec3, 3>> closingCone(const TriMesh& shell) {
  const SideEdges numbered = numberEdges(shell.faces);
  const std::vector<int> net = netUses(shell.faces, numbered);
  std::vector<std::pair<int, int>> rim;  // directed, with repeats
  std::vector<char> listed(net.size(), 0);
  for (std::size_t s = 0; s < numbered.edgeOfSide.size(); ++s) {
    const int e = numbered.edgeOfSide[s];
    if (e < 0 || listed[e]) continue;
    listed[e] = 1;
    const int a = shell.faces[s / 3][s % 3], b = shell.faces[s / 3][(s % 3 + 1) % 3];
    const int lo = std::min(a, b), hi = std::max(a, b), n = net[e];
    for (int i = 0; i < std::abs(n); ++i) rim.emplace_back(n > 0 ? lo : hi, n > 0 ? hi : lo);
  }
  std::sort(rim.begin(), rim.end());  // a canonical order
  UnionFind pieces(static_cast<int>(shell.vertices.size()));
  for (const auto& [a, b] : rim) pieces.joinKeepingSmallest(a, b);
  struct Piece {
    Vec3 sum = Vec3::Zero(), area = Vec3::Zero();
    int n = 0;
    double radius = 0.0;
    Vec3 apex = Vec3::Zero();
  };
  std::unordered_map<int, Piece> piece;
  std::vector<char> counted(shell.vertices.size(), 0);
  for (const auto& [a, b] : rim) {
    Piece& p = piece[pieces.find(a)];
    p.area += 0.5 * shell.vertices[a].cross(shell.vertices[b]);
    for (int v : {a, b})
      if (!counted[v]) counted[v] = 1, p.sum += shell.vertices[v], ++p.n;
  }
  for (const auto& [a, b] : rim) {
    Piece& p = piece[pieces.find(a)];
    p.radius = std::max(p.radius, (shell.vertices[a] - p.sum / p.n).norm());
  }
  for (auto& [root, p] : piece) {
    p.apex = p.sum / p.n;
    if (p.area.norm() > 0.0) p.apex -= 0.25 * p.radius * p.area.normalized();
  }
  std::vector<std::array<Vec3, 3>> cone;
  for (const auto& [a, b] : rim) cone.push_back({shell.vertices[b], shell.vertices[a], piece[pieces.find(a)].apex});
  return cone;
}

}  // namespace

struct ShellsInside::Impl {
  struct Solid {
    Box3 box;
    std::unique_ptr<InsideTest> test;
  };
  struct Open {
    Box3 box;
    std::unique_ptr<InsideTest> closedUp;  // the shell with its cone
    std::vector<std::array<Vec3, 3>> cone;
  };
  std::vector<Solid> solids;
  std::vector<Open> open;  // bound by their generalised winding number
  int surfaceOnly = 0;
};

ShellsInside::ShellsInside(const TriMesh& soup, double weld) : impl_(std::make_unique<Impl>()) {
  const Box3 box = boundingBox(soup);
  const std::vector<int> root = closeVertexRoots(soup.vertices, box, weld * box.size().norm());
  std::vector<Face> faces;
  for (Face f : soup.faces) {
    for (int& v : f) v = root[v];
    if (f[0] != f[1] && f[1] != f[2] && f[2] != f[0]) faces.push_back(f);
  }
  // Copies and double-sided faces as the repair resolves them (neither moves a point): a closed
  // shell an exporter wrote on both sides bounds what one side does, not nothing.
  TriMesh welded{soup.vertices, resolveDuplicates(faces).faces};
  std::size_t rimEdges = 0;
  for (TriMesh& shell : splitEdgeConnected(welded)) {
    TriMesh closed = balanced(shell) ? shell : peeled(shell);
    if (closed.faces.empty() || (!balanced(closed) && !orientConsistently(closed))) {
      // Open: where its faces (a box without its lid) wind around a point at least half way.
      Impl::Open o{boundingBox(shell), nullptr, closingCone(shell)};
      rimEdges += o.cone.size();
      if (rimEdges > kWindingRimEdges) {
        ++impl_->surfaceOnly;
        continue;
      }
      TriMesh withCone = shell;
      for (const auto& t : o.cone) {
        const int base = static_cast<int>(withCone.vertices.size());
        withCone.vertices.insert(withCone.vertices.end(), t.begin(), t.end());
        withCone.faces.push_back({base, base + 1, base + 2});
      }
      o.closedUp = std::make_unique<InsideTest>(withCone);
      // Padded: the margin of kHalfWinding reaches a little past a missing face.
      const Vec3 pad = Vec3::Constant(0.01 * o.box.size().norm());
      o.box.lo -= pad, o.box.hi += pad;
      impl_->open.push_back(std::move(o));
      continue;
    }
    shell = std::move(closed);
    impl_->solids.push_back({boundingBox(shell), std::make_unique<InsideTest>(shell)});
  }
}

ShellsInside::~ShellsInside() = default;

bool ShellsInside::insideClosed(const Vec3& q) const {
  for (const Impl::Solid& s : impl_->solids) {
    if ((q.array() < s.box.lo.array()).any() || (q.array() > s.box.hi.array()).any()) continue;
    if (s.test->inside(q)) return true;
  }
  return false;
}

bool ShellsInside::insideOpen(const Vec3& q) const {
  // Outside a shell's bounding box its winding number is below 1/2 (the shell lies in a
  // half-space away from q).
  for (const Impl::Open& o : impl_->open) {
    if ((q.array() < o.box.lo.array()).any() || (q.array() > o.box.hi.array()).any()) continue;
    if (std::abs(o.closedUp->winding(q) - windingNumber(o.cone, q)) >= kHalfWinding) return true;
  }
  return false;
}

int ShellsInside::solidShells() const { return static_cast<int>(impl_->solids.size()); }
int ShellsInside::openShells() const { return static_cast<int>(impl_->open.size()) + impl_->surfaceOnly; }
int ShellsInside::surfaceOnlyShells() const { return impl_->surfaceOnly; }

}  // namespace acd
