// Distances from hull points to the mesh's surface with CGAL's AABB tree (double arithmetic: a
// distance, not a predicate).
#include <acd/algo/closest_point.hpp>
#include <acd/algo/face_grid.hpp>
#include <acd/algo/hull_excess.hpp>
#include <acd/algo/inside.hpp>
#include <acd/algo/parallel.hpp>
#include <acd/algo/random.hpp>
#include <acd/algo/shell_inside.hpp>

#include <tbb/parallel_invoke.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <utility>
#include <vector>

namespace acd {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point toPoint(const Vec3& p) { return Point(p.x(), p.y(), p.z()); }
Vec3 toVec(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

struct Patch {
  std::array<Vec3, 3> corner;
  int face;
};

/// True when all three corners of the patch lie in the triangle (its plane, and inside its
/// edges), to rounding: then the whole patch does, and its distance to the surface is zero.
bool insideFace(const Triangle& t, const Patch& p) {
  const Vec3 a = toVec(t[0]), b = toVec(t[1]), c = toVec(t[2]);
  const Vec3 n = (b - a).cross(c - a);
  const double area2 = n.norm();
  const double scale = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  const double tolerance = 1e-12 * scale;
  for (const Vec3& q : p.corner) {
    if (std::abs(n.dot(q - a)) > tolerance * area2) return false;
    // Each edge's signed distance to q, inward positive.
    for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
      if (n.dot((v - u).cross(q - u)) < -tolerance * scale * area2) return false;
  }
  return true;
}

/// The largest distance from a patch's corners to triangle t, and which corner. The distance to
/// one triangle is a convex function of the point, so no point of the patch is farther from t; and
/// the distance to the surface (or the solid) is at most the distance to any of its triangles.
/// Over a flat stretch of surface this bound is exact where "centroid distance + radius" would
/// split the patch down to the resolution.
std::pair<double, int> farthestCornerFrom(const Triangle& t, const Patch& p) {
  const Vec3 a = toVec(t[0]), b = toVec(t[1]), c = toVec(t[2]);
  std::pair<double, int> farthest{0.0, 0};
  for (int k = 0; k < 3; ++k)
    farthest = std::max(farthest, {(closestPointOnTriangle(p.corner[k], a, b, c) - p.corner[k]).norm(), k});
  return farthest;
}

/// What the branch and bound found on one hull face searched to its end (no point beyond the
/// limit). The search of a face depends on nothing but its corners, the limit, the resolution and
/// the surface measured against, so a face met again is not searched again: the hull of a union in
/// the merge pass keeps most faces of the hulls it joins, and each hull is measured again after.
/// The answer is the same, bit for bit, whether a face was searched before or not.
class FaceSearches {
 public:
  using Key = std::array<double, 11>;  // the corners in order, the limit, the resolution
  struct Found {
    double distance = 0.0;             // the largest distance met, first met where it was
    Vec3 hullPoint = Vec3::Zero(), surfacePoint = Vec3::Zero();
    double bound = 0.0;                // over the patches the search settled
    int probes = 0;
  };

  bool find(const Key& key, Found& found) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = map_.find(key);
    if (it == map_.end()) return false;
    found = it->second;
    return true;
  }
  void add(const Key& key, const Found& found) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (map_.size() < kMost) map_.emplace(key, found);
  }

 private:
  static constexpr std::size_t kMost = 1 << 20;  // about 150 MB at most
  struct Bits {  // bit for bit: -0 is not 0 here, and a NaN never matches
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 0x9E3779B97F4A7C15ull;
      for (double x : k) {
        std::uint64_t b;
        std::memcpy(&b, &x, sizeof b);
        h = mix64(h ^ b);
      }
      return static_cast<std::size_t>(h);
    }
    bool operator()(const Key& a, const Key& b) const { return std::memcmp(a.data(), b.data(), sizeof(Key)) == 0; }
  };
  mutable std::mutex mutex_;
  std::unordered_map<Key, Found, Bits, Bits> map_;
};

/// The branch and bound shared by both measures. `probe(q, patch, radius, nearest, reach, face)`
/// returns the distance at q, how far every point of the patch may be from q before the bound
/// matters (the patch's radius, less q's depth inside the model) and the surface triangle nearest
/// to q when there is one, or a negative distance when the whole patch is known to be 0.
template <class Probe>
HullExcess branchAndBound(const TriMesh& hull, double limit, double resolution, Probe probe, int firstFace = -1,
                          FaceSearches* searched = nullptr) {
  HullExcess out;
  std::vector<Patch> stack;
  auto patchOf = [&](int f) {
    return Patch{{hull.vertices[hull.faces[f][0]], hull.vertices[hull.faces[f][1]], hull.vertices[hull.faces[f][2]]}, f};
  };
  for (std::size_t f = 0; f < hull.faces.size(); ++f)
    if (static_cast<int>(f) != firstFace) stack.push_back(patchOf(static_cast<int>(f)));
  if (firstFace >= 0 && firstFace < static_cast<int>(hull.faces.size())) stack.push_back(patchOf(firstFace));
  auto record = [&out](double d, const Vec3& hullPoint, const Vec3& surfacePoint, int face) {
    if (d <= out.distance) return;
    out.distance = d;
    out.hullPoint = hullPoint;
    out.surfacePoint = surfacePoint;
    out.hullFace = face;
  };
  // Faces are visited in their order and split depth first, so the answer does not depend on
  // threads; a patch is skipped only when no point of it can exceed the limit, so the first point
  // beyond the limit is the same whichever bound skipped it. Depth first, a face's patches come
  // one after the other: what the face gave is known when the next face starts.
  int face = -1;
  FaceSearches::Key key{};
  FaceSearches::Found found;
  auto faceDone = [&] {
    if (face >= 0) searched->add(key, found);
  };
  auto recordOnFace = [&](double d, const Vec3& hullPoint, const Vec3& surfacePoint, int f) {
    if (d > found.distance) found.distance = d, found.hullPoint = hullPoint, found.surfacePoint = surfacePoint;
    record(d, hullPoint, surfacePoint, f);
  };
  auto settle = [&](double bound) {
    found.bound = std::max(found.bound, bound);
    out.bound = std::max(out.bound, bound);
  };
  while (!stack.empty()) {
    const Patch p = stack.back();
    stack.pop_back();
    if (searched && p.face != face) {  // a face's first patch: the face itself
      faceDone();
      face = p.face;
      found = {};
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 3; ++i) key[3 * k + i] = p.corner[k][i];
      key[9] = limit, key[10] = resolution;
      if (searched->find(key, found)) {
        record(found.distance, found.hullPoint, found.surfacePoint, p.face);
        out.bound = std::max(out.bound, found.bound);
        out.probes += found.probes;
        face = -1;  // nothing to add
        continue;
      }
    }
    const Vec3 centroid = (p.corner[0] + p.corner[1] + p.corner[2]) / 3.0;
    double radius = 0.0;
    for (const Vec3& c : p.corner) radius = std::max(radius, (c - centroid).norm());
    Vec3 nearest = Vec3::Zero();
    double reach = radius;
    const Triangle* nearestFace = nullptr;
    ++out.probes, ++found.probes;
    const double d = probe(centroid, p, radius, nearest, reach, nearestFace);
    if (d < 0) continue;  // zero all over
    recordOnFace(d, centroid, nearest, p.face);
    if (d > limit) {
      out.exceeds = true;
      out.bound = std::max(out.bound, d + reach);
      return out;
    }
    if (nearestFace && d + reach > limit) {
      const auto [farthest, corner] = farthestCornerFrom(*nearestFace, p);
      if (farthest < d + reach) reach = std::max(0.0, farthest - d);
      if (d + reach <= limit) {
        // Settled without the points the splits would have probed: the corner farthest from the
        // triangle stands in for them, so that `distance` stays a close lower bound.
        Vec3 cornerNearest = Vec3::Zero();
        double cornerReach = 0.0;
        const Triangle* cornerFace = nullptr;
        ++out.probes, ++found.probes;
        const double dc = probe(p.corner[corner], p, 0.0, cornerNearest, cornerReach, cornerFace);
        recordOnFace(dc, p.corner[corner], cornerNearest, p.face);
      }
    }
    if (d + reach <= limit || radius <= resolution) {  // within the limit, or too small to split further
      settle(d + reach);
      continue;
    }
    const Vec3 m01 = 0.5 * (p.corner[0] + p.corner[1]), m12 = 0.5 * (p.corner[1] + p.corner[2]),
               m20 = 0.5 * (p.corner[2] + p.corner[0]);
    stack.push_back({{p.corner[0], m01, m20}, p.face});
    stack.push_back({{m01, p.corner[1], m12}, p.face});
    stack.push_back({{m20, m12, p.corner[2]}, p.face});
    stack.push_back({{m01, m12, m20}, p.face});
  }
  faceDone();
  out.bound = std::max(out.bound, out.distance);
  return out;
}

std::vector<Triangle> trianglesOf(const TriMesh& mesh) {
  std::vector<Triangle> triangles;
  triangles.reserve(mesh.faces.size());
  for (const Face& f : mesh.faces) {
    const Triangle t(toPoint(mesh.vertices[f[0]]), toPoint(mesh.vertices[f[1]]), toPoint(mesh.vertices[f[2]]));
    if (!t.is_degenerate()) triangles.push_back(t);
  }
  return triangles;
}

}  // namespace

HullExcess measureHullExcess(const TriMesh& mesh, const TriMesh& hull, double limit, double resolution) {
  const std::vector<Triangle> triangles = trianglesOf(mesh);
  if (triangles.empty() || hull.faces.empty()) return {};
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  return branchAndBound(hull, limit, resolution,
                        [&](const Vec3& q, const Patch& p, double, Vec3& nearest, double&, const Triangle*& face) {
    const auto [point, primitive] = tree.closest_point_and_primitive(toPoint(q));
    nearest = toVec(point);
    face = &*primitive;
    const double d = (nearest - q).norm();
    // On the surface all over: a patch inside the face it lies on (a hull face over a flat cap, or
    // over a face of a convex part). Without this, flat faces would be split down to the limit.
    if (d == 0.0 && insideFace(*primitive, p)) return -1.0;
    return d;
  });
}

struct ModelExcess::Impl {
  Impl(const TriMesh& model, ModelSolid solid, int threads) : triangles(trianglesOf(model)) {
    // The inside test and the distance tree share nothing: built side by side.
    auto build = [&] {
      tbb::parallel_invoke(
          [&] {
            if (solid == ModelSolid::Whole) whole = std::make_unique<InsideTest>(model);
            else shells = std::make_unique<ShellsInside>(model);
          },
          [&] {
            tree.insert(triangles.begin(), triangles.end());
            tree.build();
            tree.accelerate_distance_queries();
          });
    };
    if (threads > 0) workerArena(threads).execute(build);
    else build();
  }
  bool insideClosed(const Vec3& q) const { return whole ? whole->inside(q) : shells->insideClosed(q); }
  bool insideOpen(const Vec3& q) const { return shells && shells->insideOpen(q); }
  bool inside(const Vec3& q) const { return insideClosed(q) || insideOpen(q); }
  std::vector<Triangle> triangles;
  Tree tree;
  std::unique_ptr<InsideTest> whole;
  std::unique_ptr<ShellsInside> shells;
  mutable FaceSearches searched;
};

ModelExcess::ModelExcess(const TriMesh& model, ModelSolid solid, int threads)
    : impl_(std::make_unique<Impl>(model, solid, threads)) {}
ModelExcess::~ModelExcess() = default;

int ModelExcess::openShells() const { return impl_->shells ? impl_->shells->openShells() : 0; }

HullExcess ModelExcess::measure(const TriMesh& hull, double limit, double resolution, int firstFace) const {
  if (impl_->triangles.empty() || hull.faces.empty()) return {};
  return branchAndBound(hull, limit, resolution,
                        [&](const Vec3& q, const Patch&, double radius, Vec3& nearest, double& reach,
                            const Triangle*& face) {
                          const bool inside = impl_->insideClosed(q);
                          // Inside, the patch is within its radius of the model: no distance needed.
                          if (inside && radius <= limit) return -1.0;
                          const auto [point, primitive] = impl_->tree.closest_point_and_primitive(toPoint(q));
                          nearest = toVec(point);
                          const double d = (nearest - q).norm();
                          if (!inside) {
                            // Inside an open shell (its winding number) counts zero, but says
                            // nothing of q's neighbours: split on. Asked only where it matters
                            // (the sum is costly): a distance within the limit settles anyway.
                            if (d + radius > limit && impl_->insideOpen(q)) {
                              nearest = q;
                              reach = radius;
                              return 0.0;
                            }
                            face = &*primitive;
                            return d;
                          }
                          // Inside at depth d: the ball of radius d around q is in the model, so
                          // no point of the patch is farther out than radius - d.
                          if (radius <= d) return -1.0;
                          nearest = q;
                          reach = radius - d;
                          return 0.0;
                        },
                        firstFace, &impl_->searched);
}

struct InputExcess::Impl {
  Impl(TriMesh in, TriMesh stand, double off)
      : input(std::move(in)), standIn(std::move(stand)), standOff(off), inputFaces({&input}), standInFaces({&standIn}),
        standInSide(standIn) {}
  TriMesh input, standIn;
  double standOff;
  FaceGrid inputFaces, standInFaces;
  InsideTest standInSide;
  mutable FaceSearches searched;
};

InputExcess::InputExcess(TriMesh input, TriMesh standIn, double standOff)
    : impl_(std::make_unique<Impl>(std::move(input), std::move(standIn), standOff)) {}
InputExcess::~InputExcess() = default;

HullExcess InputExcess::measure(const TriMesh& hull, double limit, double resolution, int firstFace,
                                double cornerExcess) const {
  if (impl_->input.faces.empty() || hull.faces.empty()) return {};
  // Every point of a triangle lies within 1/sqrt(3) of its longest edge from one of its corners
  // (the circumradius of an equilateral one, the worst case), and the excess is 1-Lipschitz: a
  // face that is short enough is settled by its corners' bound, without a probe. A dense input's
  // hulls are mostly such faces.
  TriMesh open;
  open.vertices = hull.vertices;
  std::vector<int> openFace;  // open's faces -> hull's
  double settled = 0.0;
  int first = -1;
  for (std::size_t f = 0; f < hull.faces.size(); ++f) {
    const Face& t = hull.faces[f];
    double longest = 0.0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (hull.vertices[t[k]] - hull.vertices[t[(k + 1) % 3]]).norm());
    const double bound = 0.578 * longest + cornerExcess;
    if (bound <= limit) {
      settled = std::max(settled, bound);
      continue;
    }
    if (static_cast<int>(f) == firstFace) first = static_cast<int>(openFace.size());
    openFace.push_back(static_cast<int>(f));
    open.faces.push_back(t);
  }
  HullExcess out;
  if (!open.faces.empty()) out = searchFrom(open, limit, resolution, first);
  if (out.hullFace >= 0) out.hullFace = openFace[out.hullFace];
  if (!out.exceeds) out.bound = std::max(out.bound, settled);
  return out;
}

HullExcess InputExcess::searchFrom(const TriMesh& hull, double limit, double resolution, int firstFace) const {
  const Impl& m = *impl_;
  Triangle nearestFace;  // the probe's, read by the search before the next probe
  return branchAndBound(hull, limit, resolution,
                        [&](const Vec3& q, const Patch& p, double radius, Vec3& nearest, double& reach,
                            const Triangle*& face) {
                          nearest = q;  // the grids give distances only
                          // The stand-in's surface and the input's lie within the stand-off of each
                          // other, so the distance to the input is the stand-in's give or take that:
                          // enough to settle most patches without the input's (finer) grid.
                          const double off = m.standOff;
                          const double within = limit + radius;
                          const FaceGrid::Nearest onStandIn = m.standInFaces.nearest(q, std::max(off + radius, within));
                          const double w = onStandIn.distance;
                          // Farther than the stand-off (and the patch's radius) from the stand-in's
                          // surface, the whole patch is on one side of the input, the stand-in's.
                          const bool clear = w > off + radius;
                          if (clear && m.standInSide.inside(q)) return -1.0;
                          if (clear && w - off > limit) return w - off;  // beyond, and no nearer than that
                          // No point of the patch is farther from the stand-in than its corners are
                          // from the stand-in's face nearest to q (the distance to one triangle is
                          // convex), nor farther from the input than that and the stand-off. The
                          // stand-in's faces are as large as tau allows whatever the input's
                          // resolution, so this settles the band's patches without the input's
                          // grid (at most w + radius: the old bound, never looser).
                          double far = w + radius;
                          if (onStandIn.face >= 0 && w + off + radius > limit) {
                            const Face& t = m.standIn.faces[onStandIn.face];
                            const Triangle standInFace(toPoint(m.standIn.vertices[t[0]]), toPoint(m.standIn.vertices[t[1]]),
                                                       toPoint(m.standIn.vertices[t[2]]));
                            far = std::min(far, farthestCornerFrom(standInFace, p).first);
                          }
                          if (far + off <= limit) {
                            // Outside, at least w - off from the input; no point of the patch
                            // farther than far + off: settled.
                            const double d = clear ? std::max(0.0, w - off) : 0.0;
                            reach = far + off - d;
                            return d;
                          }
                          // Only the distance decides beyond limit + radius: a value there is a
                          // lower bound, which still says "beyond".
                          const FaceGrid::Nearest n = m.inputFaces.nearest(q, within);
                          const double d = std::min(n.distance, std::nextafter(within, std::numeric_limits<double>::infinity()));
                          if (n.face >= 0 && n.distance <= within) {
                            // Its corners' distance to this face bounds the patch's (the search's
                            // own refinement, which settles flat stretches without splitting).
                            const Face& t = m.input.faces[n.face];
                            nearestFace = Triangle(toPoint(m.input.vertices[t[0]]), toPoint(m.input.vertices[t[1]]),
                                                   toPoint(m.input.vertices[t[2]]));
                            face = &nearestFace;
                          }
                          if (clear) return d;  // outside the input: the excess is the distance
                          // Side unknown: no point of the patch stands off the input by more than
                          // its distance to the surface.
                          reach = d + radius;
                          return 0.0;
                        },
                        firstFace, &impl_->searched);
}

namespace {

/// A closed convex mesh's faces as half-spaces n.x <= d.
struct HalfSpaces {
  explicit HalfSpaces(const TriMesh& hull) : box(boundingBox(hull)) {
    std::vector<std::array<double, 4>> planes;  // unit normal, offset
    for (const Face& f : hull.faces) {
      const Vec3 &a = hull.vertices[f[0]], &b = hull.vertices[f[1]], &c = hull.vertices[f[2]];
      const Vec3 n = (b - a).cross(c - a);
      if (n.norm() == 0.0) continue;
      const Vec3 unit = n.normalized();
      planes.push_back({unit.x(), unit.y(), unit.z(), unit.dot(a)});
    }
    // The faces of a cut cap share one plane: keep it once.
    std::sort(planes.begin(), planes.end());
    std::array<double, 4> last{2, 2, 2, 0};
    for (const auto& p : planes) {
      if (std::abs(p[0] - last[0]) <= 1e-12 && std::abs(p[1] - last[1]) <= 1e-12 && std::abs(p[2] - last[2]) <= 1e-12 &&
          std::abs(p[3] - last[3]) <= 1e-12)
        continue;
      last = p;
      nx.push_back(p[0]), ny.push_back(p[1]), nz.push_back(p[2]), offsets.push_back(p[3] + 1e-12);
    }
  }
  /// Within the box (1e-9, less `margin`), for the point tests' one box test.
  bool inBox(const Vec3& q, double margin = 0.0) const {
    const double slack = 1e-9 - margin;
    return !(q.array() < box.lo.array() - slack).any() && !(q.array() > box.hi.array() + slack).any();
  }
  /// Within 1e-12 of plane i (less `margin`).
  bool below(std::size_t i, const Vec3& q, double margin = 0.0) const {
    return nx[i] * q.x() + ny[i] * q.y() + nz[i] * q.z() <= offsets[i] - margin;
  }
  Box3 box;
  std::vector<double> nx, ny, nz, offsets;
};

}  // namespace

double ModelExcess::addedVolume(const TriMesh& hull, const std::vector<const TriMesh*>& covered, int samples,
                                std::uint64_t key, double stopAbove) const {
  if (hull.faces.empty() || samples <= 0) return 0.0;
  // The hull as a fan of tetrahedra from its vertex centroid; a sample picks a tetrahedron by volume.
  Vec3 apex = Vec3::Zero();
  for (const Vec3& v : hull.vertices) apex += v;
  apex /= static_cast<double>(hull.vertices.size());
  std::vector<double> cumulative;
  double total = 0.0;
  for (const Face& f : hull.faces) {
    const Vec3 &a = hull.vertices[f[0]], &b = hull.vertices[f[1]], &c = hull.vertices[f[2]];
    total += std::abs((a - apex).dot((b - apex).cross(c - apex))) / 6.0;
    cumulative.push_back(total);
  }
  if (total <= 0.0) return 0.0;
  std::vector<HalfSpaces> others;
  for (const TriMesh* h : covered) others.emplace_back(*h);
  // A sample lies in one tetrahedron of the fan, inside the convex hull of its four corners: a
  // plane (or the box) of a covering hull that all four corners keep to, it keeps to as well.
  // So a sample is tested only against the planes its corners leave (few: most corners are the
  // covering hulls' own), and a tetrahedron whose corners leave none is hidden untested. The
  // corners are held to a margin above the rounding of a sample's coordinates and of its plane
  // tests, so each test skipped is one the sample would pass: the count is the one testing
  // every plane gives.
  const Box3 hullBox = boundingBox(hull);
  const double margin = 1e-13 * std::max({1.0, hullBox.lo.cwiseAbs().maxCoeff(), hullBox.hi.cwiseAbs().maxCoeff()});
  const std::size_t corners = hull.vertices.size() + 1;  // the hull's vertices, then the apex
  const auto cornerAt = [&](std::size_t c) -> const Vec3& { return c < hull.vertices.size() ? hull.vertices[c] : apex; };
  struct Left {                      // for one covering hull
    std::vector<std::uint32_t> first;  // per corner, into planes (corners + 1)
    std::vector<std::uint32_t> planes; // the planes each corner leaves
    std::vector<char> box;             // per corner: leaves the box
  };
  std::vector<Left> left(others.size());
  for (std::size_t k = 0; k < others.size(); ++k) {
    const HalfSpaces& h = others[k];
    Left& l = left[k];
    l.first.assign(1, 0);
    l.box.resize(corners);
    for (std::size_t c = 0; c < corners; ++c) {
      const Vec3& p = cornerAt(c);
      l.box[c] = !h.inBox(p, margin);
      for (std::size_t i = 0; i < h.offsets.size(); ++i)
        if (!h.below(i, p, margin)) l.planes.push_back(static_cast<std::uint32_t>(i));
      l.first.push_back(static_cast<std::uint32_t>(l.planes.size()));
    }
  }
  const auto tetCorners = [&](const Face& f) {
    return std::array<std::size_t, 4>{corners - 1, std::size_t(f[0]), std::size_t(f[1]), std::size_t(f[2])};
  };
  const auto hiddenBy = [&](std::size_t k, const Face& f, const Vec3& q) {
    const HalfSpaces& h = others[k];
    const Left& l = left[k];
    const auto tet = tetCorners(f);
    if (std::any_of(tet.begin(), tet.end(), [&](std::size_t c) { return l.box[c]; }) && !h.inBox(q)) return false;
    for (const std::size_t c : tet)
      for (std::uint32_t i = l.first[c]; i < l.first[c + 1]; ++i)
        if (!h.below(l.planes[i], q)) return false;
    return true;
  };
  std::vector<char> hiddenTet(hull.faces.size(), 0);
  for (std::size_t t = 0; t < hull.faces.size(); ++t) {
    const auto tet = tetCorners(hull.faces[t]);
    for (const Left& l : left)
      if (std::none_of(tet.begin(), tet.end(), [&](std::size_t c) { return l.box[c] || l.first[c + 1] > l.first[c]; }))
        hiddenTet[t] = 1;
  }
  int outside = 0;
  // The samples outside that prove the volume above stopAbove whatever the rest give.
  const double enough = std::floor(stopAbove / total * samples) + 1;
  for (int i = 0; i < samples && outside < enough; ++i) {
    const std::uint64_t base = mix64(key ^ mix64(static_cast<std::uint64_t>(i)));
    const double pick = unitInterval(mix64(base + 1)) * total;
    const std::size_t t = std::min<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), pick) -
                                                    cumulative.begin(), cumulative.size() - 1);
    if (hiddenTet[t]) continue;
    // Uniform in a tetrahedron: three uniforms folded into the simplex s + t + u <= 1.
    double s = unitInterval(mix64(base + 2)), r = unitInterval(mix64(base + 3)), u = unitInterval(mix64(base + 4));
    if (s + r > 1.0) s = 1.0 - s, r = 1.0 - r;
    if (r + u > 1.0) {
      const double old = u;
      u = 1.0 - s - r;
      r = 1.0 - old;
    } else if (s + r + u > 1.0) {
      const double old = u;
      u = s + r + u - 1.0;
      s = 1.0 - r - old;
    }
    const Face& f = hull.faces[t];
    const Vec3 q = apex + s * (hull.vertices[f[0]] - apex) + r * (hull.vertices[f[1]] - apex) +
                   u * (hull.vertices[f[2]] - apex);
    bool hidden = false;
    for (std::size_t k = 0; k < others.size() && !hidden; ++k) hidden = hiddenBy(k, f, q);
    if (!hidden && !impl_->inside(q)) ++outside;
  }
  return total * outside / samples;
}

}  // namespace acd
