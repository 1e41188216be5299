// Hulls with a vertex budget by supporting planes; see hull_vertex_cap.hpp.
#include <acd/algo/hull_vertex_cap.hpp>

#include <acd/algo/hull.hpp>
#include <acd/algo/mass_properties.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

namespace acd {

namespace {

/// Directions to try: the hull's facet normals (one per degree or so) and the 26 directions of
/// a cube's faces, edges and corners, which fit any blob tolerably.
std::vector<Vec3> candidateDirections(const std::vector<Vec3>& facetNormals, const Eigen::Matrix3d& frame) {
  std::vector<Vec3> dirs;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) dirs.push_back(frame * Vec3(x, y, z).normalized());
  const double sameDirection = std::cos(M_PI / 180.0);
  for (const Vec3& u : facetNormals) {
    bool seen = false;
    for (const Vec3& d : dirs)
      if (d.dot(u) > sameDirection) {
        seen = true;
        break;
      }
    if (!seen) dirs.push_back(u);
  }
  return dirs;
}

/// The polytope bounded by the supporting planes of `pts` with these normals (pushed out by
/// `margin`), which must enclose a bounded region: a box around its corners cut by the planes.
ConvexPolytope enclosedBy(const std::vector<Vec3>& pts, const std::vector<Vec3>& normals, double margin, double eps,
                          bool& bounded) {
  std::vector<HalfSpace> planes;
  for (const Vec3& n : normals) planes.push_back({n, maxAlong(pts, n) + margin});
  // Corners: every triple of planes that meets in a point inside all the others.
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  int corners = 0;
  for (std::size_t a = 0; a < planes.size(); ++a)
    for (std::size_t b = a + 1; b < planes.size(); ++b)
      for (std::size_t c = b + 1; c < planes.size(); ++c) {
        Eigen::Matrix3d m;
        m << planes[a].normal.transpose(), planes[b].normal.transpose(), planes[c].normal.transpose();
        if (std::abs(m.determinant()) < 1e-9) continue;
        const Vec3 x = m.partialPivLu().solve(Vec3(planes[a].offset, planes[b].offset, planes[c].offset));
        bool inside = true;
        for (const HalfSpace& h : planes) inside = inside && h.distance(x) <= 1e-9 * (1.0 + x.norm());
        if (inside) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x), ++corners;
      }
  bounded = corners >= 4;
  if (!bounded) return {};
  const Vec3 pad = Vec3::Constant(1e-3 * (hi - lo).norm() + margin);
  ConvexPolytope p = ConvexPolytope::box(lo - pad, hi + pad, eps);
  for (const HalfSpace& h : planes)
    if (p.cutBy(h)) p = p.clipped(h);
  return p;
}

/// For budgets below a box's 8 corners: the smallest enclosing tetrahedron or (K >= 6)
/// triangular prism over a few orientations about the coordinate and principal axes.
ConvexPolytope smallStart(const TriMesh& hull, int maxCorners, double margin, double eps) {
  const std::vector<Vec3>& pts = hull.vertices;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : pts) mean += p;
  mean /= static_cast<double>(pts.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : pts) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
  std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
  for (int k = 0; k < 3; ++k) axes.push_back(es.eigenvectors().col(k).normalized());
  ConvexPolytope best;
  double bestVolume = std::numeric_limits<double>::infinity();
  const double rise = 1.0 / 3.0;  // a regular tetrahedron's side faces, against its base plane
  for (const Vec3& a : axes) {
    const Vec3 u = a.unitOrthogonal(), v = a.cross(u);
    for (int step = 0; step < 6; ++step) {
      const double theta = step * (M_PI / 9.0);  // 0..100 degrees: the shapes repeat every 120
      std::vector<Vec3> side;
      for (int k = 0; k < 3; ++k) {
        const double t = theta + k * (2.0 * M_PI / 3.0);
        side.push_back(std::cos(t) * u + std::sin(t) * v);
      }
      std::vector<std::vector<Vec3>> shapes;
      std::vector<Vec3> tetra = {-a};
      for (const Vec3& s : side) tetra.push_back((std::sqrt(1.0 - rise * rise) * s + rise * a).normalized());
      shapes.push_back(tetra);
      if (maxCorners >= 6) shapes.push_back({a, -a, side[0], side[1], side[2]});
      for (const std::vector<Vec3>& normals : shapes) {
        bool bounded = false;
        ConvexPolytope p = enclosedBy(pts, normals, margin, eps, bounded);
        if (!bounded || p.empty()) continue;
        const double vol = p.volume();
        if (vol < bestVolume && static_cast<int>(p.corners().size()) <= maxCorners) bestVolume = vol, best = std::move(p);
      }
    }
  }
  return best;
}

}  // namespace

ConvexPolytope capVertices(const TriMesh& hull, const std::vector<Vec3>& facetNormals, const VertexCapOptions& o,
                           bool& reached) {
  const int maxCorners = o.maxVertices;
  const double eps = o.eps;
  const Box3 box = boundingBox(hull);
  // A hull within the budget is its own region: its facet planes, unpadded.
  if (static_cast<int>(hull.vertices.size()) <= maxCorners) {
    ConvexPolytope region = ConvexPolytope::box(box.lo, box.hi, eps);
    for (const Vec3& u : facetNormals) {
      const HalfSpace h{u, maxAlong(hull.vertices, u)};
      if (region.cutBy(h)) region = region.clipped(h);
    }
    for (const HalfSpace& h : o.keep)
      if (region.cutBy(h)) region = region.clipped(h);
    reached = static_cast<int>(region.corners().size()) <= maxCorners;
    return region;
  }
  std::vector<HalfSpace> candidates;
  for (const Vec3& u : candidateDirections(facetNormals, o.frame))
    candidates.push_back({u, maxAlong(hull.vertices, u) + o.margin});
  const Vec3 pad = Vec3::Constant(o.margin);
  const bool axisAligned = o.frame.isIdentity(0.0);
  ConvexPolytope region;
  if (maxCorners < 8) {
    region = smallStart(hull, maxCorners, o.margin, eps);
  } else if (axisAligned) {
    region = ConvexPolytope::box(box.lo - pad, box.hi + pad, eps);
  } else {  // the box along the frame's axes
    bool bounded = false;
    std::vector<Vec3> sides;
    for (int k = 0; k < 3; ++k) sides.push_back(o.frame.col(k)), sides.push_back(-o.frame.col(k));
    region = enclosedBy(hull.vertices, sides, o.margin, eps, bounded);
  }
  for (const HalfSpace& h : o.keep)
    if (region.cutBy(h)) region = region.clipped(h);
  reached = false;
  if (region.empty()) return region;
  const double enough = 1e-4 * signedVolume(hull);  // smaller gains are not worth a corner
  const std::size_t nc = candidates.size();
  std::vector<double> bound(nc, std::numeric_limits<double>::infinity());
  std::vector<std::size_t> order(nc);
  double volume = region.volume();
  for (;;) {
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return bound[a] > bound[b]; });
    const double shortest = std::min(o.minEdge, region.shortestEdge());
    double bestGain = enough;
    std::size_t best = nc;
    ConvexPolytope bestRegion;
    for (std::size_t c : order) {
      if (bound[c] <= bestGain) break;  // no later candidate can beat the best one
      const HalfSpace& h = candidates[c];
      if (!region.cutBy(h)) {
        bound[c] = 0.0;
        continue;
      }
      ConvexPolytope cut = region.clipped(h);
      const double gain = volume - cut.volume();
      bound[c] = gain;
      if (gain <= bestGain || cut.empty()) continue;
      if (static_cast<int>(cut.corners().size()) > maxCorners || cut.shortestEdge() < shortest) continue;
      bestGain = gain, best = c, bestRegion = std::move(cut);
    }
    if (best == nc) break;
    region = std::move(bestRegion);
    volume = region.volume();
    bound[best] = 0.0;
  }
  reached = static_cast<int>(region.corners().size()) <= maxCorners;
  return region;
}

CappedHulls capHullVertices(const std::vector<TriMesh>& hulls, const HullCapOptions& options) {
  CappedHulls out;
  if (options.maxVertices < 4) {
    out.status = Status::error(StatusCode::InvalidParameter,
                               "--max-hull-vertices must be at least 4 (a solid needs 4 corners), got " +
                                   std::to_string(options.maxVertices));
    return out;
  }
  if (!(options.minEdge >= 0.0 && options.minEdge < 0.1)) {
    out.status = Status::error(StatusCode::InvalidParameter, "minimum edge must lie in [0, 0.1)");
    return out;
  }
  for (const TriMesh& hull : hulls) {
    const double volume = hull.empty() ? 0.0 : signedVolume(hull);
    TriMesh result = hull;
    const bool within = static_cast<int>(hull.vertices.size()) <= options.maxVertices;
    if (!within && volume > 0.0) {
      const double size = 0.5 * boundingBox(hull).size().norm();
      VertexCapOptions o;
      o.maxVertices = options.maxVertices;
      o.eps = 1e-10 * size;
      o.minEdge = options.minEdge * size;
      // A hair outside the hull: corners computed by clipping carry rounding, and the result
      // must hold every hull vertex however it is evaluated.
      o.margin = 1e-9 * size;
      o.frame = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(massProperties(hull).inertia).eigenvectors();
      bool reached = false;
      const TriMesh capped = capVertices(hull, uniqueFacetNormals(hull), o, reached).mesh();
      if (!capped.empty()) result = capped;
    }
    if (within) ++out.unchanged;
    const int nv = static_cast<int>(result.vertices.size());
    out.reached += nv <= options.maxVertices ? 1 : 0;
    out.vertices.push_back(nv);
    out.hullVolume.push_back(volume);
    out.addedVolume.push_back(result.empty() ? 0.0 : std::max(0.0, signedVolume(result) - volume));
    out.hulls.push_back(std::move(result));
  }
  return out;
}

}  // namespace acd
