// Alpha wrapping and the surface distance that measures it (acd/algo/alpha_wrap.hpp).
#include <acd/algo/alpha_wrap.hpp>
#include <acd/algo/inside.hpp>
#include <acd/algo/stopwatch.hpp>

#include <acd/algo/surface_mesh_copy.hpp>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <limits>
#include <random>

namespace acd {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point toPoint(const Vec3& p) { return Point(p.x(), p.y(), p.z()); }

std::vector<Triangle> nonDegenerateTriangles(const TriMesh& m) {
  std::vector<Triangle> out;
  out.reserve(m.faces.size());
  for (const Face& f : m.faces) {
    Triangle t(toPoint(m.vertices[f[0]]), toPoint(m.vertices[f[1]]), toPoint(m.vertices[f[2]]));
    if (!t.is_degenerate()) out.push_back(t);
  }
  return out;
}

/// Vertices (strided down to `samples`) and `samples` area-weighted points, from a fixed seed.
std::vector<Vec3> surfacePoints(const TriMesh& m, int samples) {
  std::vector<Vec3> out;
  const std::size_t stride = std::max<std::size_t>(1, m.vertices.size() / std::max(1, samples));
  for (std::size_t v = 0; v < m.vertices.size(); v += stride) out.push_back(m.vertices[v]);
  std::vector<double> cumulative;
  cumulative.reserve(m.faces.size());
  double total = 0.0;
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) cumulative.push_back(total += faceNormal(m, f).norm());
  if (total <= 0.0) return out;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < samples; ++i) {
    const std::size_t f = std::min<std::size_t>(
        std::lower_bound(cumulative.begin(), cumulative.end(), uni(rng) * total) - cumulative.begin(),
        cumulative.size() - 1);
    double s = uni(rng), t = uni(rng);
    if (s + t > 1.0) s = 1.0 - s, t = 1.0 - t;
    const Face& tri = m.faces[f];
    const Vec3 &a = m.vertices[tri[0]], &b = m.vertices[tri[1]], &c = m.vertices[tri[2]];
    out.push_back(a + s * (b - a) + t * (c - a));
  }
  return out;
}

/// Largest distance from the points to the surface in `tree`.
double oneSided(const std::vector<Vec3>& points, const Tree& tree) {
  std::vector<double> d(points.size(), 0.0);
  tbb::parallel_for(std::size_t(0), points.size(), [&](std::size_t i) {
    d[i] = std::sqrt(tree.squared_distance(toPoint(points[i])));
  });
  return d.empty() ? 0.0 : *std::max_element(d.begin(), d.end());
}

}  // namespace

WrapParameters wrapParametersFor(double tau) {
  WrapParameters p;
  p.offset = tau / 10.0;
  p.alpha = std::max(tau, 0.02);
  return p;
}

Wrap alphaWrap(const TriMesh& soup, double alpha, double offset) {
  const auto start = acd::Clock::now();
  Wrap w;
  if (soup.faces.empty() || !(alpha > 0.0) || !(offset > 0.0)) {
    w.status = Status::error(StatusCode::InvalidParameter, "alpha wrap needs faces and positive alpha and offset");
    return w;
  }
  try {
    std::vector<Point> points;
    points.reserve(soup.vertices.size());
    for (const Vec3& p : soup.vertices) points.push_back(toPoint(p));
    // Only triangles with an area, as CGAL's oracle keeps them: with none left its tree is empty
    // and the wrap reads the box of nothing (undefined behaviour).
    std::vector<std::array<std::size_t, 3>> faces;
    faces.reserve(soup.faces.size());
    for (const Face& f : soup.faces)
      if (!CGAL::collinear(points[f[0]], points[f[1]], points[f[2]]))
        faces.push_back({std::size_t(f[0]), std::size_t(f[1]), std::size_t(f[2])});
    if (faces.empty()) {
      w.status = Status::error(StatusCode::InvalidParameter, "alpha wrap needs a face with an area (every face is flat)");
      return w;
    }
    CGAL::Surface_mesh<Point> wrap;
    CGAL::alpha_wrap_3(points, faces, alpha, offset, wrap);
    wrap.collect_garbage();
    w.mesh = copyFromSurfaceMesh(wrap);
  } catch (const std::exception& e) {
    w.mesh = TriMesh{};
    w.status = Status::error(StatusCode::InternalError, std::string("alpha wrap failed: ") + e.what());
    return w;
  }
  w.status = w.mesh.faces.empty() ? Status::error(StatusCode::InternalError, "alpha wrap produced an empty surface")
                                  : Status::success();
  w.seconds = acd::secondsSince(start);
  return w;
}

SurfaceDistance surfaceDistance(const TriMesh& a, const TriMesh& b, int samples) {
  SurfaceDistance d;
  const std::vector<Triangle> ta = nonDegenerateTriangles(a), tb = nonDegenerateTriangles(b);
  if (ta.empty() || tb.empty()) {
    d.aToB = d.bToA = std::numeric_limits<double>::infinity();
    return d;
  }
  Tree treeA(ta.begin(), ta.end()), treeB(tb.begin(), tb.end());
  treeA.accelerate_distance_queries();
  treeB.accelerate_distance_queries();
  d.aToB = oneSided(surfacePoints(a, samples), treeB);
  d.bToA = oneSided(surfacePoints(b, samples), treeA);
  return d;
}

double distanceOutside(const TriMesh& a, const TriMesh& solid, int samples) {
  const std::vector<Triangle> t = nonDegenerateTriangles(solid);
  if (t.empty()) return std::numeric_limits<double>::infinity();
  Tree tree(t.begin(), t.end());
  tree.accelerate_distance_queries();
  const InsideTest inside(solid);
  std::vector<Vec3> outside;
  for (const Vec3& p : surfacePoints(a, samples))
    if (!inside.inside(p)) outside.push_back(p);
  return oneSided(outside, tree);
}

double hausdorffDistance(const TriMesh& a, const TriMesh& b, int samples) {
  return surfaceDistance(a, b, samples).hausdorff();
}

}  // namespace acd
