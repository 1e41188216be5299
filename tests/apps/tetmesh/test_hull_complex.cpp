// The complex of hulls: contacts, overlap clipping and interface overlay on boxes with known answers.
#include "hull_complex.hpp"
#include "tet_checks.hpp"
#include "tetgen_run.hpp"

#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

using namespace tetmesh;

namespace {

/// Meshes the complex of these hulls with TetGen (no refinement) and checks the basics.
TetMesh meshOf(const HullComplex& c) {
  TetGenOptions o;
  o.radiusEdge = 0;
  const TetGenResult r = runTetGen(c.plc, o);
  EXPECT_TRUE(r.ok) << r.error;
  for (int t = 0; t < static_cast<int>(r.mesh.tets.size()); ++t) EXPECT_GT(tetVolume(r.mesh, t), 0.0);
  for (const auto& [face, tets] : tmtest::tetFaces(r.mesh)) EXPECT_LE(tets.size(), 2u);
  return r.mesh;
}

std::vector<double> volumePerLabel(const TetMesh& m, int n) {
  std::vector<double> v(n + 1, 0.0);
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) v.at(m.labels[t]) += tetVolume(m, t);
  return v;
}

double interfaceArea(const TetMesh& m) {
  double area = 0;
  for (const auto& [face, tets] : tmtest::tetFaces(m))
    if (tets.size() == 2 && m.labels[tets[0]] != m.labels[tets[1]]) area += tmtest::triangleArea(m, face);
  return area;
}

/// Smallest dihedral angle of any tet, in degrees, from the angles between outward face normals
/// (computed here, not by the mesher's own quality measure).
double smallestDihedral(const TetMesh& m) {
  double smallest = 180.0;
  for (const auto& t : m.tets) {
    std::array<Vec3, 4> normal;
    for (int k = 0; k < 4; ++k) {
      const Vec3 &a = m.points[t[(k + 1) % 4]], &b = m.points[t[(k + 2) % 4]], &c = m.points[t[(k + 3) % 4]];
      Vec3 n = (b - a).cross(c - a).normalized();
      if (n.dot(m.points[t[k]] - a) > 0) n = -n;  // away from the opposite corner
      normal[k] = n;
    }
    for (int x = 0; x < 4; ++x)
      for (int y = x + 1; y < 4; ++y)
        smallest =
            std::min(smallest, 180.0 - std::acos(std::clamp(normal[x].dot(normal[y]), -1.0, 1.0)) * 180.0 / M_PI);
  }
  return smallest;
}

/// Tets that cannot be reached from the first one through shared faces.
int unreachableTets(const TetMesh& m) {
  std::vector<std::vector<int>> next(m.tets.size());
  for (const auto& [face, tets] : tmtest::tetFaces(m))
    if (tets.size() == 2) next[tets[0]].push_back(tets[1]), next[tets[1]].push_back(tets[0]);
  std::vector<char> seen(m.tets.size(), 0);
  std::vector<int> stack{0};
  int reached = 0;
  while (!stack.empty() && !m.tets.empty()) {
    const int t = stack.back();
    stack.pop_back();
    if (seen[t]) continue;
    seen[t] = 1, ++reached;
    for (int u : next[t]) stack.push_back(u);
  }
  return static_cast<int>(m.tets.size()) - reached;
}

}  // namespace

TEST(HullComplex, TwoBoxesFaceToFaceShareOneInterfaceAndMakeNoSlivers) {
  const HullComplex c = buildHullComplex(
      {acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), acd::shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1))});
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  EXPECT_EQ(c.contactPairs, 1);
  EXPECT_EQ(c.contactPlanes, 1);
  const TetMesh m = meshOf(c);
  EXPECT_NEAR(interfaceArea(m), 1.0, 1e-12);
  EXPECT_EQ(unreachableTets(m), 0);
  // Cubes cut into tets without Steiner points: every dihedral angle is 45 degrees or more.
  EXPECT_GE(smallestDihedral(m), 30.0);
  EXPECT_LE(m.tets.size(), 14u);
}

TEST(HullComplex, AGapNarrowerThanTheClosedGapIsClosed) {
  // An L of two boxes 1e-6 apart (of a half-diagonal of about 1.6): closed at closedGap 2e-4,
  // both faces moved half way; left open without it.
  const std::vector<acd::TriMesh> l{acd::shapes::box(Vec3(0, 0, 0), Vec3(2, 1, 1)),
                                    acd::shapes::box(Vec3(0, 1 + 1e-6, 0), Vec3(1, 2, 1))};
  HullComplexOptions closing;
  closing.closedGap = 2e-4;
  const HullComplex c = buildHullComplex(l, closing);
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  EXPECT_EQ(c.contactPairs, 1);
  EXPECT_EQ(c.contactPlanes, 1);
  const TetMesh m = meshOf(c);
  EXPECT_NEAR(interfaceArea(m), 1.0, 1e-9);
  EXPECT_EQ(unreachableTets(m), 0);  // one piece
  const auto v = volumePerLabel(m, 2);
  EXPECT_NEAR(v[1], 2.0 * (1 + 0.5e-6), 1e-9);
  EXPECT_NEAR(v[2], 1.0 - 0.5e-6, 1e-9);
  EXPECT_GE(smallestDihedral(m), 29.9);  // 30 degrees, less what the half-gap shift takes off

  const HullComplex open = buildHullComplex(l);
  ASSERT_TRUE(open.status.ok()) << open.status.message;
  EXPECT_EQ(open.contactPairs, 0);
  const TetMesh apart = meshOf(open);
  EXPECT_NEAR(interfaceArea(apart), 0.0, 1e-12);
  EXPECT_GT(unreachableTets(apart), 0);  // two pieces
}

TEST(HullComplex, SeparateHullsHaveNoContact) {
  const HullComplex c = buildHullComplex(
      {acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), acd::shapes::box(Vec3(2, 0, 0), Vec3(3, 1, 1))});
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  EXPECT_EQ(c.contactPairs, 0);
  EXPECT_EQ(c.interfaceFacets, 0);
  const TetMesh m = meshOf(c);
  const auto v = volumePerLabel(m, 2);
  EXPECT_NEAR(v[1], 1.0, 1e-12);
  EXPECT_NEAR(v[2], 1.0, 1e-12);
}

TEST(HullComplex, PartlyOverlappingFacesBecomeOneInterface) {
  // A unit cube on a 2 x 2 x 1 slab, half over its edge: it stands at z = 1 on
  // [1.5, 2.5] x [0.5, 1.5], so the faces share [1.5, 2] x [0.5, 1.5], area 0.5.
  const HullComplex c = buildHullComplex(
      {acd::shapes::box(Vec3(0, 0, 0), Vec3(2, 2, 1)), acd::shapes::box(Vec3(1.5, 0.5, 1), Vec3(2.5, 1.5, 2))});
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  EXPECT_EQ(c.contactPairs, 1);
  EXPECT_EQ(c.overlappingPairs, 0);
  EXPECT_EQ(c.contactPlanes, 1);
  EXPECT_GT(c.interfaceFacets, 0);
  const TetMesh m = meshOf(c);
  const auto v = volumePerLabel(m, 2);
  EXPECT_NEAR(v[1], 4.0, 1e-12);
  EXPECT_NEAR(v[2], 1.0, 1e-12);
  EXPECT_NEAR(interfaceArea(m), 0.5, 1e-12);
}

TEST(HullComplex, OverlappingHullsAreSplitAtOnePlane) {
  // Two unit-section bars overlapping over x in [1, 1.5]: the overlap goes to one side of a
  // plane x = const in [1, 1.5]; together they fill the union, volume 2 * 1.5 - 0.5 = 2.5.
  const HullComplex c = buildHullComplex(
      {acd::shapes::box(Vec3(0, 0, 0), Vec3(1.5, 1, 1)), acd::shapes::box(Vec3(1, 0, 0), Vec3(2.5, 1, 1))});
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  EXPECT_EQ(c.overlappingPairs, 1);
  EXPECT_NEAR(c.maxOverlapDepth, 0.5, 1e-12);
  const TetMesh m = meshOf(c);
  const auto v = volumePerLabel(m, 2);
  EXPECT_NEAR(v[1] + v[2], 2.5, 1e-12);
  EXPECT_NEAR(v[1], 1.25, 1e-12);  // split in the middle of the overlap
  EXPECT_NEAR(interfaceArea(m), 1.0, 1e-12);
  EXPECT_NEAR(c.clippedVolume[0] + c.clippedVolume[1], 0.5, 1e-12);
}

TEST(HullComplex, FourBoxesMeetingAtAnEdgeConform) {
  // Four unit cubes around the z axis; a fifth across the top of two of them. Interfaces
  // cross each other (T-junctions where the top slab meets the vertical interface).
  std::vector<acd::TriMesh> hulls{
      acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), acd::shapes::box(Vec3(-1, 0, 0), Vec3(0, 1, 1)),
      acd::shapes::box(Vec3(-1, -1, 0), Vec3(0, 0, 1)), acd::shapes::box(Vec3(0, -1, 0), Vec3(1, 0, 1)),
      acd::shapes::box(Vec3(-0.5, -0.25, 1), Vec3(0.75, 0.5, 1.5))};
  const HullComplex c = buildHullComplex(hulls);
  ASSERT_TRUE(c.status.ok()) << c.status.message;
  const TetMesh m = meshOf(c);
  const auto v = volumePerLabel(m, 5);
  for (int i = 1; i <= 4; ++i) EXPECT_NEAR(v[i], 1.0, 1e-12) << i;
  EXPECT_NEAR(v[5], 1.25 * 0.75 * 0.5, 1e-12);
  // Interfaces: four unit squares between the cubes, plus the slab's bottom 1.25 x 0.75.
  EXPECT_NEAR(interfaceArea(m), 4.0 + 1.25 * 0.75, 1e-12);
  // TetGen gets triangles only (it aborts on some polygons with points inserted on their
  // edges), each once, none degenerate; the points the T-junctions add are corners of them.
  std::set<std::array<int, 3>> seen;
  for (const Plc::Facet& f : c.plc.facets) {
    ASSERT_EQ(f.polygon.size(), 3u);
    std::array<int, 3> key{f.polygon[0], f.polygon[1], f.polygon[2]};
    const Vec3 area = (c.plc.points[key[1]] - c.plc.points[key[0]]).cross(c.plc.points[key[2]] - c.plc.points[key[0]]);
    EXPECT_GT(area.norm(), 1e-9);
    std::sort(key.begin(), key.end());
    EXPECT_TRUE(seen.insert(key).second) << "facet given twice";
  }
  std::set<std::array<double, 3>> corners;
  for (const acd::TriMesh& h : hulls)
    for (const Vec3& p : h.vertices) corners.insert({p.x(), p.y(), p.z()});
  EXPECT_GT(c.plc.points.size(), corners.size());  // the overlay added points, and they are used
}

TEST(HullComplex, RefusesAFlatHull) {
  acd::TriMesh flat = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 0));
  const HullComplex c = buildHullComplex({flat});
  EXPECT_FALSE(c.status.ok());
  EXPECT_NE(c.status.message.find("hull 1"), std::string::npos) << c.status.message;
}
