// Repairs, shells and the watertight wrap (acd/repair.hpp, acd/algo/shells.hpp, acd/alpha_wrap.hpp,
// acd/robust.hpp) on the generated bad-mesh set (tests/bad_meshes.hpp). Each repair has a test
// with its exact outcome; every case is decomposed or refused as bad_meshes.hpp says, and the
// components are checked with the tests' own geometry (helpers.hpp), not the library's.
#include <acd/algo/shells.hpp>
#include <acd/alpha_wrap.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/hull.hpp>
#include <acd/io.hpp>
#include <acd/normalize.hpp>
#include <acd/repair.hpp>
#include <acd/robust.hpp>

#include <gtest/gtest.h>

#include <random>

#include "bad_meshes.hpp"
#include "helpers.hpp"

using namespace acd;
using acdtest::MeshIndex;

namespace {

const badmeshes::Case& find(const std::vector<badmeshes::Case>& cases, const std::string& name) {
  for (const auto& c : cases)
    if (c.name == name) return c;
  throw std::runtime_error("no case " + name);
}

TriMesh caseMesh(const std::string& name) {
  static const std::vector<badmeshes::Case> cases = badmeshes::all();
  return find(cases, name).mesh;
}

bool hasZeroAreaFace(const TriMesh& m) {
  const double d2 = boundingBox(m).size().squaredNorm();
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f)
    if (0.5 * faceNormal(m, f).norm() <= 1e-14 * d2) return true;
  return false;
}

int componentsOf(const TriMesh& m) { return static_cast<int>(splitEdgeConnected(m).size()); }

DecomposeOptions atTau(double tau) {
  DecomposeOptions o;
  o.tau = tau;
  return o;
}

}  // namespace

// ------------------------------------------------------------------ each repair, exactly
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

// ------------------------------------------------------------------ shells
TEST(Shells, CavitiesAreFoundByNestingDepth) {
  const TriMesh outer = shapes::box(Vec3(0, 0, 0), Vec3(5, 5, 5));
  const TriMesh cavity = shapes::box(Vec3(1, 1, 1), Vec3(4, 4, 4));
  const TriMesh inner = shapes::box(Vec3(2, 2, 2), Vec3(3, 3, 3));
  const TriMesh apart = shapes::box(Vec3(7, 0, 0), Vec3(8, 1, 1));
  const TriMesh crossing = shapes::box(Vec3(4.5, 4.5, 4.5), Vec3(6, 6, 6));  // through the outer wall only
  const ShellNesting n = classifyShells({outer, cavity, inner, apart, crossing});
  EXPECT_EQ(n.depth, std::vector<int>({0, 1, 2, 0, 0}));
  EXPECT_EQ(n.cavities, 1);
  EXPECT_EQ(n.overlaps, std::vector<char>({1, 0, 0, 0, 1}));
}

TEST(Shells, PrepareDropsCavitiesAndKeepsOverlapsApart) {
  for (const char* name : {"nested_cavity", "nested_cavity_outward"}) {
    const PreparedModel p = prepareModel(caseMesh(name), atTau(0.1));
    ASSERT_TRUE(p.status.ok());
    EXPECT_EQ(p.cavitiesDropped, 1) << name;
    ASSERT_EQ(p.shells.size(), 1u) << name;
    EXPECT_NEAR(signedVolume(p.shells[0]), 27.0, 1e-12);
  }
  const PreparedModel loose = prepareModel(caseMesh("solid_in_cavity"), atTau(0.1));
  EXPECT_EQ(loose.cavitiesDropped, 1);
  EXPECT_EQ(loose.shells.size(), 2u);
  const PreparedModel overlap = prepareModel(caseMesh("shells_overlapping"), atTau(0.1));
  EXPECT_EQ(overlap.overlappingShells, 2);
  EXPECT_EQ(overlap.shells.size(), 2u);
}

// ------------------------------------------------------------------ the wrap
TEST(Wrap, ParametersFollowTau) {
  for (double tau : {0.02, 0.05, 0.2}) {
    const WrapParameters p = wrapParametersFor(tau);
    EXPECT_GT(p.offset, 0.0);
    EXPECT_LT(p.offset, tau);  // room is left in the tau budget
    EXPECT_GE(p.alpha, p.offset);
  }
}

TEST(Wrap, IsClosedOutsideTheInputAtTheOffset) {
  const TriMesh sphere = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  const Wrap w = alphaWrap(sphere, 0.1, 0.01);
  ASSERT_TRUE(w.status.ok()) << w.status.message;
  EXPECT_TRUE(isClosedOriented(w.mesh));
  EXPECT_GT(signedVolume(w.mesh), signedVolume(sphere));
  EXPECT_EQ(countSelfIntersections(w.mesh), 0);
  // Independent distances: every wrap vertex at about the offset from the sphere's surface.
  const MeshIndex index(sphere);
  double lo = 1e9, hi = 0;
  for (const Vec3& p : w.mesh.vertices) {
    const double d = index.distance(p);
    lo = std::min(lo, d), hi = std::max(hi, d);
    EXPECT_FALSE(index.inside(p));
  }
  EXPECT_GT(lo, 0.005);
  EXPECT_LT(hi, 0.02);
  // The library's Hausdorff estimate agrees with a brute-force one in both directions.
  const double h = hausdorffDistance(w.mesh, sphere);
  const MeshIndex wrapIndex(w.mesh);
  std::mt19937_64 rng(3);
  double brute = hi;
  for (const Vec3& p : acdtest::sampleSurface(sphere, 4000, rng)) brute = std::max(brute, wrapIndex.distance(p));
  EXPECT_NEAR(h, brute, 0.002);
}

// ------------------------------------------------------------------ every bad mesh, end to end
/// Checks one decomposition with the tests' own geometry: every component closed and outward,
/// its hull within tau of it (surface points of the component no deeper than tau inside the
/// hull), no component unresolved, and every component vertex on the input's surface (pieces of
/// the input) or within the reported Hausdorff distance of it (pieces of the wrap).
void checkCase(const badmeshes::Case& c, const Decomposition& d) {
  SCOPED_TRACE(c.name + ": " + c.problem);
  if (c.outcome == badmeshes::Outcome::Refused) {
    EXPECT_FALSE(d.status.ok());
    EXPECT_EQ(d.status.message.find('\n'), std::string::npos);
    EXPECT_FALSE(d.status.message.empty());
    return;
  }
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  ASSERT_FALSE(d.components.empty());
  bool anyWrap = false;
  const double scale = d.normalization.scale;
  const double diagonal = boundingBox(c.mesh).size().norm();
  const MeshIndex input(c.mesh);
  for (std::size_t i = 0; i < d.components.size(); ++i) {
    SCOPED_TRACE("component " + std::to_string(i));
    const Component& k = d.components[i];
    anyWrap |= k.ofWrap;
    EXPECT_FALSE(k.unresolved) << k.note;
    EXPECT_TRUE(isClosedOriented(k.mesh));
    EXPECT_GT(signedVolume(k.mesh), 0.0);
    // Concavity, measured independently: how deep the component's vertices lie inside its hull.
    const TriMesh hullMesh = convexHull(k.mesh.vertices).mesh;  // MeshIndex keeps a reference
    const MeshIndex hull(hullMesh);
    double depth = 0;
    for (const Vec3& p : k.mesh.vertices) depth = std::max(depth, hull.distance(p));
    EXPECT_LE(depth * scale, d.options.tau + 1e-9);
    if (c.holes) continue;  // patch vertices lie where the hole was, off the input's surface
    const double allowed = (k.ofWrap ? d.wrap.hausdorff / scale : 0.0) + 2e-5 * diagonal;
    double far = 0;
    for (const Vec3& p : k.mesh.vertices) far = std::max(far, input.distance(p));
    EXPECT_LE(far, allowed) << (k.ofWrap ? "wrap" : "input") << " component vertex this far from the input";
  }
  EXPECT_EQ(anyWrap, c.outcome == badmeshes::Outcome::Wrap);
  EXPECT_EQ(d.wrap.used, anyWrap);
  if (d.wrap.used) {
    EXPECT_GT(d.wrap.hausdorff, 0.0);
    EXPECT_DOUBLE_EQ(d.wrap.hausdorff, std::max(d.wrap.wrapToInput, d.wrap.inputToWrap));
    EXPECT_GE(d.wrap.wrapToInput, d.wrap.offset * 0.9);  // the wrap lies offset outside the input
    if (c.name != "self_intersecting")  // its inner spike lies deep inside the wrap
      EXPECT_LE(d.wrap.hausdorff, d.wrap.alpha + d.wrap.offset);
    EXPECT_FALSE(d.wrap.reason.empty());
  }
  for (const std::string& line : d.repairs) EXPECT_EQ(line.find('\n'), std::string::npos);
}

TEST(BadMeshes, EachIsDecomposedOrRefusedAsExpected) {
  for (const badmeshes::Case& c : badmeshes::all()) checkCase(c, decompose(c.mesh, atTau(0.1)));
}

TEST(BadMeshes, NoWrapRestoresTheRefusal) {
  DecomposeOptions o = atTau(0.1);
  o.wrap = false;
  for (const badmeshes::Case& c : badmeshes::all()) {
    if (c.outcome != badmeshes::Outcome::Wrap) continue;
    const Decomposition d = decompose(c.mesh, o);
    if (c.name == "self_intersecting") {  // a clean solid, decomposed; the component stays above tau
      ASSERT_TRUE(d.status.ok()) << d.status.message;
      EXPECT_TRUE(std::any_of(d.components.begin(), d.components.end(), [](const Component& k) { return k.unresolved; }));
      continue;
    }
    EXPECT_FALSE(d.status.ok()) << c.name;
    EXPECT_EQ(d.status.message.find('\n'), std::string::npos) << c.name;
  }
  // The repairs still apply without the wrap.
  EXPECT_TRUE(decompose(caseMesh("double_sided_face"), o).status.ok());
}

TEST(BadMeshes, ResultDoesNotDependOnFaceOrder) {
  for (const char* name : {"stl_soup", "double_sided_face", "non_manifold_edge_4", "nested_cavity"}) {
    TriMesh m = caseMesh(name);
    const Decomposition a = decompose(m, atTau(0.1));
    std::reverse(m.faces.begin(), m.faces.end());
    const Decomposition b = decompose(m, atTau(0.1));
    ASSERT_TRUE(a.status.ok() && b.status.ok()) << name;
    EXPECT_EQ(a.components.size(), b.components.size()) << name;
    double va = 0, vb = 0;
    for (const Component& c : a.components) va += c.volume;
    for (const Component& c : b.components) vb += c.volume;
    EXPECT_NEAR(va, vb, 1e-9) << name;
  }
}

TEST(BadMeshes, SelfIntersectingCowEndsWithinTauOfItsWrap) {
  const ReadResult r = readMesh(std::string(ACD_DATA_DIR) + "/meshes/cow.off");
  if (!r.status.ok()) GTEST_SKIP() << "corpus not present (scripts/fetch_corpus.sh)";
  const Decomposition d = decompose(r.mesh, atTau(0.05));
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.wrap.used);
  int ofWrap = 0;
  const MeshIndex input(r.mesh);
  for (const Component& c : d.components) {
    EXPECT_FALSE(c.unresolved) << c.note;
    ofWrap += c.ofWrap;
    // Vertices of a wrap component outside the cow lie on the wrap or on its cut caps: within the
    // wrap's distance to the cow plus tau (the caps' vertices are not all on the wrap's surface, so
    // the sampled Hausdorff distance alone does not bound them). Inside the cow they may lie
    // anywhere: the wrap of a surface that passes through itself has inner sheets, and a
    // component there covers only what the model covers.
    double far = 0;
    for (const Vec3& p : c.mesh.vertices)
      if (input.winding(p) == 0) far = std::max(far, input.distance(p));
    EXPECT_LE(far * d.normalization.scale, d.wrap.hausdorff + d.options.tau);
  }
  EXPECT_EQ(ofWrap, static_cast<int>(d.components.size()));
  EXPECT_LT(d.wrap.hausdorff, 0.1);
  // The volume decomposed is the wrap's (a fuzz finding: the report compared the wrap's pieces
  // with the self-intersecting shell's volume, 29 % apart).
  double volume = 0;
  for (const Component& c : d.components) volume += c.volume;
  EXPECT_NEAR(volume, d.stats.inputVolume, 1e-6 * d.stats.inputVolume);
}
