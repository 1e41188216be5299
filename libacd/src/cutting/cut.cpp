// Plane cut with capped cross-sections. The only CGAL part is the 2-D constrained
// Delaunay triangulation of the section, whose exact predicates make the cap
// triangulation reliable; its no-intersection tag turns a broken section into a
// clean failure instead of a silently wrong mesh.
#include <acd/algo/union_find.hpp>
#include <acd/algo/cut.hpp>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <list>
#include <numeric>
#include <unordered_map>

namespace acd {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<int, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;

/// Triangulates the region bounded by the directed section edges (ccw around the
/// region seen from +normal). Returns false when the loops are not simple and disjoint.
bool triangulateSection(const std::vector<Vec3>& points, const std::vector<std::pair<int, int>>& edges,
                        const Vec3& normal, std::vector<Face>& cap, std::string& error) {
  const Vec3 n = normal.normalized();
  const Vec3 u = n.unitOrthogonal();
  const Vec3 w = n.cross(u);  // (u, w, n) right-handed: ccw in (u, w) is ccw seen from +n
  // CGAL's default generator is per thread and steers point location: reset it so the cap
  // triangulation (not unique for cocircular points) does not depend on which thread runs it.
  CGAL::get_default_random() = CGAL::Random(0);
  CDT cdt;
  std::unordered_map<int, CDT::Vertex_handle> handle;
  try {
    for (const auto& [a, b] : edges)
      for (int v : {a, b}) {
        if (handle.count(v)) continue;
        const Vec3& p = points[v];
        const auto before = cdt.number_of_vertices();
        auto vh = cdt.insert(K::Point_2(u.dot(p), w.dot(p)));
        if (cdt.number_of_vertices() == before) {
          error = "two section vertices project to the same point";
          return false;
        }
        vh->info() = v + 1;
        handle[v] = vh;
      }
    for (const auto& [a, b] : edges) cdt.insert_constraint(handle[a], handle[b]);
  } catch (const std::exception&) {
    error = "section loops intersect";
    return false;
  }
  if (static_cast<std::size_t>(cdt.number_of_vertices()) != handle.size()) {
    error = "section vertices merged";
    return false;
  }
  // Nesting depth by flooding from the infinite face; odd depth = inside the section.
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::list<CDT::Face_handle> frontier{cdt.infinite_face()};
  cdt.infinite_face()->info() = 0;
  std::list<CDT::Face_handle> next;
  for (int depth = 0; !frontier.empty(); ++depth) {
    while (!frontier.empty()) {
      auto f = frontier.front();
      frontier.pop_front();
      for (int i = 0; i < 3; ++i) {
        auto g = f->neighbor(i);
        if (g->info() != -1) continue;
        if (cdt.is_constrained(CDT::Edge(f, i))) {
          g->info() = depth + 1;
          next.push_back(g);
        } else {
          g->info() = depth;
          frontier.push_back(g);
        }
      }
    }
    frontier.swap(next);
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1)
      cap.push_back({f->vertex(0)->info() - 1, f->vertex(1)->info() - 1, f->vertex(2)->info() - 1});
  // Every constrained edge must be used by the cap in the loop's direction, else the loops
  // were oriented against their nesting (a sign the section is not what we think).
  std::unordered_map<std::uint64_t, int> directed;
  for (const Face& f : cap)
    for (int k = 0; k < 3; ++k)
      directed[(static_cast<std::uint64_t>(f[k]) << 32) | static_cast<std::uint32_t>(f[(k + 1) % 3])]++;
  for (const auto& [a, b] : edges)
    if (!directed.count((static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b))) {
      error = "section loops are inconsistently nested";
      return false;
    }
  return true;
}

/// A section region away from the notch is cut too when both its sides are at least this share of
/// the mesh's volume (measured with compare_peers: docs/ALGORITHM.md section 10).
constexpr double kLargePiece = 0.1;

/// Cap regions: cap faces joined across shared edges (`regions`, over the faces). Returns their
/// number; `keep` is the region with the corner nearest `near` (ties: the smaller root).
int capRegions(const std::vector<Vec3>& points, const std::vector<Face>& cap, const Vec3& near, UnionFind& regions,
               int& keep) {
  const int nc = static_cast<int>(cap.size());
  std::unordered_map<std::uint64_t, int> firstAt;
  for (int f = 0; f < nc; ++f)
    for (int k = 0; k < 3; ++k) {
      auto [it, inserted] = firstAt.emplace(edgeKey(cap[f][k], cap[f][(k + 1) % 3]), f);
      if (!inserted) regions.join(f, it->second);
    }
  int count = 0;
  keep = -1;
  double best = std::numeric_limits<double>::infinity();
  for (int f = 0; f < nc; ++f) {
    const int r = regions.find(f);
    count += r == f;
    for (int v : cap[f]) {
      const double d = (points[v] - near).squaredNorm();
      if (d < best || (d == best && r < keep)) best = d, keep = r;
    }
  }
  return count;
}

/// The cut through the cap region nearest `near`, and through the other regions between large
/// pieces: the surface stays whole across the rest. Fills `result` and returns true when that
/// gives at least two closed pieces and not every region is cut; false (result untouched) when
/// the section has one region, or when some piece would meet itself across a cut region (a
/// handle), so that the caller cuts everywhere.
bool cutNear(const std::vector<Vec3>& points, const std::vector<Face>& below, const std::vector<Face>& above,
             const std::vector<Face>& cap, const Vec3& near, CutResult& result) {
  const int nc = static_cast<int>(cap.size());
  UnionFind regions(nc);
  int keep = -1;
  if (capRegions(points, cap, near, regions, keep) < 2) return false;
  // Faces: lower surface, upper surface, then every region's cap on each side.
  std::vector<Face> faces = below;
  std::vector<signed char> sideOf(below.size(), -1);
  faces.insert(faces.end(), above.begin(), above.end());
  sideOf.resize(faces.size(), 1);
  std::vector<int> regionOf(faces.size(), -1);
  for (int f = 0; f < nc; ++f) {
    const int r = regions.find(f);
    faces.push_back(cap[f]), sideOf.push_back(-1), regionOf.push_back(r);
    faces.push_back({cap[f][0], cap[f][2], cap[f][1]}), sideOf.push_back(1), regionOf.push_back(r);
  }
  const int nf = static_cast<int>(faces.size());
  std::vector<std::pair<std::uint64_t, int>> at;  // (edge, face), sorted: an edge's faces side by side
  at.reserve(3 * faces.size());
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) at.emplace_back(edgeKey(faces[f][k], faces[f][(k + 1) % 3]), f);
  std::sort(at.begin(), at.end());
  // Pieces of the faces `in`, joined across their edges: an edge with two faces joins them; an
  // edge of a cut region (its outline or inside it) has four, joined side by side.
  UnionFind piece(nf);
  auto pieces = [&](const std::vector<char>& in) {
    piece = UnionFind(nf);
    auto join = [&](int a, int b) { piece.join(a, b); };
    int list[4];
    for (std::size_t i = 0, j; i < at.size(); i = j) {
      int n = 0;
      for (j = i; j < at.size() && at[j].first == at[i].first; ++j)
        if (in[at[j].second]) {
          if (n == 4) return false;
          list[n++] = at[j].second;
        }
      if (n == 2) {
        join(list[0], list[1]);
      } else if (n == 4) {
        int lower[2], upper[2], nl = 0, nu = 0;
        for (int f : list) {
          if (sideOf[f] < 0 && nl < 2) lower[nl++] = f;
          else if (sideOf[f] > 0 && nu < 2) upper[nu++] = f;
          else return false;
        }
        join(lower[0], lower[1]);
        join(upper[0], upper[1]);
      } else if (n != 0) {
        return false;
      }
    }
    return true;
  };
  // Which regions are cut: the one at the notch, and any other whose two sides would both be
  // pieces of at least kLargePiece of the whole when every region is cut (a plane across a body
  // and its legs: the legs would need their own cuts; a fingertip would not).
  std::vector<char> cutRegion(nc, 0);
  cutRegion[keep] = 1;
  if (!pieces(std::vector<char>(nf, 1))) return false;
  std::vector<double> volume(nf, 0.0);
  double total = 0.0;
  for (int f = 0; f < nf; ++f) {
    const double v = points[faces[f][0]].dot(points[faces[f][1]].cross(points[faces[f][2]])) / 6.0;
    volume[piece.find(f)] += v;
    if (regionOf[f] < 0) total += v;
  }
  std::vector<int> lowerPiece(nc, -1), upperPiece(nc, -1);
  for (int f = static_cast<int>(below.size() + above.size()); f < nf; ++f)
    (sideOf[f] < 0 ? lowerPiece : upperPiece)[regionOf[f]] = piece.find(f);
  bool all = true;
  for (int r = 0; r < nc; ++r) {
    if (lowerPiece[r] < 0 || r == keep) continue;
    cutRegion[r] = std::min(volume[lowerPiece[r]], volume[upperPiece[r]]) >= kLargePiece * total;
    all &= cutRegion[r] != 0;
  }
  if (all) return false;  // the plain cut
  std::vector<char> in(nf, 1);
  for (int f = 0; f < nf; ++f)
    if (regionOf[f] >= 0 && !cutRegion[regionOf[f]]) in[f] = 0;
  if (!pieces(in)) return false;
  // A handle: some piece would meet itself across a cut region; cut them all.
  for (int f = static_cast<int>(below.size() + above.size()); f < nf; f += 2)
    if (in[f] && piece.find(f) == piece.find(f + 1)) return false;
  // Pieces in the order of their first face; a piece is "below" when it holds the kept region's
  // lower cap.
  std::vector<int> index(nf, -1);
  std::vector<std::vector<Face>> groups;
  std::vector<char> lowerSide;
  for (int f = 0; f < nf; ++f) {
    if (!in[f]) continue;
    int& g = index[piece.find(f)];
    if (g < 0) g = static_cast<int>(groups.size()), groups.emplace_back(), lowerSide.push_back(0);
    groups[g].push_back(faces[f]);
    if (regionOf[f] == keep && sideOf[f] < 0) lowerSide[g] = 1;
  }
  if (groups.size() < 2) return false;
  CutResult out;
  std::vector<int> remap(points.size(), -1);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    TriMesh m = compactFaces(points, groups[g], remap);
    if (!isClosedOriented(m)) return false;
    (lowerSide[g] ? out.below : out.above).push_back(std::move(m));
  }
  out.ok = true;
  result = std::move(out);
  return true;
}

}  // namespace

CutResult cutByPlane(const TriMesh& mesh, const Plane& plane, double snap, const Vec3* near) {
  CutResult result;
  const double len = plane.normal.norm();
  if (!(len > 0.0) || !std::isfinite(plane.offset)) {
    result.error = "invalid plane";
    return result;
  }
  const Vec3 n = plane.normal / len;
  const double offset = plane.offset / len;
  std::vector<Vec3> points = mesh.vertices;
  std::vector<double> dist(points.size());
  std::vector<int> side(points.size());
  bool anyBelow = false, anyAbove = false;
  for (std::size_t v = 0; v < points.size(); ++v) {
    dist[v] = n.dot(points[v]) - offset;
    side[v] = std::abs(dist[v]) <= snap ? 0 : (dist[v] < 0 ? -1 : 1);
    anyBelow |= side[v] < 0;
    anyAbove |= side[v] > 0;
  }
  if (!anyBelow || !anyAbove) {  // nothing to cut: the whole mesh is on one side
    (anyAbove ? result.above : result.below).push_back(mesh);
    result.ok = true;
    return result;
  }

  std::unordered_map<std::uint64_t, int> crossing;
  auto crossPoint = [&](int a, int b) {
    auto [it, inserted] = crossing.emplace(edgeKey(a, b), static_cast<int>(points.size()));
    if (inserted) {
      const int lo = std::min(a, b), hi = std::max(a, b);  // same point whichever face asks first
      const double t = dist[lo] / (dist[lo] - dist[hi]);
      points.push_back(points[lo] + t * (points[hi] - points[lo]));
      side.push_back(0);
      dist.push_back(0.0);
    }
    return it->second;
  };

  std::vector<Face> below, above;
  auto emit = [&](int s, Face f) { (s < 0 ? below : above).push_back(f); };
  for (const Face& f : mesh.faces) {
    const int s0 = side[f[0]], s1 = side[f[1]], s2 = side[f[2]];
    const bool hasBelow = s0 < 0 || s1 < 0 || s2 < 0, hasAbove = s0 > 0 || s1 > 0 || s2 > 0;
    if (!hasBelow && !hasAbove) {  // in the plane: the solid lies on the side opposite its normal
      const Vec3 fn = (points[f[1]] - points[f[0]]).cross(points[f[2]] - points[f[0]]);
      emit(fn.dot(n) > 0 ? -1 : 1, f);
    } else if (!hasAbove) {
      emit(-1, f);
    } else if (!hasBelow) {
      emit(1, f);
    } else {
      // Rotate so that f[0] is the vertex alone on its side (or the one in the plane).
      int r = 0;
      for (int k = 0; k < 3; ++k) {
        const int sk = side[f[k]], sa = side[f[(k + 1) % 3]], sb = side[f[(k + 2) % 3]];
        if (sk == 0 || (sa == sb && sa == -sk)) r = k;
      }
      const int a = f[r], b = f[(r + 1) % 3], c = f[(r + 2) % 3];
      if (side[a] == 0) {
        const int p = crossPoint(b, c);
        emit(side[b], {a, b, p});
        emit(side[c], {a, p, c});
      } else {
        const int p = crossPoint(a, b), q = crossPoint(a, c);
        emit(side[a], {a, p, q});
        emit(side[b], {p, b, c});
        emit(side[b], {p, c, q});
      }
    }
  }

  // The section: edges of the lower surface without a twin in it. The cap of the lower part
  // runs them backwards (its normal is +n). The input is closed, so only edges in the plane can
  // lack a twin; the closure check below catches an input that is not.
  std::unordered_map<std::uint64_t, int> directed;
  auto inPlane = [&](int a, int b) { return side[a] == 0 && side[b] == 0; };
  for (const Face& f : below)
    for (int k = 0; k < 3; ++k)
      if (inPlane(f[k], f[(k + 1) % 3]))
        directed[(static_cast<std::uint64_t>(f[k]) << 32) | static_cast<std::uint32_t>(f[(k + 1) % 3])]++;
  std::vector<std::pair<int, int>> section;
  for (const Face& f : below)
    for (int k = 0; k < 3; ++k) {
      const int a = f[k], b = f[(k + 1) % 3];
      if (inPlane(a, b) && !directed.count((static_cast<std::uint64_t>(b) << 32) | static_cast<std::uint32_t>(a)))
        section.emplace_back(b, a);
    }
  std::vector<Face> cap;
  if (!section.empty() && !triangulateSection(points, section, n, cap, result.error)) return result;
  if (near && cutNear(points, below, above, cap, *near, result)) return result;
  for (const Face& f : cap) {
    below.push_back(f);
    above.push_back({f[0], f[2], f[1]});
  }
  const TriMesh lower{points, below}, upper{points, above};
  if (!isClosedOriented(lower) || !isClosedOriented(upper)) {
    result.error = "cut pieces are not closed";
    return result;
  }
  result.below = splitEdgeConnected(lower);
  result.above = splitEdgeConnected(upper);
  result.ok = true;
  return result;
}

}  // namespace acd
