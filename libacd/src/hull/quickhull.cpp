// Quickhull (Barber, Dobkin, Huhdanpaa 1996) with exact side tests. Each triangle keeps the points
// strictly outside it; the farthest of them is added, the triangles it sees strictly are removed,
// and the horizon is closed with new triangles to it. With exact tests the triangles a point sees
// form a disc, so the horizon is one loop; a point in the plane of a triangle does not see it,
// so no new triangle is ever flat.
#include <acd/algo/quickhull.hpp>

#include <CGAL/Mpzf.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace acd {

TriangleSide::TriangleSide(const Vec3& p, const Vec3& q, const Vec3& r) : p_(p), q_(q), r_(r) {
  const Vec3 u = q - p, v = r - p;  // a difference of doubles that is tiny is exact
  n_ = u.cross(v);
  // The terms' absolute values, for the rounding error bound of a double evaluation.
  m_ = Vec3(std::abs(u.y() * v.z()) + std::abs(u.z() * v.y()), std::abs(u.z() * v.x()) + std::abs(u.x() * v.z()),
            std::abs(u.x() * v.y()) + std::abs(u.y() * v.x()));
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    zero_[i] = (u[j] == 0 || v[k] == 0) && (u[k] == 0 || v[j] == 0);
    for (const auto& [a, b] : {std::pair{u[j], v[k]}, std::pair{u[k], v[j]}}) {
      const double product = std::abs(a * b);
      if (a != 0 && b != 0 && !(product > 1e-280 && product < 1e280)) normal_ = false;
    }
  }
}

int TriangleSide::exactSign(const Vec3& s) const {
  using E = CGAL::Mpzf;
  const E ux = E(q_.x()) - E(p_.x()), uy = E(q_.y()) - E(p_.y()), uz = E(q_.z()) - E(p_.z());
  const E vx = E(r_.x()) - E(p_.x()), vy = E(r_.y()) - E(p_.y()), vz = E(r_.z()) - E(p_.z());
  const E dx = E(s.x()) - E(p_.x()), dy = E(s.y()) - E(p_.y()), dz = E(s.z()) - E(p_.z());
  const E e = dx * (uy * vz - uz * vy) + dy * (uz * vx - ux * vz) + dz * (ux * vy - uy * vx);
  return e.sign();
}

bool collinear(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Collinear exactly when the normal (b - a) x (c - a) is zero. A component whose double value
  // stands clear of its rounding error (orient2d's bound, differences included, with room) is
  // certainly not zero; otherwise the exact normal decides, once for all three components.
  const Vec3 u = b - a, v = c - a;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double terms = std::abs(u[j] * v[k]) + std::abs(u[k] * v[j]);
    if (terms > 1e-250 && terms < 1e250 && std::abs(u[j] * v[k] - u[k] * v[j]) > 1e-15 * terms) return false;
  }
  using E = CGAL::Mpzf;
  const E ux = E(b.x()) - E(a.x()), uy = E(b.y()) - E(a.y()), uz = E(b.z()) - E(a.z());
  const E vx = E(c.x()) - E(a.x()), vy = E(c.y()) - E(a.y()), vz = E(c.z()) - E(a.z());
  return (uy * vz - uz * vy).sign() == 0 && (uz * vx - ux * vz).sign() == 0 && (ux * vy - uy * vx).sign() == 0;
}

namespace {

struct Triangle {
  std::array<int, 3> v;
  std::array<int, 3> across{-1, -1, -1};
  TriangleSide side;
  std::vector<int> outside;  // points strictly outside this triangle and no earlier one
  bool alive = true;
};

class Builder {
 public:
  explicit Builder(const std::vector<Vec3>& points) : p_(points) {}

  QuickHull run() {
    QuickHull out;
    if (!startSimplex()) {
      out.degenerate = true;
      return out;
    }
    while (!work_.empty()) {
      const int t = work_.back();
      work_.pop_back();
      if (!tri_[t].alive || tri_[t].outside.empty()) continue;
      if (!addFarthest(t)) {
        out.failed = true;
        return out;
      }
    }
    std::vector<int> index(tri_.size(), -1);
    for (std::size_t t = 0; t < tri_.size(); ++t)
      if (tri_[t].alive) index[t] = static_cast<int>(out.faces.size()), out.faces.push_back(tri_[t].v);
    for (const Triangle& t : tri_)
      if (t.alive) out.across.push_back({index[t.across[0]], index[t.across[1]], index[t.across[2]]});
    return out;
  }

 private:
  int addTriangle(int a, int b, int c) {
    tri_.push_back({{a, b, c}, {-1, -1, -1}, TriangleSide(p_[a], p_[b], p_[c]), {}, true});
    return static_cast<int>(tri_.size()) - 1;
  }

  /// Hands each point to the first of `tris` it is strictly outside of; returns false when it is none's.
  bool assign(int point, const std::vector<int>& tris) {
    for (int t : tris)
      if (tri_[t].side.sign(p_[point]) > 0) {
        tri_[t].outside.push_back(point);
        return true;
      }
    return false;
  }

  /// The first tetrahedron: extreme points by coordinates, then farthest from the line and the
  /// plane (in doubles; the choice only has to be valid, which the exact tests check).
  bool startSimplex() {
    const int n = static_cast<int>(p_.size());
    if (n < 4) return false;
    auto lexLess = [&](int a, int b) {
      return std::lexicographical_compare(p_[a].data(), p_[a].data() + 3, p_[b].data(), p_[b].data() + 3);
    };
    int a = 0, b = 0;
    for (int i = 1; i < n; ++i) {
      if (lexLess(i, a)) a = i;
      if (lexLess(b, i)) b = i;
    }
    if (a == b) return false;
    int c = -1;
    double best = -1.0;
    const Vec3 axis = p_[b] - p_[a];
    for (int i = 0; i < n; ++i) {
      const double d = axis.cross(p_[i] - p_[a]).squaredNorm();
      if (d > best) best = d, c = i;
    }
    if (collinear(p_[a], p_[b], p_[c])) {
      c = -1;
      for (int i = 0; i < n && c < 0; ++i)
        if (!collinear(p_[a], p_[b], p_[i])) c = i;
      if (c < 0) return false;
    }
    const TriangleSide base(p_[a], p_[b], p_[c]);
    int d = -1;
    best = -1.0;
    for (int i = 0; i < n; ++i) {
      const double h = std::abs(base.height(p_[i]));
      if (h > best) best = h, d = i;
    }
    if (base.sign(p_[d]) == 0) {
      d = -1;
      for (int i = 0; i < n && d < 0; ++i)
        if (base.sign(p_[i]) != 0) d = i;
      if (d < 0) return false;
    }
    if (base.sign(p_[d]) > 0) std::swap(b, c);  // d below the base: the base faces away from it
    // Faces a b c, a d b, b d c, c d a: each seen counter-clockwise from outside.
    const int f0 = addTriangle(a, b, c), f1 = addTriangle(a, d, b), f2 = addTriangle(b, d, c), f3 = addTriangle(c, d, a);
    tri_[f0].across = {f1, f2, f3};
    tri_[f1].across = {f3, f2, f0};
    tri_[f2].across = {f1, f3, f0};
    tri_[f3].across = {f2, f1, f0};
    const std::vector<int> all{f0, f1, f2, f3};
    for (int i = 0; i < n; ++i)
      if (i != a && i != b && i != c && i != d) assign(i, all);
    for (int t : all)
      if (!tri_[t].outside.empty()) work_.push_back(t);
    return true;
  }

  /// Adds the point of t's outside set farthest from its plane (ties: the smaller index).
  bool addFarthest(int t) {
    int apex = -1;
    double best = -std::numeric_limits<double>::infinity();
    for (int q : tri_[t].outside) {
      const double h = tri_[t].side.height(p_[q]);
      if (h > best || (h == best && q < apex)) best = h, apex = q;
    }
    const Vec3& x = p_[apex];
    // The triangles the apex sees, by a search over neighbours from t; the edges from a seen one to
    // an unseen one make the horizon.
    ++stamp_;
    std::vector<int> visible{t}, stack{t};
    mark(t, true);
    struct Edge {
      int from, to, outer;
    };
    std::vector<Edge> horizon;
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const int u = tri_[s].across[k];
        if (!classified(u)) {
          const bool sees = tri_[u].side.sign(x) > 0;
          mark(u, sees);
          if (sees) visible.push_back(u), stack.push_back(u);
        }
        if (!isVisible(u)) horizon.push_back({tri_[s].v[k], tri_[s].v[(k + 1) % 3], u});
      }
    }
    // One new triangle per horizon edge, edge direction kept (so it faces outward too).
    std::vector<int> made;
    made.reserve(horizon.size());
    for (const Edge& e : horizon) {
      if (startsAt(e.from) >= 0) return false;  // the horizon is not one loop
      const int n = addTriangle(e.from, e.to, apex);
      startAt_[e.from] = n;
      startStamp_[e.from] = stamp_;
      tri_[n].across[0] = e.outer;
      Triangle& outer = tri_[e.outer];
      int slot = -1;
      for (int k = 0; k < 3; ++k)
        if (outer.v[k] == e.to && outer.v[(k + 1) % 3] == e.from) slot = k;
      if (slot < 0) return false;
      outer.across[slot] = n;
      made.push_back(n);
    }
    for (int n : made) {
      Triangle& tri = tri_[n];
      const int next = startsAt(tri.v[1]);  // the new triangle on edge to -> apex
      if (next < 0) return false;
      tri.across[1] = next;
      tri_[next].across[2] = n;
    }
    for (int s : visible) {
      for (int q : tri_[s].outside)
        if (q != apex) assign(q, made);
      tri_[s].outside.clear();
      tri_[s].outside.shrink_to_fit();
      tri_[s].alive = false;
    }
    for (int n : made)
      if (!tri_[n].outside.empty()) work_.push_back(n);
    return true;
  }

  void mark(int t, bool visible) {
    if (static_cast<int>(markStamp_.size()) <= t) markStamp_.resize(tri_.size() * 2, 0), visibleMark_.resize(tri_.size() * 2, 0);
    markStamp_[t] = stamp_;
    visibleMark_[t] = visible;
  }
  bool classified(int t) const { return t < static_cast<int>(markStamp_.size()) && markStamp_[t] == stamp_; }
  bool isVisible(int t) const { return classified(t) && visibleMark_[t]; }
  int startsAt(int v) {
    if (startAt_.empty()) startAt_.assign(p_.size(), -1), startStamp_.assign(p_.size(), 0);
    return startStamp_[v] == stamp_ ? startAt_[v] : -1;
  }

  const std::vector<Vec3>& p_;
  std::vector<Triangle> tri_;
  std::vector<int> work_;
  int stamp_ = 0;
  std::vector<int> markStamp_;
  std::vector<char> visibleMark_;
  std::vector<int> startAt_, startStamp_;
};

}  // namespace

QuickHull quickHull(const std::vector<Vec3>& points) { return Builder(points).run(); }

}  // namespace acd
