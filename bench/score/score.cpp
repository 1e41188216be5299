// acd-score MODEL HULLS.obj: a second evaluator of a set of convex hulls against a closed model,
// sharing no measurement code with libacd (bench/compare_peers.sh reports it beside
// `acd evaluate`). Everything here is CGAL directly: the model is read by CGAL's reader and
// tested with Side_of_triangle_mesh; each hull is rebuilt by convex_hull_3 from its OBJ object's
// vertices and tested against its facets; distances come from AABB trees.
//
// Figures, in the model's normalised units (its minimum enclosing sphere has radius 1):
//   iou                 |model ∩ union| / |model ∪ union|, Monte Carlo in the joint bounding box;
//                       the model's solid is what any of its shells encloses (an assembly's shells overlap);
//                       the open shells enclose where their generalised winding number, summed, is at least 1/2
//   hull_outside_max    largest distance from a hull-surface sample outside the model to the model
//   hull_outside_p99    its 99th percentile over all hull-surface samples (covered ones count 0)
//   model_to_hulls_max  largest distance from a model-surface sample to the union of hulls
//   model_to_hulls_p99
// Output: one JSON object on stdout; a model that is not closed gets null IoU and volumes (its
// shells still have an inside for the hull distances). Exit 2 when a file cannot be read.
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Min_sphere_of_points_d_traits_3.h>
#include <CGAL/Min_sphere_of_spheres_d.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Triangle = K::Triangle_3;
namespace PMP = CGAL::Polygon_mesh_processing;

// A convex hull: its facets (outward) and bounding box. A point is tested against each facet's
// plane in double where the facet is well shaped, and with the exact orientation predicate where
// it is thin (a plane constructed from a thin triangle can point anywhere).
struct Hull {
  CGAL::Bbox_3 box;
  std::vector<Triangle> triangles;
  std::vector<K::Vector_3> normals;  // unit, outward; zero for a thin facet
  std::vector<double> offsets;       // normal · point on the facet
};

[[noreturn]] void refuse(const std::string& message) {
  std::fprintf(stderr, "acd-score: %s\n", message.c_str());
  std::exit(2);
}

// The objects of an OBJ file (`o` or `g` starts one; faces index the file's global vertex list).
std::vector<std::vector<Point>> readObjObjectPoints(const std::string& path) {
  std::ifstream in(path);
  if (!in) refuse(path + ": cannot open");
  std::vector<Point> vertices;
  std::vector<std::vector<int>> used(1);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      double x, y, z;
      if (!(ls >> x >> y >> z)) refuse(path + ": bad vertex line");
      vertices.emplace_back(x, y, z);
    } else if (tag == "o" || tag == "g") {
      if (!used.back().empty()) used.emplace_back();
    } else if (tag == "f") {
      std::string corner;
      while (ls >> corner) {
        const int i = std::atoi(corner.c_str());
        used.back().push_back(i > 0 ? i - 1 : static_cast<int>(vertices.size()) + i);
      }
    }
  }
  std::vector<std::vector<Point>> objects;
  for (const auto& ids : used) {
    if (ids.empty()) continue;
    std::vector<Point> pts;
    for (int i : ids) {
      if (i < 0 || i >= static_cast<int>(vertices.size())) refuse(path + ": face index out of range");
      pts.push_back(vertices[i]);
    }
    objects.push_back(std::move(pts));
  }
  return objects;
}

bool buildHull(const std::vector<Point>& points, Hull& hull) {
  Mesh m;
  CGAL::convex_hull_3(points.begin(), points.end(), m);
  if (m.number_of_faces() < 4) return false;  // flat or degenerate: no volume
  for (auto f : m.faces()) {
    auto h = m.halfedge(f);
    const Point a = m.point(m.source(h)), b = m.point(m.target(h)), c = m.point(m.target(m.next(h)));
    hull.triangles.emplace_back(a, b, c);
    const K::Vector_3 n = CGAL::cross_product(b - a, c - a);
    const double longest = std::max({(b - a).squared_length(), (c - b).squared_length(), (a - c).squared_length()});
    const bool thin = n.squared_length() < 1e-8 * longest * longest;
    hull.normals.push_back(thin ? K::Vector_3(0, 0, 0) : n / std::sqrt(n.squared_length()));
    hull.offsets.push_back(thin ? 0.0 : hull.normals.back() * (a - CGAL::ORIGIN));
  }
  hull.box = CGAL::bbox_3(points.begin(), points.end());
  return true;
}

bool insideHull(const Hull& h, const Point& p, double tolerance) {
  if (p.x() < h.box.xmin() - tolerance || p.x() > h.box.xmax() + tolerance || p.y() < h.box.ymin() - tolerance ||
      p.y() > h.box.ymax() + tolerance || p.z() < h.box.zmin() - tolerance || p.z() > h.box.zmax() + tolerance)
    return false;
  const K::Vector_3 v = p - CGAL::ORIGIN;
  for (std::size_t i = 0; i < h.triangles.size(); ++i) {
    if (h.normals[i] == CGAL::NULL_VECTOR) {
      const auto& t = h.triangles[i];
      if (CGAL::orientation(t[0], t[1], t[2], p) == CGAL::POSITIVE) return false;
    } else if (h.normals[i] * v - h.offsets[i] > tolerance) {
      return false;
    }
  }
  return true;
}

bool insideUnion(const std::vector<Hull>& hulls, const Point& p, double tolerance) {
  for (const auto& h : hulls)
    if (insideHull(h, p, tolerance)) return true;
  return false;
}

// Area-weighted random points on triangles.
std::vector<Point> samplesOn(const std::vector<Triangle>& triangles, long count, std::mt19937_64& rng) {
  std::vector<double> cumulative;
  double total = 0;
  for (const auto& t : triangles) cumulative.push_back(total += std::sqrt(t.squared_area()));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point> out;
  out.reserve(count);
  for (long i = 0; i < count; ++i) {
    const double pick = u(rng) * total;
    const double r1 = u(rng), r2 = u(rng);
    const std::size_t k = std::min<std::size_t>(std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin(),
                                                triangles.size() - 1);
    const double s = std::sqrt(r1);
    const auto& t = triangles[k];
    out.push_back(CGAL::ORIGIN + (1 - s) * (t[0] - CGAL::ORIGIN) + s * (1 - r2) * (t[1] - CGAL::ORIGIN) +
                  s * r2 * (t[2] - CGAL::ORIGIN));
  }
  return out;
}

// The open shells (a box without its lid, a scan with holes, a solid an exporter left cracked
// into pieces): their generalised winding number (Jacobson et al. 2013), the triangles' solid
// angles by the formula of Van Oosterom and Strackee, summed over all of them together: a crack
// splits one closed surface into open pieces that each wind only part way around its inside.
// At least 1/2, less a margin: on the plane of a box's missing lid the winding number is 1/2
// exactly, and hull samples there lie a rounding off it.
constexpr double kHalfWinding = 0.499;

double windingNumber(const std::vector<Triangle>& triangles, const Point& q) {
  double sum = 0.0;
  for (const Triangle& t : triangles) {
    const K::Vector_3 a = t[0] - q, b = t[1] - q, c = t[2] - q;
    const double la = std::sqrt(a.squared_length()), lb = std::sqrt(b.squared_length()),
                 lc = std::sqrt(c.squared_length());
    const double num = a * CGAL::cross_product(b, c);
    const double den = la * lb * lc + (a * b) * lc + (b * c) * la + (c * a) * lb;
    sum += 2.0 * std::atan2(num, den);
  }
  return sum / (4.0 * M_PI);
}

double percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: acd-score MODEL HULLS.obj [--samples N] [--surface-samples M] [--seed S]\n");
    return 1;
  }
  long volumeSamples = 1'000'000, surfaceSamples = 200'000;
  unsigned long seed = 1;
  for (int i = 3; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--samples") volumeSamples = std::atol(argv[i + 1]);
    else if (flag == "--surface-samples") surfaceSamples = std::atol(argv[i + 1]);
    else if (flag == "--seed") seed = std::strtoul(argv[i + 1], nullptr, 10);
    else refuse("unknown option " + flag);
  }
  const auto start = std::chrono::steady_clock::now();

  Mesh model;
  if (!PMP::IO::read_polygon_mesh(argv[1], model) || model.is_empty()) refuse(std::string(argv[1]) + ": cannot read");
  // A model that is not closed has no volume to compare (IoU null); its shells still have an
  // inside for the distance of the hulls (open ones by their winding number).
  const bool closed = CGAL::is_closed(model);
  if (!CGAL::is_triangle_mesh(model)) PMP::triangulate_faces(model);
  if (closed && PMP::volume(model) < 0) PMP::reverse_face_orientations(model);

  // Normalised units: the minimum enclosing sphere of the model's vertices has radius 1.
  using SphereTraits = CGAL::Min_sphere_of_points_d_traits_3<K, double>;
  std::vector<Point> modelPoints(model.points().begin(), model.points().end());
  CGAL::Min_sphere_of_spheres_d<SphereTraits> sphere(modelPoints.begin(), modelPoints.end());
  const double radius = sphere.radius();
  if (!(radius > 0)) refuse(std::string(argv[1]) + ": degenerate model");
  const double tolerance = 1e-9 * radius;

  std::vector<Hull> hulls;
  int skipped = 0;
  for (const auto& pts : readObjObjectPoints(argv[2])) {
    Hull h;
    if (buildHull(pts, h)) hulls.push_back(std::move(h));
    else ++skipped;
  }
  if (hulls.empty()) refuse(std::string(argv[2]) + ": no hull with volume");

  using ModelTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;
  ModelTree modelTree(faces(model).first, faces(model).second, model);
  modelTree.accelerate_distance_queries();
  // Inside the model: inside any of its shells, each tested on its own (an assembly's shells pass
  // through one another; the parity of crossings over the whole would call their overlap outside).
  std::vector<Mesh> shells;
  PMP::split_connected_components(model, shells);
  std::vector<std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, K>>> sides;
  std::vector<Triangle> openTriangles;  // bound where they wind around a point at least half way
  for (const Mesh& shell : shells) {
    if (CGAL::is_closed(shell)) {
      sides.push_back(std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, K>>(shell));
      continue;
    }
    for (auto f : shell.faces()) {
      auto h = shell.halfedge(f);
      openTriangles.emplace_back(shell.point(shell.source(h)), shell.point(shell.target(h)),
                                 shell.point(shell.target(shell.next(h))));
    }
  }
  auto insideModel = [&](const Point& p) {
    for (const auto& side : sides)
      if ((*side)(p) != CGAL::ON_UNBOUNDED_SIDE) return CGAL::ON_BOUNDED_SIDE;
    return CGAL::ON_UNBOUNDED_SIDE;
  };
  auto insideOpenShells = [&](const Point& p) {
    return !openTriangles.empty() && std::abs(windingNumber(openTriangles, p)) >= kHalfWinding;
  };
  std::vector<Triangle> hullTriangles, modelTriangles;
  for (const auto& h : hulls) hullTriangles.insert(hullTriangles.end(), h.triangles.begin(), h.triangles.end());
  for (auto f : model.faces()) {
    auto h = model.halfedge(f);
    modelTriangles.emplace_back(model.point(model.source(h)), model.point(model.target(h)),
                                model.point(model.target(model.next(h))));
  }
  using HullTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, std::vector<Triangle>::const_iterator>>>;
  HullTree hullTree(hullTriangles.cbegin(), hullTriangles.cend());
  hullTree.accelerate_distance_queries();

  std::mt19937_64 rng(seed);
  // Volumes: uniform points in the joint bounding box.
  CGAL::Bbox_3 box = PMP::bbox(model);
  for (const auto& h : hulls) box += h.box;
  std::uniform_real_distribution<double> ux(box.xmin(), box.xmax()), uy(box.ymin(), box.ymax()), uz(box.zmin(), box.zmax());
  long inModel = 0, inUnion = 0, inBoth = 0;
  for (long i = 0; i < volumeSamples; ++i) {
    const double x = ux(rng), y = uy(rng), z = uz(rng);
    const Point p(x, y, z);
    const bool m = insideModel(p) != CGAL::ON_UNBOUNDED_SIDE;
    const bool u = insideUnion(hulls, p, tolerance);
    inModel += m, inUnion += u, inBoth += (m && u);
  }
  const double boxVolume = (box.xmax() - box.xmin()) * (box.ymax() - box.ymin()) * (box.zmax() - box.zmin());
  const long either = inModel + inUnion - inBoth;
  const double iou = either > 0 ? static_cast<double>(inBoth) / either : 0.0;

  // Hull surface -> model: 0 inside the model, else the distance to its surface. The winding
  // number of open shells (a sum over their faces) is asked only of samples farther than 0.005
  // from the surface: nearer ones count their distance, which is below that anyway.
  std::vector<double> outside;
  for (const Point& p : samplesOn(hullTriangles, surfaceSamples, rng)) {
    double d = 0.0;
    if (insideModel(p) == CGAL::ON_UNBOUNDED_SIDE) {
      d = std::sqrt(modelTree.squared_distance(p)) / radius;
      if (d > 0.005 && insideOpenShells(p)) d = 0.0;
    }
    outside.push_back(d);
  }
  // Model surface -> union of hulls: 0 inside some hull, else the distance to the nearest hull facet.
  std::vector<double> uncovered;
  for (const Point& p : samplesOn(modelTriangles, surfaceSamples, rng)) {
    uncovered.push_back(insideUnion(hulls, p, tolerance) ? 0.0 : std::sqrt(hullTree.squared_distance(p)) / radius);
  }

  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double scale3 = radius * radius * radius;
  auto orNull = [&](double x) { return closed ? std::to_string(x) : std::string("null"); };
  std::printf("{\"evaluator\": \"acd-score\", \"closed\": %s, \"hulls\": %zu, \"skipped_hulls\": %d, \"iou\": %s, "
              "\"iou_stderr\": %s, \"model_volume\": %s, \"model_volume_exact\": %s, \"union_volume\": %.6f, "
              "\"hull_outside_max\": %.6f, \"hull_outside_p99\": %.6f, \"model_to_hulls_max\": %.6f, "
              "\"model_to_hulls_p99\": %.6f, \"volume_samples\": %ld, \"surface_samples\": %ld, \"seconds\": %.3f}\n",
              closed ? "true" : "false", hulls.size(), skipped, orNull(iou).c_str(),
              orNull(either > 0 ? std::sqrt(iou * (1 - iou) / either) : 0.0).c_str(),
              orNull(boxVolume * inModel / volumeSamples / scale3).c_str(),
              orNull(closed ? PMP::volume(model) / scale3 : 0.0).c_str(), boxVolume * inUnion / volumeSamples / scale3,
              *std::max_element(outside.begin(), outside.end()), percentile(outside, 0.99),
              *std::max_element(uncovered.begin(), uncovered.end()), percentile(uncovered, 0.99), volumeSamples,
              surfaceSamples, seconds);
  return 0;
}
