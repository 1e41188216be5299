// Quickhull over distinct points with exact orientation tests: the triangles of the hull and
// their neighbours, before any merging of coplanar triangles (convexHull does that).
#pragma once

#include <acd/mesh.hpp>

#include <array>
#include <vector>

namespace acd {

/// Sign of (s - p) . ((q - p) x (r - p)) for one triangle p, q, r and many points s, exactly: a
/// double evaluation where it is clear of its rounding error, else ring arithmetic (CGAL's Mpzf).
class TriangleSide {
 public:
  TriangleSide(const Vec3& p, const Vec3& q, const Vec3& r);
  /// +1: s is on the side the normal (q - p) x (r - p) points to; -1: the other; 0: in the plane.
  int sign(const Vec3& s) const {
    const Vec3 d = s - p_;
    const double det = d.dot(n_);
    const double terms = d.cwiseAbs().dot(m_);
    // Shewchuk's bound for this evaluation (the differences' rounding included) is 7.8e-16 of the
    // terms' sum (orient3d's errboundA): beyond 1e-15 of it the double result has the exact sign.
    // The bound assumes no product underflowed: near the underflow range the exact test decides.
    if (terms > kUnderflowMargin && normal_) {
      if (det > 1e-15 * terms) return 1;
      if (det < -1e-15 * terms) return -1;
    } else if ((d.x() == 0 || zero_[0]) && (d.y() == 0 || zero_[1]) && (d.z() == 0 || zero_[2])) {
      return 0;  // every term has a factor that is exactly zero (a point on a cut cap in its own frame)
    }
    return exactSign(s);
  }
  /// (s - p) . n in doubles: how far s is beyond the plane, in units of |n|.
  double height(const Vec3& s) const { return (s - p_).dot(n_); }

 private:
  static constexpr double kUnderflowMargin = 1e-250;
  int exactSign(const Vec3& s) const;
  Vec3 p_, q_, r_, n_, m_;
  bool zero_[3];       // normal component i is exactly zero: each of its two products has a zero factor
  bool normal_ = true;  // no product of the normal underflowed or overflowed
};

/// Exactly collinear (TriangleSide's exact test: the triangle has no side).
bool collinear(const Vec3& a, const Vec3& b, const Vec3& c);

struct QuickHull {
  std::vector<std::array<int, 3>> faces;   // point indices, counter-clockwise seen from outside
  std::vector<std::array<int, 3>> across;  // the face across edge k (corners k, k + 1) of each face
  bool degenerate = false;                 // all points in one plane (or fewer than 4)
  bool failed = false;                     // an inconsistency the exact tests should rule out
};

/// The hull of distinct points. Points on the hull's surface that are not needed may or may not
/// be corners of its triangles; convexHull's canonical output does not depend on which.
QuickHull quickHull(const std::vector<Vec3>& points);

}  // namespace acd
