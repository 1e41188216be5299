// Simplified hull regions by supporting planes; see hull_simplify.hpp.
#include "hull_simplify.hpp"

#include "separation.hpp"

#include <acd/algo/convex_polytope.hpp>
#include <acd/algo/hull_vertex_cap.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <utility>

namespace tetmesh {

namespace {

using acd::ConvexPolytope;
using acd::HalfSpace;
using acd::TriMesh;

struct RegionSetup {
  const TriMesh* hull = nullptr;
  std::vector<HalfSpace> keep;        // planes to the neighbours, oriented to keep this side
  std::vector<Vec3> facetNormals;     // the hull's own
  double margin = 0.0;                // supporting planes are pushed out by this much
};

/// The region of one hull: its vertex-capped polytope within the planes to its neighbours.
ConvexPolytope buildRegion(const RegionSetup& s, int maxCorners, double eps, double minEdge, bool& reached) {
  acd::VertexCapOptions o;
  o.maxVertices = maxCorners;
  o.eps = eps;
  o.minEdge = minEdge;
  o.margin = s.margin;
  o.keep = s.keep;
  return acd::capVertices(*s.hull, s.facetNormals, o, reached);
}

/// Separating-axis gap between two regions (with their corners) over their face normals (< 0: they overlap).
double regionGap(const ConvexPolytope& a, const std::vector<Vec3>& ca, const ConvexPolytope& b,
                 const std::vector<Vec3>& cb) {
  double gap = -std::numeric_limits<double>::infinity();
  for (const ConvexPolytope::Face& f : a.faces()) gap = std::max(gap, minAlong(cb, f.normal) - maxAlong(ca, f.normal));
  for (const ConvexPolytope::Face& f : b.faces()) gap = std::max(gap, minAlong(ca, f.normal) - maxAlong(cb, f.normal));
  return gap;
}

bool boxesMeet(const acd::Box3& a, const acd::Box3& b, double tol) {
  return !((a.lo.array() - tol > b.hi.array()).any() || (b.lo.array() - tol > a.hi.array()).any());
}

acd::Box3 boxOf(const std::vector<Vec3>& pts) {
  acd::Box3 b;
  b.lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  b.hi = -b.lo;
  for (const Vec3& p : pts) b.lo = b.lo.cwiseMin(p), b.hi = b.hi.cwiseMax(p);
  return b;
}

}  // namespace

SimplifiedHulls simplifyHulls(const std::vector<TriMesh>& hulls, const HullSimplifyOptions& options) {
  SimplifiedHulls out;
  const int n = static_cast<int>(hulls.size());
  if (n == 0) return out;
  std::vector<acd::Box3> boxes(n);
  acd::Box3 all = acd::boundingBox(hulls[0]);
  for (int i = 0; i < n; ++i) {
    boxes[i] = acd::boundingBox(hulls[i]);
    all.lo = all.lo.cwiseMin(boxes[i].lo), all.hi = all.hi.cwiseMax(boxes[i].hi);
  }
  const double scale = 0.5 * all.size().norm();
  const double tol = options.tolerance * scale, minEdge = options.minEdge * scale, margin = options.margin * scale;

  std::vector<std::vector<Vec3>> normals(n);
  std::vector<RegionSetup> setup(n);
  for (int i = 0; i < n; ++i) {
    normals[i] = uniqueFacetNormals(hulls[i]);
    setup[i].hull = &hulls[i];
    setup[i].facetNormals = normals[i];
    // Neighbours share the vertices of their cut section, so their supporting planes often pass
    // through the same point; pushed out by different margins, their faces stay apart instead
    // of nearly coinciding (near-coincident faces make slivers and trip TetGen).
    setup[i].margin = margin * (1.0 + std::fmod(0.6180339887 * (i + 1), 1.0));
  }

  // Planes between pairs, shared when they agree (the two sides of one cut lie on one plane).
  std::vector<HalfSpace> planes;
  std::set<std::pair<int, int>> separated;
  auto separate = [&](int i, int j, const Contact& ct) {
    if (!separated.insert({i, j}).second) return;
    if (ct.gap < -tol) ++out.overlappingHulls;
    HalfSpace h{ct.normal, ct.offset};
    // Any offset between the two hulls separates them. An earlier plane of the same direction
    // whose offset lies in that gap is reused: two parallel planes a hair apart would leave a
    // sliver of a gap between regions.
    const double lo = std::min(ct.offset, maxAlong(hulls[i].vertices, h.normal)) - tol;
    const double hi = std::max(ct.offset, minAlong(hulls[j].vertices, h.normal)) + tol;
    bool shared = false;
    for (const HalfSpace& p : planes) {
      const double dot = p.normal.dot(h.normal);
      if (dot > 1.0 - 1e-9 && p.offset >= lo && p.offset <= hi) h = p, shared = true;
      if (dot < -1.0 + 1e-9 && -p.offset >= lo && -p.offset <= hi) h = {-p.normal, -p.offset}, shared = true;
      if (shared) break;
    }
    if (!shared) planes.push_back(h);
    setup[i].keep.push_back(h);
    setup[j].keep.push_back({-h.normal, -h.offset});
  };
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (!boxesMeet(boxes[i], boxes[j], tol)) continue;
      const Contact ct = findContact(hulls[i].vertices, hulls[j].vertices, normals[i], normals[j], tol);
      if (ct.gap <= tol) separate(i, j, ct);  // touching or overlapping hulls
    }

  std::vector<ConvexPolytope> regions(n);
  out.reached.assign(n, false);
  std::vector<bool> dirty(n, true);
  for (out.rounds = 1; out.rounds <= 10; ++out.rounds) {
    for (int i = 0; i < n; ++i) {
      if (!dirty[i]) continue;
      bool reached = false;
      regions[i] = buildRegion(setup[i], options.maxVertices, tol, minEdge, reached);
      out.reached[i] = reached;
    }
    std::fill(dirty.begin(), dirty.end(), false);
    std::vector<std::vector<Vec3>> corners(n);
    std::vector<acd::Box3> rboxes(n);
    for (int i = 0; i < n; ++i) corners[i] = regions[i].corners(), rboxes[i] = boxOf(corners[i]);
    bool any = false;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j) {
        if (separated.count({i, j}) || !boxesMeet(rboxes[i], rboxes[j], -tol)) continue;
        if (regionGap(regions[i], corners[i], regions[j], corners[j]) >= -tol) continue;
        separate(i, j, findContact(hulls[i].vertices, hulls[j].vertices, normals[i], normals[j], tol));
        dirty[i] = dirty[j] = any = true;
      }
    if (!any) break;
  }
  out.separatingPlanes = static_cast<int>(planes.size());
  out.separatedPairs = static_cast<int>(separated.size());
  for (const ConvexPolytope& r : regions) out.regions.push_back(r.mesh());
  return out;
}

}  // namespace tetmesh
