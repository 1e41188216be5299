// Quadric edge collapse held to a distance from the input (acd/algo/working_mesh.hpp).
#include <acd/algo/working_mesh.hpp>

#include <acd/algo/closest_point.hpp>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace acd {

namespace {

/// Garland & Heckbert's quadric: the sum of weight * (n.p + d)^2 over planes, a symmetric 4x4.
struct Quadric {
  double xx = 0, xy = 0, xz = 0, xw = 0, yy = 0, yz = 0, yw = 0, zz = 0, zw = 0, ww = 0;

  static Quadric ofPlane(const Vec3& n, double d, double weight) {
    Quadric q;
    q.xx = weight * n.x() * n.x(), q.xy = weight * n.x() * n.y(), q.xz = weight * n.x() * n.z();
    q.xw = weight * n.x() * d, q.yy = weight * n.y() * n.y(), q.yz = weight * n.y() * n.z();
    q.yw = weight * n.y() * d, q.zz = weight * n.z() * n.z(), q.zw = weight * n.z() * d, q.ww = weight * d * d;
    return q;
  }
  Quadric& operator+=(const Quadric& q) {
    xx += q.xx, xy += q.xy, xz += q.xz, xw += q.xw, yy += q.yy, yz += q.yz, yw += q.yw, zz += q.zz, zw += q.zw;
    ww += q.ww;
    return *this;
  }
  double error(const Vec3& p) const {
    const double x = p.x(), y = p.y(), z = p.z();
    return std::max(0.0, xx * x * x + 2 * xy * x * y + 2 * xz * x * z + 2 * xw * x + yy * y * y + 2 * yz * y * z +
                             2 * yw * y + zz * z * z + 2 * zw * z + ww);
  }
};

double distanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  return (closestPointOnTriangle(p, a, b, c) - p).norm();
}

/// Faces turning further than this (cosine of the angle between old and new normal) are refused: a
/// fold would make the working surface pass through itself.
constexpr double kLeastNormalCosine = 0.35;
/// A closed piece keeps at least this many faces (a tetrahedron and a little more).
constexpr int kLeastFaces = 8;
/// Pieces of more faces than this are first simplified slab by slab, in parallel (at most
/// kMostSlabs): a count fixed by the piece, never by the threads, so the result is the same on any.
constexpr std::size_t kFacesPerSlab = 100000;
constexpr std::size_t kMostSlabs = 16;

class Collapser {
  struct Lane;

 public:
  /// `mesh` must outlive the collapser: its vertices and faces are read, not copied.
  Collapser(const TriMesh& mesh, double tolerance)
      : input_(mesh.vertices), inputFaces_(mesh.faces), pos_(mesh.vertices), faces_(mesh.faces), tolerance_(tolerance) {
    const std::size_t n = pos_.size();
    faceAlive_.assign(faces_.size(), 1);
    vertexFaces_.resize(n);
    quadric_.resize(n);
    version_.assign(n, 0);
    homed_.resize(faces_.size());
    bound_.assign(n, 0.0);  // each input vertex starts as a corner of its face
    liveFaces_ = static_cast<int>(faces_.size());
    {  // each vertex's list at its final size at once (grown by doubling, it was allocated 3 or 4 times)
      std::vector<int> valence(n, 0);
      for (const Face& t : faces_)
        for (int v : t) ++valence[v];
      for (std::size_t v = 0; v < n; ++v) vertexFaces_[v].reserve(valence[v]);
    }
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      const Face& t = faces_[f];
      const Vec3 normal = (pos_[t[1]] - pos_[t[0]]).cross(pos_[t[2]] - pos_[t[0]]);
      const double twiceArea = normal.norm();
      for (int k = 0; k < 3; ++k) {
        if (vertexFaces_[t[k]].empty()) homed_[f].push_back(t[k]);  // each input vertex on its first face
        vertexFaces_[t[k]].push_back(static_cast<int>(f));
      }
      if (twiceArea <= 0) continue;
      const Vec3 unit = normal / twiceArea;
      const Quadric q = Quadric::ofPlane(unit, -unit.dot(pos_[t[0]]), 0.5 * twiceArea);
      for (int k = 0; k < 3; ++k) quadric_[t[k]] += q;
    }
    inputFacesStart_.assign(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v)
      inputFacesStart_[v + 1] = inputFacesStart_[v] + static_cast<int>(vertexFaces_[v].size());
    for (std::size_t v = 0; v < n; ++v)
      inputFacesOf_.insert(inputFacesOf_.end(), vertexFaces_[v].begin(), vertexFaces_[v].end());
    inputFaceCentre_.reserve(inputFaces_.size());
    inputFaceRadius_.reserve(inputFaces_.size());
    for (const Face& t : inputFaces_) {
      const Vec3 centre = (input_[t[0]] + input_[t[1]] + input_[t[2]]) / 3.0;
      double radius = 0.0;
      for (int k = 0; k < 3; ++k) radius = std::max(radius, (input_[t[k]] - centre).norm());
      inputFaceCentre_.push_back(centre);
      inputFaceRadius_.push_back(radius);
    }
    sortIntoSlabs();
  }

  WorkingMesh run() {
    WorkingMesh out;
    out.tolerance = tolerance_;
    // Slab by slab in parallel first, each collapsing only edges whose ends and their neighbours
    // are all its own: the slabs touch disjoint faces and vertices, so each one's result does not
    // depend on the others or on the thread count. Then one pass over everything (the strips along
    // the slab walls and what the coarser mesh allows). (A second round of slabs, their walls
    // halfway between the first ones, was slower: the strips are few collapses, and the order a
    // slab gives the coarse mesh's collapses made them costlier.)
    if (slabs_ > 1) {
      std::vector<Lane> lanes(slabs_);
      for (int s = 0; s < slabs_; ++s) lanes[s].slab = s;
      tbb::parallel_for(0, slabs_, [&](int s) {
        gatherEdges(lanes[s]);
        drain(lanes[s]);
      });
      for (const Lane& lane : lanes) out.collapses += lane.collapses, liveFaces_ -= lane.removedFaces;
    }
    gatherEdges(whole_);
    drain(whole_);
    out.collapses += whole_.collapses;
    std::vector<Face> alive;
    for (std::size_t f = 0; f < faces_.size(); ++f)
      if (faceAlive_[f]) alive.push_back(faces_[f]);
    // The bounds kept the decisions; what is reported is exact: each input vertex to its face.
    for (std::size_t f = 0; f < faces_.size(); ++f)
      if (faceAlive_[f]) {
        const Face& t = faces_[f];
        for (int x : homed_[f])
          out.inputToWorking =
              std::max(out.inputToWorking, distanceToTriangle(input_[x], pos_[t[0]], pos_[t[1]], pos_[t[2]]));
      }
    std::vector<int> remap(pos_.size(), -1);
    out.mesh = compactFaces(pos_, alive, remap);
    return out;
  }

 private:
  struct Candidate {
    double cost;
    int a, b;
    unsigned versionA;
    unsigned versionB : 31;
    unsigned ontoB : 1;  // the edge collapses onto b's position
  };
  /// The heap's order: least cost first, equal costs by vertex index (canonical, so pose-free).
  struct Later {
    bool operator()(const Candidate& x, const Candidate& y) const {
      if (x.cost != y.cost) return x.cost > y.cost;
      if (x.a != y.a) return x.a > y.a;
      return x.b > y.b;
    }
  };

  /// The edge's collapse onto the end of less quadric error (the lower index on a tie): the working
  /// vertices are input vertices, so they lie on the input, and a flat region stays exactly flat.
  void push(Lane& L, int a, int b) {
    if (a > b) std::swap(a, b);
    Quadric q = quadric_[a];
    q += quadric_[b];
    const double ea = q.error(pos_[a]), eb = q.error(pos_[b]);
    L.heap.push_back({std::min(ea, eb), a, b, version_[a], version_[b] & 0x7fffffffu, eb < ea});
    if (L.heaped) std::push_heap(L.heap.begin(), L.heap.end(), Later{});
  }

  bool stale(const Candidate& c) const {
    return version_[c.a] != c.versionA || (version_[c.b] & 0x7fffffffu) != c.versionB;
  }

  /// Vertices into slabs of about kFacesPerSlab faces' worth each, across the longest axis of the
  /// piece's frame (the canonical frame: the same slabs in every pose), by rank along it.
  void sortIntoSlabs() {
    const std::size_t n = pos_.size();
    slab_.assign(n, 0);
    slabs_ = static_cast<int>(std::clamp<std::size_t>(faces_.size() / kFacesPerSlab, 1, kMostSlabs));
    if (slabs_ == 1) return;
    Vec3 lo = pos_[0], hi = lo;
    for (const Vec3& v : pos_) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    std::vector<int> order(n);
    for (std::size_t v = 0; v < n; ++v) order[v] = static_cast<int>(v);
    std::sort(order.begin(), order.end(), [&](int u, int v) {
      return pos_[u][axis] != pos_[v][axis] ? pos_[u][axis] < pos_[v][axis] : u < v;
    });
    for (std::size_t r = 0; r < n; ++r) slab_[order[r]] = static_cast<int>(r * slabs_ / n);
  }

  /// Whether the lane may collapse an edge at v (the whole mesh's lane: every vertex).
  bool owns(const Lane& L, int v) const { return L.slab < 0 || slab_[v] == L.slab; }

  /// The lane's first candidates: every live edge it owns, once (closed, oriented), then heaped.
  void gatherEdges(Lane& L) {
    L.heap.clear();
    L.heaped = false;
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      if (!faceAlive_[f]) continue;
      const Face& t = faces_[f];
      if (L.slab >= 0) L.liveFaces += owns(L, t[0]) ? 1 : 0;
      for (int k = 0; k < 3; ++k)
        if (t[k] < t[(k + 1) % 3] && owns(L, t[k]) && owns(L, t[(k + 1) % 3])) push(L, t[k], t[(k + 1) % 3]);
    }
    if (L.slab < 0) L.liveFaces = liveFaces_;
    std::make_heap(L.heap.begin(), L.heap.end(), Later{});
    L.heaped = true;
  }

  /// Collapses the lane's candidates, cheapest first, until none is left (or the mesh is least).
  void drain(Lane& L) {
    while (!L.heap.empty() && (L.slab >= 0 || liveFaces_ > kLeastFaces)) {
      std::pop_heap(L.heap.begin(), L.heap.end(), Later{});
      const Candidate c = L.heap.back();
      L.heap.pop_back();
      if (stale(c)) continue;  // an end changed since
      if (L.heap.size() > 4 * static_cast<std::size_t>(std::max(0, L.liveFaces)) + 1024) dropStale(L);
      if (collapse(L, c)) ++L.collapses;
    }
  }

  /// Each collapse leaves the candidates of the edges it changed behind in the heap; dropping them
  /// now and then keeps the heap near the number of live edges (a smaller heap misses the cache
  /// less, and the order of the live candidates, so the result, is the same).
  void dropStale(Lane& L) {
    L.heap.erase(std::remove_if(L.heap.begin(), L.heap.end(), [&](const Candidate& c) { return stale(c); }), L.heap.end());
    std::make_heap(L.heap.begin(), L.heap.end(), Later{});
  }

  /// The live faces around v (dropping the dead ones from its list on the way).
  const std::vector<int>& facesAround(int v) {
    std::vector<int>& list = vertexFaces_[v];
    list.erase(std::remove_if(list.begin(), list.end(), [&](int f) { return !faceAlive_[f]; }), list.end());
    return list;
  }

  /// The vertices sharing a live face with v, sorted, into `out` (a buffer kept between calls:
  /// allocating it per collapse was a fifth of the simplification's instructions).
  void neighbours(int v, std::vector<int>& out) {
    out.clear();
    for (int f : facesAround(v))
      for (int u : faces_[f])
        if (u != v) out.push_back(u);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  /// Held to the input: every input vertex given a face the collapse of `c` (its ends meeting at
  /// p) moves keeps it while it stays within the tolerance (one distance), else takes the nearest
  /// new face, which must be within; the new homes go to L.rehomed. False when one is beyond.
  /// A face keeps its shape but for one corner moved by `shift`, so each of its points moves by at
  /// most `shift`: a vertex's known bound plus the shift, when within the tolerance, keeps it there
  /// without the exact distance (the same decision the exact distance would make). Faces around
  /// the end that stays do not move at all: their vertices keep their homes and bounds (every
  /// bound is within the tolerance) and are not listed.
  bool rehomeInputVertices(Lane& L, const Candidate& c, const Vec3& p) {
    const int a = c.a, b = c.b;
    const int moved = c.ontoB ? a : b;
    auto corner = [&](int v) -> const Vec3& { return v == a || v == b ? p : pos_[v]; };
    const double shift = (p - pos_[moved]).norm();
    L.rehomed.clear();
    for (int f : L.changed) {
      if (untouched(f, c)) continue;
      const bool stays = !(contains(f, a) && contains(f, b));
      const double faceShift = contains(f, moved) ? shift : 0.0;
      for (int x : homed_[f]) {
        double best = std::numeric_limits<double>::infinity();
        int home = -1;
        if (stays && bound_[x] + faceShift <= tolerance_) {
          L.rehomed.push_back({f, x, bound_[x] + faceShift});
          continue;
        }
        if (stays) {
          const Face& t = faces_[f];
          best = distanceToTriangle(input_[x], corner(t[0]), corner(t[1]), corner(t[2]));
          home = f;
        }
        if (!(best <= tolerance_))
          for (int g : L.kept) {
            const Face& t = faces_[g];
            const double d = distanceToTriangle(input_[x], corner(t[0]), corner(t[1]), corner(t[2]));
            if (d < best) best = d, home = g;
          }
        if (!(best <= tolerance_)) return false;
        L.rehomed.push_back({home, x, best});
      }
    }
    return true;
  }

  bool collapse(Lane& L, const Candidate& c) {
    const int a = c.a, b = c.b;
    const Vec3 p = c.ontoB ? pos_[b] : pos_[a];
    std::vector<int>&fa = L.fa, &fb = L.fb, &shared = L.shared, &kept = L.kept, &changed = L.changed;
    fa = facesAround(a);
    fb = facesAround(b);
    shared.clear();
    kept.clear();
    for (int f : fa) (contains(f, b) ? shared : kept).push_back(f);
    for (int f : fb)
      if (!contains(f, a)) kept.push_back(f);
    changed = kept;  // every face the collapse moves or removes
    changed.insert(changed.end(), shared.begin(), shared.end());
    if (shared.size() != 2 || (L.slab < 0 && liveFaces_ - 2 < kLeastFaces)) return false;
    // The link condition: the ends' only common neighbours are the two faces' third corners, so the
    // surface stays a manifold.
    neighbours(a, L.na);
    neighbours(b, L.nb);
    const std::vector<int>&na = L.na, &nb = L.nb;
    // A slab's lane touches nothing beyond its own vertices' faces (what makes the lanes disjoint).
    if (L.slab >= 0 && !(std::all_of(na.begin(), na.end(), [&](int v) { return owns(L, v); }) &&
                         std::all_of(nb.begin(), nb.end(), [&](int v) { return owns(L, v); })))
      return false;
    std::vector<int>& common = L.common;
    common.clear();
    std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(common));
    if (common.size() != 2) return false;

    auto corner = [&](int v) -> const Vec3& { return v == a || v == b ? p : pos_[v]; };
    for (int f : kept) {
      const Face& t = faces_[f];
      const Vec3 before = (pos_[t[1]] - pos_[t[0]]).cross(pos_[t[2]] - pos_[t[0]]);
      const Vec3 after = (corner(t[1]) - corner(t[0])).cross(corner(t[2]) - corner(t[0]));
      if (!(before.dot(after) > kLeastNormalCosine * before.norm() * after.norm())) return false;
    }
    if (!rehomeInputVertices(L, c, p)) return false;
    // And the other way: each new face stays near the input at its centroid (its corners are input
    // vertices; simplifyPieces measures more points of the result), against the input faces around its corners and around the input
    // vertices it now stands for.
    auto nearInput = [&](const Vec3& q, int g) {
      auto within = [&](int x) {
        // q within the tolerance (less a margin for rounding) of input vertex x is within it of
        // every input face around x: the search below would say so at its first face.
        if (inputFacesStart_[x] < inputFacesStart_[x + 1] &&
            (q - input_[x]).squaredNorm() <= tolerance_ * tolerance_ * (1 - 1e-9))
          return true;
        for (int k = inputFacesStart_[x]; k < inputFacesStart_[x + 1]; ++k) {
          const int face = inputFacesOf_[k];
          // Beyond the face's bounding sphere by more than the tolerance (and rounding): the exact
          // distance is skipped, with the same answer.
          const double reach = inputFaceRadius_[face] + tolerance_;
          if ((q - inputFaceCentre_[face]).squaredNorm() > reach * reach * (1 + 1e-9)) continue;
          const Face& i = inputFaces_[face];
          if (distanceToTriangle(q, input_[i[0]], input_[i[1]], input_[i[2]]) <= tolerance_) return true;
        }
        return false;
      };
      for (int v : faces_[g])
        if (within(v == a || v == b ? (c.ontoB ? b : a) : v)) return true;
      // The input vertices g stands for now: those that came to it, and, when the collapse left
      // it where it was, those it had.
      const auto from = std::lower_bound(L.rehomed.begin(), L.rehomed.end(), Rehome{g, -1, 0.0}, byFaceThenVertex);
      auto to = from;
      while (to != L.rehomed.end() && to->face == g) ++to;
      static const std::vector<int> none;
      const std::vector<int>& had = untouched(g, c) ? homed_[g] : none;
      // The input vertex nearest to q first: its faces hold q's nearest input point as a rule.
      int nearest = -1;
      double nearestDistance = std::numeric_limits<double>::infinity();
      auto nearer = [&](int x) {
        const double d = (input_[x] - q).squaredNorm();
        if (d < nearestDistance) nearestDistance = d, nearest = x;
      };
      for (auto it = from; it != to; ++it) nearer(it->vertex);
      for (int x : had) nearer(x);
      if (nearest >= 0 && within(nearest)) return true;
      for (auto it = from; it != to; ++it)
        if (it->vertex != nearest && within(it->vertex)) return true;
      for (int x : had)
        if (x != nearest && within(x)) return true;
      return false;
    };
    std::sort(L.rehomed.begin(), L.rehomed.end(), byFaceThenVertex);  // for nearInput
    for (int g : kept) {
      const Face& t = faces_[g];
      const Vec3 u = corner(t[0]), v = corner(t[1]), w = corner(t[2]);
      if (!nearInput((u + v + w) / 3.0, g)) return false;
    }

    pos_[a] = p;  // a stays, at b's position when collapsing onto b
    quadric_[a] += quadric_[b];
    for (int f : changed)
      if (!untouched(f, c)) homed_[f].clear();  // its vertices are in L.rehomed
    for (const Rehome& r : L.rehomed) homed_[r.face].push_back(r.vertex), bound_[r.vertex] = r.bound;
    for (int f : shared) faceAlive_[f] = 0;
    if (L.slab < 0)
      liveFaces_ -= 2;
    else
      L.removedFaces += 2;
    L.liveFaces -= 2;
    for (int f : fb)
      if (faceAlive_[f])
        for (int& v : faces_[f])
          if (v == b) v = a;
    std::vector<int>& around = vertexFaces_[a];
    around = kept;
    std::sort(around.begin(), around.end());
    vertexFaces_[b].clear();
    ++version_[a];
    ++version_[b];
    neighbours(a, L.na);
    for (int n : L.na)
      if (owns(L, n)) push(L, a, n);
    return true;
  }

  /// An input vertex given a face by a collapse, with an upper bound on its distance to it.
  struct Rehome {
    int face, vertex;
    double bound;
  };
  static bool byFaceThenVertex(const Rehome& x, const Rehome& y) {
    return x.face != y.face ? x.face < y.face : x.vertex < y.vertex;
  }

  /// One run of collapses: over one slab or (slab -1) over the whole mesh, with its own heap and
  /// scratch lists.
  struct Lane {
    int slab = -1;
    std::vector<Candidate> heap;  // by Later; holds stale candidates until dropStale
    bool heaped = false;          // heap is a heap (the first edges are gathered, then heaped at once)
    std::vector<Rehome> rehomed;  // a collapse's new homes
    std::vector<int> fa, fb, shared, kept, changed, na, nb, common;  // a collapse's scratch lists
    int liveFaces = 0;     // about how many faces the lane has (for dropStale)
    int removedFaces = 0;  // by a slab's lane, for liveFaces_ after the slabs
    int collapses = 0;
  };

  bool contains(int f, int v) const { return faces_[f][0] == v || faces_[f][1] == v || faces_[f][2] == v; }
  /// Whether the collapse of `c` leaves face f where it is: around the end that stays, not on the edge.
  bool untouched(int f, const Candidate& c) const { return !contains(f, c.ontoB ? c.a : c.b); }

  const std::vector<Vec3>& input_;  // the mesh given, which outlives the collapser (no copy)
  const std::vector<Face>& inputFaces_;
  std::vector<int> inputFacesStart_, inputFacesOf_;  // each input vertex's input faces (CSR)
  std::vector<Vec3> inputFaceCentre_;     // each input face's centroid
  std::vector<double> inputFaceRadius_;   // and its farthest corner from it
  std::vector<Vec3> pos_;
  std::vector<Face> faces_;
  double tolerance_;
  std::vector<char> faceAlive_;
  std::vector<std::vector<int>> vertexFaces_;
  std::vector<Quadric> quadric_;
  std::vector<unsigned> version_;
  std::vector<std::vector<int>> homed_;       // by face: the input vertices it is nearest to (as far as known)
  std::vector<double> bound_;                 // by input vertex: at least its distance to its face
  std::vector<int> slab_;  // by vertex: its slab (all 0 when there is one)
  int slabs_ = 1;
  Lane whole_;  // the serial pass over the whole mesh
  int liveFaces_ = 0;
};

}  // namespace

WorkingMesh simplifyWithin(const TriMesh& closed, double tolerance) {
  if (closed.faces.size() <= static_cast<std::size_t>(kLeastFaces) || !(tolerance > 0)) {
    WorkingMesh same;
    same.mesh = closed;

    same.tolerance = tolerance;
    return same;
  }
  return Collapser(closed, tolerance).run();
}

}  // namespace acd
