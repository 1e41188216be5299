// Measures a decomposition (any set of hulls) against the closed model it approximates.
//
// Everything happens in the model's normalised units (minimum enclosing sphere of radius 1).
// Random numbers come from a counter-based hash of (seed, stream, sample index), and work is
// split into fixed blocks whose partial results are combined in block order, so the result
// does not depend on the number of threads.
//
// Point-in-model test: acd::InsideTest (inside.hpp).
//
// Hulls: the convex hull of each input hull's vertices (acd/algo/hull.hpp, the decomposition's own
// builder; so any input orientation or non-convexity is harmless), as half-spaces n.x <= d for the volume test, as triangles
// (a canonical fan per planar facet) for surface sampling and exact point-to-hull distances.
#include <acd/algo/closest_point.hpp>
#include <acd/algo/cut_choice.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/hull_excess.hpp>
#include <acd/algo/hull_set.hpp>
#include <acd/algo/parallel.hpp>
#include <acd/algo/stopwatch.hpp>
#include <acd/diagnosis.hpp>
#include <acd/evaluate.hpp>
#include <acd/algo/inside.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/quickhull.hpp>
#include <acd/algo/random.hpp>
#include <acd/algo/union_find.hpp>


#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <unordered_map>

namespace acd {
namespace {

// Slack of the half-space test, in normalised units: inside a hull iff n.x <= d + kHullSlack.
constexpr double kHullSlack = 1e-10;
// Cells of the grid over the union of the hulls (about), for evaluate's millions of samples. The
// grid only spares queries the planes: any size gives the same answers. Building it tests every
// cell against the hulls, so the promise's coverage check, with tens of thousands of points, takes
// about one cell per kPointsPerCell of them.
constexpr std::size_t kUnionCells = std::size_t(1) << 15;
constexpr std::size_t kPointsPerCell = 8;

// ---------------------------------------------------------------- random numbers

using Stream = UniformStream;  // acd/algo/random.hpp

// ---------------------------------------------------------------- convex hulls

inline bool lexLess(const Vec3& a, const Vec3& b) {
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

struct Hull {
  std::vector<Vec3> normals;  // outward unit normals
  std::vector<double> offsets;
  std::vector<std::array<Vec3, 3>> triangles;  // boundary of the convex hull, in a canonical order
  Vec3 lo, hi;  // bounding box of the hull's vertices
};

/// Convex hull of the points as half-spaces and triangles; false for fewer than 4 non-coplanar points.
/// The output does not depend on the order of the points nor on the hull algorithm's internal order.
bool buildHull(const std::vector<Vec3>& points, Hull& hull) {
  const ConvexHull ch = convexHull(points);  // exact predicates; corners only
  if (ch.degenerate || ch.mesh.faces.empty()) return false;
  const TriMesh& m = ch.mesh;
  std::vector<Vec3> used = m.vertices;
  std::sort(used.begin(), used.end(), lexLess);
  hull.lo = hull.hi = used.front();
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : used) {
    hull.lo = hull.lo.cwiseMin(p);
    hull.hi = hull.hi.cwiseMax(p);
    centroid += p;
  }
  centroid /= static_cast<double>(used.size());
  // Facets: triangles joined across edges where they are exactly coplanar, so that the result does
  // not depend on how the hull was triangulated.
  const auto nf = static_cast<int>(m.faces.size());
  UnionFind group(nf);
  std::map<std::pair<int, int>, int> firstUse;  // undirected edge -> first triangle using it
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.faces[f][k], b = m.faces[f][(k + 1) % 3];
      const auto [it, inserted] = firstUse.emplace(std::minmax(a, b), f);
      if (inserted) continue;
      const int g = it->second;
      int apex = -1;  // the corner of g off this edge
      for (int v : m.faces[g])
        if (v != a && v != b) apex = v;
      const Face& t = m.faces[f];
      if (apex >= 0 && TriangleSide(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]).sign(m.vertices[apex]) == 0)
        group.join(f, g);
    }
  std::vector<std::vector<Vec3>> facets(nf);
  for (int f = 0; f < nf; ++f)
    for (int v : m.faces[f]) facets[group.find(f)].push_back(m.vertices[v]);
  std::vector<std::vector<Vec3>> polygons;
  for (auto& vs : facets) {
    if (vs.size() < 3) continue;
    std::sort(vs.begin(), vs.end(), lexLess);
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
    if (vs.size() < 3) continue;
    // Normal from the vertex set alone: the widest triangle on the first vertex, turned outwards.
    std::size_t far = 1;
    for (std::size_t k = 2; k < vs.size(); ++k)
      if ((vs[k] - vs[0]).squaredNorm() > (vs[far] - vs[0]).squaredNorm()) far = k;
    Vec3 n = Vec3::Zero();
    for (std::size_t k = 1; k < vs.size(); ++k) {
      const Vec3 c = (vs[far] - vs[0]).cross(vs[k] - vs[0]);
      if (c.squaredNorm() > n.squaredNorm()) n = c;
    }
    if (!(n.squaredNorm() > 0.0)) continue;
    if (n.dot(centroid - vs[0]) > 0) n = -n;
    // Counter-clockwise around the outward normal, from the smallest vertex; then a fan.
    const Vec3 u = (vs[far] - vs[0]).normalized(), w = n.normalized().cross(u);
    Vec3 mid = Vec3::Zero();
    for (const Vec3& v : vs) mid += v;
    mid /= static_cast<double>(vs.size());
    std::vector<std::pair<double, int>> angle;
    for (std::size_t k = 0; k < vs.size(); ++k)
      angle.emplace_back(std::atan2((vs[k] - mid).dot(w), (vs[k] - mid).dot(u)), static_cast<int>(k));
    std::sort(angle.begin(), angle.end());
    std::vector<Vec3> poly;
    for (const auto& [a, k] : angle) poly.push_back(vs[k]);
    std::rotate(poly.begin(), std::min_element(poly.begin(), poly.end(), lexLess), poly.end());
    polygons.push_back(std::move(poly));
  }
  std::sort(polygons.begin(), polygons.end(), [](const auto& a, const auto& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(), lexLess);
  });
  for (const auto& poly : polygons) {
    Vec3 n = Vec3::Zero();  // Newell normal of the facet
    for (std::size_t k = 0; k < poly.size(); ++k) n += poly[k].cross(poly[(k + 1) % poly.size()]);
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) hull.triangles.push_back({poly[0], poly[k], poly[k + 1]});
    const double len = n.norm();
    if (!(len > 0.0)) continue;
    n /= len;
    if (n.dot(centroid) > n.dot(poly[0])) n = -n;  // outward
    // Supporting offset over all hull vertices: a rounded normal cannot cut the hull.
    double d = -std::numeric_limits<double>::infinity();
    for (const Vec3& p : used) d = std::max(d, n.dot(p));
    hull.normals.push_back(n);
    hull.offsets.push_back(d);
  }
  return !hull.normals.empty();
}

/// The hulls as one HullSet (acd/algo/hull_set.hpp) indexed over the sampling box: a point is in
/// their union iff some hull holds it, box and facets, within kHullSlack.
HullSet hullUnion(const std::vector<Hull>& hulls, const Box3& box, tbb::task_arena& arena,
                  std::size_t cells = kUnionCells) {
  HullSet set(kHullSlack);
  std::vector<HalfSpace> facets;
  for (const Hull& h : hulls) {
    facets.clear();
    for (std::size_t i = 0; i < h.normals.size(); ++i) facets.push_back({h.normals[i], h.offsets[i]});
    set.add(Box3{h.lo, h.hi}, facets);
  }
  set.buildIndex(box, cells, arena);
  return set;
}

/// Distance from p to the hull's boundary: its distance to the solid hull for a point outside it.
/// Asked only for points outside the union (HullSet says no hull holds them, box and facets), so
/// whether a point is inside a hull is decided in one place, the HullSet.
double distanceToHullBoundary(const Hull& h, const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : h.triangles) best = std::min(best, (closestPointOnTriangle(p, t[0], t[1], t[2]) - p).squaredNorm());
  return std::sqrt(best);
}

double boxDistance(const Vec3& lo, const Vec3& hi, const Vec3& p) {
  return (lo - p).cwiseMax(p - hi).cwiseMax(0.0).norm();
}

/// Bounding-volume hierarchy over triangles for exact closest-distance queries
/// (nearer child first, boxes farther than the best distance so far are skipped).
class TriangleBvh {
 public:
  explicit TriangleBvh(std::vector<std::array<Vec3, 3>> tris) : tris_(std::move(tris)) {
    std::vector<int> order(tris_.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<Vec3> centre(tris_.size());
    for (std::size_t t = 0; t < tris_.size(); ++t) centre[t] = (tris_[t][0] + tris_[t][1] + tris_[t][2]) / 3.0;
    nodes_.reserve(2 * tris_.size() / kLeaf + 2);
    if (!tris_.empty()) build(order, centre, 0, static_cast<int>(order.size()));
    std::vector<std::array<Vec3, 3>> sorted(tris_.size());
    for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = tris_[order[k]];
    tris_.swap(sorted);
  }

  double distance(const Vec3& p) const {
    if (nodes_.empty()) return std::numeric_limits<double>::infinity();
    double best = std::numeric_limits<double>::infinity();
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (box2(n, p) >= best) continue;
      if (n.count > 0) {
        for (int k = n.first; k < n.first + n.count; ++k) {
          const auto& t = tris_[k];
          best = std::min(best, (closestPointOnTriangle(p, t[0], t[1], t[2]) - p).squaredNorm());
        }
        continue;
      }
      const int l = n.first, r = n.first + 1;
      const double dl = box2(nodes_[l], p), dr = box2(nodes_[r], p);
      if (dl <= dr) {
        if (dr < best) stack[top++] = r;
        if (dl < best) stack[top++] = l;
      } else {
        if (dl < best) stack[top++] = l;
        if (dr < best) stack[top++] = r;
      }
    }
    return std::sqrt(best);
  }

 private:
  static constexpr int kLeaf = 4;
  struct Node {
    Vec3 lo, hi;
    int first = 0;  // leaf: first triangle; inner: index of the left child (right = first + 1)
    int count = 0;  // triangles in a leaf, 0 for inner nodes
  };
  static double box2(const Node& n, const Vec3& p) { return (n.lo - p).cwiseMax(p - n.hi).cwiseMax(0.0).squaredNorm(); }

  void build(std::vector<int>& order, const std::vector<Vec3>& centre, int begin, int end) {
    // Median splits: depth ~ log2(n / kLeaf), far below what the query stack holds.
    struct Job { int node, begin, end; };
    nodes_.emplace_back();
    std::vector<Job> jobs{{0, begin, end}};
    while (!jobs.empty()) {
      const Job j = jobs.back();
      jobs.pop_back();
      Vec3 lo = tris_[order[j.begin]][0], hi = lo, clo = centre[order[j.begin]], chi = clo;
      for (int k = j.begin; k < j.end; ++k) {
        for (const Vec3& v : tris_[order[k]]) {
          lo = lo.cwiseMin(v);
          hi = hi.cwiseMax(v);
        }
        clo = clo.cwiseMin(centre[order[k]]);
        chi = chi.cwiseMax(centre[order[k]]);
      }
      nodes_[j.node].lo = lo;
      nodes_[j.node].hi = hi;
      if (j.end - j.begin <= kLeaf) {
        nodes_[j.node].first = j.begin;
        nodes_[j.node].count = j.end - j.begin;
        continue;
      }
      int axis = 0;
      (chi - clo).maxCoeff(&axis);
      const int mid = (j.begin + j.end) / 2;
      std::nth_element(order.begin() + j.begin, order.begin() + mid, order.begin() + j.end, [&](int a, int b) {
        return centre[a][axis] < centre[b][axis] || (centre[a][axis] == centre[b][axis] && a < b);
      });
      const int left = static_cast<int>(nodes_.size());
      nodes_.emplace_back();
      nodes_.emplace_back();
      nodes_[j.node].first = left;
      jobs.push_back({left, j.begin, mid});
      jobs.push_back({left + 1, mid, j.end});
    }
  }

  std::vector<std::array<Vec3, 3>> tris_;
  std::vector<Node> nodes_;
};

// ---------------------------------------------------------------- surface sampling

/// Area-weighted triangle picking; samples are a pure function of (stream, index).
class SurfaceSampler {
 public:
  explicit SurfaceSampler(std::vector<std::array<Vec3, 3>> tris) : tris_(std::move(tris)) {
    cdf_.reserve(tris_.size());
    double total = 0.0;
    for (const auto& t : tris_) {
      total += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
      cdf_.push_back(total);
    }
  }
  double area() const { return cdf_.empty() ? 0.0 : cdf_.back(); }
  Vec3 sample(const Stream& rng, std::uint64_t i) const {
    const double u = rng.uniform(i, 0) * cdf_.back();
    std::size_t k = static_cast<std::size_t>(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin());
    k = std::min(k, tris_.size() - 1);
    const double r1 = std::sqrt(rng.uniform(i, 1)), r2 = rng.uniform(i, 2);
    const auto& t = tris_[k];
    return (1.0 - r1) * t[0] + r1 * (1.0 - r2) * t[1] + r1 * r2 * t[2];
  }

 private:
  std::vector<std::array<Vec3, 3>> tris_;
  std::vector<double> cdf_;
};

// ---------------------------------------------------------------- input checks

Status checkMesh(const TriMesh& m, const std::string& name, bool needClosed) {
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    if (!m.vertices[v].allFinite())
      return Status::error(StatusCode::NonFiniteVertex, name + " vertex " + std::to_string(v) + " is not finite");
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    for (int v : m.faces[f])
      if (v < 0 || v >= static_cast<int>(m.vertices.size()))
        return Status::error(StatusCode::IndexOutOfRange,
                             name + " face " + std::to_string(f) + " uses vertex " + std::to_string(v) +
                                 " of " + std::to_string(m.vertices.size()));
  if (!needClosed || isClosedOriented(m)) return Status::success();
  std::unordered_map<std::uint64_t, int> uses;
  for (const Face& f : m.faces)
    for (int k = 0; k < 3; ++k) ++uses[edgeKey(f[k], f[(k + 1) % 3])];
  for (const auto& [key, n] : uses) {
    const std::string edge = std::to_string(key >> 32) + "-" + std::to_string(key & 0xffffffffu);
    if (n == 1) return Status::error(StatusCode::OpenMesh, name + " is not closed: boundary edge " + edge);
    if (n > 2) return Status::error(StatusCode::NonManifoldEdge, name + " has non-manifold edge " + edge);
  }
  return Status::error(StatusCode::InconsistentOrientation, name + " is not consistently oriented");
}

}  // namespace

namespace {

/// The hulls to measure: the convex hull of each one's (used) vertices, normalised with the
/// model's transform, built on the arena's threads (each on its own, kept in the hulls' order).
/// Hulls without 4 non-coplanar vertices are counted in `skipped`.
std::vector<Hull> normalisedHulls(const std::vector<TriMesh>& hulls, const Normalization& norm, tbb::task_arena& arena,
                                  int& skipped) {
  std::vector<Hull> built(hulls.size());
  std::vector<char> usable(hulls.size(), 0);
  arena.execute([&] {
    tbb::parallel_for(std::size_t(0), hulls.size(), [&](std::size_t i) {
      const TriMesh& in = hulls[i];
      std::vector<Vec3> pts;
      if (in.faces.empty()) {
        for (const Vec3& p : in.vertices) pts.push_back(norm.apply(p));
      } else {
        std::vector<char> used(in.vertices.size(), 0);
        for (const Face& f : in.faces)
          for (int v : f) used[v] = 1;
        for (std::size_t v = 0; v < in.vertices.size(); ++v)
          if (used[v]) pts.push_back(norm.apply(in.vertices[v]));
      }
      usable[i] = buildHull(pts, built[i]);
    });
  });
  std::vector<Hull> hs;
  for (std::size_t i = 0; i < hulls.size(); ++i)
    if (usable[i])
      hs.push_back(std::move(built[i]));
    else
      ++skipped;
  return hs;
}

/// Monte-Carlo volumes: uniform points in the box, in the model, in the union of the hulls, in both.
void sampleVolumes(const Box3& box, const HullSet& index, const InsideTest& locator, tbb::task_arena& arena,
                   const EvaluateOptions& options, Evaluation& ev) {
  const Vec3 size = box.size();
  constexpr std::int64_t kBlock = 1 << 14;
  const std::int64_t n = options.volumeSamples;
  const std::size_t blocks = static_cast<std::size_t>((n + kBlock - 1) / kBlock);
  struct Counts { std::int64_t model = 0, onion = 0, both = 0; };
  std::vector<Counts> per(blocks);
  const Stream rng(options.seed, 1);
  forEachBlock(arena, std::size_t(0), blocks, [&](std::size_t b) {
    Counts c;
    const std::int64_t end = std::min<std::int64_t>(n, static_cast<std::int64_t>(b + 1) * kBlock);
    for (std::int64_t i = static_cast<std::int64_t>(b) * kBlock; i < end; ++i) {
      const auto u = static_cast<std::uint64_t>(i);
      const Vec3 p(box.lo.x() + size.x() * rng.uniform(u, 0), box.lo.y() + size.y() * rng.uniform(u, 1),
                   box.lo.z() + size.z() * rng.uniform(u, 2));
      const bool inU = index.inside(p), inM = locator.inside(p);
      c.model += inM;
      c.onion += inU;
      c.both += inM && inU;
    }
    per[b] = c;
  });
  for (const Counts& c : per) {
    ev.samplesInModel += c.model;
    ev.samplesInUnion += c.onion;
    ev.samplesInBoth += c.both;
  }
  ev.volumeSamples = n;
  const double N = static_cast<double>(n);
  const double pU = ev.samplesInUnion / N;
  ev.unionVolume = ev.boxVolume * pU;
  ev.unionVolumeStdErr = ev.boxVolume * std::sqrt(pU * (1.0 - pU) / N);
  ev.unionToModelRatio = ev.unionVolume / ev.modelVolume;
  ev.misclassifiedShare = static_cast<double>(ev.samplesInModel + ev.samplesInUnion - 2 * ev.samplesInBoth) / N;
  // IoU standard error: given the K samples that fell in model or union, the number in both is
  // Binomial(K, IoU), so SE = sqrt(IoU (1 - IoU) / K) (the randomness of K itself is ignored).
  const std::int64_t k = ev.samplesInModel + ev.samplesInUnion - ev.samplesInBoth;
  if (k > 0) {
    ev.iou = static_cast<double>(ev.samplesInBoth) / static_cast<double>(k);
    ev.iouStdErr = std::sqrt(ev.iou * (1.0 - ev.iou) / static_cast<double>(k));
  }

}

/// Distance from a point outside them to the nearest of the hulls; `order` is scratch space.
double distanceToHulls(const std::vector<Hull>& hs, const Vec3& p, std::vector<std::pair<double, int>>& order) {
  // Nearest hulls first by box distance, a lower bound of the hull distance.
  order.resize(hs.size());
  for (std::size_t h = 0; h < hs.size(); ++h) order[h] = {boxDistance(hs[h].lo, hs[h].hi, p), static_cast<int>(h)};
  std::sort(order.begin(), order.end());
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [bound, h] : order) {
    if (bound >= best) break;
    best = std::min(best, distanceToHullBoundary(hs[h], p));
  }
  return best;
}

/// Surface distances: from sample points on the hulls to the model (outside it only), and from
/// sample points on the model to the union of the hulls.
void sampleSurfaceDistances(const TriMesh& m, const std::vector<Hull>& hs, const HullSet& index,
                            const InsideTest& locator, tbb::task_arena& arena, const EvaluateOptions& options,
                            Evaluation& ev) {
  constexpr std::int64_t kBlock = 1 << 12;
  const std::int64_t n = options.surfaceSamples;
  const std::size_t blocks = static_cast<std::size_t>((n + kBlock - 1) / kBlock);
  struct Acc { double sum = 0.0, max = 0.0; };

  // Hull surfaces -> model solid.
  std::vector<std::array<Vec3, 3>> modelSurface;
  modelSurface.reserve(m.faces.size());
  for (const Face& f : m.faces) modelSurface.push_back({m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]});
  const TriangleBvh tree(modelSurface);

  std::vector<std::array<Vec3, 3>> hullSurface;
  for (const Hull& h : hs) hullSurface.insert(hullSurface.end(), h.triangles.begin(), h.triangles.end());
  const SurfaceSampler hullSampler(std::move(hullSurface)), modelSampler(std::move(modelSurface));

  std::vector<Acc> per(blocks);
  const Stream hullRng(options.seed, 2), modelRng(options.seed, 3);
  forEachBlock(arena, std::size_t(0), blocks, [&](std::size_t b) {
    Acc acc;
    const std::int64_t end = std::min<std::int64_t>(n, static_cast<std::int64_t>(b + 1) * kBlock);
    for (std::int64_t i = static_cast<std::int64_t>(b) * kBlock; i < end; ++i) {
      const Vec3 p = hullSampler.sample(hullRng, static_cast<std::uint64_t>(i));
      if (locator.inside(p)) continue;
      const double d = tree.distance(p);
      acc.sum += d;
      acc.max = std::max(acc.max, d);
    }
    per[b] = acc;
  });
  double sum = 0.0;
  for (const Acc& a : per) {
    sum += a.sum;
    ev.hullOutsideMax = std::max(ev.hullOutsideMax, a.max);
  }
  ev.hullOutsideMean = sum / static_cast<double>(n);

  // Model surface -> union of hulls.
  std::fill(per.begin(), per.end(), Acc{});
  if (modelSampler.area() > 0.0) {
    forEachBlock(arena, std::size_t(0), blocks, [&](std::size_t b) {
      Acc acc;
      std::vector<std::pair<double, int>> order(hs.size());
      const std::int64_t end = std::min<std::int64_t>(n, static_cast<std::int64_t>(b + 1) * kBlock);
      for (std::int64_t i = static_cast<std::int64_t>(b) * kBlock; i < end; ++i) {
        const Vec3 p = modelSampler.sample(modelRng, static_cast<std::uint64_t>(i));
        if (index.inside(p)) continue;
        const double best = distanceToHulls(hs, p, order);
        acc.sum += best;
        acc.max = std::max(acc.max, best);
      }
      per[b] = acc;
    });
  }
  sum = 0.0;
  for (const Acc& a : per) {
    sum += a.sum;
    ev.modelToHullsMax = std::max(ev.modelToHullsMax, a.max);
  }
  ev.modelToHullsMean = sum / static_cast<double>(n);

}

}  // namespace

Evaluation evaluate(const TriMesh& model, const std::vector<TriMesh>& hulls, const EvaluateOptions& options) {
  const auto t0 = acd::Clock::now();
  Evaluation ev;
  auto fail = [&](Status s) {
    ev.status = std::move(s);
    ev.seconds = acd::secondsSince(t0);
    return ev;
  };
  if (options.volumeSamples < 1 || options.surfaceSamples < 0 || options.threads < 0)
    return fail(Status::error(StatusCode::InvalidParameter,
                              "volumeSamples must be >= 1, surfaceSamples >= 0 and threads >= 0"));
  if (model.empty()) return fail(Status::error(StatusCode::EmptyMesh, "model has no faces"));
  if (Status s = checkMesh(model, "model", true); !s.ok()) return fail(s);
  if (hulls.empty()) return fail(Status::error(StatusCode::InvalidParameter, "no hulls"));
  for (std::size_t h = 0; h < hulls.size(); ++h)
    if (Status s = checkMesh(hulls[h], "hull " + std::to_string(h), false); !s.ok()) return fail(s);

  const Normalization norm = minimumSphereNormalization(model);
  const TriMesh m = applyNormalization(model, norm);
  ev.modelVolume = std::abs(signedVolume(m));
  if (!(ev.modelVolume > 1e-12)) return fail(Status::error(StatusCode::InvalidParameter, "model encloses no volume"));

  tbb::task_arena arena = workerArena(options.threads);
  std::vector<Hull> hs = normalisedHulls(hulls, norm, arena, ev.skippedHulls);
  ev.hulls = static_cast<int>(hs.size());
  if (hs.empty())
    return fail(Status::error(StatusCode::InvalidParameter,
                              "no usable hulls: all " + std::to_string(hulls.size()) +
                                  " have fewer than 4 non-coplanar vertices"));

  Box3 box = boundingBox(m);
  for (const Hull& h : hs) {
    box.lo = box.lo.cwiseMin(h.lo);
    box.hi = box.hi.cwiseMax(h.hi);
  }
  const Vec3 size = box.size();
  ev.boxVolume = size.prod();

  const InsideTest locator(m);
  const HullSet index = hullUnion(hs, box, arena);

  sampleVolumes(box, index, locator, arena, options, ev);

  if (options.surfaceSamples > 0) sampleSurfaceDistances(m, hs, index, locator, arena, options, ev);

  if (ev.skippedHulls > 0)
    ev.status.message = "skipped " + std::to_string(ev.skippedHulls) + " of " + std::to_string(hulls.size()) +
                        " hulls with fewer than 4 non-coplanar vertices";
  ev.seconds = acd::secondsSince(t0);
  return ev;
}

Coverage surfaceOutsideHulls(const TriMesh& surface, const std::vector<TriMesh>& hulls, std::int64_t samples,
                             std::uint64_t seed, int threads) {
  Coverage out;
  if (surface.faces.empty() || hulls.empty()) return out;
  const Normalization norm = minimumSphereNormalization(surface);
  int skipped = 0;
  tbb::task_arena arena = workerArena(threads);
  const std::vector<Hull> hs = normalisedHulls(hulls, norm, arena, skipped);
  if (hs.empty()) return out;
  const TriMesh m = applyNormalization(surface, norm);
  std::vector<std::array<Vec3, 3>> triangles;
  for (const Face& f : m.faces) triangles.push_back({m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]});
  const SurfaceSampler sampler(std::move(triangles));
  Box3 box = boundingBox(m);
  for (const Hull& h : hs) box.lo = box.lo.cwiseMin(h.lo), box.hi = box.hi.cwiseMax(h.hi);
  const Stream rng(seed, 4);
  // The vertices, then the samples: point k of them. Blocks of a fixed size, each keeping the first
  // point farthest out, taken in order: the same point as one pass, on any number of threads.
  const std::int64_t vertices = static_cast<std::int64_t>(m.vertices.size());
  const std::int64_t points = vertices + (sampler.area() > 0.0 ? samples : 0);
  const HullSet index = hullUnion(hs, box, arena, std::clamp<std::size_t>(static_cast<std::size_t>(points) / kPointsPerCell, 512, kUnionCells));
  const std::int64_t block = 4096;
  std::vector<Coverage> found(static_cast<std::size_t>((points + block - 1) / block));
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, found.size(), [&](std::size_t b) {
      std::vector<std::pair<double, int>> order;
      Coverage& c = found[b];
      const std::int64_t end = std::min(points, static_cast<std::int64_t>(b + 1) * block);
      for (std::int64_t k = static_cast<std::int64_t>(b) * block; k < end; ++k) {
        const Vec3 p = k < vertices ? m.vertices[k] : sampler.sample(rng, static_cast<std::uint64_t>(k - vertices));
        if (index.inside(p)) continue;
        const double d = distanceToHulls(hs, p, order);
        if (d > c.max) c.max = d, c.worst = p;
      }
    });
  });
  for (const Coverage& c : found)
    if (c.max > out.max) out = c;
  if (out.max > 0.0) out.worst = norm.undo(out.worst);
  out.max /= norm.scale;
  return out;
}

Coverage inputOutsideHulls(const TriMesh& input, const Decomposition& d) {
  std::vector<TriMesh> hulls;
  for (const Component& c : d.components) hulls.push_back(c.hull);
  Coverage c = surfaceOutsideHulls(input, hulls, 20000, 1, d.options.threads);
  c.max *= d.normalization.scale;
  return c;
}

HullsOffInput hullsOffInput(const TriMesh& input, const Decomposition& d, bool hullsAsDecomposed) {
  HullsOffInput out;
  out.excess.assign(d.components.size(), 0.0);
  if (input.faces.empty() || d.components.empty()) return out;
  const double tau = d.options.tau;
  // The decomposition keeps tau to its measure's resolution: the same allowance here.
  const double allowed = tau * (1.0 + kExcessResolution);
  std::vector<Vec3> where(d.components.size(), Vec3::Zero());
  const bool measure = !(hullsAsDecomposed && d.repairs.empty() && !d.wrap.used);
  if (!measure) {
    for (std::size_t i = 0; i < d.components.size(); ++i) out.excess[i] = d.components[i].hullExcess;
  } else {
    const ModelExcess solid(applyNormalization(input, d.normalization), ModelSolid::AnyClosedShell, d.options.threads);
    tbb::task_arena arena = workerArena(d.options.threads);
    arena.execute([&] {
      tbb::parallel_for(std::size_t{0}, d.components.size(), [&](std::size_t i) {
        // The search decides "beyond the limit?" and settles patches below it, so a value found
        // under the limit is only a lower bound. At tau it decides the promise; beyond, the
        // limit is raised past what was found until nothing exceeds it: the value is then
        // within 5%.
        const TriMesh hull = applyNormalization(d.components[i].hull, d.normalization);
        HullExcess e = solid.measure(hull, allowed, kExcessResolution * tau);
        while (e.exceeds) {
          const HullExcess above = solid.measure(hull, 1.05 * e.distance, kExcessResolution * tau);
          if (!above.exceeds) break;
          e = above;
        }
        out.excess[i] = e.distance;
        where[i] = e.hullPoint;
      });
    });
    out.openShells = solid.openShells();
  }
  for (std::size_t i = 0; i < out.excess.size(); ++i)
    if (out.excess[i] > out.max) out.max = out.excess[i], out.component = static_cast<int>(i);
  if (measure && out.component >= 0) out.worst = d.normalization.undo(where[out.component]);
  out.kept = out.max <= allowed;
  return out;
}

Evaluation evaluateModel(const TriMesh& model, const std::vector<TriMesh>& hulls, const EvaluateOptions& options) {
  const PreparedSolid prepared = prepareSolid(model);
  if (!prepared.status.ok()) {
    Evaluation failed;
    failed.status = prepared.status;
    return failed;
  }
  TriMesh joined;  // the repaired pieces, one mesh again
  for (const TriMesh& piece : prepared.components) {
    const int base = static_cast<int>(joined.vertices.size());
    joined.vertices.insert(joined.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (const Face& f : piece.faces) joined.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  return evaluate(joined, hulls, options);
}

}  // namespace acd
