// CGAL's convex_hull_3 (quickhull with exact predicates) into a polygon soup, mapped back to input indices.
#include <acd/hull.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <cmath>
#include <unordered_map>

namespace acd {

namespace {
struct PointHash {
  std::size_t operator()(const std::array<double, 3>& p) const {
    std::size_t h = 1469598103934665603ull;
    for (double d : p) h = (h ^ std::hash<double>()(d)) * 1099511628211ull;
    return h;
  }
};
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using HullMesh = CGAL::Surface_mesh<K::Point_3>;

/// Sign of (a - b) . ((q - p) x (r - p)), exactly, for one facet p, q, r and many points. A double
/// evaluation decides when it is clear of its rounding error (below 10 eps of the terms' absolute
/// sum; 1e-14 leaves a wide margin); else ring arithmetic on the doubles in CGAL's Mpzf, which is
/// exact and, unlike the rationals of CGAL's own hull predicate, needs no gcd: pieces' cut faces
/// make these near-zero cases common.
class FacetSide {
 public:
  FacetSide(const K::Point_3& p, const K::Point_3& q, const K::Point_3& r) : p_(p), q_(q), r_(r) {
    const double ux = q.x() - p.x(), uy = q.y() - p.y(), uz = q.z() - p.z();
    const double vx = r.x() - p.x(), vy = r.y() - p.y(), vz = r.z() - p.z();
    n_[0] = uy * vz - uz * vy, n_[1] = uz * vx - ux * vz, n_[2] = ux * vy - uy * vx;
    m_[0] = std::abs(uy * vz) + std::abs(uz * vy);
    m_[1] = std::abs(uz * vx) + std::abs(ux * vz);
    m_[2] = std::abs(ux * vy) + std::abs(uy * vx);
  }
  CGAL::Sign operator()(const K::Point_3& a, const K::Point_3& b) const {
    const double dx = a.x() - b.x(), dy = a.y() - b.y(), dz = a.z() - b.z();
    const double det = dx * n_[0] + dy * n_[1] + dz * n_[2];
    const double terms = std::abs(dx) * m_[0] + std::abs(dy) * m_[1] + std::abs(dz) * m_[2];
    if (det > 1e-14 * terms) return CGAL::POSITIVE;
    if (det < -1e-14 * terms) return CGAL::NEGATIVE;
    if (terms == 0) return CGAL::ZERO;
    using E = CGAL::Mpzf;
    const E eux = E(q_.x()) - E(p_.x()), euy = E(q_.y()) - E(p_.y()), euz = E(q_.z()) - E(p_.z());
    const E evx = E(r_.x()) - E(p_.x()), evy = E(r_.y()) - E(p_.y()), evz = E(r_.z()) - E(p_.z());
    const E edx = E(a.x()) - E(b.x()), edy = E(a.y()) - E(b.y()), edz = E(a.z()) - E(b.z());
    const E e = edx * (euy * evz - euz * evy) + edy * (euz * evx - eux * evz) + edz * (eux * evy - euy * evx);
    return e.sign();
  }

 private:
  const K::Point_3 &p_, &q_, &r_;
  double n_[3], m_[3];
};

/// CGAL's hull traits with the two predicates quickhull spends its time in (which side of a facet
/// a point is on; which of two points is farther) evaluated by FacetSide. Same answers, exactly.
struct HullTraits : CGAL::Convex_hull_traits_3<K, HullMesh, CGAL::Tag_true> {
  struct Less_signed_distance_to_plane_3 {
    using result_type = bool;
    bool operator()(const Plane_3& h, const Point_3& s, const Point_3& t) const {
      return FacetSide(h.p(), h.q(), h.r())(s, t) == CGAL::NEGATIVE;
    }
  };
  Less_signed_distance_to_plane_3 less_signed_distance_to_plane_3_object() const { return {}; }
};

// Akl-Toussaint elimination: the points extreme in 26 directions span a polytope inside the hull,
// and a point strictly inside it cannot be a hull vertex. The test is a floating-point orientation
// with a margin above its worst rounding error, so a point is dropped only when it is certainly
// inside; points on or near a face stay. The hull is the same; quickhull sees a fraction of the
// points (most of a piece's surface lies inside its hull).
void dropInteriorPoints(std::vector<K::Point_3>& pts) {
  if (pts.size() < 256) return;
  std::vector<std::size_t> extreme;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        if (dx == 0 && dy == 0 && dz == 0) continue;
        std::size_t best = 0;
        double bestValue = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < pts.size(); ++i) {
          const double v = dx * pts[i].x() + dy * pts[i].y() + dz * pts[i].z();
          if (v > bestValue) bestValue = v, best = i;  // ties: the first point
        }
        extreme.push_back(best);
      }
  std::sort(extreme.begin(), extreme.end());
  extreme.erase(std::unique(extreme.begin(), extreme.end()), extreme.end());
  if (extreme.size() < 4) return;
  std::vector<K::Point_3> corners;
  for (std::size_t i : extreme) corners.push_back(pts[i]);
  CGAL::Surface_mesh<K::Point_3> inner;
  CGAL::convex_hull_3(corners.begin(), corners.end(), inner);
  if (inner.number_of_faces() < 4) return;
  double lo[3] = {pts[0].x(), pts[0].y(), pts[0].z()}, hi[3] = {lo[0], lo[1], lo[2]};
  for (const auto& p : pts)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  // |error| of (b-a)x(c-a).(p-a) is below ~16 eps |b-a||c-a||p-a| <= 16 eps (2 size)^3: 1e-12 size^3 is far above it.
  const double margin = 1e-12 * size * size * size;
  struct Facet {
    double a[3], n[3];
  };
  std::vector<Facet> facets;
  for (auto f : inner.faces()) {
    auto h = inner.halfedge(f);
    const auto& a = inner.point(inner.source(h));
    const auto& b = inner.point(inner.target(h));
    const auto& c = inner.point(inner.target(inner.next(h)));
    const double u[3] = {b.x() - a.x(), b.y() - a.y(), b.z() - a.z()};
    const double v[3] = {c.x() - a.x(), c.y() - a.y(), c.z() - a.z()};
    facets.push_back({{a.x(), a.y(), a.z()},
                      {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}});
  }
  // Outward normals (CGAL's orientation), checked: the corners' centroid must be inside every facet.
  double centre[3] = {0, 0, 0};
  for (const auto& c : corners)
    for (int k = 0; k < 3; ++k) centre[k] += c[k] / static_cast<double>(corners.size());
  for (const Facet& f : facets)
    if ((centre[0] - f.a[0]) * f.n[0] + (centre[1] - f.a[1]) * f.n[1] + (centre[2] - f.a[2]) * f.n[2] >= 0) return;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& p = pts[i];
    bool inside = true;
    for (const Facet& f : facets) {
      const double s = (p.x() - f.a[0]) * f.n[0] + (p.y() - f.a[1]) * f.n[1] + (p.z() - f.a[2]) * f.n[2];
      if (s > -margin) {  // outward normals: negative is inside
        inside = false;
        break;
      }
    }
    if (!inside) pts[kept++] = p;
  }
  pts.resize(kept);
}

}  // namespace
}  // namespace acd

namespace CGAL::Convex_hull_3::internal {
/// Quickhull's side-of-facet test for HullTraits (see FacetSide).
template <>
class Is_on_positive_side_of_plane_3<acd::HullTraits, boost::false_type> {
  const acd::K::Point_3& p;
  acd::FacetSide side;

 public:
  using Protector = Protect_FPU_rounding<false>;
  Is_on_positive_side_of_plane_3(const acd::HullTraits&, const acd::K::Point_3& p_, const acd::K::Point_3& q_,
                                 const acd::K::Point_3& r_)
      : p(p_), side(p_, q_, r_) {}
  bool operator()(const acd::K::Point_3& s) const { return side(s, p) == POSITIVE; }
};
}  // namespace CGAL::Convex_hull_3::internal

namespace acd {

ConvexHull convexHull(const std::vector<Vec3>& points) {
  ConvexHull out;
  std::vector<K::Point_3> pts;
  pts.reserve(points.size());
  std::unordered_map<std::array<double, 3>, int, PointHash> index;
  index.reserve(points.size() * 2);
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const Vec3& p = points[i];
    // Unique points only: CGAL 5.5's quickhull can erase a list element twice on duplicates (CGAL issue 6543).
    if (index.emplace(std::array<double, 3>{p.x(), p.y(), p.z()}, i).second) pts.emplace_back(p.x(), p.y(), p.z());
  }
  if (pts.size() < 4) {
    out.degenerate = true;
    return out;
  }
  // Into a Surface_mesh: CGAL 5.5's polygon-soup output of convex_hull_3 is unreliable
  // (different, wrong face counts from run to run on the same points).
  CGAL::get_default_random() = CGAL::Random(0);  // per-thread state: keep the result thread-independent
  dropInteriorPoints(pts);
  HullMesh sm;
  CGAL::convex_hull_3(pts.begin(), pts.end(), sm, HullTraits());
  if (sm.number_of_faces() < 4) {
    out.degenerate = true;
    return out;
  }
  // Canonical output, whatever CGAL's internal order (which follows heap addresses, so it changes
  // with threads): vertices sorted by input index, each planar facet re-triangulated by clipping
  // ears from its lowest-index corner, faces sorted.
  using SM = CGAL::Surface_mesh<K::Point_3>;
  std::vector<int> src(sm.number_of_vertices() + sm.number_of_removed_vertices(), -1);
  std::vector<int> sorted;
  for (auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    src[v.idx()] = index.at({p.x(), p.y(), p.z()});
    sorted.push_back(src[v.idx()]);
  }
  std::sort(sorted.begin(), sorted.end());
  std::unordered_map<int, int> hullIndex;
  for (int i = 0; i < static_cast<int>(sorted.size()); ++i) {
    hullIndex[sorted[i]] = i;
    out.mesh.vertices.push_back(points[sorted[i]]);
    out.source.push_back(sorted[i]);
  }
  // Facets: faces joined across exactly coplanar edges.
  const int nf = static_cast<int>(sm.number_of_faces() + sm.number_of_removed_faces());
  std::vector<int> group(nf);
  std::iota(group.begin(), group.end(), 0);
  auto root = [&](int f) {
    while (group[f] != f) f = group[f] = group[group[f]];
    return f;
  };
  for (auto h : sm.halfedges()) {
    const auto o = sm.opposite(h);
    if (sm.is_border(h) || sm.is_border(o)) continue;
    const auto& p = sm.point(sm.source(h));
    const auto& q = sm.point(sm.target(h));
    const auto& r = sm.point(sm.target(sm.next(h)));
    const auto& t = sm.point(sm.target(sm.next(o)));
    if (CGAL::coplanar(p, q, r, t)) group[root(static_cast<int>(sm.face(h)))] = root(static_cast<int>(sm.face(o)));
  }
  std::unordered_map<int, std::unordered_map<int, int>> ringNext;  // facet -> (source -> next source)
  for (auto h : sm.halfedges()) {
    const auto o = sm.opposite(h);
    if (sm.is_border(h)) continue;
    const int g = root(static_cast<int>(sm.face(h)));
    if (!sm.is_border(o) && root(static_cast<int>(sm.face(o))) == g) continue;
    ringNext[g][src[sm.source(h).idx()]] = src[sm.target(h).idx()];
  }
  for (auto& [g, next] : ringNext) {
    int first = std::numeric_limits<int>::max();
    for (const auto& [a, b] : next) first = std::min(first, a);
    std::vector<int> ring{first};
    for (int v = next.at(first); v != first && ring.size() <= next.size(); v = next.at(v)) ring.push_back(v);
    auto pt = [&](int v) { return K::Point_3(points[v].x(), points[v].y(), points[v].z()); };
    // Ear clipping: on a convex polygon every corner that is not collinear with its neighbours is an
    // ear. Clip the fattest ear first (largest area, ties to the earlier corner) so that no sliver
    // triangles with meaningless normals are made.
    while (ring.size() > 3) {
      std::size_t ear = ring.size();
      double fattest = -1.0;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const int a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
        if (CGAL::collinear(pt(a), pt(b), pt(c))) continue;
        const double area = (points[b] - points[a]).cross(points[c] - points[a]).norm();
        if (area > fattest) fattest = area, ear = i;
      }
      if (ear == ring.size()) break;  // only collinear points left: nothing with area to add
      const std::size_t prev = (ear + ring.size() - 1) % ring.size(), nextI = (ear + 1) % ring.size();
      out.mesh.faces.push_back({hullIndex.at(ring[prev]), hullIndex.at(ring[ear]), hullIndex.at(ring[nextI])});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(ear));
    }
    if (ring.size() == 3 && !CGAL::collinear(pt(ring[0]), pt(ring[1]), pt(ring[2])))
      out.mesh.faces.push_back({hullIndex.at(ring[0]), hullIndex.at(ring[1]), hullIndex.at(ring[2])});
  }
  for (Face& f : out.mesh.faces) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(out.mesh.faces.begin(), out.mesh.faces.end());
  (void)sizeof(SM);
  const double volume = signedVolume(out.mesh);
  const double extent = boundingBox(out.mesh).size().maxCoeff();
  if (std::abs(volume) <= 1e-14 * extent * extent * extent) {  // coplanar input: a flat, two-sided "hull"
    out = ConvexHull{};
    out.degenerate = true;
    return out;
  }
  if (volume < 0)
    for (Face& f : out.mesh.faces) std::swap(f[1], f[2]);
  return out;
}

}  // namespace acd
