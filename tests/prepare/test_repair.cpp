// The safe repairs (libacd/src/prepare/repair.cpp, acd/repair.hpp) on the generated bad-mesh set
// (tests/bad_meshes.hpp): each repair with its exact outcome, checked with the tests' own geometry.
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>
#include <acd/repair.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <algorithm>

#include "bad_meshes.hpp"
#include "helpers.hpp"

using namespace acd;

namespace {

TriMesh caseMesh(const std::string& name) { return badmeshes::byName(name); }

bool hasZeroAreaFace(const TriMesh& m) {
  const double d2 = boundingBox(m).size().squaredNorm();
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f)
    if (0.5 * faceNormal(m, f).norm() <= 1e-14 * d2) return true;
  return false;
}

int componentsOf(const TriMesh& m) { return static_cast<int>(splitEdgeConnected(m).size()); }

}  // namespace

TEST(Repair, CleanMeshIsUnchanged) {
  const TriMesh box = caseMesh("clean_box");
  const MeshRepair r = repairMesh(box);
  ASSERT_TRUE(r.status.ok());
  EXPECT_TRUE(r.repairs.empty());
  EXPECT_EQ(r.mesh.faces.size(), 12u);
  EXPECT_EQ(r.mesh.vertices.size(), 8u);
  EXPECT_DOUBLE_EQ(signedVolume(r.mesh), 1.0);
}

TEST(Repair, ZeroAreaFaceIsCollapsed) {
  const TriMesh m = caseMesh("zero_area_face");
  ASSERT_TRUE(hasZeroAreaFace(m));
  const MeshRepair r = repairMesh(m);
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.removedDegenerateFaces, 1);
  EXPECT_EQ(r.leftDegenerateFaces, 0);
  EXPECT_FALSE(hasZeroAreaFace(r.mesh));
  EXPECT_TRUE(isClosedOriented(r.mesh));
  EXPECT_NEAR(signedVolume(r.mesh), 1.0, 1e-12);
}

TEST(Repair, NeedleFacesAreCollapsed) {
  const MeshRepair r = repairMesh(caseMesh("needle_faces"));
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.mergedVertices, 0);  // 3e-6 is above the merge tolerance (1e-6 of the diagonal)
  EXPECT_EQ(r.removedDegenerateFaces, 2);
  EXPECT_EQ(r.mesh.faces.size(), 12u);
  EXPECT_EQ(r.mesh.vertices.size(), 8u);
  EXPECT_TRUE(isClosedOriented(r.mesh));
  EXPECT_NEAR(signedVolume(r.mesh), 1.0, 1e-5);
}

TEST(Repair, SoupVerticesAreMerged) {
  const MeshRepair r = repairMesh(caseMesh("stl_soup"));
  EXPECT_EQ(r.mergedVertices, 36 - 8);
  EXPECT_EQ(r.mesh.vertices.size(), 8u);
  EXPECT_TRUE(isClosedOriented(r.mesh));
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 2);
  const MeshRepair noisy = repairMesh(caseMesh("float_noise_soup"));
  EXPECT_EQ(noisy.mesh.vertices.size(), sphere.vertices.size());
  EXPECT_EQ(noisy.mergedVertices, static_cast<int>(3 * sphere.faces.size() - sphere.vertices.size()));
  EXPECT_TRUE(isClosedOriented(noisy.mesh));
}

TEST(Repair, MergeToleranceIsRelativeToTheModel) {
  // The same soup at a millionth of the size merges the same way; a gap of 1e-5 of the size stays.
  TriMesh tiny = caseMesh("stl_soup");
  for (Vec3& p : tiny.vertices) p *= 1e-6;
  EXPECT_EQ(repairMesh(tiny).mesh.vertices.size(), 8u);
  TriMesh gap = caseMesh("clean_box");
  gap.vertices.push_back(gap.vertices[0] + Vec3(1e-5, 0, 0));
  gap.faces[0][0] = 8;  // the first face uses the near copy: a crack 1e-5 wide
  const MeshRepair r = repairMesh(gap);
  EXPECT_EQ(r.mergedVertices, 0);
}

TEST(Repair, DoubleSidedFaceKeepsOneSide) {
  const MeshRepair r = repairMesh(caseMesh("double_sided_face"));
  EXPECT_EQ(r.doubleSidedKeptOne, 1);
  EXPECT_EQ(r.doubleSidedDroppedBoth, 0);
  EXPECT_EQ(r.mesh.faces.size(), 12u);
  EXPECT_TRUE(isClosedOriented(r.mesh));
  EXPECT_NEAR(signedVolume(r.mesh), 1.0, 1e-12);
}

TEST(Repair, InnerWallIsDroppedBothSides) {
  const MeshRepair r = repairMesh(caseMesh("inner_wall"));
  EXPECT_EQ(r.doubleSidedDroppedBoth, 2);  // two triangles, each given by both cells
  EXPECT_EQ(r.mesh.faces.size(), 20u);
  EXPECT_EQ(componentsOf(r.mesh), 1);
  EXPECT_TRUE(isClosedOriented(r.mesh));
  EXPECT_NEAR(std::abs(signedVolume(r.mesh)), 2.0, 1e-12);
}

TEST(Repair, DoubleSidedSheetKeepsOneSide) {
  const MeshRepair r = repairMesh(caseMesh("double_sided_sheet"));
  EXPECT_EQ(r.doubleSidedKeptOne, 2);
  EXPECT_EQ(r.mesh.faces.size(), 2u);
}

TEST(Repair, DuplicateFaceIsDropped) {
  const MeshRepair r = repairMesh(caseMesh("duplicate_face"));
  EXPECT_EQ(r.droppedDuplicateFaces, 1);
  EXPECT_EQ(r.mesh.faces.size(), 12u);
  EXPECT_TRUE(isClosedOriented(r.mesh));
}

TEST(Repair, OrientationIsMadeConsistent) {
  const MeshRepair r = repairMesh(caseMesh("inconsistent_orientation"));
  EXPECT_EQ(r.flippedFaces, 3);
  EXPECT_TRUE(isClosedOriented(r.mesh));
  EXPECT_NEAR(signedVolume(r.mesh), 1.0, 1e-12);
}

TEST(Repair, NonManifoldEdgesAndVerticesAreSplit) {
  const MeshRepair edge4 = repairMesh(caseMesh("non_manifold_edge_4"));
  EXPECT_EQ(edge4.mergedVertices, 2);
  EXPECT_EQ(edge4.splitVertices, 2);
  EXPECT_EQ(componentsOf(edge4.mesh), 2);
  for (const TriMesh& part : splitEdgeConnected(edge4.mesh)) EXPECT_TRUE(isClosedOriented(part));
  const MeshRepair vertex = repairMesh(caseMesh("non_manifold_vertex"));
  EXPECT_EQ(vertex.splitVertices, 1);
  EXPECT_EQ(componentsOf(vertex.mesh), 2);
  const MeshRepair fin = repairMesh(caseMesh("non_manifold_edge_3"));
  EXPECT_EQ(fin.splitVertices, 2);
  EXPECT_EQ(componentsOf(fin.mesh), 2);  // the closed box and the loose fin
}

TEST(Repair, BrokenDataIsRefusedWithOneLine) {
  for (const char* name : {"non_finite_vertex", "index_out_of_range"}) {
    const MeshRepair r = repairMesh(caseMesh(name));
    EXPECT_FALSE(r.status.ok()) << name;
    EXPECT_EQ(r.status.message.find('\n'), std::string::npos);
  }
  EXPECT_EQ(repairMesh(TriMesh{}).status.code, StatusCode::EmptyMesh);
}


namespace {

void expectSameRepair(const TriMesh& input, const std::string& what) {
  RepairOptions always;
  always.skipWhenClean = false;
  const MeshRepair skipped = repairMesh(input), full = repairMesh(input, always);
  ASSERT_EQ(skipped.status.ok(), full.status.ok()) << what;
  EXPECT_EQ(skipped.repairs, full.repairs) << what;
  EXPECT_EQ(skipped.splitVertices, full.splitVertices) << what;
  EXPECT_EQ(skipped.mesh.vertices, full.mesh.vertices) << what;
  EXPECT_EQ(skipped.mesh.faces, full.mesh.faces) << what;
}

}  // namespace

// The shortcut for clean surfaces must give exactly what CGAL's steps give, on clean inputs
// (where it applies) and on every bad case (where it must not, or must not matter).
TEST(Repair, CleanSurfaceShortcutGivesWhatCgalGives) {
  for (const badmeshes::Case& c : badmeshes::all()) expectSameRepair(c.mesh, c.name);
  expectSameRepair(shapes::torus(2.0, 0.6, 24, 12), "torus");
  expectSameRepair(shapes::icosphere(Vec3(0, 0, 0), 1.0, 3), "icosphere");
  expectSameRepair(shapes::voxels({{0, 0, 0}, {1, 1, 0}}), "cubes sharing an edge");
  expectSameRepair(shapes::voxels({{0, 0, 0}, {1, 1, 1}}), "cubes sharing a corner");
  for (const char* name : {"armadillo", "elephant", "knot", "camel"}) {
    const ReadResult r = readMesh(acdtest::corpus(name));
    ASSERT_TRUE(r.status.ok()) << name;
    expectSameRepair(r.mesh, name);
  }
  // Open surfaces take the shortcut too (a sphere with faces taken out, one with a pinched border
  // vertex, corpus scans with holes): what CGAL's steps would give, exactly.
  TriMesh holed = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  holed.faces.erase(holed.faces.begin() + 40, holed.faces.begin() + 43);
  expectSameRepair(holed, "icosphere with a hole");
  TriMesh pinched = shapes::icosphere(Vec3(0, 0, 0), 1.0, 2);
  const int corner = pinched.faces[0][0];
  std::vector<Face> kept;
  for (const Face& f : pinched.faces)
    if (f == pinched.faces[0] || std::find(f.begin(), f.end(), corner) == f.end() || (&f - pinched.faces.data()) % 2)
      kept.push_back(f);
  pinched.faces = kept;
  expectSameRepair(pinched, "icosphere with holes meeting at a vertex");
  for (const char* name : {"lion-head", "mushroom", "holes", "blade", "ChineseDragon-10kv"}) {
    const ReadResult r = readMesh(acdtest::corpus(name));
    if (r.status.ok()) expectSameRepair(r.mesh, name);
  }
}

// A closed, oriented surface with one cap face skips the soup's orientation (it would change
// nothing) but not the cap's repair: what all of CGAL's steps give, exactly.
TEST(Repair, CapFaceOnAnOrientedSurfaceIsRepairedAsByAllSteps) {
  TriMesh capped = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  // Faces (u, v, w1) and (v, u, w2) share edge u-v: a vertex m just off its middle splits the
  // first in two and closes the second's edge with the cap (v, m, u), its angle at m 179.99 degrees.
  const Face f1 = capped.faces[0];
  const int u = f1[0], v = f1[1], w1 = f1[2];
  const Vec3 mid = 0.5 * (capped.vertices[u] + capped.vertices[v]);
  const double edge = (capped.vertices[u] - capped.vertices[v]).norm();
  capped.vertices.push_back(mid + 1e-4 * edge * mid.normalized());
  const int m = static_cast<int>(capped.vertices.size()) - 1;
  capped.faces[0] = {u, m, w1};
  capped.faces.push_back({m, v, w1});
  capped.faces.push_back({v, m, u});
  ASSERT_TRUE(isClosedOriented(capped));
  expectSameRepair(capped, "icosphere with a cap face");
  const MeshRepair r = repairMesh(capped);
  ASSERT_TRUE(r.status.ok());
  EXPECT_GE(r.removedDegenerateFaces, 1);
  EXPECT_TRUE(isClosedOriented(r.mesh));
}

// A vertex where two fans meet is not clean even though every edge is used once each way.
TEST(Repair, PinchedVertexIsSplitWithTheShortcutOn) {
  const MeshRepair r = repairMesh(shapes::voxels({{0, 0, 0}, {1, 1, 1}}));
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.splitVertices, 1);
  EXPECT_TRUE(isClosedOriented(r.mesh));
}

namespace {

/// prepareSolid told that repairMesh found the surface clean gives what its full checks give.
/// Returns whether the repair found it clean (the shortcut applied).
bool expectSamePreparation(const TriMesh& input, const std::string& what) {
  const MeshRepair r = repairMesh(input);
  if (!r.status.ok()) return false;
  PrepareOptions known;
  known.knownClean = r.clean;
  const PreparedSolid fast = prepareSolid(r.mesh, known), full = prepareSolid(r.mesh);
  EXPECT_EQ(fast.status.code, full.status.code) << what;
  EXPECT_EQ(fast.repairs, full.repairs) << what;
  EXPECT_EQ(fast.components.size(), full.components.size()) << what;
  for (std::size_t i = 0; i < std::min(fast.components.size(), full.components.size()); ++i) {
    EXPECT_EQ(fast.components[i].vertices, full.components[i].vertices) << what << " piece " << i;
    EXPECT_EQ(fast.components[i].faces, full.components[i].faces) << what << " piece " << i;
  }
  return r.clean;
}

}  // namespace

// A surface the repairs found clean skips prepareSolid's checks: the pieces, their orientation and
// the repairs' lines must be exactly what the checks give, and every other case must take them.
TEST(Repair, KnownCleanSurfacePreparesAsTheFullChecks) {
  for (const badmeshes::Case& c : badmeshes::all()) expectSamePreparation(c.mesh, c.name);
  EXPECT_TRUE(expectSamePreparation(shapes::torus(2.0, 0.6, 24, 12), "torus"));
  TriMesh insideOut = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  for (Face& f : insideOut.faces) std::swap(f[1], f[2]);
  EXPECT_TRUE(expectSamePreparation(insideOut, "inside-out sphere"));
  // Two solids, the second inside out: split, one turned, both lines.
  TriMesh two = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  TriMesh second = shapes::icosphere(Vec3(5, 0, 0), 1.0, 2);
  const int offset = static_cast<int>(two.vertices.size());
  two.vertices.insert(two.vertices.end(), second.vertices.begin(), second.vertices.end());
  for (const Face& f : second.faces) two.faces.push_back({f[0] + offset, f[2] + offset, f[1] + offset});
  EXPECT_TRUE(expectSamePreparation(two, "box and inside-out sphere"));
  // A face and its reverse alone close nothing: not clean (they go), and prepared as the checks do.
  TriMesh sheet = two;
  const int n = static_cast<int>(sheet.vertices.size());
  sheet.vertices.insert(sheet.vertices.end(), {Vec3(9, 0, 0), Vec3(10, 0, 0), Vec3(9, 1, 0)});
  sheet.faces.push_back({n, n + 1, n + 2});
  sheet.faces.push_back({n, n + 2, n + 1});
  expectSamePreparation(sheet, "with a double-sided triangle");
  // Open: clean, but the shortcut is for closed surfaces only.
  TriMesh open = shapes::icosphere(Vec3(0, 0, 0), 1.0, 2);
  open.faces.pop_back();
  expectSamePreparation(open, "open sphere");
  for (const char* name : {"armadillo", "elephant", "knot"}) {
    const ReadResult r = readMesh(acdtest::corpus(name));
    ASSERT_TRUE(r.status.ok()) << name;
    EXPECT_TRUE(expectSamePreparation(r.mesh, name)) << name;
  }
}
