// The conforming complex of a set of convex hulls; see hull_complex.hpp for the method.
#include "hull_complex.hpp"

#include "separation.hpp"

#include <acd/algo/convex_polytope.hpp>
#include <acd/algo/hull.hpp>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <unordered_map>

namespace tetmesh {

namespace {

using acd::Face;
using acd::TriMesh;

// ------------------------------------------------------------------ welding points
/// Points closer than `tol` are one point (first come keeps its position).
class PointWelder {
 public:
  explicit PointWelder(double tol) : tol_(tol), cell_(2.0 * tol) {}

  int add(const Vec3& p) {
    const std::array<long long, 3> c = cellOf(p);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto it = grid_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == grid_.end()) continue;
          for (int id : it->second)
            if ((points_[id] - p).norm() <= tol_) return id;
        }
    const int id = static_cast<int>(points_.size());
    points_.push_back(p);
    grid_[key(c)].push_back(id);
    return id;
  }

  const std::vector<Vec3>& points() const { return points_; }

 private:
  std::array<long long, 3> cellOf(const Vec3& p) const {
    return {static_cast<long long>(std::floor(p.x() / cell_)), static_cast<long long>(std::floor(p.y() / cell_)),
            static_cast<long long>(std::floor(p.z() / cell_))};
  }
  static std::uint64_t key(const std::array<long long, 3>& c) {
    std::uint64_t h = 1469598103934665603ull;
    for (long long v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
    return h;
  }

  double tol_, cell_;
  std::vector<Vec3> points_;
  std::unordered_map<std::uint64_t, std::vector<int>> grid_;
};

// ------------------------------------------------------------------ planes
/// A contact plane n . x = c (|n| = 1): libacd's half-space type, whose plane it is.
using ContactPlane = acd::HalfSpace;

/// A region stays where side * (n . x - c) <= 0 for this plane.
struct SideConstraint {
  int plane = -1;
  double side = 1.0;
};

/// Closest point to p on the intersection of the given planes (1 to 3 of them, independent).
Vec3 projectOnto(const Vec3& p, const std::vector<const ContactPlane*>& planes) {
  std::vector<const ContactPlane*> use;
  for (const ContactPlane* q : planes) {
    // Keep only planes independent enough of those already used.
    std::vector<const ContactPlane*> trial = use;
    trial.push_back(q);
    Eigen::MatrixXd N(trial.size(), 3);
    for (std::size_t r = 0; r < trial.size(); ++r) N.row(r) = trial[r]->normal.transpose();
    const Eigen::MatrixXd G = N * N.transpose();
    if (G.determinant() > 1e-6) use = trial;
    if (use.size() == 3) break;
  }
  if (use.empty()) return p;
  Eigen::MatrixXd N(use.size(), 3);
  Eigen::VectorXd r(use.size());
  for (std::size_t k = 0; k < use.size(); ++k) {
    N.row(k) = use[k]->normal.transpose();
    r(k) = use[k]->distance(p);
  }
  const Eigen::VectorXd lambda = (N * N.transpose()).ldlt().solve(r);
  return p - N.transpose() * lambda;
}

/// Keeps the part of the convex hull of `pts` where side * (n . x - c) <= tol.
std::vector<Vec3> clipConvex(const std::vector<Vec3>& pts, const ContactPlane& plane, double side, double tol,
                             double& removedVolume) {
  const acd::ConvexHull hull = acd::convexHull(pts);
  if (hull.degenerate || hull.mesh.empty()) return {};
  const TriMesh& m = hull.mesh;
  std::vector<double> d(m.vertices.size());
  bool any = false;
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    d[v] = side * plane.distance(m.vertices[v]);
    any = any || d[v] > tol;
  }
  if (!any) return m.vertices;
  std::vector<Vec3> out;
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    if (d[v] <= tol) out.push_back(m.vertices[v]);
  std::set<std::uint64_t> edges;
  for (const Face& f : m.faces)
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      if (!edges.insert(acd::edgeKey(a, b)).second) continue;
      if ((d[a] < -tol && d[b] > tol) || (d[b] < -tol && d[a] > tol)) {
        const double t = d[a] / (d[a] - d[b]);
        out.push_back(m.vertices[a] + t * (m.vertices[b] - m.vertices[a]));
      }
    }
  const double before = acd::signedVolume(m);
  const acd::ConvexHull kept = acd::convexHull(out);
  removedVolume += before - (kept.degenerate ? 0.0 : acd::signedVolume(kept.mesh));
  return kept.degenerate ? std::vector<Vec3>{} : out;
}

// ------------------------------------------------------------------ overlay on one plane
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
struct VertexInfo {
  int id = -1;  // global point; -1 for points the triangulation made (constraint crossings)
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_triangulation_plus_2<
    CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>>;

struct PlaneFrame {
  Vec3 origin, u, v;
  explicit PlaneFrame(const ContactPlane& p) {
    origin = p.offset * p.normal;
    const Vec3 a = std::abs(p.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    u = p.normal.cross(a).normalized();
    v = p.normal.cross(u);
  }
  K::Point_2 to2(const Vec3& x) const { return {(x - origin).dot(u), (x - origin).dot(v)}; }
  Vec3 to3(const K::Point_2& q) const { return origin + q.x() * u + q.y() * v; }
};

bool insideTriangle2(const K::Point_2& p, const K::Point_2& a, const K::Point_2& b, const K::Point_2& c) {
  const auto o1 = CGAL::orientation(a, b, p), o2 = CGAL::orientation(b, c, p), o3 = CGAL::orientation(c, a, p);
  const bool hasNeg = o1 == CGAL::NEGATIVE || o2 == CGAL::NEGATIVE || o3 == CGAL::NEGATIVE;
  const bool hasPos = o1 == CGAL::POSITIVE || o2 == CGAL::POSITIVE || o3 == CGAL::POSITIVE;
  return !(hasNeg && hasPos);
}

/// Distance from p to segment ab and the parameter of its projection.
double segmentDistance(const Vec3& p, const Vec3& a, const Vec3& b, double& t) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  t = len2 > 0 ? (p - a).dot(ab) / len2 : 0.0;
  const double tc = std::clamp(t, 0.0, 1.0);
  return (a + tc * ab - p).norm();
}

/// Inserts into every facet edge the points of the complex that lie on it (within `tol`), and
/// drops facets thinner than `tol` (three nearly collinear points the overlay can leave).
/// TetGen needs both: a point on a segment that is not a vertex of it stops its recovery.
void resolveTJunctions(Plc& plc, double tol) {
  const std::vector<Vec3>& P = plc.points;
  std::vector<int> byX(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) byX[i] = static_cast<int>(i);
  std::sort(byX.begin(), byX.end(), [&](int a, int b) { return P[a].x() < P[b].x(); });
  std::map<std::uint64_t, std::vector<int>> onEdge;
  auto pointsOn = [&](int a0, int b0) -> const std::vector<int>& {
    const int a = std::min(a0, b0), b = std::max(a0, b0);  // cached in this direction
    const std::uint64_t key = acd::edgeKey(a, b);
    auto it = onEdge.find(key);
    if (it != onEdge.end()) return it->second;
    std::vector<int>& found = onEdge[key];
    const Vec3 lo = P[a].cwiseMin(P[b]) - Vec3::Constant(tol), hi = P[a].cwiseMax(P[b]) + Vec3::Constant(tol);
    auto first = std::lower_bound(byX.begin(), byX.end(), lo.x(), [&](int i, double x) { return P[i].x() < x; });
    for (auto it2 = first; it2 != byX.end() && P[*it2].x() <= hi.x(); ++it2) {
      const int w = *it2;
      if (w == a || w == b || (P[w].array() < lo.array()).any() || (P[w].array() > hi.array()).any()) continue;
      double t = 0;
      if (segmentDistance(P[w], P[a], P[b], t) <= tol && t > 0 && t < 1) found.push_back(w);
    }
    const Vec3 d = P[b] - P[a];
    std::sort(found.begin(), found.end(), [&](int x, int y) { return (P[x] - P[a]).dot(d) < (P[y] - P[a]).dot(d); });
    return found;
  };
  std::vector<Plc::Facet> kept;
  for (const Plc::Facet& f : plc.facets) {
    // Thin facets go: their long edge is split by their third point in the neighbouring facet.
    Vec3 area = Vec3::Zero();
    double longest = 0;
    const int m = static_cast<int>(f.polygon.size());
    for (int k = 0; k < m; ++k) {
      const Vec3& a = P[f.polygon[k]];
      const Vec3& b = P[f.polygon[(k + 1) % m]];
      area += a.cross(b);
      longest = std::max(longest, (b - a).norm());
    }
    if (!(area.norm() > 2.0 * tol * longest)) continue;
    Plc::Facet g;
    g.marker = f.marker;
    for (int k = 0; k < m; ++k) {
      const int a = f.polygon[k], b = f.polygon[(k + 1) % m];
      g.polygon.push_back(a);
      const std::vector<int>& in = pointsOn(a, b);
      // Keep the order from a to b (the cache stores it for the smaller index first).
      if (a < b)
        g.polygon.insert(g.polygon.end(), in.begin(), in.end());
      else
        g.polygon.insert(g.polygon.end(), in.rbegin(), in.rend());
    }
    kept.push_back(std::move(g));
  }
  plc.facets = std::move(kept);
}

/// Splits every facet with more than three corners into triangles (constrained Delaunay in its
/// plane), dropping the slivers that collinear corners make. Polygons here are triangles or
/// faces with points inserted on their edges; TetGen 1.5 inserts such a point into its own
/// triangulation of the facet, and when rounding puts it a hair outside, its segment
/// recovery walks off the facet and aborts (`sscoutsegment`). Triangles avoid that.
void splitIntoTriangles(Plc& plc) {
  std::vector<Plc::Facet> out;
  for (const Plc::Facet& f : plc.facets) {
    const int m = static_cast<int>(f.polygon.size());
    if (m <= 3) {
      out.push_back(f);
      continue;
    }
    Vec3 normal = Vec3::Zero();
    for (int k = 0; k < m; ++k) normal += plc.points[f.polygon[k]].cross(plc.points[f.polygon[(k + 1) % m]]);
    ContactPlane plane{normal.normalized(), 0.0};
    plane.offset = plane.normal.dot(plc.points[f.polygon[0]]);
    const PlaneFrame frame(plane);
    Cdt cdt;
    std::vector<Cdt::Vertex_handle> vh;
    for (int id : f.polygon) {
      Cdt::Vertex_handle h = cdt.insert(frame.to2(plc.points[id]));
      if (h->info().id < 0) h->info().id = id;
      vh.push_back(h);
    }
    for (int k = 0; k < m; ++k)
      if (vh[k] != vh[(k + 1) % m]) cdt.insert_constraint(vh[k], vh[(k + 1) % m]);
    double longest = 0;
    for (int k = 0; k < m; ++k)
      longest = std::max(longest, (plc.points[f.polygon[k]] - plc.points[f.polygon[(k + 1) % m]]).norm());
    // Inside the polygon: faces reached from outside across an odd number of its edges (the
    // triangulation covers the convex hull of the corners, more than a non-convex polygon).
    std::set<Cdt::Face_handle> inside, outside{cdt.infinite_face()};
    std::vector<std::pair<Cdt::Face_handle, bool>> stack{{cdt.infinite_face(), false}};
    while (!stack.empty()) {
      const auto [fh, in] = stack.back();
      stack.pop_back();
      for (int e = 0; e < 3; ++e) {
        const Cdt::Face_handle next = fh->neighbor(e);
        const bool nextIn = cdt.is_constrained({fh, e}) ? !in : in;
        if (inside.count(next) || outside.count(next)) continue;
        (nextIn ? inside : outside).insert(next);
        stack.push_back({next, nextIn});
      }
    }
    for (auto t = cdt.finite_faces_begin(); t != cdt.finite_faces_end(); ++t) {  // in a fixed order
      if (!inside.count(t)) continue;
      const int a = t->vertex(0)->info().id, b = t->vertex(1)->info().id, c = t->vertex(2)->info().id;
      if (a < 0 || b < 0 || c < 0 || a == b || b == c || a == c) continue;
      const Vec3 area = (plc.points[b] - plc.points[a]).cross(plc.points[c] - plc.points[a]);
      if (!(area.norm() > 1e-9 * longest * longest)) continue;  // collinear corners
      // Keep the triangle's orientation that of the polygon.
      if (area.dot(normal) > 0)
        out.push_back({{a, b, c}, f.marker});
      else
        out.push_back({{a, c, b}, f.marker});
    }
  }
  plc.facets = std::move(out);
}

/// The constraints and points of one contact plane's overlay.
struct PlaneItems {
  std::vector<std::pair<int, int>> edges;
  std::vector<int> points;
};

/// What the steps of buildHullComplex share: the hulls, the tolerance, the contact planes and
/// which side of them each region keeps, the welded points and the triangles of each region.
struct ComplexBuild {
  ComplexBuild(const std::vector<TriMesh>& h, double tolerance, double closedGap)
      : hulls(h),
        n(static_cast<int>(h.size())),
        tol(tolerance),
        gap(std::max(tolerance, closedGap)),
        welder(tolerance) {}

  const std::vector<TriMesh>& hulls;
  int n;
  double tol;
  double gap;  // hulls apart by less are in contact: the gap is closed
  std::vector<ContactPlane> planes;
  std::vector<double> reach;                             // per plane: vertices this near go onto it
  std::vector<std::vector<SideConstraint>> constraints;  // per region
  PointWelder welder;
  std::vector<std::vector<Face>> regionTris;              // per region, in global numbering
  std::vector<std::vector<std::vector<Face>>> planeTris;  // per plane, per region: its face on the plane
  std::vector<std::vector<Face>> freeTris;                // per region: the rest
  std::vector<std::vector<int>> touching;                 // per region: the planes it touches
  std::vector<PlaneItems> items;                          // per plane
  std::map<std::uint64_t, std::set<int>> splits;          // edge -> points strictly inside it
  std::vector<Plc::Facet> overlayFacets;

  int planeCount() const { return static_cast<int>(planes.size()); }
  // Welding moves a point by up to tol: a point of a contact face may now be 2 tol off its plane.
  bool onPlane(int id, int k) const { return std::abs(planes[k].distance(welder.points()[id])) <= 3 * tol; }
};

/// The hulls' bounding boxes and the box of them all; an error if a hull has no volume.
acd::Status boxesOf(const std::vector<TriMesh>& hulls, std::vector<acd::Box3>& boxes, acd::Box3& box) {
  const int n = static_cast<int>(hulls.size());
  box.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  box.hi = -box.lo;
  boxes.resize(n);
  for (int i = 0; i < n; ++i) {
    if (hulls[i].faces.size() < 4 || !(acd::signedVolume(hulls[i]) > 0))
      return acd::Status::error(acd::StatusCode::DegenerateFace,
                                "hull " + std::to_string(i + 1) + " is not a solid (no volume)");
    boxes[i] = acd::boundingBox(hulls[i]);
    box.lo = box.lo.cwiseMin(boxes[i].lo);
    box.hi = box.hi.cwiseMax(boxes[i].hi);
  }
  return {};
}

/// Step 1: contacts between pairs of hulls, on clustered planes; each region keeps one side.
void findContacts(ComplexBuild& b, const std::vector<acd::Box3>& boxes, HullComplex& out) {
  const std::vector<TriMesh>& hulls = b.hulls;
  const int n = b.n;
  const double tol = b.tol;
  std::vector<ContactPlane>& planes = b.planes;
  std::vector<std::vector<SideConstraint>>& constraints = b.constraints;
  constraints.resize(n);
  std::vector<std::vector<Vec3>> normals(n);
  for (int i = 0; i < n; ++i) normals[i] = uniqueFacetNormals(hulls[i]);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const bool apart =
          ((boxes[i].lo.array() - b.gap > boxes[j].hi.array()) || (boxes[j].lo.array() - b.gap > boxes[i].hi.array()))
              .any();
      if (apart) continue;
      const Contact ct = findContact(hulls[i].vertices, hulls[j].vertices, normals[i], normals[j], tol);
      if (ct.gap > b.gap) continue;
      // A gap narrower than b.gap is closed: both sides go onto the plane half way across it.
      const double halfGap = std::max(0.0, 0.5 * ct.gap);
      const Vec3 best = ct.normal;
      const double depth = maxAlong(hulls[i].vertices, best) - minAlong(hulls[j].vertices, best);
      ++out.contactPairs;
      if (depth > tol) {
        ++out.overlappingPairs;
        out.maxOverlapDepth = std::max(out.maxOverlapDepth, depth);
      }
      ContactPlane pl{best, ct.offset};
      // The same plane as an earlier contact (possibly facing the other way)? Judged by the
      // points in contact, not by the normals: a normal from a thin hull facet is inaccurate,
      // and a plane found twice would be overlaid twice (overlapping facets).
      std::vector<Vec3> touching;
      for (const Vec3& p : hulls[i].vertices)
        if (std::abs(pl.distance(p)) <= 2 * tol + halfGap) touching.push_back(p);
      for (const Vec3& p : hulls[j].vertices)
        if (std::abs(pl.distance(p)) <= 2 * tol + halfGap) touching.push_back(p);
      int id = -1;
      double sideI = 1.0;
      for (int k = 0; k < static_cast<int>(planes.size()) && id < 0; ++k) {
        const double dot = planes[k].normal.dot(pl.normal);
        if (std::abs(dot) < 1.0 - 1e-6) continue;
        bool same = !touching.empty();
        for (const Vec3& p : touching) same = same && std::abs(planes[k].distance(p)) <= 10 * tol + halfGap;
        if (same) id = k, sideI = dot > 0 ? 1.0 : -1.0;
      }
      if (id < 0) {
        id = static_cast<int>(planes.size());
        planes.push_back(pl);
        b.reach.push_back(tol);
      }
      b.reach[id] = std::max(b.reach[id], tol + halfGap);
      auto addConstraint = [&](int r, double side) {
        for (const SideConstraint& s : constraints[r])
          if (s.plane == id) return;
        constraints[r].push_back({id, side});
      };
      addConstraint(i, sideI);
      addConstraint(j, -sideI);
    }
  out.contactPlanes = static_cast<int>(planes.size());
}

/// Step 2: the regions — each hull clipped where it overlaps, near-plane vertices snapped onto their planes.
void clipRegions(const ComplexBuild& b, HullComplex& out) {
  const std::vector<TriMesh>& hulls = b.hulls;
  const int n = b.n;
  const double tol = b.tol;
  const std::vector<ContactPlane>& planes = b.planes;
  const std::vector<std::vector<SideConstraint>>& constraints = b.constraints;
  out.regions.resize(n);
  out.clippedVolume.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    std::vector<Vec3> pts = hulls[i].vertices;
    for (const SideConstraint& s : constraints[i]) {
      pts = clipConvex(pts, planes[s.plane], s.side, tol, out.clippedVolume[i]);
      if (pts.empty()) break;
    }
    // Onto the planes it is near; then points closer than tol are one, the one on most planes kept
    // (so the faces on contact planes stay on them).
    std::vector<int> onPlanes(pts.size(), 0);
    for (std::size_t q = 0; q < pts.size(); ++q) {
      std::vector<const ContactPlane*> near;
      for (const SideConstraint& s : constraints[i])
        if (std::abs(planes[s.plane].distance(pts[q])) <= b.reach[s.plane]) near.push_back(&planes[s.plane]);
      if (!near.empty()) pts[q] = projectOnto(pts[q], near);
      onPlanes[q] = static_cast<int>(near.size());
    }
    std::vector<int> order(pts.size());
    for (std::size_t q = 0; q < pts.size(); ++q) order[q] = static_cast<int>(q);
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return onPlanes[x] > onPlanes[y]; });
    std::vector<Vec3> kept;
    for (int q : order) {
      bool close = false;
      for (const Vec3& k : kept) close = close || (k - pts[q]).norm() <= tol;
      if (!close) kept.push_back(pts[q]);
    }
    const acd::ConvexHull h = acd::convexHull(kept);
    if (!h.degenerate) out.regions[i] = h.mesh;
  }
}

/// Global points and region triangles in global numbering. Points on more contact planes are
/// welded first, so that they are the ones kept.
void weldRegions(ComplexBuild& b, const HullComplex& out) {
  const int n = b.n;
  const double tol = b.tol;
  const std::vector<ContactPlane>& planes = b.planes;
  const std::vector<std::vector<SideConstraint>>& constraints = b.constraints;
  PointWelder& welder = b.welder;
  std::vector<std::vector<Face>>& regionTris = b.regionTris;
  regionTris.assign(n, {});
  std::vector<std::vector<int>> regionIds(n);
  {
    struct Entry {
      int region, vertex, planes;
    };
    std::vector<Entry> entries;
    for (int i = 0; i < n; ++i) {
      regionIds[i].assign(out.regions[i].vertices.size(), -1);
      for (int v = 0; v < static_cast<int>(out.regions[i].vertices.size()); ++v) {
        int count = 0;
        for (const SideConstraint& s : constraints[i])
          count += std::abs(planes[s.plane].distance(out.regions[i].vertices[v])) <= tol ? 1 : 0;
        entries.push_back({i, v, count});
      }
    }
    std::stable_sort(entries.begin(), entries.end(),
                     [](const Entry& a, const Entry& b) { return a.planes > b.planes; });
    for (const Entry& e : entries) regionIds[e.region][e.vertex] = welder.add(out.regions[e.region].vertices[e.vertex]);
  }
  for (int i = 0; i < n; ++i)
    for (const Face& f : out.regions[i].faces) {
      const Face g{regionIds[i][f[0]], regionIds[i][f[1]], regionIds[i][f[2]]};
      if (g[0] != g[1] && g[1] != g[2] && g[0] != g[2]) regionTris[i].push_back(g);
    }
}

/// Which triangles lie on a contact plane (they go through the overlay), which are free.
/// The planes each region touches: its own contacts first, then any other contact plane it
/// reaches (a face on a plane of other regions' contact must go through that overlay too, or
/// it would be a second facet over the overlay's triangles).
void classifyTriangles(ComplexBuild& b) {
  const int n = b.n, np = b.planeCount();
  const std::vector<ContactPlane>& planes = b.planes;
  const std::vector<std::vector<SideConstraint>>& constraints = b.constraints;
  const std::vector<std::vector<Face>>& regionTris = b.regionTris;
  auto onPlane = [&](int id, int k) { return b.onPlane(id, k); };
  b.planeTris.assign(np, std::vector<std::vector<Face>>(n));
  b.freeTris.assign(n, {});
  b.touching.assign(n, {});
  std::vector<std::vector<std::vector<Face>>>& planeTris = b.planeTris;
  std::vector<std::vector<Face>>& freeTris = b.freeTris;
  std::vector<std::vector<int>>& touching = b.touching;
  for (int i = 0; i < n; ++i) {
    for (const SideConstraint& s : constraints[i]) touching[i].push_back(s.plane);
    for (int k = 0; k < static_cast<int>(planes.size()); ++k) {
      if (std::find(touching[i].begin(), touching[i].end(), k) != touching[i].end()) continue;
      bool reaches = false;
      for (const Face& f : regionTris[i])
        for (int v : f) reaches = reaches || onPlane(v, k);
      if (reaches) touching[i].push_back(k);
    }
  }
  for (int i = 0; i < n; ++i)
    for (const Face& f : regionTris[i]) {
      int on = -1;
      for (int k : touching[i])
        if (onPlane(f[0], k) && onPlane(f[1], k) && onPlane(f[2], k)) {
          on = k;
          break;
        }
      if (on >= 0)
        planeTris[on][i].push_back(f);
      else
        freeTris[i].push_back(f);
    }
}

/// Constraints and points of each plane: boundary edges of each region's face there, and the
/// edges and vertices of regions that touch the plane without a face on it.
void collectPlaneItems(ComplexBuild& b) {
  const int n = b.n, np = b.planeCount();
  const std::vector<std::vector<Face>>& regionTris = b.regionTris;
  const std::vector<std::vector<std::vector<Face>>>& planeTris = b.planeTris;
  const std::vector<std::vector<int>>& touching = b.touching;
  auto onPlane = [&](int id, int k) { return b.onPlane(id, k); };
  b.items.assign(np, {});
  std::vector<PlaneItems>& items = b.items;
  for (int k = 0; k < np; ++k) {
    std::set<int> pts;
    std::set<std::uint64_t> seenEdges;
    for (int i = 0; i < n; ++i) {
      if (std::find(touching[i].begin(), touching[i].end(), k) == touching[i].end()) continue;
      std::map<std::uint64_t, std::pair<int, int>> count;  // edge -> (uses, first a)
      std::map<std::uint64_t, std::pair<int, int>> ends;
      for (const Face& f : planeTris[k][i])
        for (int e = 0; e < 3; ++e) {
          const int a = f[e], b = f[(e + 1) % 3];
          const std::uint64_t key = acd::edgeKey(a, b);
          count[key].first++;
          ends[key] = {a, b};
        }
      for (const auto& [key, c] : count)
        if (c.first == 1 && seenEdges.insert(key).second) items[k].edges.push_back(ends[key]);
      // Lower-dimensional contact: edges and vertices of the region on the plane.
      for (const Face& f : regionTris[i])
        for (int e = 0; e < 3; ++e) {
          const int a = f[e], b = f[(e + 1) % 3];
          if (onPlane(a, k)) pts.insert(a);
          if (onPlane(a, k) && onPlane(b, k) && !count.count(acd::edgeKey(a, b)) &&
              seenEdges.insert(acd::edgeKey(a, b)).second)
            items[k].edges.push_back({a, b});
        }
    }
    for (const auto& e : items[k].edges) pts.insert(e.first), pts.insert(e.second);
    items[k].points.assign(pts.begin(), pts.end());
  }
}

/// One plane of one overlay pass: its constraints triangulated (splitting edges where points
/// of any plane fall on them), the triangles a region's face covers kept as facets. Returns
/// whether a split was added (then another pass is needed).
bool overlayPlane(ComplexBuild& build, int k, std::map<std::array<int, 3>, std::size_t>& emitted, bool changed) {
  const int n = build.n;
  const double tol = build.tol;
  const std::vector<ContactPlane>& planes = build.planes;
  const std::vector<std::vector<std::vector<Face>>>& planeTris = build.planeTris;
  const std::vector<PlaneItems>& items = build.items;
  PointWelder& welder = build.welder;
  std::map<std::uint64_t, std::set<int>>& splits = build.splits;
  std::vector<Plc::Facet>& overlayFacets = build.overlayFacets;
  if (items[k].edges.empty()) return changed;
  const PlaneFrame frame(planes[k]);
  auto P = [&](int id) -> const Vec3& { return welder.points()[id]; };
  // Points of this plane that lie on an edge of it split that edge.
  for (const auto& [a, b] : items[k].edges)
    for (int w : items[k].points) {
      if (w == a || w == b) continue;
      double t = 0;
      if (segmentDistance(P(w), P(a), P(b), t) <= tol && t > 0 && t < 1)
        changed = splits[acd::edgeKey(a, b)].insert(w).second || changed;
    }
  Cdt cdt;
  std::unordered_map<int, Cdt::Vertex_handle> handle;
  auto vertex = [&](int id) {
    auto it = handle.find(id);
    if (it != handle.end()) return it->second;
    Cdt::Vertex_handle vh = cdt.insert(frame.to2(P(id)));
    if (vh->info().id < 0) vh->info().id = id;  // else an equal 2D point: keep the first id
    handle.emplace(id, vh);
    return vh;
  };
  for (int id : items[k].points) vertex(id);
  std::vector<std::pair<std::uint64_t, std::pair<int, int>>> pieces;  // edge -> consecutive points
  std::vector<Cdt::Constraint_id> ids;
  for (const auto& [a, b] : items[k].edges) {
    std::vector<int> chain{a};
    auto it = splits.find(acd::edgeKey(a, b));
    if (it != splits.end()) {
      std::vector<int> inner(it->second.begin(), it->second.end());
      const Vec3 from = P(a), d = P(b) - from;  // (clang cannot capture a structured binding)
      std::sort(inner.begin(), inner.end(), [&](int x, int y) { return (P(x) - from).dot(d) < (P(y) - from).dot(d); });
      chain.insert(chain.end(), inner.begin(), inner.end());
    }
    chain.push_back(b);
    for (std::size_t c = 0; c + 1 < chain.size(); ++c) {
      Cdt::Vertex_handle va = vertex(chain[c]), vb = vertex(chain[c + 1]);
      if (va == vb) continue;
      ids.push_back(cdt.insert_constraint(va, vb));
      pieces.push_back({acd::edgeKey(a, b), {a, b}});
    }
  }
  // Points the triangulation created where constraints cross become global points.
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->info().id < 0) v->info().id = welder.add(frame.to3(v->point()));
  // Every point along a constraint splits the original edge.
  for (std::size_t c = 0; c < ids.size(); ++c) {
    const auto [a, b] = pieces[c].second;
    for (auto v = cdt.vertices_in_constraint_begin(ids[c]); v != cdt.vertices_in_constraint_end(ids[c]); ++v) {
      const int id = (*v)->info().id;
      if (id != a && id != b) changed = splits[pieces[c].first].insert(id).second || changed;
    }
  }
  // Triangles covered by a region's face on the plane become facets.
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const int a = f->vertex(0)->info().id, b = f->vertex(1)->info().id, c = f->vertex(2)->info().id;
    if (a == b || b == c || a == c) continue;
    const K::Point_2 centroid = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    int covered = 0;
    for (int i = 0; i < n; ++i)
      for (const Face& t : planeTris[k][i])
        if (insideTriangle2(centroid, frame.to2(P(t[0])), frame.to2(P(t[1])), frame.to2(P(t[2])))) {
          ++covered;
          break;
        }
    if (covered == 0) continue;
    std::array<int, 3> key{a, b, c};
    std::sort(key.begin(), key.end());
    const int marker = covered >= 2 ? kInterfaceFacet : kBoundaryFacet;
    auto [it, fresh] = emitted.emplace(key, overlayFacets.size());
    if (!fresh) {
      overlayFacets[it->second].marker = std::max(overlayFacets[it->second].marker, marker);
      continue;
    }
    overlayFacets.push_back({{a, b, c}, marker});
  }
  return changed;
}

/// Free triangles, with the points other facets put on their edges, then the whole complex in
/// triangles and one seed per region.
void assemblePlc(ComplexBuild& b, double scale, HullComplex& out) {
  const int n = b.n;
  const double tol = b.tol;
  const std::vector<std::vector<Face>>& freeTris = b.freeTris;
  const std::map<std::uint64_t, std::set<int>>& splits = b.splits;
  const PointWelder& welder = b.welder;
  Plc& plc = out.plc;
  plc.facets = b.overlayFacets;
  for (int i = 0; i < n; ++i)
    for (const Face& f : freeTris[i]) {
      Plc::Facet facet;
      for (int e = 0; e < 3; ++e) {
        const int a = f[e], b = f[(e + 1) % 3];
        facet.polygon.push_back(a);
        auto it = splits.find(acd::edgeKey(a, b));
        if (it == splits.end()) continue;
        std::vector<int> inner(it->second.begin(), it->second.end());
        const Vec3 d = welder.points()[b] - welder.points()[a];
        std::sort(inner.begin(), inner.end(), [&](int x, int y) {
          return (welder.points()[x] - welder.points()[a]).dot(d) < (welder.points()[y] - welder.points()[a]).dot(d);
        });
        facet.polygon.insert(facet.polygon.end(), inner.begin(), inner.end());
      }
      plc.facets.push_back(facet);
    }
  plc.points = welder.points();
  // Only numerically collinear points here: anything coarser was welded above, and dropping a
  // facet thinner than tol could open a hole where two such facets share their long edge.
  resolveTJunctions(plc, std::min(tol, 1e-10 * scale));
  splitIntoTriangles(plc);
  for (const Plc::Facet& f : plc.facets) (f.marker == kInterfaceFacet ? out.interfaceFacets : out.boundaryFacets)++;

  // One seed per region: the mean of its vertices, strictly inside a convex solid.
  for (int i = 0; i < n; ++i) {
    if (out.regions[i].empty()) continue;
    Vec3 seed = Vec3::Zero();
    for (const Vec3& p : out.regions[i].vertices) seed += p;
    seed /= static_cast<double>(out.regions[i].vertices.size());
    plc.regions.push_back({seed, i + 1});
  }
}

}  // namespace

HullComplex buildHullComplex(const std::vector<TriMesh>& hulls, const HullComplexOptions& options) {
  HullComplex out;
  if (hulls.empty()) {
    out.status = acd::Status::error(acd::StatusCode::EmptyMesh, "no hulls to mesh");
    return out;
  }
  // Scale and tolerance.
  acd::Box3 box;
  std::vector<acd::Box3> boxes;
  out.status = boxesOf(hulls, boxes, box);
  if (!out.status.ok()) return out;
  const double scale = 0.5 * box.size().norm();
  ComplexBuild b(hulls, options.tolerance * scale, options.closedGap * scale);

  findContacts(b, boxes, out);  // 1. contacts between pairs, on clustered planes
  clipRegions(b, out);          // 2. regions: overlaps clipped, near-plane vertices snapped
  weldRegions(b, out);
  classifyTriangles(b);
  collectPlaneItems(b);

  // 3. Overlay each plane until no plane adds a point to an edge another plane uses.
  bool changed = true;
  for (int pass = 0; pass < 20 && changed; ++pass) {
    changed = false;
    ++out.overlayPasses;
    b.overlayFacets.clear();
    // A thin triangle along the line where two contact planes meet lies on both, and both
    // overlays make it: it is one facet (an interface if either says so).
    std::map<std::array<int, 3>, std::size_t> emitted;
    for (int k = 0; k < b.planeCount(); ++k) changed = overlayPlane(b, k, emitted, changed);
  }
  if (changed) {
    out.status =
        acd::Status::error(acd::StatusCode::InternalError, "the interfaces between hulls did not settle after " +
                                                               std::to_string(out.overlayPasses) + " overlay passes");
    return out;
  }
  assemblePlc(b, scale, out);
  return out;
}

}  // namespace tetmesh
