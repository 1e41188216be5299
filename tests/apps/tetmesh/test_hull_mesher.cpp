// The whole pipeline on generated shapes with known answers and on a corpus model.
#include "hull_mesher.hpp"
#include "tet_checks.hpp"

#include <acd/algo/merge.hpp>
#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <set>

using namespace tetmesh;

namespace {

/// The complex given to TetGen: its regions' faces are kept exactly, so volumes are exact.
HullMeshOptions fastOptions(double tau) {
  HullMeshOptions o;
  o.mesher = Mesher::Complex;
  o.simplify = 0;
  o.tau = tau;
  o.threads = 1;
  return o;
}

/// Every face of the mesh is used by one tet (boundary) or two (inside); nothing else.
void expectConforming(const TetMesh& m) {
  for (const auto& [face, tets] : tmtest::tetFaces(m)) ASSERT_LE(tets.size(), 2u) << "a face in more than two tets";
}

}  // namespace

TEST(HullMesher, BoxGivesItsExactVolumeWithPositiveTets) {
  const acd::TriMesh box = acd::shapes::box(Vec3(-1, 0, 2), Vec3(2, 1.5, 6));  // volume 3 * 1.5 * 4 = 18
  HullMeshOptions o = fastOptions(0.2);
  o.tetgen.radiusEdge = 2.0;
  const HullMeshResult r = meshHulls(box, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.hulls.size(), 1u);
  ASSERT_GT(r.quality.tets, 0);
  EXPECT_NEAR(r.quality.volume, 18.0, 1e-12 * 18.0);
  EXPECT_NEAR(r.modelVolume, 18.0, 1e-12 * 18.0);
  EXPECT_EQ(r.quality.nonPositiveTets, 0);
  for (int t = 0; t < r.quality.tets; ++t) {
    EXPECT_GT(tetVolume(r.mesh, t), 0.0);
    EXPECT_EQ(r.mesh.labels[t], 1);
  }
  // The quality bound holds: TetGen's q2 leaves no tet above radius-edge 2 in a box.
  EXPECT_LE(r.quality.maxRadiusEdge, 2.0 + 1e-9);
  expectConforming(r.mesh);
}

TEST(HullMesher, LShapeHasTwoLabelsAndAConformingInterface) {
  const acd::TriMesh l = acd::shapes::lShape();  // three unit cubes, volume 3
  const HullMeshResult r = meshHulls(l, fastOptions(0.05));
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.decomposition.components.size(), 2u);
  const TetMesh& m = r.mesh;
  EXPECT_NEAR(r.quality.volume, 3.0, 1e-12);  // the hulls of two boxes are the boxes
  EXPECT_EQ(r.quality.nonPositiveTets, 0);
  std::set<int> labels(m.labels.begin(), m.labels.end());
  EXPECT_EQ(labels, (std::set<int>{1, 2}));
  // Each label's tets fill exactly its component's volume.
  std::map<int, double> volume;
  for (int t = 0; t < static_cast<int>(m.tets.size()); ++t) volume[m.labels[t]] += tetVolume(m, t);
  for (int c = 0; c < 2; ++c)
    EXPECT_NEAR(volume[c + 1], acd::signedVolume(r.decomposition.components[c].mesh), 1e-12);
  // Conforming: tets of the two labels meet face to face, only on the cut plane, and the
  // shared faces cover exactly the cut section the two components share.
  std::vector<acd::TriMesh> pieces{r.decomposition.components[0].mesh, r.decomposition.components[1].mesh};
  const std::vector<acd::SharedFaces> shared = acd::sharedFacePairs(pieces);
  ASSERT_EQ(shared.size(), 1u);
  const acd::TriMesh& cap = pieces[0];
  int capFace = -1;  // a triangle of the section, to know its plane
  for (int f = 0; f < static_cast<int>(cap.faces.size()) && capFace < 0; ++f) {
    std::array<Vec3, 3> c{cap.vertices[cap.faces[f][0]], cap.vertices[cap.faces[f][1]], cap.vertices[cap.faces[f][2]]};
    for (const acd::Face& g : pieces[1].faces) {
      int same = 0;
      for (int k = 0; k < 3; ++k)
        for (const Vec3& p : c) same += pieces[1].vertices[g[k]] == p ? 1 : 0;
      if (same == 3) capFace = f;
    }
  }
  ASSERT_GE(capFace, 0);
  const Vec3 normal = acd::faceNormal(cap, capFace).normalized();
  const double offset = normal.dot(cap.vertices[cap.faces[capFace][0]]);
  double interfaceArea = 0, boundaryArea = 0;
  for (const auto& [face, tets] : tmtest::tetFaces(m)) {
    ASSERT_LE(tets.size(), 2u);
    if (tets.size() == 1) boundaryArea += tmtest::triangleArea(m, face);
    if (tets.size() == 2 && m.labels[tets[0]] != m.labels[tets[1]]) {
      interfaceArea += tmtest::triangleArea(m, face);
      for (int v : face) EXPECT_NEAR(normal.dot(m.points[v]), offset, 1e-12) << "interface face off the cut plane";
    }
  }
  EXPECT_NEAR(interfaceArea, shared[0].area, 1e-12);
  EXPECT_NEAR(boundaryArea, acd::surfaceArea(l), 1e-12);  // the surface of the L, nothing inside
  EXPECT_GT(r.complex.interfaceFacets, 0);
}

TEST(HullMesher, ElephantHullUnionIsMeshedWatertight) {
  const acd::ReadResult in = acd::readMesh(std::string(ACD_DATA_DIR) + "/meshes/elephant.off");
  ASSERT_TRUE(in.status.ok()) << in.status.message;
  HullMeshOptions o = fastOptions(0.2);
  o.threads = 0;
  o.tetgen.radiusEdge = 0;  // no refinement: this checks the complex, not TetGen's speed
  const HullMeshResult r = meshHulls(in.mesh, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const int n = static_cast<int>(r.hulls.size());
  ASSERT_GT(n, 3);
  EXPECT_EQ(r.quality.nonPositiveTets, 0);
  // The tets fill the regions exactly (a hole in the complex would let TetGen carve inside),
  // and the regions cover the model: hulls contain their components.
  // (2e-6: 47 hulls, each snapped to the mesher's grid; 1.1e-6 measured.)
  EXPECT_NEAR(r.quality.volume, r.hullsVolume, 2e-6 * r.hullsVolume);
  EXPECT_GE(r.hullsVolume, r.modelVolume * (1 - 1e-6));
  EXPECT_LE(r.maxOutside, 1e-9);
  std::set<int> labels(r.mesh.labels.begin(), r.mesh.labels.end());
  for (int label : labels) {
    EXPECT_GE(label, 1);
    EXPECT_LE(label, n);
  }
  EXPECT_EQ(static_cast<int>(labels.size()), n);  // every component got tets
  // Per label, the tets fill that region.
  std::vector<double> volume(n + 1, 0.0);
  for (int t = 0; t < r.quality.tets; ++t) volume[r.mesh.labels[t]] += tetVolume(r.mesh, t);
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(volume[i + 1], acd::signedVolume(r.regions[i]), 1e-6 * r.hullsVolume) << "label " << i + 1;
  expectConforming(r.mesh);
}

TEST(HullMesher, RejectsBadParameters) {
  HullMeshOptions o = fastOptions(0.2);
  o.simplify = 3;
  const HullMeshResult r = meshHulls(acd::shapes::lShape(), o);
  EXPECT_FALSE(r.status.ok());
  EXPECT_NE(r.status.message.find("simplify"), std::string::npos);
}

TEST(DirectMesher, RefusesASelfIntersectingSurfaceBeforeTetGen) {
  // Two boxes that pass through each other, as one closed (but self-intersecting) surface.
  acd::TriMesh a = acd::shapes::box(Vec3(0, 0, 0), Vec3(2, 2, 2));
  const acd::TriMesh b = acd::shapes::box(Vec3(1, 1, 1), Vec3(3, 3, 3));
  const int base = static_cast<int>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const acd::Face& f : b.faces) a.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  const DirectMeshResult r = meshModelDirectly(a, TetGenOptions{});
  EXPECT_FALSE(r.status.ok());
  EXPECT_GT(r.selfIntersections, 0);
  EXPECT_NE(r.status.message.find("intersects itself"), std::string::npos) << r.status.message;
}

TEST(DirectMesher, MeshesAClosedModel) {
  const acd::TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const DirectMeshResult r = meshModelDirectly(box, TetGenOptions{});
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NEAR(r.quality.volume, 6.0, 1e-12);
  EXPECT_EQ(r.quality.nonPositiveTets, 0);
}

TEST(HullMesher, SimplifiedHullsMeetTheBudgetAndTheRegionsAreMeshedWatertight) {
  HullMeshOptions o = fastOptions(0.2);
  o.simplify = 12;
  const HullMeshResult r = meshHulls(acd::shapes::torus(2.0, 0.6, 32, 12), o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_GE(r.hulls.size(), 2u);
  EXPECT_EQ(r.simplifyMissed, 0);
  for (const acd::TriMesh& h : r.hulls) EXPECT_LE(h.vertices.size(), 12u);
  EXPECT_LE(r.maxOutside, 1e-9);  // each simplified hull contains its component
  EXPECT_FALSE(r.simplifyFallback);
  EXPECT_EQ(r.simplifyUsed, 12);
  // The simplified hulls are kept apart at planes between the exact hulls, so nothing is
  // clipped off and every component lies in the region meshed for it.
  EXPECT_EQ(r.complex.overlappingPairs, 0);
  EXPECT_LE(r.maxOutsideRegion, 1e-9);
  EXPECT_NEAR(r.quality.volume, r.hullsVolume, 1e-6 * r.hullsVolume);
  EXPECT_EQ(r.quality.nonPositiveTets, 0);
  expectConforming(r.mesh);
}
