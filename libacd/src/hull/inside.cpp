// Exact point-in-model test. A ray from the query point towards +z; the signed crossings with
// the model's triangles (sign = orientation of the triangle's xy-projection) sum to the winding
// number, and a point is inside when it is not zero. The predicates are exact (filtered, with
// CGAL's exact fallback), and a query point lying exactly on a projected edge or vertex is moved
// symbolically by (eps, eps^2) in xy, so every ray meets a shared edge exactly once. Triangles
// are bucketed in an xy grid of about two cells per triangle.
#include <acd/algo/inside.hpp>

#include <acd/algo/float_bounds.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace acd {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;
using P3 = K::Point_3;

// ---------------------------------------------------------------- exact predicates

inline int sign(double v) { return (v > 0) - (v < 0); }

/// Exact sign of orient2d(a, b, q) (positive when q is left of a->b).
inline int orient2d(double ax, double ay, double bx, double by, double qx, double qy) {
  const double l = (bx - ax) * (qy - ay), r = (by - ay) * (qx - ax);
  const double det = l - r;
  const double bound = 3.3306690738754716e-16 * (std::abs(l) + std::abs(r));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return static_cast<int>(CGAL::orientation(P2(ax, ay), P2(bx, by), P2(qx, qy)));
}

/// orient2d(a, b, q') with q' = q + (eps, eps^2), eps -> 0: zero only when a and b coincide in xy.
inline int orient2dPerturbed(double ax, double ay, double bx, double by, double qx, double qy) {
  const int s = orient2d(ax, ay, bx, by, qx, qy);
  if (s != 0) return s;
  if (by != ay) return by < ay ? 1 : -1;    // d/dqx of the determinant is -(by - ay)
  return bx > ax ? 1 : (bx < ax ? -1 : 0);  // d/dqy is (bx - ax)
}

}  // namespace

class InsideTest::Impl {
 public:
  explicit Impl(const TriMesh& m) {
    const Box3 box = boundingBox(m);
    lo_ = box.lo;
    hi_ = box.hi;
    tris_.reserve(m.faces.size());
    for (const Face& f : m.faces) {
      const Vec3 &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
      const int s = orient2d(a.x(), a.y(), b.x(), b.y(), c.x(), c.y());
      if (s == 0) continue;  // vertical in projection: no generic vertical ray meets it
      tris_.push_back(Tri{a, b, c, s});
    }
    // Grid over xy with about two cells per triangle.
    const double w = std::max(hi_.x() - lo_.x(), 1e-300), h = std::max(hi_.y() - lo_.y(), 1e-300);
    const double cells = std::clamp(2.0 * static_cast<double>(tris_.size()), 1.0, 4.0e6);
    nx_ = std::clamp(static_cast<int>(std::sqrt(cells * w / h)), 1, 4096);
    ny_ = std::clamp(static_cast<int>(cells / nx_), 1, 4096);
    sx_ = nx_ / w;
    sy_ = ny_ / h;
    start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<int> fill;
      if (pass == 1) {
        std::partial_sum(start_.begin(), start_.end(), start_.begin());
        items_.resize(start_.back());
        fill.assign(start_.begin(), start_.end() - 1);
      }
      for (int t = 0; t < static_cast<int>(tris_.size()); ++t) {
        const Vec3 lo = tris_[t].lo(), hi = tris_[t].hi();
        const int x0 = cellX(lo.x()), x1 = cellX(hi.x());
        const int y0 = cellY(lo.y()), y1 = cellY(hi.y());
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) {
            const std::size_t c = static_cast<std::size_t>(y) * nx_ + x;
            if (pass == 0)
              ++start_[c + 1];
            else
              items_[fill[c]++] = Item{floatAbove(hi.z()), t};
          }
      }
    }
  }

  int winding(const Vec3& q) const {
    if (!(q.x() >= lo_.x() && q.x() <= hi_.x() && q.y() >= lo_.y() && q.y() <= hi_.y() && q.z() <= hi_.z())) return 0;
    const std::size_t c = static_cast<std::size_t>(cellY(q.y())) * nx_ + cellX(q.x());
    int winding = 0;
    for (int k = start_[c]; k < start_[c + 1]; ++k) {
      // Conservative prefilter on the cell's contiguous records (tops rounded up to float).
      const Item& it = items_[k];
      if (q.z() > it.maxz) continue;
      const Tri& t = tris_[it.tri];
      const Vec3 lo = t.lo(), hi = t.hi();
      if (q.z() > hi.z()) continue;  // entirely below the point
      // Bounding box of the triangle against q' = q + (eps, eps^2).
      if (q.x() < lo.x() || q.x() >= hi.x() || q.y() < lo.y() || q.y() >= hi.y()) continue;
      if (orient2dPerturbed(t.a.x(), t.a.y(), t.b.x(), t.b.y(), q.x(), q.y()) != t.s) continue;
      if (orient2dPerturbed(t.b.x(), t.b.y(), t.c.x(), t.c.y(), q.x(), q.y()) != t.s) continue;
      if (orient2dPerturbed(t.c.x(), t.c.y(), t.a.x(), t.a.y(), q.x(), q.y()) != t.s) continue;
      bool above = q.z() < lo.z();
      if (!above) {
        // Below the triangle's plane iff the orientation is opposite to the projected one.
        const auto o = CGAL::orientation(P3(t.a.x(), t.a.y(), t.a.z()), P3(t.b.x(), t.b.y(), t.b.z()),
                                         P3(t.c.x(), t.c.y(), t.c.z()), P3(q.x(), q.y(), q.z()));
        above = static_cast<int>(o) == -t.s;
      }
      if (above) winding += t.s;
    }
    return winding;
  }

 private:
  struct Tri {  // corners only: its box is recomputed (a million-face model's boxes were 48 MB)
    Vec3 a, b, c;
    int s;  // orientation of the xy-projection
    Vec3 lo() const { return a.cwiseMin(b).cwiseMin(c); }
    Vec3 hi() const { return a.cwiseMax(b).cwiseMax(c); }
  };
  struct Item {  // 8 bytes: a million-face model has about ten million of them
    float maxz;
    int tri;
  };
  // Monotone in x, so a point inside a triangle's box always lands in one of the triangle's cells.
  int cellX(double x) const { return std::clamp(static_cast<int>(std::floor((x - lo_.x()) * sx_)), 0, nx_ - 1); }
  int cellY(double y) const { return std::clamp(static_cast<int>(std::floor((y - lo_.y()) * sy_)), 0, ny_ - 1); }

  Vec3 lo_, hi_;
  std::vector<Tri> tris_;
  int nx_ = 1, ny_ = 1;
  double sx_ = 1, sy_ = 1;
  std::vector<int> start_;
  std::vector<Item> items_;
};

InsideTest::InsideTest(const TriMesh& mesh) : impl_(std::make_unique<Impl>(mesh)) {}
InsideTest::~InsideTest() = default;
bool InsideTest::inside(const Vec3& q) const { return impl_->winding(q) != 0; }
int InsideTest::winding(const Vec3& q) const { return impl_->winding(q); }

}  // namespace acd
