// ShellsInside (libacd/src/hull/shell_inside.cpp): the input's solid as the union of its closed
// shells, each on its own, against analytic boxes. Assemblies overlap, touch along edges, nest and
// come flipped; open shells bound nothing.
#include <gtest/gtest.h>

#include <acd/algo/shapes.hpp>
#include <acd/algo/shell_inside.hpp>
#include <algorithm>
#include <cmath>
#include <random>

#include "helpers.hpp"

using namespace acd;
using acd::shapes::box;

namespace {

bool inBox(const Vec3& q, const Vec3& lo, const Vec3& hi) {
  return (q.array() > lo.array()).all() && (q.array() < hi.array()).all();
}

TriMesh flipped(TriMesh m) {
  for (Face& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

/// Random points in [-1, 3]^3, none within 1e-6 of a coordinate plane through a box face.
std::vector<Vec3> probes(int n) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 3.0);
  std::vector<Vec3> out;
  while (static_cast<int>(out.size()) < n) {
    const Vec3 q(u(rng), u(rng), u(rng));
    bool nearFace = false;
    for (int k = 0; k < 3; ++k)
      for (double plane : {0.0, 0.5, 1.0, 1.5, 2.0, 0.25, 0.75}) nearFace |= std::abs(q[k] - plane) < 1e-6;
    if (!nearFace) out.push_back(q);
  }
  return out;
}

}  // namespace

TEST(ShellsInside, OverlappingBoxesOneFlippedAreTheirUnion) {
  // One winding number over the whole would be 1 - 1 = 0 in the overlap.
  const Vec3 aLo(0, 0, 0), aHi(1.5, 1, 1), bLo(0.5, 0, 0), bHi(2, 1, 1);
  const ShellsInside solid(concatenate({box(aLo, aHi), flipped(box(bLo, bHi))}));
  EXPECT_EQ(solid.solidShells(), 2);
  EXPECT_EQ(solid.openShells(), 0);
  for (const Vec3& q : probes(4000))
    ASSERT_EQ(solid.inside(q), inBox(q, aLo, aHi) || inBox(q, bLo, bHi)) << q.transpose();
}

TEST(ShellsInside, BoxesSharingAnEdgeAreOneShellThatBoundsBoth) {
  // Merged vertices make the shared edge non-manifold (four faces): still a closed 2-cycle.
  TriMesh a = box(Vec3(0, 0, 0), Vec3(1, 1, 1)), b = box(Vec3(1, 1, 0), Vec3(2, 2, 1));
  TriMesh both = concatenate({a, b});
  // Weld b's corners on the shared edge x = y = 1 onto a's.
  for (Face& f : both.faces)
    for (int& v : f)
      for (int w = 0; w < 8; ++w)
        if (v >= 8 && both.vertices[v] == both.vertices[w]) v = w;
  both = compact(both);
  ASSERT_EQ(splitEdgeConnected(both).size(), 1u);
  const ShellsInside solid(both);
  EXPECT_EQ(solid.solidShells(), 1);
  for (const Vec3& q : probes(4000))
    ASSERT_EQ(solid.inside(q), inBox(q, Vec3(0, 0, 0), Vec3(1, 1, 1)) || inBox(q, Vec3(1, 1, 0), Vec3(2, 2, 1)));
}

TEST(ShellsInside, ShellWithSomeFacesFlippedIsOrientedAgain) {
  TriMesh m = box(Vec3(0, 0, 0), Vec3(2, 1, 1));
  for (std::size_t i = 0; i < m.faces.size(); i += 3) std::swap(m.faces[i][1], m.faces[i][2]);
  const ShellsInside solid(m);
  EXPECT_EQ(solid.solidShells(), 1);
  for (const Vec3& q : probes(2000)) ASSERT_EQ(solid.inside(q), inBox(q, Vec3(0, 0, 0), Vec3(2, 1, 1)));
}

TEST(ShellsInside, NestedShellsAndAnOpenOne) {
  // A box in a box: inside either is inside. A box without its top bounds the box (by its winding
  // number).
  TriMesh open = box(Vec3(2.25, 2.25, 2.25), Vec3(2.75, 2.75, 2.75));
  open.faces.erase(std::remove_if(open.faces.begin(), open.faces.end(),
                                  [&](const Face& f) {
                                    return open.vertices[f[0]].z() == 2.75 && open.vertices[f[1]].z() == 2.75 &&
                                           open.vertices[f[2]].z() == 2.75;
                                  }),
                   open.faces.end());
  ASSERT_EQ(open.faces.size(), 10u);
  const ShellsInside solid(
      concatenate({box(Vec3(0, 0, 0), Vec3(2, 2, 2)), flipped(box(Vec3(0.5, 0.5, 0.5), Vec3(1.5, 1.5, 1.5))), open}));
  EXPECT_EQ(solid.solidShells(), 2);
  EXPECT_EQ(solid.openShells(), 1);
  for (const Vec3& q : probes(4000))
    ASSERT_EQ(solid.inside(q),
              inBox(q, Vec3(0, 0, 0), Vec3(2, 2, 2)) || inBox(q, Vec3(2.25, 2.25, 2.25), Vec3(2.75, 2.75, 2.75)))
        << q.transpose();
}

TEST(ShellsInside, AFinWeldedToABoxIsPeeledOff) {
  // A triangle on the box's edge from (0,0,0) to (1,0,0), standing out below it: three faces on
  // that edge. The fin bounds nothing; the box still does.
  TriMesh m = box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  int a = -1, b = -1;
  for (int v = 0; v < static_cast<int>(m.vertices.size()); ++v) {
    if (m.vertices[v] == Vec3(0, 0, 0)) a = v;
    if (m.vertices[v] == Vec3(1, 0, 0)) b = v;
  }
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  m.vertices.push_back(Vec3(0.5, -1, -1));
  m.faces.push_back({a, b, static_cast<int>(m.vertices.size()) - 1});
  const ShellsInside solid(m);
  EXPECT_EQ(solid.solidShells(), 1);
  for (const Vec3& q : probes(2000)) ASSERT_EQ(solid.inside(q), inBox(q, Vec3(0, 0, 0), Vec3(1, 1, 1)));
}

TEST(ShellsInside, ABoxWithoutItsLidBoundsTheBox) {
  // Open: its winding number is above 1/2 inside the box and 1/2 on the missing lid.
  TriMesh m = box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  m.faces.erase(std::remove_if(m.faces.begin(), m.faces.end(),
                               [&](const Face& f) {
                                 return m.vertices[f[0]].z() == 1 && m.vertices[f[1]].z() == 1 &&
                                        m.vertices[f[2]].z() == 1;
                               }),
                m.faces.end());
  const ShellsInside solid(m);
  EXPECT_EQ(solid.solidShells(), 0);
  EXPECT_EQ(solid.openShells(), 1);
  // Within a hair of the missing lid the margin of 1/2 (0.499) calls points inside.
  for (const Vec3& q : probes(2000))
    if (std::abs(q.z() - 1.0) > 0.01)
      ASSERT_EQ(solid.inside(q), inBox(q, Vec3(0, 0, 0), Vec3(1, 1, 1))) << q.transpose();
  EXPECT_TRUE(solid.inside(Vec3(0.3, 0.6, 1.0)));         // on the missing lid
  EXPECT_TRUE(solid.inside(Vec3(0.3, 0.6, 1.0 + 1e-6)));  // a rounding above it
  EXPECT_FALSE(solid.inside(Vec3(0.5, 0.5, 1.1)));
  // A flat sheet bounds nothing.
  const ShellsInside sheet(TriMesh{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}, {{0, 1, 2}}});
  EXPECT_FALSE(sheet.inside(Vec3(0.2, 0.2, 0.05)));
}

namespace {

/// A unit sphere (icosphere of `level`) without its faces whose centroid lies above z = h.
TriMesh cappedSphere(int level, double h) {
  const TriMesh s = shapes::icosphere(Vec3::Zero(), 1.0, level);
  TriMesh m{s.vertices, {}};
  for (const Face& f : s.faces)
    if ((s.vertices[f[0]].z() + s.vertices[f[1]].z() + s.vertices[f[2]].z()) / 3 < h) m.faces.push_back(f);
  return compact(m);
}

}  // namespace

TEST(ShellsInside, OpenShellsAgreeWithTheirWindingNumberSummedFaceByFace) {
  // A sphere with a wide hole, and a box open at two opposite sides (two rims), one flipped.
  TriMesh tube = box(Vec3(2, -0.5, -0.5), Vec3(3, 0.5, 0.5));
  tube.faces.erase(std::remove_if(tube.faces.begin(), tube.faces.end(),
                                  [&](const Face& f) {
                                    const double x = tube.vertices[f[0]].x();
                                    return tube.vertices[f[1]].x() == x && tube.vertices[f[2]].x() == x;
                                  }),
                   tube.faces.end());
  ASSERT_EQ(tube.faces.size(), 8u);
  const std::vector<TriMesh> shells = {cappedSphere(3, 0.3), flipped(tube)};
  const ShellsInside solid(concatenate(shells));
  EXPECT_EQ(solid.openShells(), 2);
  EXPECT_EQ(solid.surfaceOnlyShells(), 0);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 3.5);
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 q(u(rng), 0.5 * u(rng) - 0.5, 0.5 * u(rng) - 0.5);
    bool expected = false, clear = true;
    for (const TriMesh& s : shells) {
      const double w = std::abs(acdtest::windingSummed(s, q));
      clear = clear && std::abs(w - 0.5) > 0.01;
      expected = expected || w >= 0.5;
    }
    if (!clear) continue;
    ++compared;
    ASSERT_EQ(solid.inside(q), expected) << q.transpose();
  }
  EXPECT_GT(compared, 2500);
}

TEST(ShellsInside, ADenseOpenShellStillBoundsItsSolid) {
  // 73,724 faces (an icosphere less a cap): past what summing face by face could afford (50,000),
  // but its rim is short.
  const TriMesh open = cappedSphere(6, 0.8);
  ASSERT_GT(open.faces.size(), 50000u);
  const ShellsInside solid(open);
  EXPECT_EQ(solid.openShells(), 1);
  EXPECT_EQ(solid.surfaceOnlyShells(), 0);
  for (const Vec3& q : {Vec3(0, 0, 0), Vec3(0, 0, -0.95), Vec3(0.6, 0.6, 0.1), Vec3(0, 0, 0.7)})
    EXPECT_TRUE(solid.inside(q)) << q.transpose();
  for (const Vec3& q : {Vec3(1.1, 0, 0), Vec3(0, 0, 1.05), Vec3(0.7, 0.7, 0.7)})
    EXPECT_FALSE(solid.inside(q)) << q.transpose();
}

TEST(ShellsInside, AShellGivenOnBothSidesBoundsItsSolid) {
  // Each face of the box twice, once per orientation (as some exporters write every shell):
  // one side is the box; both together would wind around nothing.
  const TriMesh b = box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const ShellsInside solid(concatenate({flipped(b), b}));
  EXPECT_EQ(solid.solidShells(), 1);
  for (const Vec3& q : probes(2000))
    ASSERT_EQ(solid.inside(q), inBox(q, Vec3(0, 0, 0), Vec3(1, 1, 1))) << q.transpose();
}
