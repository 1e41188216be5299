// Algorithm 1 end to end: component counts on shapes with known answers, and the invariants every
// decomposition must satisfy (closed pieces, volume kept, concavity <= tau, interior-disjoint pieces
// that cover the model, hulls close to their pieces, thread-count independence), also on the corpus.
#include <acd/algo/concavity.hpp>
#include <acd/algo/surface_graph.hpp>
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/algo/hull.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include "helpers.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <string>

using namespace acd;
using acdtest::MeshIndex;
using acdtest::corpus;

namespace {

DecomposeOptions withTau(double tau, bool grouping = true) {
  DecomposeOptions o;
  o.tau = tau;
  o.featureGrouping = grouping;
  o.threads = 0;
  return o;
}

double concavityOf(const TriMesh& mesh, double epsilon) {
  const TriMesh m = applyNormalization(mesh, minimumSphereNormalization(mesh));
  SurfaceGraph graph(m);
  ConcavityOptions o;
  o.epsilon = epsilon;
  return measureConcavity(m, graph, o).concavity;
}

struct InvariantReport {
  int components = 0;
  int unresolved = 0;
  double maxHullGap = 0;  // largest distance from a hull-surface sample to its component's surface
};

/// Checks everything a decomposition of `input` must satisfy. Reports failures with gtest
/// assertions and returns a summary for further checks.
///
/// Hull gap (largest distance from a point of a component's hull surface to the component's
/// surface): the paper's concavity alone does not bound it (a thin washer has concavity ~0 while
/// its hull spans the hole), so the driver measures it too and keeps every resolved component's
/// within tau (acd/algo/hull_excess.hpp). Here it is sampled with the tests' own distance code.
///
/// What concavity <= tau does bound: the bridge planes are tangent to the hull, so a vertex's
/// distance to its bridge plane is at least its distance to the hull's boundary. Hence every
/// vertex of a component lies within Component::concavity (<= tau) of its hull's surface.
InvariantReport checkInvariants(const TriMesh& input, const Decomposition& d, bool strictHullGap = true,
                                int samples = 20000, std::uint64_t seed = 42) {
  InvariantReport rep;
  EXPECT_TRUE(d.status.ok()) << toString(d.status.code) << ": " << d.status.message;
  if (!d.status.ok()) return rep;
  rep.components = static_cast<int>(d.components.size());
  EXPECT_GE(rep.components, 1);
  const double tau = d.options.tau;
  const Normalization& n = d.normalization;
  const TriMesh model = applyNormalization(input, n);
  const double modelVolume = std::abs(signedVolume(model));
  EXPECT_NEAR(d.stats.inputVolume, modelVolume, 1e-9 * modelVolume);

  // Per component: closed, outward, volume bookkeeping, concavity, hull.
  std::vector<TriMesh> parts, hulls;
  double volume = 0;
  for (std::size_t i = 0; i < d.components.size(); ++i) {
    SCOPED_TRACE("component " + std::to_string(i));
    const Component& c = d.components[i];
    parts.push_back(applyNormalization(c.mesh, n));
    hulls.push_back(applyNormalization(c.hull, n));
    EXPECT_TRUE(isClosedOriented(c.mesh));
    EXPECT_GT(c.volume, 0.0);
    EXPECT_NEAR(c.volume, signedVolume(parts.back()), 1e-9 * std::max(c.volume, 1e-12) + 1e-15);
    EXPECT_NEAR(c.hullVolume, signedVolume(hulls.back()), 1e-9 * std::max(c.hullVolume, 1e-12) + 1e-15);
    EXPECT_GE(c.hullVolume, c.volume * (1 - 1e-9));
    // The paper's promise per component holds with MergeScope::Component; with Model, a merged
    // component may be more concave, and its hull is held to tau of the model instead (below).
    if (!c.unresolved && d.options.mergeScope == MergeScope::Component)
      EXPECT_LE(c.concavity, tau) << "component " << i << " concavity " << c.concavity;
    if (!c.unresolved) EXPECT_LE(c.hullExcess, tau) << "component " << i << " hull excess " << c.hullExcess;
    rep.unresolved += c.unresolved;
    volume += c.volume;
  }
  // Only a self-intersecting input may leave a component unresolved (its sections have crossing
  // loops); each one says why. Everything else must end below tau.
  if (rep.unresolved > 0 && countSelfIntersections(input, 1) > 0) {
    for (const Component& c : d.components)
      if (c.unresolved) EXPECT_NE(c.note.find("self-intersects"), std::string::npos) << c.note;
  } else {
    EXPECT_EQ(rep.unresolved, 0) << "unresolved components";
  }
  EXPECT_NEAR(volume, d.stats.inputVolume, 1e-6 * d.stats.inputVolume);

  std::vector<std::unique_ptr<MeshIndex>> partIndex;
  for (const TriMesh& p : parts) partIndex.push_back(std::make_unique<MeshIndex>(p));
  const MeshIndex modelIndex(model);
  const bool withinModel = d.options.merge && d.options.mergeScope == MergeScope::Model;

  std::mt19937_64 rng(seed);
  double maxDepth = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const TriMesh& h = hulls[i];
    if (h.empty()) {
      ADD_FAILURE() << "component " << i << " has an empty hull";
      continue;
    }
    const MeshIndex hullIndex(h);
    // Every vertex lies within the component's concavity of the hull's surface.
    double depth = 0;
    int deepest = -1;
    for (std::size_t v = 0; v < parts[i].vertices.size(); ++v) {
      const Vec3& p = parts[i].vertices[v];
      if (!hullIndex.inside(p)) continue;
      const double dist = hullIndex.distance(p);
      if (dist > depth) depth = dist, deepest = static_cast<int>(v);
    }
    maxDepth = std::max(maxDepth, depth);
    // (1e-6: the driver measures on coordinates rounded to the canonical grid, 2.4e-7.)
    EXPECT_LE(depth, d.components[i].concavity + 1e-6)
        << "component " << i << ": vertex " << deepest << " at "
        << (deepest >= 0 ? parts[i].vertices[deepest] : Vec3::Zero()).transpose()
        << " (normalised) lies this deep inside the hull, but the component's concavity is "
        << d.components[i].concavity << " (tau " << tau << ")";
    // Hull gap: from the component, or with MergeScope::Model from the model (a hull point inside
    // the model counts zero: it lies in another component).
    double gap = 0;
    Vec3 where = Vec3::Zero();
    for (const Vec3& p : acdtest::sampleSurface(h, 400, rng)) {
      const double dist = !withinModel ? partIndex[i]->distance(p) : modelIndex.inside(p) ? 0.0 : modelIndex.distance(p);
      if (dist > gap) gap = dist, where = p;
    }
    rep.maxHullGap = std::max(rep.maxHullGap, gap);
    if (strictHullGap && !d.components[i].unresolved)
      EXPECT_LE(gap, tau) << "component " << i << ": hull point " << where.transpose()
                                << " (normalised) is this far from the component; its concavity is "
                                << d.components[i].concavity;
  }
  ::testing::Test::RecordProperty("max_hull_gap", std::to_string(rep.maxHullGap));
  ::testing::Test::RecordProperty("max_vertex_depth_in_hull", std::to_string(maxDepth));
  ::testing::Test::RecordProperty("components", rep.components);

  // Interior-disjoint and covering: sample the model's bounding box.
  const Box3 box = boundingBox(model);
  const Vec3 lo = box.lo - 0.02 * box.size(), hi = box.hi + 0.02 * box.size();
  std::uniform_real_distribution<double> ux(lo.x(), hi.x()), uy(lo.y(), hi.y()), uz(lo.z(), hi.z());
  int overlaps = 0, holes = 0, outside = 0, inModel = 0;
  std::ostringstream first;
  for (int s = 0; s < samples; ++s) {
    const double x = ux(rng), y = uy(rng), z = uz(rng);  // drawn in this order
    const Vec3 p(x, y, z);
    const bool in = modelIndex.inside(p);
    inModel += in;
    int count = 0;
    std::vector<int> containing;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      const Vec3 &a = partIndex[i]->lo(), &b = partIndex[i]->hi();
      if ((p.array() < a.array()).any() || (p.array() > b.array()).any()) continue;
      if (partIndex[i]->inside(p)) ++count, containing.push_back(static_cast<int>(i));
    }
    if (count == (in ? 1 : 0)) continue;
    // Within 1e-9 of a cut or of the surface the answer may go either way.
    double near = modelIndex.distance(p);
    for (int i : containing) near = std::min(near, partIndex[i]->distance(p));
    if (near <= 1e-9) continue;
    if (count > 1) ++overlaps;
    else if (in) ++holes;
    else ++outside;
    if (first.tellp() == 0)
      first << "first bad sample " << p.transpose() << ": in model " << in << ", in " << count << " components";
  }
  EXPECT_GT(inModel, samples / 100) << "sampling missed the model";
  EXPECT_EQ(overlaps, 0) << "samples inside two or more components. " << first.str();
  EXPECT_EQ(holes, 0) << "samples inside the model but in no component. " << first.str();
  EXPECT_EQ(outside, 0) << "samples outside the model but inside a component. " << first.str();
  return rep;
}

}  // namespace

// ------------------------------------------------------------------ the inside test itself

TEST(DecomposeHelpers, InsideTestOnKnownSolids) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const MeshIndex b(box);
  EXPECT_TRUE(b.inside(Vec3(0.5, 0.5, 0.5)));
  EXPECT_TRUE(b.inside(Vec3(0.3, 0.7, 0.01)));
  EXPECT_FALSE(b.inside(Vec3(1.5, 0.5, 0.5)));
  EXPECT_FALSE(b.inside(Vec3(0.5, 0.5, -0.1)));
  // Rays through shared edges and vertices (x = y diagonal, the top face's corner) are counted once.
  EXPECT_TRUE(b.inside(Vec3(0.5, 0.5, 0.2)));
  EXPECT_TRUE(b.inside(Vec3(0.25, 0.25, 0.2)));
  EXPECT_FALSE(b.inside(Vec3(0.25, 0.25, 1.2)));
  EXPECT_NEAR(b.distance(Vec3(0.5, 0.5, 2)), 1.0, 1e-15);
  EXPECT_NEAR(b.distance(Vec3(0.5, 0.5, 0.4)), 0.4, 1e-15);

  const TriMesh torus = shapes::torus(2.0, 0.5, 48, 24);
  const MeshIndex t(torus);
  EXPECT_TRUE(t.inside(Vec3(2, 0, 0)));
  EXPECT_FALSE(t.inside(Vec3(0, 0, 0)));
  EXPECT_FALSE(t.inside(Vec3(2, 0, 0.6)));
  // Monte-Carlo volume agrees with the divergence theorem.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.6, 2.6), v(-0.6, 0.6);
  int in = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = u(rng), y = u(rng), z = v(rng);  // drawn in this order
    in += t.inside(Vec3(x, y, z));
  }
  const double mc = 5.2 * 5.2 * 1.2 * in / n;
  EXPECT_NEAR(mc, signedVolume(torus), 0.02 * signedVolume(torus));
}

namespace {

/// A hand-made "decomposition" of the L into two boxes; `lower` is the second box's lower y.
Decomposition fakeLDecomposition(double lower) {
  Decomposition d;
  d.normalization = minimumSphereNormalization(shapes::lShape());
  d.options = resolvedOptions(withTau(0.05));
  d.options.mergeScope = MergeScope::Component;  // the paper's promise: every component within tau
  const double s3 = std::pow(d.normalization.scale, 3);
  for (const auto& [lo, hi] : {std::pair{Vec3(0, 0, 0), Vec3(2, 1, 1)}, std::pair{Vec3(0, lower, 0), Vec3(1, 2, 1)}}) {
    Component c;
    c.mesh = shapes::box(lo, hi);
    c.hull = c.mesh;
    c.volume = c.hullVolume = signedVolume(c.mesh) * s3;
    d.components.push_back(c);
  }
  d.stats.inputVolume = 3.0 * s3;
  return d;
}

/// Runs checkInvariants and returns the messages of the failures it reported.
std::vector<std::string> failuresOf(const TriMesh& input, const Decomposition& d) {
  ::testing::TestPartResultArray results;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &results);
    checkInvariants(input, d, true, 5000);
  }
  std::vector<std::string> messages;
  for (int i = 0; i < results.size(); ++i) messages.push_back(results.GetTestPartResult(i).message());
  return messages;
}

bool anyContains(const std::vector<std::string>& messages, const std::string& what) {
  for (const auto& m : messages)
    if (m.find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(DecomposeHelpers, InvariantsAcceptACorrectDecompositionAndCatchBrokenOnes) {
  const TriMesh l = shapes::lShape();
  EXPECT_TRUE(failuresOf(l, fakeLDecomposition(1.0)).empty());
  const auto overlap = failuresOf(l, fakeLDecomposition(0.5));
  EXPECT_TRUE(anyContains(overlap, "inside two or more components"));
  EXPECT_TRUE(anyContains(overlap, "d.stats.inputVolume"));  // the volumes do not add up either
  const auto hole = failuresOf(l, fakeLDecomposition(1.5));
  EXPECT_TRUE(anyContains(hole, "inside the model but in no component"));
  Decomposition concave = fakeLDecomposition(1.0);
  concave.components[0].concavity = 0.25;
  EXPECT_TRUE(anyContains(failuresOf(l, concave), "component 0 concavity 0.25"));
  Decomposition standsOff = fakeLDecomposition(1.0);
  standsOff.options.mergeScope = MergeScope::Model;  // no promise on a merged component's concavity, on its hull
  standsOff.components[0].hullExcess = 0.25;
  EXPECT_TRUE(anyContains(failuresOf(l, standsOff), "component 0 hull excess 0.25"));
}

// ------------------------------------------------------------------ generated shapes

TEST(Decompose, ConvexInputsStayOneComponent) {
  std::mt19937_64 rng(200);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  std::vector<Vec3> cloud;
  for (int i = 0; i < 200; ++i) {
    const double x = 3 * uni(rng), y = uni(rng), z = 2 * uni(rng);  // drawn in this order
    cloud.emplace_back(x, y, z);
  }
  const std::vector<std::pair<const char*, TriMesh>> cases = {
      {"box", shapes::box(Vec3(0, 0, 0), Vec3(2, 1, 3))},
      {"icosphere", shapes::icosphere(Vec3(1, 2, 3), 5.0, 3)},
      {"random hull", hullMesh(cloud)}};
  for (const auto& [name, mesh] : cases) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(isClosedOriented(mesh));
    const Decomposition d = decompose(mesh, withTau(0.05));
    checkInvariants(mesh, d);
    ASSERT_EQ(d.components.size(), 1u);
    EXPECT_EQ(d.stats.cuts, 0);
    EXPECT_LE(d.components[0].concavity, 0.05);
    EXPECT_NEAR(d.components[0].hullVolume, d.components[0].volume, 1e-9 * d.components[0].volume);
  }
}

TEST(Decompose, LShapeGivesTwoComponents) {
  const TriMesh l = shapes::lShape();
  const Decomposition d = decompose(l, withTau(0.05));
  checkInvariants(l, d);
  EXPECT_EQ(d.components.size(), 2u);
  for (const Component& c : d.components) EXPECT_NEAR(c.hullVolume, c.volume, 1e-9 * c.volume);  // boxes
}

TEST(Decompose, UShapeInvariants) {
  const TriMesh u = shapes::uShape();
  const Decomposition d = decompose(u, withTau(0.05));
  checkInvariants(u, d);
  EXPECT_GE(d.components.size(), 3u);
  for (const Component& c : d.components) EXPECT_NEAR(c.hullVolume, c.volume, 1e-9 * c.volume);  // convex
}

// Three boxes (two arms and the base) suffice: the cut must follow the slot bottom, not the
// diagonal bisector of one of its edges.
TEST(Decompose, UShapeGivesThreeComponents) {
  const TriMesh u = shapes::uShape();
  const Decomposition d = decompose(u, withTau(0.05));
  checkInvariants(u, d);
  EXPECT_EQ(d.components.size(), 3u);
}

// A block of 10 x 5 x 5 cells with a straight square bore (3 x 3 cells, 4 deep): five boxes, the
// block under the bore's floor and its four walls. Every candidate plane lies in a wall or in the
// floor, so they tie; the plane across the floor must not win the ties (it cut the bore into rings,
// and through a wrap to 11 parts, before it had to win by a margin).
TEST(Decompose, AStraightBoreGivesItsFloorAndFourWalls) {
  std::vector<std::array<int, 3>> cells;
  for (int x = 0; x < 10; ++x)
    for (int y = 0; y < 5; ++y)
      for (int z = 0; z < 5; ++z)
        if (!(x < 4 && y >= 1 && y <= 3 && z >= 1 && z <= 3)) cells.push_back({x, y, z});
  const TriMesh block = shapes::voxels(cells);
  for (double tau : {0.05, 0.02}) {
    SCOPED_TRACE(tau);
    DecomposeOptions o = recommendedOptions();  // as the acd command decomposes
    o.tau = tau;
    const Decomposition d = decompose(block, o);
    checkInvariants(block, d);
    EXPECT_EQ(d.components.size(), 5u);
  }
}

TEST(Decompose, DumbbellOnBothSidesOfItsConcavity) {
  const TriMesh db = shapes::dumbbell();
  // Its concavity (bar radius 0.15 under balls of radius 1, scaled by 1/3) is about 0.28: tau = 0.05
  // must cut it, tau = 0.5 must not.
  const double c = concavityOf(db, 0.025);
  ASSERT_GT(c, 0.05);
  ASSERT_LT(c, 0.5);
  const Decomposition fine = decompose(db, withTau(0.05));
  checkInvariants(db, fine);
  EXPECT_EQ(fine.components.size(), 3u);
  const Decomposition coarse = decompose(db, withTau(0.5));
  checkInvariants(db, coarse);
  EXPECT_EQ(coarse.components.size(), 1u);
  EXPECT_EQ(coarse.stats.cuts, 0);
}

TEST(Decompose, TorusIsCut) {
  const TriMesh torus = shapes::torus(2.0, 0.5, 48, 24);
  const Decomposition d = decompose(torus, withTau(0.05));
  const InvariantReport r = checkInvariants(torus, d);
  EXPECT_GE(r.components, 4);  // a ring needs at least 4 convex-ish arcs at this tolerance
}

class DecomposeNoGrouping : public ::testing::TestWithParam<std::string> {};

TEST_P(DecomposeNoGrouping, InvariantsHold) {
  const std::string name = GetParam();
  TriMesh mesh;
  if (name == "L") mesh = shapes::lShape();
  else if (name == "U") mesh = shapes::uShape();
  else if (name == "dumbbell") mesh = shapes::dumbbell();
  else if (name == "torus") mesh = shapes::torus(2.0, 0.5, 48, 24);
  else mesh = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  for (double tau : {0.05, 0.5}) {
    SCOPED_TRACE("tau " + std::to_string(tau));
    const Decomposition d = decompose(mesh, withTau(tau, false));
    EXPECT_FALSE(d.options.featureGrouping);
    checkInvariants(mesh, d);
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, DecomposeNoGrouping,
                         ::testing::Values("L", "U", "dumbbell", "torus", "icosphere"),
                         [](const auto& info) { return info.param; });

TEST(Decompose, RejectsInvalidParametersAndInput) {
  const TriMesh l = shapes::lShape();
  for (double tau : {0.0, -1.0, std::nan(""), 1e9}) {
    const Decomposition d = decompose(l, withTau(tau));
    EXPECT_EQ(d.status.code, StatusCode::InvalidParameter) << tau;
    EXPECT_TRUE(d.components.empty());
  }
  DecomposeOptions o = withTau(0.05);
  o.threads = -3;
  EXPECT_EQ(decompose(l, o).status.code, StatusCode::InvalidParameter);
  TriMesh open = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  open.faces.pop_back();
  DecomposeOptions refuseOpen = withTau(0.05);
  refuseOpen.fillHoles = false;  // by default the hole is closed first (test_open_surface_holes.cpp)
  refuseOpen.wrap = false;       // and what stays open is wrapped (test_robust.cpp)
  const Decomposition d = decompose(open, refuseOpen);
  EXPECT_EQ(d.status.code, StatusCode::OpenMesh);
  EXPECT_TRUE(d.components.empty());
}

TEST(Decompose, SeveralPiecesAreDecomposedSeparately) {
  TriMesh two = shapes::lShape();
  const TriMesh far = shapes::uShape();
  const int base = static_cast<int>(two.vertices.size());
  for (const Vec3& v : far.vertices) two.vertices.push_back(v + Vec3(10, 0, 0));
  for (Face f : far.faces) two.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  const Decomposition d = decompose(two, withTau(0.05));
  checkInvariants(two, d);
  // Each piece is decomposed on its own (normalised together, which scales tau, so compare with the
  // pieces decomposed at the tau that corresponds to the joint normalisation).
  const double joint = minimumSphereNormalization(two).scale;
  const double lTau = 0.05 * minimumSphereNormalization(shapes::lShape()).scale / joint;
  const double uTau = 0.05 * minimumSphereNormalization(far).scale / joint;
  ASSERT_LE(lTau, 2.0);
  ASSERT_LE(uTau, 2.0);
  const std::size_t separate = decompose(shapes::lShape(), withTau(lTau)).components.size() +
                               decompose(far, withTau(uTau)).components.size();
  EXPECT_EQ(d.components.size(), separate);
  EXPECT_GE(d.components.size(), 5u);
  std::set<int> sources;
  for (const Component& c : d.components) sources.insert(c.source);
  EXPECT_EQ(sources, std::set<int>({0, 1}));
}

TEST(Decompose, OutputDoesNotDependOnThreadCount) {
  TriMesh mesh;
  std::string which = "elephant";
  const std::string path = corpus(which);
  if (std::ifstream(path)) {
    ReadResult r = readMesh(path);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    mesh = std::move(r.mesh);
  } else {
    which = "dumbbell";
    mesh = shapes::dumbbell();
  }
  RecordProperty("model", which);
  DecomposeOptions o = withTau(0.05);
  o.threads = 1;
  const Decomposition one = decompose(mesh, o);
  o.threads = 2;
  const Decomposition two = decompose(mesh, o);
  ASSERT_TRUE(one.status.ok()) << one.status.message;
  ASSERT_TRUE(two.status.ok()) << two.status.message;
  ASSERT_EQ(one.components.size(), two.components.size());
  EXPECT_GT(one.components.size(), 1u);
  for (std::size_t i = 0; i < one.components.size(); ++i) {
    const Component &a = one.components[i], &b = two.components[i];
    ASSERT_EQ(a.mesh.vertices, b.mesh.vertices) << "component " << i;
    ASSERT_EQ(a.mesh.faces, b.mesh.faces) << "component " << i;
    ASSERT_EQ(a.hull.vertices, b.hull.vertices) << "component " << i;
    EXPECT_EQ(a.concavity, b.concavity);
    EXPECT_EQ(a.volume, b.volume);
  }
  EXPECT_EQ(one.stats.cuts, two.stats.cuts);
}

// The recursion stops at maxComponents: the pieces still to cut when the count would pass it
// are kept as they are and said to be unresolved. A comb of seven teeth needs more than four.
TEST(Decompose, TheComponentCapHoldsAndDoesNotDependOnThreads) {
  std::vector<std::array<int, 3>> cells;
  for (int x = 0; x < 13; ++x) cells.push_back({x, 0, 0});
  for (int tooth = 0; tooth < 7; ++tooth)
    for (int y = 1; y <= 3; ++y) cells.push_back({2 * tooth, y, 0});
  const TriMesh comb = shapes::voxels(cells);
  DecomposeOptions o = withTau(0.02);
  o.merge = false;
  o.invariant = false;  // the volumes add up exactly in the input's own coordinates
  const Decomposition all = decompose(comb, o);
  ASSERT_TRUE(all.status.ok()) << all.status.message;
  ASSERT_GT(all.components.size(), 4u);
  for (const Component& c : all.components) EXPECT_FALSE(c.unresolved);
  o.maxComponents = 4;
  std::vector<Decomposition> capped;
  for (int threads : {1, 2}) {
    o.threads = threads;
    capped.push_back(decompose(comb, o));
    const Decomposition& d = capped.back();
    ASSERT_TRUE(d.status.ok()) << d.status.message;
    EXPECT_LE(d.components.size(), 4u);
    int unresolved = 0;
    double volume = 0.0;
    for (const Component& c : d.components) {
      unresolved += c.unresolved;
      if (c.unresolved) EXPECT_EQ(c.note, "maximum number of components reached");
      volume += c.volume;
    }
    EXPECT_GE(unresolved, 1);
    EXPECT_NEAR(volume, d.stats.inputVolume, 1e-9 * d.stats.inputVolume);
  }
  ASSERT_EQ(capped[0].components.size(), capped[1].components.size());
  for (std::size_t i = 0; i < capped[0].components.size(); ++i) {
    EXPECT_EQ(capped[0].components[i].mesh.vertices, capped[1].components[i].mesh.vertices) << i;
    EXPECT_EQ(capped[0].components[i].mesh.faces, capped[1].components[i].mesh.faces) << i;
  }
}

// ------------------------------------------------------------------ corpus

struct CorpusCase {
  std::string model;
  double tau;
};

void PrintTo(const CorpusCase& c, std::ostream* os) { *os << c.model << " tau " << c.tau; }

class DecomposeCorpus : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(DecomposeCorpus, Invariants) {
  const CorpusCase c = GetParam();
  const std::string path = corpus(c.model);
  if (!std::ifstream(path)) GTEST_SKIP() << path << " not present (scripts/fetch_corpus.sh)";
  ReadResult r = readMesh(path);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  // The partition invariants hold for the input itself: no wrap here (a self-intersecting model
  // may keep an unresolved component; its decomposition through the wrap: test_robust.cpp).
  // They are those of the mesh decomposed, so at full resolution: armadillo and bunny00 go through
  // the working mesh by default, whose promise against the input test_working_model.cpp checks.
  DecomposeOptions o = recommendedOptions();  // as the acd command decomposes
  o.tau = c.tau;
  o.wrap = false;
  o.workingShare = 0.0;
  const Decomposition d = decompose(r.mesh, o);
  ASSERT_TRUE(d.status.ok()) << toString(d.status.code) << ": " << d.status.message;
  const InvariantReport rep = checkInvariants(r.mesh, d);
  // Every corpus model is far from convex at these tolerances, but for the handle at tau 0.2: the
  // merge held to the model fits it in one hull (its hole is narrow; the hull stays within tau of
  // the model, checked above with the tests' own distances).
  EXPECT_GE(rep.components, c.model == "handle" && c.tau == 0.2 ? 1 : 2);
  // Upper bounds at tau 0.05: 1.5 times the parts of commit 8fe3a39 (the acd command's options,
  // without the wrap), so that a change that makes many more parts fails here rather than going
  // unnoticed.
  const std::map<std::string, int> measured{{"armadillo", 30}, {"bunny00", 15}, {"camel", 26}, {"cow", 20},
                                            {"dino", 26},      {"eight", 15},   {"elephant", 29}, {"handle", 6},
                                            {"homer", 12},     {"knot", 30}};
  if (c.tau == 0.05 && measured.count(c.model))
    EXPECT_LE(rep.components, 3 * measured.at(c.model) / 2) << c.model << ": more parts than the bound";
}

INSTANTIATE_TEST_SUITE_P(
    Models, DecomposeCorpus,
    ::testing::ValuesIn([] {
      std::vector<CorpusCase> cases;
      for (const char* m : {"elephant", "armadillo", "bunny00", "camel", "dino", "homer", "handle", "knot", "eight", "cow"})
        for (double tau : {0.2, 0.05}) cases.push_back({m, tau});
      return cases;
    }()),
    [](const auto& info) {
      return info.param.model + (info.param.tau == 0.2 ? "_tau0_2" : "_tau0_05");
    });
