// The robust driver (libacd/src/driver/robust.cpp, acd/robust.hpp) on the generated bad-mesh set
// (tests/bad_meshes.hpp): every case is decomposed or refused as bad_meshes.hpp says, and the
// components are checked with the tests' own geometry (helpers.hpp), not the library's. Each
// repair, the shells and the wrap have their own tests in tests/prepare/.
#include <acd/algo/shells.hpp>
#include <acd/algo/alpha_wrap.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/algo/hull.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/repair.hpp>
#include <acd/robust.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
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

TriMesh caseMesh(const std::string& name) { return badmeshes::byName(name); }

DecomposeOptions atTau(double tau) {
  DecomposeOptions o;
  o.tau = tau;
  return o;
}

}  // namespace

// ------------------------------------------------------------------ every bad mesh, end to end
/// Checks one decomposition with the tests' own geometry: every component closed and outward,
/// its hull within tau of it (surface points of the component no deeper than tau inside the
/// hull), no component unresolved, and every component vertex in the input's solid (pieces of the
/// input: on its surface, or inside where three cuts meet, as in the union of shells that pass
/// through each other) or within the reported Hausdorff distance of it (pieces of the wrap).
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
    // A component that joins shells (the merge across shells) has no concavity to promise.
    if (splitEdgeConnected(k.mesh).size() == 1) EXPECT_LE(depth * scale, d.options.tau + 1e-9);
    if (c.holes) continue;  // patch vertices lie where the hole was, off the input's surface
    const double allowed = (k.ofWrap ? d.wrap.hausdorff / scale : 0.0) + 2e-5 * diagonal;
    double far = 0;
    for (const Vec3& p : k.mesh.vertices) far = std::max(far, input.inside(p) ? 0.0 : input.distance(p));
    EXPECT_LE(far, allowed) << (k.ofWrap ? "wrap" : "input") << " component vertex this far from the input";
  }
  EXPECT_EQ(anyWrap, c.outcome == badmeshes::Outcome::Wrap);
  EXPECT_EQ(d.wrap.used, anyWrap);
  if (d.wrap.used) {
    EXPECT_GT(d.wrap.hausdorff, 0.0);
    EXPECT_DOUBLE_EQ(d.wrap.hausdorff, std::max(d.wrap.wrapToInput, d.wrap.inputToWrap));
    EXPECT_GE(d.wrap.wrapToInput, d.wrap.offset * 0.9);  // the wrap lies offset outside the input
    // The wrap's distance to the input is measured, not bounded by CGAL: it is usually just above
    // alpha + offset, but the triangle cloud's wrap stands 0.249 off in the model's frame (0.103 in
    // the canonical frame) at alpha 0.1 (docs/ALGORITHM.md). Three times that catches a wrap gone wrong.
    if (c.name != "self_intersecting")  // its inner spike lies deep inside the wrap
      EXPECT_LE(d.wrap.hausdorff, 3 * (d.wrap.alpha + d.wrap.offset));
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

/// Largest distance from a sample of `model`'s surface to the union of the hulls (0 inside one),
/// with the tests' own geometry: a point is inside a convex hull when it is behind every face.
double modelUncovered(const TriMesh& model, const Decomposition& d, int samples) {
  std::vector<std::unique_ptr<MeshIndex>> hulls;
  for (const Component& c : d.components) hulls.push_back(std::make_unique<MeshIndex>(c.hull));
  std::mt19937_64 rng(5);
  double worst = 0;
  for (const Vec3& p : acdtest::sampleSurface(model, samples, rng)) {
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t h = 0; h < d.components.size() && nearest > 0; ++h) {
      const TriMesh& hull = d.components[h].hull;
      bool inside = true;
      for (int f = 0; f < static_cast<int>(hull.faces.size()) && inside; ++f)
        inside = faceNormal(hull, f).dot(p - hull.vertices[hull.faces[f][0]]) <= 0;
      nearest = std::min(nearest, inside ? 0.0 : hulls[h]->distance(p));
    }
    worst = std::max(worst, nearest);
  }
  return worst;
}

// The cow passes through itself (its tail), so some sections cross themselves and a piece stays
// above tau. The faces around the crossings are replaced (removeSelfIntersections) in that piece
// alone, which is decomposed again, its merges held to the cow; where that fails (at tau 0.02),
// in the whole cow. Through its wrap, before, it took
// 14 parts at tau 0.1 and 27 at 0.05, and its hulls reached 1.12 tau when the merges were held to
// the wrap. Here with the tests' own distances: points of the hulls' surfaces outside the cow
// (winding 0), and points of the cow's surface outside every hull. (At tau 0.02 the piece whose
// cuts stall at the tail has its hull within tau, but a vertex of the fold lies deeper than tau
// below it: it is cut again, and repaired.)
TEST(BadMeshes, SelfIntersectingCowIsRepairedAroundItsCrossings) {
  const ReadResult r = readMesh(std::string(ACD_DATA_DIR) + "/meshes/cow.off");
  if (!r.status.ok()) GTEST_SKIP() << "corpus not present (scripts/fetch_corpus.sh)";
  for (double tau : {0.1, 0.05, 0.02}) {
    SCOPED_TRACE(tau);
    DecomposeOptions o = recommendedOptions();  // as the acd command decomposes: the merge held to the model
    o.tau = tau;
    const Decomposition d = decompose(r.mesh, o);
    ASSERT_TRUE(d.status.ok()) << d.status.message;
    EXPECT_FALSE(d.wrap.used);
    EXPECT_TRUE(std::any_of(d.repairs.begin(), d.repairs.end(), [](const std::string& line) {
      return line.find("removed its self-intersections") != std::string::npos;
    }));
    if (tau >= 0.05)
      EXPECT_TRUE(std::any_of(d.repairs.begin(), d.repairs.end(), [](const std::string& line) {
        return line.find("removed its self-intersections in that component only") != std::string::npos;
      }));
    const MeshIndex input(r.mesh);
    std::mt19937_64 rng(11);
    double out = 0, volume = 0;
    for (const Component& c : d.components) {
      EXPECT_FALSE(c.unresolved) << c.note;
      EXPECT_FALSE(c.ofWrap);
      volume += c.volume;
      for (const Vec3& p : acdtest::sampleSurface(c.hull, 4000, rng))
        if (input.winding(p) == 0) out = std::max(out, input.distance(p));
    }
    const double scale = d.normalization.scale;
    EXPECT_LE(out * scale, tau);
    EXPECT_GT(out * scale, 0.5 * tau);  // the hulls do reach out: the test can fail
    EXPECT_LE(modelUncovered(r.mesh, d, 40000) * scale, tau);
    // The components add up to the repaired cow, which lost only the crossing fold of the tail.
    EXPECT_NEAR(volume, d.stats.inputVolume, 1e-6 * d.stats.inputVolume);
    EXPECT_NEAR(d.stats.inputVolume, signedVolume(r.mesh) * scale * scale * scale, 0.01 * d.stats.inputVolume);
  }
}

// A surface that crosses itself everywhere (a sphere of 1740 faces with every vertex moved at
// random by up to 0.25 of its radius: thousands of crossing pairs) is not repaired locally: the
// repair's time grows with the crossings (35 s and a failure on a larger one), so beyond 2000
// pairs the shell goes straight to its wrap.
TEST(BadMeshes, ASurfaceCrossingItselfEverywhereGoesToItsWrap) {
  TriMesh crumpled = shapes::revolve([](double z) { return std::sqrt(std::max(0.0, 1.0 - z * z)); }, -1.0, 1.0, 30, 30);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  for (Vec3& p : crumpled.vertices) {
    const double x = jitter(rng), y = jitter(rng), z = jitter(rng);
    p += Vec3(x, y, z);
  }
  ASSERT_GT(countSelfIntersections(crumpled, 2001), 2000);
  const Decomposition d = decompose(crumpled, atTau(0.2));
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_TRUE(d.wrap.used);
  for (const std::string& line : d.repairs) EXPECT_EQ(line.find("removed its self-intersections"), std::string::npos) << line;
  EXPECT_TRUE(std::any_of(d.repairs.begin(), d.repairs.end(), [](const std::string& line) {
    return line.find("too many for a local repair") != std::string::npos;
  }));
  for (const Component& c : d.components) EXPECT_FALSE(c.unresolved) << c.note;
}


// The repairs' shells are not checked a second time inside decompose (driver/clean_shell.hpp). A
// model decomposed through them (repair on) must cut as the solid decomposition of the model as
// read does (repair off, which checks and prepares the mesh itself): the same components, of the
// same volumes and hull volumes (the routes differ by rounding: the repaired one works in each
// shell's units). Two corpus models; a box whose faces come in reverse order with every other one
// inside out; and two cubes that share one corner, which the repairs split into two shells, each
// with its own copy of the corner.
TEST(CleanShells, CutAsTheModelItselfDoes) {
  std::vector<std::pair<std::string, TriMesh>> models;
  for (const std::string name : {"elephant", "knot"}) {
    const ReadResult r = readMesh(std::string(ACD_DATA_DIR) + "/meshes/" + name + ".off");
    ASSERT_TRUE(r.status.ok()) << name;
    models.emplace_back(name, r.mesh);
  }
  TriMesh box = shapes::box({0, 0, 0}, {2, 1, 1});
  for (std::size_t f = 0; f < box.faces.size(); f += 2) std::swap(box.faces[f][1], box.faces[f][2]);
  std::reverse(box.faces.begin(), box.faces.end());
  models.emplace_back("box", box);
  models.emplace_back("corner", concatenate({shapes::box({0, 0, 0}, {1, 1, 1}), shapes::box({1, 1, 1}, {2, 2, 2})}));
  for (const auto& [name, mesh] : models) {
    DecomposeOptions on = atTau(0.05), off = atTau(0.05);
    off.repair = false;
    const Decomposition a = decompose(mesh, on), b = decompose(mesh, off);
    ASSERT_TRUE(a.status.ok()) << name << ": " << a.status.message;
    ASSERT_TRUE(b.status.ok()) << name << ": " << b.status.message;
    ASSERT_EQ(a.components.size(), b.components.size()) << name;
    double volume = 0.0;
    for (std::size_t i = 0; i < a.components.size(); ++i) {
      EXPECT_NEAR(a.components[i].volume, b.components[i].volume, 1e-9) << name << " component " << i;
      EXPECT_NEAR(a.components[i].hullVolume, b.components[i].hullVolume, 1e-6) << name << " component " << i;
      volume += a.components[i].volume;
    }
    const double s = a.normalization.scale;  // volumes are in normalised units
    if (name == "box" || name == "corner") EXPECT_NEAR(volume, 2.0 * s * s * s, 1e-9) << name;  // outward, all of it
  }
}

// The reported total is the call's own time, the repairs included: a soup of 20k faces (every
// face with its own corners) spends a good part of it merging them before any cut.
TEST(CleanShells, TheTotalTimeCountsTheRepairs) {
  const TriMesh mesh = badmeshes::soup(shapes::icosphere(Vec3(0, 0, 0), 1.0, 5));
  const auto start = std::chrono::steady_clock::now();
  const Decomposition d = decompose(mesh, atTau(0.05));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_GT(d.repairSeconds, 0.0);
  EXPECT_LE(d.times.total, wall);
  EXPECT_GE(d.times.total, 0.95 * wall) << "repairs " << d.repairSeconds << " s, prepare " << d.times.prepare << " s";
  EXPECT_GE(d.times.total, d.times.prepare + d.times.merging + d.times.hulls);
}
