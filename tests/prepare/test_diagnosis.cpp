#include <acd/diagnosis.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace acd;

namespace {

TriMesh unitBox() { return shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)); }

TriMesh concat(const TriMesh& a, const TriMesh& b) {
  TriMesh m = a;
  const int offset = static_cast<int>(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Face f : b.faces) m.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
  return m;
}

Face reversed(const Face& f) { return {f[0], f[2], f[1]}; }

/// Box with a triangular fin hanging off edge 0-2: that edge gets three faces.
TriMesh boxWithFin() {
  TriMesh m = unitBox();
  m.vertices.emplace_back(-1, -1, -1);
  m.faces.push_back({2, 0, 8});
  return m;
}

/// Box plus a zero-area triangle spanning edge 0-1 through its midpoint.
TriMesh boxWithSliver() {
  TriMesh m = unitBox();
  m.vertices.emplace_back(0.5, 0, 0);
  m.faces.push_back({0, 8, 1});
  return m;
}

TriMesh tetrahedron(const Vec3& apex, const Vec3& a, const Vec3& b, const Vec3& c) {
  TriMesh m{{apex, a, b, c}, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}};
  if (signedVolume(m) < 0)
    for (Face& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

/// Two tetrahedra touching only at the origin, which is vertex 0 and vertex 4 at the same position.
TriMesh tetrahedraSharingAVertex() {
  TriMesh m = concat(tetrahedron(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)),
                     tetrahedron(Vec3(0, 0, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, -1)));
  // Share the vertex itself, not only its position.
  for (Face& f : m.faces)
    for (int& v : f)
      if (v == 4) v = 0;
  return m;
}

/// A closed, non-orientable triangulated surface: a grid whose j-wrap mirrors i.
TriMesh kleinBottle(int n, int m) {
  TriMesh mesh;
  unsigned state = 12345;
  auto random = [&]() {
    state = state * 1103515245u + 12345u;
    return static_cast<double>((state >> 8) & 0xffff) / 65536.0;
  };
  for (int i = 0; i < n * m; ++i) {
    const double x = random(), y = random(), z = random();  // drawn in this order
    mesh.vertices.emplace_back(x, y, z);
  }
  auto id = [&](int i, int j) {
    if (j == m) {
      j = 0;
      i = (n - i % n) % n;
    }
    return (i % n) * m + j;
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      mesh.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      mesh.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return mesh;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

bool hasRepair(const PreparedSolid& p, const std::string& part) {
  for (const std::string& r : p.repairs)
    if (contains(r, part)) return true;
  return false;
}

void expectClosedAndOutward(const PreparedSolid& p) {
  ASSERT_TRUE(p.status.ok()) << p.status.message;
  ASSERT_FALSE(p.components.empty());
  for (const TriMesh& c : p.components) {
    EXPECT_TRUE(isClosedOriented(c));
    EXPECT_GT(signedVolume(c), 0.0);
  }
}

}  // namespace

// ---------------------------------------------------------------- diagnose

TEST(Diagnosis, Box) {
  const MeshDiagnosis d = diagnose(shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3)));
  EXPECT_EQ(d.vertices, 8);
  EXPECT_EQ(d.faces, 12);
  EXPECT_EQ(d.edges, 18);
  EXPECT_EQ(d.boundaryEdges, 0);
  EXPECT_EQ(d.nonManifoldEdges, 0);
  EXPECT_EQ(d.nonManifoldVertices, 0);
  EXPECT_EQ(d.components, 1);
  EXPECT_EQ(d.degenerateFaces, 0);
  EXPECT_EQ(d.duplicateFaces, 0);
  EXPECT_EQ(d.duplicateVertices, 0);
  EXPECT_EQ(d.unreferencedVertices, 0);
  EXPECT_TRUE(d.orientationConsistent);
  EXPECT_TRUE(d.closed);
  EXPECT_EQ(d.genus, 0);
  EXPECT_NEAR(d.volume, 6.0, 1e-12);
  EXPECT_NEAR(d.area, 22.0, 1e-12);
  EXPECT_EQ(d.bbox.hi, Vec3(1, 2, 3));
  EXPECT_EQ(d.firstProblem, "");
}

TEST(Diagnosis, TorusHasGenusOne) {
  const MeshDiagnosis d = diagnose(shapes::torus(2.0, 0.5, 32, 16));
  EXPECT_TRUE(d.closed);
  EXPECT_EQ(d.components, 1);
  EXPECT_EQ(d.genus, 1);
  EXPECT_GT(d.volume, 0.0);
  EXPECT_EQ(d.firstProblem, "");
}

TEST(Diagnosis, OpenBox) {
  TriMesh m = unitBox();
  m.faces.pop_back();
  const MeshDiagnosis d = diagnose(m);
  EXPECT_EQ(d.boundaryEdges, 3);
  EXPECT_FALSE(d.closed);
  EXPECT_EQ(d.genus, -1);
  EXPECT_TRUE(d.orientationConsistent);
  EXPECT_TRUE(contains(d.firstProblem, "boundary edge")) << d.firstProblem;
}

TEST(Diagnosis, TwoDisjointBoxes) {
  const MeshDiagnosis d = diagnose(concat(unitBox(), shapes::box(Vec3(3, 0, 0), Vec3(4, 1, 1))));
  EXPECT_EQ(d.components, 2);
  EXPECT_TRUE(d.closed);
  EXPECT_EQ(d.genus, 0);
  EXPECT_NEAR(d.volume, 2.0, 1e-12);
}

// The count alone (the repairs' clean-surface test), on meshes whose pinches are known.
TEST(Diagnosis, NonManifoldVertexCountAlone) {
  const TriMesh pinched = tetrahedraSharingAVertex();
  EXPECT_EQ(countNonManifoldVertices(pinched.faces, static_cast<int>(pinched.vertices.size())), 1);
  const TriMesh box = unitBox();
  EXPECT_EQ(countNonManifoldVertices(box.faces, static_cast<int>(box.vertices.size())), 0);
  // Two boxes corner to corner, the corner shared: one pinch; kept apart: none.
  TriMesh two = concat(unitBox(), shapes::box(Vec3(1, 1, 1), Vec3(2, 2, 2)));
  EXPECT_EQ(countNonManifoldVertices(two.faces, static_cast<int>(two.vertices.size())), 0);
  const int corner = 7, other = 8;  // the first box's (1,1,1) and the second box's
  ASSERT_EQ(two.vertices[corner], Vec3(1, 1, 1));
  ASSERT_EQ(two.vertices[other], Vec3(1, 1, 1));
  for (Face& f : two.faces)
    for (int& v : f)
      if (v == other) v = corner;
  EXPECT_EQ(countNonManifoldVertices(two.faces, static_cast<int>(two.vertices.size())), 1);
  EXPECT_EQ(diagnose(two).nonManifoldVertices, 1);
}

TEST(Diagnosis, NonManifoldEdge) {
  const MeshDiagnosis d = diagnose(boxWithFin());
  EXPECT_EQ(d.nonManifoldEdges, 1);
  EXPECT_EQ(d.boundaryEdges, 2);
  EXPECT_FALSE(d.closed);
  EXPECT_EQ(d.firstProblem, "non-manifold edge 0-2 is shared by 3 faces");
}

TEST(Diagnosis, NonManifoldVertex) {
  const MeshDiagnosis d = diagnose(tetrahedraSharingAVertex());
  EXPECT_EQ(d.nonManifoldVertices, 1);
  EXPECT_EQ(d.nonManifoldEdges, 0);
  EXPECT_EQ(d.boundaryEdges, 0);
  EXPECT_EQ(d.components, 2);
  EXPECT_EQ(d.unreferencedVertices, 1);  // the second origin, no longer used
  EXPECT_EQ(d.genus, -1);
  EXPECT_TRUE(contains(d.firstProblem, "vertex 4 has the same position as vertex 0")) << d.firstProblem;

  // Without the leftover copy, the pinch is the first problem.
  TriMesh m = tetrahedraSharingAVertex();
  m.vertices[4] = Vec3(7, 7, 7);
  const MeshDiagnosis pinched = diagnose(m);
  EXPECT_TRUE(contains(pinched.firstProblem, "vertex 0 is non-manifold")) << pinched.firstProblem;
}

TEST(Diagnosis, FlippedFace) {
  TriMesh m = unitBox();
  m.faces[4] = reversed(m.faces[4]);
  const MeshDiagnosis d = diagnose(m);
  EXPECT_FALSE(d.orientationConsistent);
  EXPECT_TRUE(d.closed);
  EXPECT_EQ(d.genus, 0);
  EXPECT_TRUE(contains(d.firstProblem, "same direction")) << d.firstProblem;
  EXPECT_TRUE(contains(d.firstProblem, "4")) << d.firstProblem;
}

TEST(Diagnosis, DegenerateFaces) {
  TriMesh repeated = unitBox();
  repeated.faces.push_back({0, 0, 1});
  const MeshDiagnosis r = diagnose(repeated);
  EXPECT_EQ(r.degenerateFaces, 1);
  EXPECT_TRUE(contains(r.firstProblem, "face 12 (vertices 0, 0, 1) repeats a vertex")) << r.firstProblem;

  const MeshDiagnosis s = diagnose(boxWithSliver());
  EXPECT_EQ(s.degenerateFaces, 1);
  EXPECT_TRUE(contains(s.firstProblem, "face 12 (vertices 0, 8, 1) has zero area")) << s.firstProblem;
}

TEST(Diagnosis, DuplicateFace) {
  TriMesh m = unitBox();
  m.faces.push_back(m.faces[3]);
  const MeshDiagnosis d = diagnose(m);
  EXPECT_EQ(d.duplicateFaces, 1);
  EXPECT_EQ(d.nonManifoldEdges, 3);
  EXPECT_TRUE(contains(d.firstProblem, "face 12")) << d.firstProblem;
  EXPECT_TRUE(contains(d.firstProblem, "face 3")) << d.firstProblem;
}

TEST(Diagnosis, BadVerticesAndIndicesAreCountedNotFatal) {
  TriMesh m = unitBox();
  m.vertices.push_back(m.vertices[5]);            // duplicate, unreferenced
  m.vertices.emplace_back(NAN, 0, 0);             // non-finite, unreferenced
  m.faces.push_back({0, 1, 42});                  // out of range
  const MeshDiagnosis d = diagnose(m);
  EXPECT_EQ(d.duplicateVertices, 1);
  EXPECT_EQ(d.unreferencedVertices, 2);
  EXPECT_EQ(d.nonFiniteVertices, 1);
  EXPECT_EQ(d.indexOutOfRange, 1);
  EXPECT_FALSE(d.closed);
  EXPECT_NEAR(d.volume, 1.0, 1e-12);  // measured on what is usable
  EXPECT_EQ(d.bbox.hi, Vec3(1, 1, 1));
  EXPECT_TRUE(contains(d.firstProblem, "vertex 9 has a non-finite coordinate")) << d.firstProblem;
}

TEST(Diagnosis, EmptyMesh) {
  const MeshDiagnosis d = diagnose(TriMesh{});
  EXPECT_EQ(d.faces, 0);
  EXPECT_FALSE(d.closed);
  EXPECT_EQ(d.genus, -1);
  EXPECT_EQ(d.firstProblem, "mesh has no faces");
}

// ---------------------------------------------------------------- prepareSolid: refusals

TEST(PrepareSolid, GoodMeshPassesUnchanged) {
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 2);
  const PreparedSolid p = prepareSolid(sphere);
  expectClosedAndOutward(p);
  EXPECT_TRUE(p.repairs.empty());
  ASSERT_EQ(p.components.size(), 1u);
  EXPECT_EQ(p.components[0].vertices, sphere.vertices);
  EXPECT_EQ(p.components[0].faces, sphere.faces);
}

TEST(PrepareSolid, EmptyMesh) {
  EXPECT_EQ(prepareSolid(TriMesh{}).status.code, StatusCode::EmptyMesh);
}

TEST(PrepareSolid, NonFiniteVertex) {
  TriMesh m = unitBox();
  m.vertices[3].y() = NAN;
  const PreparedSolid p = prepareSolid(m);
  EXPECT_EQ(p.status.code, StatusCode::NonFiniteVertex);
  EXPECT_TRUE(contains(p.status.message, "vertex 3")) << p.status.message;
  EXPECT_TRUE(contains(p.status.message, "(1, nan, 0)")) << p.status.message;
  EXPECT_TRUE(p.components.empty());
}

TEST(PrepareSolid, IndexOutOfRange) {
  TriMesh m = unitBox();
  m.faces[5][1] = 99;
  const PreparedSolid p = prepareSolid(m);
  EXPECT_EQ(p.status.code, StatusCode::IndexOutOfRange);
  EXPECT_EQ(p.status.message, "face 5 refers to vertex 99 but the mesh has 8 vertices");
}

TEST(PrepareSolid, OppositeDuplicateFaceIsRefused) {
  TriMesh m = unitBox();
  m.faces.push_back(reversed(m.faces[3]));
  const PreparedSolid p = prepareSolid(m);
  EXPECT_EQ(p.status.code, StatusCode::DuplicateFace);
  EXPECT_TRUE(contains(p.status.message, "face 12")) << p.status.message;
  EXPECT_TRUE(contains(p.status.message, "face 3 with the opposite orientation")) << p.status.message;
}

TEST(PrepareSolid, ZeroAreaFaceIsRefused) {
  const PreparedSolid p = prepareSolid(boxWithSliver());
  EXPECT_EQ(p.status.code, StatusCode::DegenerateFace);
  EXPECT_EQ(p.status.message, "face 12 (vertices 0, 8, 1) has zero area");
}

TEST(PrepareSolid, NonManifoldEdgeIsRefused) {
  const PreparedSolid p = prepareSolid(boxWithFin());
  EXPECT_EQ(p.status.code, StatusCode::NonManifoldEdge);
  EXPECT_EQ(p.status.message, "non-manifold edge 0-2 is shared by 3 faces");
}

TEST(PrepareSolid, NonManifoldVertexIsSplit) {
  // Two boxes touching at one corner: once the corner copies are merged, vertex 7 pinches.
  // The safe repair gives each fan its own copy of the vertex: two closed boxes again.
  const PreparedSolid p = prepareSolid(concat(unitBox(), shapes::box(Vec3(1, 1, 1), Vec3(2, 2, 2))));
  ASSERT_TRUE(p.status.ok()) << p.status.message;
  EXPECT_TRUE(hasRepair(p, "merged 1 vertices")) << (p.repairs.empty() ? "" : p.repairs[0]);
  EXPECT_TRUE(hasRepair(p, "split 1 non-manifold vertices"));
  ASSERT_EQ(p.components.size(), 2u);
  for (const TriMesh& c : p.components) {
    EXPECT_TRUE(isClosedOriented(c));
    EXPECT_NEAR(signedVolume(c), 1.0, 1e-12);
  }
}

TEST(PrepareSolid, OpenMeshIsRefused) {
  TriMesh m = unitBox();
  m.faces.pop_back();
  const PreparedSolid p = prepareSolid(m);
  EXPECT_EQ(p.status.code, StatusCode::OpenMesh);
  EXPECT_TRUE(contains(p.status.message, "open mesh: 3 boundary edges (first: vertices ")) << p.status.message;
  EXPECT_TRUE(contains(p.status.message, "solid decomposition needs a closed mesh")) << p.status.message;
}

TEST(PrepareSolid, NonOrientableIsRefused) {
  const TriMesh klein = kleinBottle(6, 6);
  ASSERT_TRUE(diagnose(klein).closed);
  ASSERT_EQ(diagnose(klein).nonManifoldVertices, 0);
  const PreparedSolid p = prepareSolid(klein);
  EXPECT_EQ(p.status.code, StatusCode::InconsistentOrientation);
  EXPECT_TRUE(contains(p.status.message, "non-orientable")) << p.status.message;
}

// ---------------------------------------------------------------- prepareSolid: repairs

TEST(PrepareSolid, MergesDuplicateVertices) {
  TriMesh m = shapes::icosphere(Vec3(0, 0, 0), 1.0, 2);
  const int original = static_cast<int>(m.vertices.size());
  m.vertices.push_back(m.vertices[m.faces[0][0]]);
  m.faces[0][0] = original;  // the face now uses a copy: the surface is cut open at one corner
  const PreparedSolid p = prepareSolid(m);
  expectClosedAndOutward(p);
  EXPECT_TRUE(hasRepair(p, "merged 1 vertices")) << (p.repairs.empty() ? "" : p.repairs[0]);
  ASSERT_EQ(p.components.size(), 1u);
  EXPECT_EQ(static_cast<int>(p.components[0].vertices.size()), original);
}

TEST(PrepareSolid, DropsFaceWithRepeatedVertex) {
  TriMesh m = unitBox();
  m.faces.push_back({0, 0, 1});
  const PreparedSolid p = prepareSolid(m);
  expectClosedAndOutward(p);
  EXPECT_TRUE(hasRepair(p, "dropped 1 faces with a repeated vertex"));
  EXPECT_EQ(p.components[0].faces.size(), 12u);
}

TEST(PrepareSolid, DropsExactDuplicateFace) {
  TriMesh m = unitBox();
  m.faces.push_back({m.faces[3][1], m.faces[3][2], m.faces[3][0]});  // same face, rotated
  const PreparedSolid p = prepareSolid(m);
  expectClosedAndOutward(p);
  EXPECT_TRUE(hasRepair(p, "dropped 1 duplicate faces"));
  EXPECT_EQ(p.components[0].faces.size(), 12u);
}

TEST(PrepareSolid, FlipsInconsistentFace) {
  TriMesh m = unitBox();
  m.faces[4] = reversed(m.faces[4]);
  const PreparedSolid p = prepareSolid(m);
  expectClosedAndOutward(p);
  ASSERT_EQ(p.repairs.size(), 1u);
  EXPECT_EQ(p.repairs[0], "flipped 1 faces to make the orientation consistent");
  EXPECT_NEAR(signedVolume(p.components[0]), 1.0, 1e-12);
}

TEST(PrepareSolid, TurnsInsideOutMeshOutward) {
  TriMesh m = shapes::icosphere(Vec3(0, 0, 0), 1.0, 1);
  for (Face& f : m.faces) f = reversed(f);
  const PreparedSolid p = prepareSolid(m);
  expectClosedAndOutward(p);
  ASSERT_EQ(p.repairs.size(), 1u);
  EXPECT_EQ(p.repairs[0], "reversed all faces: the mesh was inside out");
}

TEST(PrepareSolid, SplitsComponents) {
  TriMesh second = shapes::torus(2.0, 0.5, 16, 8);
  for (Vec3& v : second.vertices) v.x() += 10;
  for (Face& f : second.faces) f = reversed(f);  // and one of them inside out
  const PreparedSolid p = prepareSolid(concat(unitBox(), second));
  expectClosedAndOutward(p);
  ASSERT_EQ(p.components.size(), 2u);
  EXPECT_EQ(p.components[0].faces.size(), 12u);
  EXPECT_TRUE(hasRepair(p, "reversed 1 of 2 components that were inside out"));
  EXPECT_TRUE(hasRepair(p, "split into 2 components, decomposed separately"));
}

TEST(PrepareSolid, DropsUnreferencedVertices) {
  TriMesh m = unitBox();
  m.vertices.emplace_back(5, 5, 5);
  const PreparedSolid p = prepareSolid(m);
  expectClosedAndOutward(p);
  EXPECT_TRUE(hasRepair(p, "dropped 1 vertices not used by any face"));
  EXPECT_EQ(p.components[0].vertices.size(), 8u);
}
