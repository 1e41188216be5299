// Self-intersection test and local repair, kept in their own translation unit: CGAL's
// Polygon_mesh_processing headers are slow to compile.
#include <acd/diagnosis.hpp>
#include <acd/repair.hpp>

#include <acd/algo/float_bounds.hpp>
#include <acd/algo/meeting_boxes.hpp>
#include <acd/algo/surface_mesh_copy.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <set>

namespace acd {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

/// A face's box in floats, rounded outward (it still contains the face): half the memory of
/// doubles, on inputs of millions of faces.
using FaceBox = CGAL::Box_intersection_d::Box_with_info_d<float, 3, int, CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS>;

FloatBox floatBoxOf(const TriMesh& mesh, int f) {
  const Face& t = mesh.faces[f];
  return acd::floatBoxOf(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
}

FaceBox boxOf(const TriMesh& mesh, int f) {
  FloatBox b = floatBoxOf(mesh, f);
  return FaceBox(b.lo.data(), b.hi.data(), f);
}

/// Sign tests in doubles that are certain where their value stands clear of its rounding error
/// by a wide margin, and say nothing otherwise: they spare the exact predicates most of the face
/// pairs of a dense mesh (neighbours in one plane, the commonest, are exact ties for them).
/// Products of four lengths stay far from double's overflow and underflow, or no test is made.
bool certainlyBelow(double value, double scale) {
  return scale > 1e-250 && scale < 1e250 && value < -1e-9 * scale;
}

/// Whether the points lie certainly on the far side of one of the triangle's planes: its own
/// plane (either side), or the plane through one of its edges, perpendicular to it, away from the
/// third corner. Then the points (and their convex hull) miss the triangle.
bool certainlyApart(const Vec3* t, const Vec3* points, int count) {
  const Vec3 u = t[1] - t[0], w = t[2] - t[0];
  const Vec3 n = u.cross(w);
  const double un = u.norm() * w.norm();
  bool above = true, below = true;
  for (int k = 0; k < count; ++k) {
    const Vec3 d = points[k] - t[0];
    const double side = d.dot(n), scale = un * d.norm();
    above = above && certainlyBelow(-side, scale);
    below = below && certainlyBelow(side, scale);
  }
  if (above || below) return true;
  for (int e = 0; e < 3; ++e) {
    const Vec3 &from = t[e], &to = t[(e + 1) % 3];
    const Vec3 inward = n.cross(to - from);  // toward the third corner, in the triangle's plane
    const double edgeScale = un * (to - from).norm();
    bool outside = true;
    for (int k = 0; k < count && outside; ++k) {
      const Vec3 d = points[k] - from;
      outside = certainlyBelow(d.dot(inward), edgeScale * d.norm());
    }
    if (outside) return true;
  }
  return false;
}

/// Faces sharing one corner v, the other corners of `a` (aOthers) and of `b` (bOthers): whether a
/// plane through v certainly has a's on one side and b's on the other. Then the two meet at v
/// only (each lies on its side, touching the plane at v alone). The plane's normal points from b's
/// middle towards a's, as seen from v: in a fan of faces in one plane (a dense scan's, or a
/// subdivided mesh's, where a face's neighbours across v lie almost on its edges' lines and the
/// edge planes of certainlyApart are no certain test), this separates every pair not side by side.
bool certainlyMeetAtCornerOnly(const Vec3& v, const Vec3* aOthers, const Vec3* bOthers) {
  const Vec3 towardA = aOthers[0] + aOthers[1] - 2 * v, towardB = bOthers[0] + bOthers[1] - 2 * v;
  const double lengthA = towardA.norm(), lengthB = towardB.norm();
  if (!(lengthA > 0) || !(lengthB > 0)) return false;
  const Vec3 n = towardA / lengthA - towardB / lengthB;
  const double nn = n.norm();
  for (int k = 0; k < 2; ++k) {
    const Vec3 da = aOthers[k] - v, db = bOthers[k] - v;
    if (!certainlyBelow(-da.dot(n), da.norm() * nn) || !certainlyBelow(db.dot(n), db.norm() * nn)) return false;
  }
  return true;
}

/// Whether faces f and g cross other than along the edge or at the vertex they share (CGAL's
/// rule): faces on one edge cross where they fold onto each other (coplanar, the third corners on
/// one side of it); faces on one vertex where an edge of either, away from it, meets the other.
bool facesCross(const TriMesh& mesh, int f, int g) {
  const Face &a = mesh.faces[f], &b = mesh.faces[g];
  auto point = [&](int v) {
    const Vec3& p = mesh.vertices[v];
    return K::Point_3(p.x(), p.y(), p.z());
  };
  int sharedA[3], sharedB[3], shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (a[i] == b[j]) sharedA[shared] = i, sharedB[shared] = j, ++shared;
  const Vec3 pa[3] = {mesh.vertices[a[0]], mesh.vertices[a[1]], mesh.vertices[a[2]]};
  const Vec3 pb[3] = {mesh.vertices[b[0]], mesh.vertices[b[1]], mesh.vertices[b[2]]};
  if (shared == 0 && (certainlyApart(pa, pb, 3) || certainlyApart(pb, pa, 3))) return false;
  if (shared == 2) {
    // Folded onto each other, the two (oriented alike) face opposite ways: normals pointing
    // certainly alike rule that out.
    const Vec3 da1 = pa[1] - pa[0], da2 = pa[2] - pa[0], db1 = pb[1] - pb[0], db2 = pb[2] - pb[0];
    const double scale = da1.norm() * da2.norm() * db1.norm() * db2.norm();
    if (certainlyBelow(-da1.cross(da2).dot(db1.cross(db2)), scale)) return false;
  }
  const K::Triangle_3 ta(point(a[0]), point(a[1]), point(a[2])), tb(point(b[0]), point(b[1]), point(b[2]));
  if (shared >= 2) {
    const int i = sharedA[0], j = sharedA[1];
    const K::Point_3 p = point(a[i]), q = point(a[j]), r = point(a[3 - i - j]);
    const K::Point_3 s = point(b[3 - sharedB[0] - sharedB[1]]);
    return CGAL::coplanar(p, q, r, s) && CGAL::coplanar_orientation(p, q, r, s) == CGAL::POSITIVE;
  }
  if (shared == 1) {
    const int i = sharedA[0], j = sharedB[0];
    const Vec3 farA[2] = {pa[(i + 1) % 3], pa[(i + 2) % 3]}, farB[2] = {pb[(j + 1) % 3], pb[(j + 2) % 3]};
    if (certainlyMeetAtCornerOnly(pa[i], farA, farB)) return false;
    const K::Segment_3 awayA(point(a[(i + 1) % 3]), point(a[(i + 2) % 3]));
    const K::Segment_3 awayB(point(b[(j + 1) % 3]), point(b[(j + 2) % 3]));
    return (!certainlyApart(pa, farB, 2) && CGAL::do_intersect(ta, awayB)) ||
           (!certainlyApart(pb, farA, 2) && CGAL::do_intersect(tb, awayA));
  }
  return CGAL::do_intersect(ta, tb);
}

/// The box search stops, by throwing, once the limit is reached.
struct LimitReached {};

/// Exact predicates need finite coordinates (the repairs refuse others; the report's count runs
/// on the input as read).
bool allFinite(const TriMesh& mesh) {
  return std::all_of(mesh.vertices.begin(), mesh.vertices.end(), [](const Vec3& p) { return p.allFinite(); });
}

bool degenerate(const TriMesh& mesh, int f) {
  const Face& t = mesh.faces[f];
  const Vec3 &p = mesh.vertices[t[0]], &q = mesh.vertices[t[1]], &r = mesh.vertices[t[2]];
  return CGAL::collinear(K::Point_3(p.x(), p.y(), p.z()), K::Point_3(q.x(), q.y(), q.z()), K::Point_3(r.x(), r.y(), r.z()));
}

}  // namespace

int countSelfIntersections(const TriMesh& mesh, int limit) {
  if (!isOrientedEdgeManifold(mesh.faces) || !allFinite(mesh)) return -1;  // not a surface to count on
  if (limit == 0) return 0;
  // A degenerate face counts as crossing itself (as CGAL's self_intersections reports it).
  int count = 0;
  std::vector<FloatBox> boxes;
  std::vector<int> faceOf;  // by box
  boxes.reserve(mesh.faces.size());
  faceOf.reserve(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (degenerate(mesh, static_cast<int>(f))) {
      if (++count == limit) return count;
      continue;
    }
    boxes.push_back(floatBoxOf(mesh, static_cast<int>(f)));
    faceOf.push_back(static_cast<int>(f));
  }
  // One thread: the search runs beside the decomposition (describeInput). Every pair of faces
  // that cross has boxes that meet, and each such pair comes once, so the count is of the set,
  // whichever search lists the pairs. A grid lists them at a fraction of the cost of CGAL's
  // general search on a mesh's faces, most of them of one size; boxes too unlike for a grid
  // (a few faces across the whole model among many small ones) go to CGAL's.
  try {
    auto cross = [&](int x, int y) {
      if (facesCross(mesh, faceOf[x], faceOf[y]) && ++count == limit) throw LimitReached{};
    };
    if (!forEachMeetingPair(boxes, cross)) {
      std::vector<FaceBox> cgalBoxes;
      cgalBoxes.reserve(boxes.size());
      for (std::size_t b = 0; b < boxes.size(); ++b) cgalBoxes.emplace_back(boxes[b].lo.data(), boxes[b].hi.data(), faceOf[b]);
      std::vector<const FaceBox*> pointers;
      pointers.reserve(cgalBoxes.size());
      for (const FaceBox& b : cgalBoxes) pointers.push_back(&b);
      CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
          pointers.begin(), pointers.end(),
          [&](const FaceBox* x, const FaceBox* y) {
            if (facesCross(mesh, x->info(), y->info()) && ++count == limit) throw LimitReached{};
          },
          std::ptrdiff_t(2000));
    }
  } catch (const LimitReached&) {
  }
  return count;
}

std::vector<int> facesCrossingOthers(const TriMesh& mesh, const std::vector<int>& among) {
  if (!isOrientedEdgeManifold(mesh.faces) || !allFinite(mesh)) return among;  // no rule applies: all suspect
  std::vector<char> crosses(mesh.faces.size(), 0);
  std::vector<FaceBox> some, all;
  for (int f : among) {
    if (degenerate(mesh, f))
      crosses[f] = 1;
    else
      some.push_back(boxOf(mesh, f));
  }
  // Only faces whose box meets the box around all of `among` can meet one of theirs: a few patch
  // faces on a scan of a million then sort a few boxes, not the whole mesh's.
  FloatBox around{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  for (const FaceBox& b : some)
    for (int k = 0; k < 3; ++k) around.lo[k] = std::min(around.lo[k], b.min_coord(k)), around.hi[k] = std::max(around.hi[k], b.max_coord(k));
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    if (degenerate(mesh, static_cast<int>(f))) continue;
    FloatBox b = floatBoxOf(mesh, static_cast<int>(f));
    if (boxesMeet(b, around)) all.push_back(FaceBox(b.lo.data(), b.hi.data(), static_cast<int>(f)));
  }
  std::vector<const FaceBox*> somePointers, allPointers;
  for (const FaceBox& b : some) somePointers.push_back(&b);
  for (const FaceBox& b : all) allPointers.push_back(&b);
  CGAL::box_intersection_d<CGAL::Sequential_tag>(
      somePointers.begin(), somePointers.end(), allPointers.begin(), allPointers.end(),
      [&](const FaceBox* x, const FaceBox* y) {
        const int f = x->info(), g = y->info();
        if (f != g && !crosses[f] && facesCross(mesh, f, g)) crosses[f] = 1;
      },
      std::ptrdiff_t(2000));
  std::vector<int> out;
  for (int f : among)
    if (crosses[f]) out.push_back(f);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Untangled removeSelfIntersections(const TriMesh& shell) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SM = CGAL::Surface_mesh<K::Point_3>;
  Untangled out;
  SM sm;
  if (copyToSurfaceMesh(shell, sm) >= 0) {
    out.status = Status::error(StatusCode::NonManifoldEdge, "not a manifold surface");
    return out;
  }
  try {
    // Keeping the genus and allowing patches up to 90 degrees from their rim: cow's tail reaches
    // 0.018 normalised units outside the result, against 0.034 with CGAL's defaults.
    const bool fixed = CGAL::Polygon_mesh_processing::experimental::remove_self_intersections(
        sm, CGAL::parameters::preserve_genus(true).with_dihedral_angle(90.0));
    if (!fixed || CGAL::Polygon_mesh_processing::does_self_intersect(sm)) {
      out.status = Status::error(StatusCode::InternalError, "self-intersections remain");
      return out;
    }
  } catch (const std::exception& e) {
    out.status = Status::error(StatusCode::InternalError, std::string("removing self-intersections failed: ") + e.what());
    return out;
  }
  sm.collect_garbage();
  out.mesh = copyFromSurfaceMesh(sm);
  // Faces kept from the input, by their corners' positions (a face whose corner moved counts as replaced).
  using Corners = std::array<double, 9>;
  auto key = [](const TriMesh& m, const Face& f) {
    const int first = static_cast<int>(std::min_element(f.begin(), f.end(), [&](int a, int b) {
                        return std::lexicographical_compare(m.vertices[a].data(), m.vertices[a].data() + 3,
                                                            m.vertices[b].data(), m.vertices[b].data() + 3);
                      }) - f.begin());
    Corners c;
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) c[3 * k + i] = m.vertices[f[(first + k) % 3]][i];
    return c;
  };
  std::set<Corners> before;
  for (const Face& f : shell.faces) before.insert(key(shell, f));
  int kept = 0;
  for (const Face& f : out.mesh.faces) kept += before.count(key(out.mesh, f)) > 0;
  out.facesReplaced = static_cast<int>(shell.faces.size()) - kept;
  if (!isClosedOriented(out.mesh) || !(signedVolume(out.mesh) > 0.0)) {
    out.status = Status::error(StatusCode::OpenMesh, "the repaired surface is not closed");
    return out;
  }
  out.status = Status::success();
  return out;
}

}  // namespace acd
