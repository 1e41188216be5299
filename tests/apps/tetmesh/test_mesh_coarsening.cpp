// Coarsening refined meshes by edge collapses: shapes whose answers are known (flat boxes, a
// sphere), checked with the tests' own angles, volumes, conformity and distances.
#include "mesh_coarsening.hpp"
#include "region_refiner.hpp"
#include "tet_checks.hpp"

#include <acd/algo/closest_point.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

using namespace tetmesh;

namespace {

TetMesh refined(const std::vector<acd::TriMesh>& regions, double facetDistance) {
  RefineOptions o;
  o.facetDistance = facetDistance;
  o.closedGap = facetDistance;
  o.sliverMove = 0.5 * facetDistance;
  RefineResult r = refineRegions(regions, o);
  EXPECT_TRUE(r.ok) << r.error;
  return r.mesh;
}

double smallestAngle(const TetMesh& m) {
  double smallest = 180.0;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) smallest = std::min(smallest, tmtest::smallestDihedralDegrees(m, t));
  return smallest;
}

double volume(const TetMesh& m, int label) {
  double v = 0.0;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) {
    if (m.labels[t] != label) continue;
    const auto& q = m.tets[t];
    v += (m.points[q[1]] - m.points[q[0]]).cross(m.points[q[2]] - m.points[q[0]]).dot(m.points[q[3]] - m.points[q[0]]) / 6.0;
  }
  return v;
}

/// Boundary triangles (one tet) of the mesh, from its tets.
std::vector<std::array<int, 3>> boundary(const TetMesh& m) {
  std::vector<std::array<int, 3>> b;
  for (const auto& [f, tets] : tmtest::tetFaces(m))
    if (tets.size() == 1) b.push_back(f);
  return b;
}

/// Every face shared by at most two tets, and every tet positive.
void expectConforming(const TetMesh& m) {
  for (const auto& [f, tets] : tmtest::tetFaces(m)) EXPECT_LE(tets.size(), 2u);
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) EXPECT_GT(tetVolume(m, t), 0.0) << "tet " << t;
}

double distanceToTriangles(const Vec3& p, const TetMesh& m, const std::vector<std::array<int, 3>>& faces) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& f : faces)
    best = std::min(best, (p - acd::closestPointOnTriangle(p, m.points[f[0]], m.points[f[1]], m.points[f[2]])).norm());
  return best;
}

}  // namespace

TEST(MeshCoarsening, TwoBoxesKeepTheirFlatInterfaceAndVolumeWithFewerTets) {
  const std::vector<acd::TriMesh> boxes = {acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)),
                                           acd::shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1))};
  const double d = 0.02;
  TetMesh m = refined(boxes, d);
  const TetMesh before = m;
  CoarsenOptions o;
  o.maxDistance = d;
  const CoarsenResult r = coarsenMesh(m, o);
  EXPECT_EQ(r.tetsBefore, static_cast<int>(before.tets.size()));
  EXPECT_EQ(r.tetsAfter, static_cast<int>(m.tets.size()));
  EXPECT_LT(m.tets.size(), before.tets.size() * 3 / 4);
  std::printf("[ boxes    ] %zu -> %zu tets, %zu -> %zu points, smallest angle %.2f -> %.2f\n", before.tets.size(), m.tets.size(),
              before.points.size(), m.points.size(), smallestAngle(before), smallestAngle(m));
  expectConforming(m);
  // Tets made by a collapse stay within [10, 170]; others keep the angle they had.
  EXPECT_GE(smallestAngle(m), std::min(10.0, smallestAngle(before)) - 1e-9);
  // Collapses move no point: every point is one of the refinement's.
  for (const Vec3& p : m.points) EXPECT_NE(std::find(before.points.begin(), before.points.end(), p), before.points.end());
  // The interface stays on x = 1 (away from its rim, which the refinement rounds) and is made of
  // the refinement's interface points.
  std::set<int> interfaceBefore;
  for (std::size_t f = 0; f < before.faces.size(); ++f)
    if (before.faceMarkers[f] == kInterfaceFacet) interfaceBefore.insert(before.faces[f].begin(), before.faces[f].end());
  int interface = 0;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (m.faceMarkers[f] != kInterfaceFacet) continue;
    ++interface;
    for (int v : m.faces[f]) {
      const Vec3& p = m.points[v];
      bool was = false;
      for (int w : interfaceBefore) was = was || before.points[w] == p;
      EXPECT_TRUE(was) << p.transpose();
      if (std::min({p.y(), 1 - p.y(), p.z(), 1 - p.z()}) > 2 * d) EXPECT_NEAR(p.x(), 1.0, 1e-5);
    }
  }
  EXPECT_GT(interface, 0);
  // Each box keeps its volume within its surface area times the distances allowed (refinement
  // and collapses), and no more than it had.
  for (int label : {1, 2}) {
    EXPECT_LE(volume(m, label), 1.0 + 1e-9);
    EXPECT_GE(volume(m, label), 1.0 - 6.0 * (d + o.maxDistance)) << "label " << label;
  }
  // Every starting boundary point within the allowed distance of the coarse boundary.
  const std::vector<std::array<int, 3>> after = boundary(m);
  double farthest = 0.0;
  for (const auto& f : boundary(before))
    for (int v : f) farthest = std::max(farthest, distanceToTriangles(before.points[v], m, after));
  EXPECT_LE(farthest, o.maxDistance * (1 + 1e-9));
  EXPECT_LE(r.farthest, o.maxDistance);
}

TEST(MeshCoarsening, ASphereStaysWithinTheDistanceAndWellShaped) {
  // A sphere of radius 1 meshed within 0.02, coarsened by 0.03 more: every surface point the
  // refinement put on it within 0.03 of the coarse surface; every corner still on the sphere.
  const acd::TriMesh sphere = acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, 4);
  TetMesh m = refined({sphere}, 0.02);
  const TetMesh before = m;
  CoarsenOptions o;
  o.maxDistance = 0.03;
  const CoarsenResult r = coarsenMesh(m, o);
  std::printf("[ sphere   ] %d -> %d tets, farthest %.4f\n", r.tetsBefore, r.tetsAfter, r.farthest);
  EXPECT_LT(r.tetsAfter, r.tetsBefore);
  expectConforming(m);
  EXPECT_GE(smallestAngle(m), std::min(10.0, smallestAngle(before)) - 1e-9);
  const std::vector<std::array<int, 3>> after = boundary(m);
  for (const auto& f : after)
    for (int v : f) EXPECT_NEAR(m.points[v].norm(), 1.0, 0.01);  // the icosphere's faces lie within 0.01 of the sphere
  for (const auto& f : boundary(before))
    for (int v : f) EXPECT_LE(distanceToTriangles(before.points[v], m, after), o.maxDistance * (1 + 1e-9));
  // One closed surface still: every boundary edge on exactly two boundary triangles.
  std::map<std::pair<int, int>, int> edges;
  for (const auto& f : after)
    for (int k = 0; k < 3; ++k) ++edges[{std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3])}];
  std::set<int> corners;
  for (const auto& f : after) corners.insert(f.begin(), f.end());
  for (const auto& [e, n] : edges) EXPECT_EQ(n, 2);
  EXPECT_EQ(static_cast<long>(corners.size()) - static_cast<long>(edges.size()) + static_cast<long>(after.size()), 2);  // a sphere
}

TEST(MeshCoarsening, TheSameMeshGivesTheSameResult) {
  const TetMesh start = refined({acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 1))}, 0.05);
  TetMesh a = start, b = start;
  CoarsenOptions o;
  o.maxDistance = 0.05;
  coarsenMesh(a, o);
  coarsenMesh(b, o);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.labels, b.labels);
}

TEST(MeshCoarsening, NoDistanceAllowedLeavesTheSurfaceAlone) {
  // With no room to move the surface only inner points may go: the boundary stays as it was.
  const TetMesh start = refined({acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, 3)}, 0.02);
  TetMesh m = start;
  CoarsenOptions o;
  o.maxDistance = 0.0;
  coarsenMesh(m, o);
  auto sorted = [](const TetMesh& mesh) {
    std::vector<std::array<double, 9>> faces;
    for (const auto& f : boundary(mesh)) {
      std::array<Vec3, 3> c{mesh.points[f[0]], mesh.points[f[1]], mesh.points[f[2]]};
      std::sort(c.begin(), c.end(), [](const Vec3& x, const Vec3& y) {
        return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
      });
      faces.push_back({c[0].x(), c[0].y(), c[0].z(), c[1].x(), c[1].y(), c[1].z(), c[2].x(), c[2].y(), c[2].z()});
    }
    std::sort(faces.begin(), faces.end());
    return faces;
  };
  EXPECT_EQ(sorted(m), sorted(start));
  expectConforming(m);
}

TEST(MeshCoarsening, AVolumeFloorIsKept) {
  // Collapses on a sphere cut its curve and lose volume; with a floor at 99.5 % of the refined
  // volume they stop there.
  const TetMesh start = refined({acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, 4)}, 0.02);
  const double before = volume(start, 1);
  CoarsenOptions o;
  o.maxDistance = 0.05;
  TetMesh free = start;
  coarsenMesh(free, o);
  EXPECT_LT(volume(free, 1), 0.995 * before);  // without the floor it goes below
  o.minVolume = {0.995 * before};
  TetMesh held = start;
  coarsenMesh(held, o);
  EXPECT_GE(volume(held, 1), 0.995 * before);
  EXPECT_LT(held.tets.size(), start.tets.size());
  expectConforming(held);
}
