// Hole filling (libacd/src/prepare/hole_filling.cpp, acd/algo/hole_filling.hpp): open meshes for
// solid ACD have their holes closed first, through prepareSolid's fill-holes policy and on to the
// decomposition.
#include <acd/algo/hole_filling.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <cmath>
#include <string>

using namespace acd;
using acdtest::corpus;

namespace {

TriMesh openBox() {
  TriMesh m = shapes::box(Vec3(0, 0, 0), Vec3(2, 1, 1));
  m.faces.pop_back();  // the two triangles of one side: one square hole with four edges
  m.faces.pop_back();
  return m;
}

/// A sphere with the faces above z = h removed: one circular hole.
TriMesh cappedSphere(double h) {
  const TriMesh s = shapes::icosphere(Vec3::Zero(), 1.0, 3);
  TriMesh m{s.vertices, {}};
  for (const Face& f : s.faces) {
    const double z = (s.vertices[f[0]].z() + s.vertices[f[1]].z() + s.vertices[f[2]].z()) / 3;
    if (z < h) m.faces.push_back(f);
  }
  return compact(m);
}

}  // namespace

TEST(HoleFilling, OpenBoxGetsItsSideBack) {
  const TriMesh open = openBox();
  ASSERT_EQ(diagnose(open).boundaryEdges, 4);
  const HoleFilling h = fillHoles(open);
  ASSERT_TRUE(h.status.ok()) << h.status.message;
  EXPECT_EQ(h.holes, 1);
  EXPECT_EQ(h.addedFaces, 2);  // a flat square needs two triangles and no refinement
  EXPECT_TRUE(isClosedOriented(h.mesh));
  EXPECT_NEAR(signedVolume(h.mesh), 2.0, 1e-12);
  // The input comes first, unchanged: callers may keep their face numbers.
  for (std::size_t f = 0; f < open.faces.size(); ++f) EXPECT_EQ(h.mesh.faces[f], open.faces[f]);
  for (std::size_t v = 0; v < open.vertices.size(); ++v) EXPECT_EQ(h.mesh.vertices[v], open.vertices[v]);
}

TEST(HoleFilling, APlanarLoopIsClosedFlat) {
  // The open box subdivided twice: its hole is the missing side, 16 edges in one plane. Faired,
  // the patch would bulge out towards the box's corners (2.044 instead of 2).
  const TriMesh open = acdtest::midpointSubdivided(acdtest::midpointSubdivided(openBox()));
  ASSERT_EQ(diagnose(open).boundaryEdges, 16);
  const HoleFilling h = fillHoles(open);
  ASSERT_TRUE(h.status.ok()) << h.status.message;
  EXPECT_TRUE(isClosedOriented(h.mesh));
  EXPECT_EQ(h.addedVertices, 0);
  EXPECT_NEAR(signedVolume(h.mesh), 2.0, 1e-12);
  for (std::size_t f = open.faces.size(); f < h.mesh.faces.size(); ++f)
    for (int v : h.mesh.faces[f]) EXPECT_EQ(h.mesh.vertices[v].x(), 2.0);  // the missing side lies at x = 2
}

TEST(HoleFilling, FairedPatchFollowsTheSphere) {
  const TriMesh open = cappedSphere(0.5);
  const HoleFilling h = fillHoles(open);
  ASSERT_TRUE(h.status.ok()) << h.status.message;
  EXPECT_EQ(h.holes, 1);
  EXPECT_GT(h.addedVertices, 0);  // refined to the density around the hole
  EXPECT_TRUE(isClosedOriented(h.mesh));
  // A flat lid over the cap would give the sphere minus its cap (about 3.88); the faired lid
  // bulges toward the sphere's full volume 4.19 (level-3 icosphere: 4.13) and never beyond it.
  const double flatLid = 4.0 / 3.0 * M_PI - M_PI * 0.5 * 0.5 * (3 * 1 - 0.5) / 3.0;
  const double v = signedVolume(h.mesh);
  EXPECT_GT(v, flatLid);
  EXPECT_LT(v, 4.0 / 3.0 * M_PI);
  EXPECT_EQ(countSelfIntersections(h.mesh), 0);
}

TEST(HoleFilling, SheetIsRefused) {
  TriMesh sheet;
  sheet.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  sheet.faces = {{0, 1, 2}, {0, 2, 3}};
  const HoleFilling h = fillHoles(sheet);
  EXPECT_FALSE(h.status.ok());
  EXPECT_EQ(h.status.code, StatusCode::OpenMesh);
  // The only patch lies on the sheet itself: it coincides with the model's faces.
  EXPECT_NE(h.status.message.find("passing through the surface"), std::string::npos) << h.status.message;
  EXPECT_TRUE(h.mesh.empty());
}

TEST(PrepareSolid, FillHolesPolicyClosesAndReports) {
  PrepareOptions o;
  o.openMeshes = OpenMeshPolicy::FillHoles;
  const PreparedSolid p = prepareSolid(openBox(), o);
  ASSERT_TRUE(p.status.ok()) << p.status.message;
  EXPECT_EQ(p.holesFilled, 1);
  ASSERT_EQ(p.components.size(), 1u);
  EXPECT_TRUE(isClosedOriented(p.components[0]));
  EXPECT_NEAR(signedVolume(p.components[0]), 2.0, 1e-12);
  ASSERT_FALSE(p.repairs.empty());
  EXPECT_NE(p.repairs.back().find("filled 1 hole"), std::string::npos) << p.repairs.back();
}

TEST(PrepareSolid, FillHolesTurnsAnInsideOutOpenMeshOutward) {
  TriMesh m = openBox();
  for (Face& f : m.faces) std::swap(f[1], f[2]);
  PrepareOptions o;
  o.openMeshes = OpenMeshPolicy::FillHoles;
  const PreparedSolid p = prepareSolid(m, o);
  ASSERT_TRUE(p.status.ok()) << p.status.message;
  EXPECT_NEAR(signedVolume(p.components[0]), 2.0, 1e-12);
}

TEST(PrepareSolid, KeepOpenPolicyKeepsTheHoles) {
  PrepareOptions o;
  o.openMeshes = OpenMeshPolicy::KeepOpen;
  TriMesh m = openBox();
  std::swap(m.faces[0][1], m.faces[0][2]);  // one face the wrong way round
  const PreparedSolid p = prepareSolid(m, o);
  ASSERT_TRUE(p.status.ok()) << p.status.message;
  EXPECT_EQ(p.holesFilled, 0);
  ASSERT_EQ(p.components.size(), 1u);
  EXPECT_EQ(p.components[0].faces.size(), 10u);
  EXPECT_EQ(diagnose(p.components[0]).boundaryEdges, 4);
  EXPECT_TRUE(diagnose(p.components[0]).orientationConsistent);
}

TEST(PrepareSolid, SheetCannotBeClosed) {
  TriMesh sheet;
  sheet.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  sheet.faces = {{0, 1, 2}, {0, 2, 3}};
  PrepareOptions o;
  o.openMeshes = OpenMeshPolicy::FillHoles;
  const PreparedSolid p = prepareSolid(sheet, o);
  EXPECT_EQ(p.status.code, StatusCode::OpenMesh);
  EXPECT_NE(p.status.message.find("surface decomposition"), std::string::npos) << p.status.message;
}

// The corpus's open models: which can be closed, and how.
TEST(HoleFilling, CorpusOpenModels) {
  struct Case {
    const char* model;
    int boundaryEdges;
    int holes;  // -1: refused
  };
  for (const Case& c : {Case{"ChineseDragon-10kv", 6, 2}, Case{"mushroom", 64, 1}, Case{"mesh_with_border", 80, 1},
                        Case{"elephant-with-holes", 1353, -1}}) {
    SCOPED_TRACE(c.model);
    const ReadResult r = readMesh(corpus(c.model));
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(diagnose(r.mesh).boundaryEdges, c.boundaryEdges);
    PrepareOptions o;
    o.openMeshes = OpenMeshPolicy::FillHoles;
    const PreparedSolid p = prepareSolid(r.mesh, o);
    if (c.holes < 0) {
      // Many of its 106 holes are long, twisted slits: every patch tried for them cuts through the model.
      EXPECT_EQ(p.status.code, StatusCode::OpenMesh);
      EXPECT_NE(p.status.message.find("without the patch passing through the surface"), std::string::npos)
          << p.status.message;
      continue;
    }
    ASSERT_TRUE(p.status.ok()) << p.status.message;
    EXPECT_EQ(p.holesFilled, c.holes);
    for (const TriMesh& piece : p.components) {
      EXPECT_TRUE(isClosedOriented(piece));
      EXPECT_GT(signedVolume(piece), 0.0);
    }
  }
}

TEST(HoleFilling, LoopsRunningStraightThroughTheirVerticesGetNoZeroAreaFace) {
  // The dragon subdivided twice (a dense input of the benchmarks): each edge of its two holes is
  // now four, on a line up to rounding, and a patch triangle on three of them has no area unless
  // it is flipped away. The patches' own faces are checked with the tests' own area.
  const ReadResult r = readMesh(corpus("ChineseDragon-10kv"));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const TriMesh dense = acdtest::midpointSubdivided(acdtest::midpointSubdivided(r.mesh));
  ASSERT_EQ(diagnose(dense).boundaryEdges, 24);
  const HoleFilling h = fillHoles(dense);
  ASSERT_TRUE(h.status.ok()) << h.status.message;
  EXPECT_EQ(h.holes, 2);
  EXPECT_TRUE(isClosedOriented(h.mesh));
  const double d2 = boundingBox(dense).size().squaredNorm();
  for (std::size_t f = dense.faces.size(); f < h.mesh.faces.size(); ++f) {
    const Face& t = h.mesh.faces[f];
    const std::vector<Vec3>& v = h.mesh.vertices;
    EXPECT_GT(0.5 * (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).norm(), 1e-14 * d2) << "patch face " << f;
  }
  PrepareOptions o;
  o.openMeshes = OpenMeshPolicy::FillHoles;
  EXPECT_TRUE(prepareSolid(dense, o).status.ok());
}

TEST(Decompose, OpenMeshIsClosedThenDecomposed) {
  const ReadResult r = readMesh(corpus("mushroom"));
  ASSERT_TRUE(r.status.ok());
  DecomposeOptions o;
  o.tau = 0.2;
  const Decomposition d = decompose(r.mesh, o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_EQ(d.stats.holesFilled, 1);
  ASSERT_FALSE(d.components.empty());
  double volume = 0;
  for (const Component& c : d.components) {
    EXPECT_TRUE(isClosedOriented(c.mesh));
    EXPECT_LE(c.concavity, o.tau);
    volume += c.volume;
  }
  EXPECT_NEAR(volume, d.stats.inputVolume, 1e-6 * d.stats.inputVolume);
  o.fillHoles = false;
  o.wrap = false;  // otherwise the open mesh is decomposed through its wrap (test_robust.cpp)
  EXPECT_EQ(decompose(r.mesh, o).status.code, StatusCode::OpenMesh);
}
