// Genus reduction (Section 5): handle caps share a pocket until handle cuts separate them.
#include <acd/algo/concavity.hpp>
#include <acd/algo/handles.hpp>
#include <acd/algo/surface_graph.hpp>
#include <acd/decompose.hpp>
#include <acd/io.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <array>
#include <string>
#include <unordered_set>

using namespace acd;
using acdtest::normalised;
using acdtest::measure;

namespace {

/// A flat plate of voxels with `holes` square holes in a row: genus = holes.
TriMesh holedPlate(int holes) {
  std::vector<std::array<int, 3>> cells;
  const int nx = 2 + 3 * holes, ny = 5;
  for (int x = 0; x < nx; ++x)
    for (int y = 0; y < ny; ++y) {
      cells.push_back({x, y, 0});
    }
  // Holes: cells (3k+2 .. 3k+2, 2) for k < holes, i.e. one cell each, separated by two solid cells.
  std::vector<std::array<int, 3>> kept;
  for (auto c : cells) {
    bool hole = false;
    for (int k = 0; k < holes; ++k)
      if (c[0] == 2 + 3 * k && c[1] == 2) hole = true;
    if (!hole) kept.push_back(c);
  }
  return shapes::voxels(kept);
}

int edgeComponents(const TriMesh& mesh, const std::vector<HandleCut>& cuts) {
  std::unordered_set<std::uint64_t> blocked;
  for (const auto& c : cuts) blocked.insert(c.edges.begin(), c.edges.end());
  SurfaceGraph graph(mesh);
  const int nf = static_cast<int>(mesh.faces.size());
  std::vector<char> seen(nf, 0);
  int comps = 0;
  for (int s = 0; s < nf; ++s) {
    if (seen[s]) continue;
    ++comps;
    std::vector<int> stack{s};
    seen[s] = 1;
    while (!stack.empty()) {
      int f = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        int g = graph.faceAcross(f, k);
        if (g < 0 || seen[g] || blocked.count(edgeKey(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]))) continue;
        seen[g] = 1;
        stack.push_back(g);
      }
    }
  }
  return comps;
}

}  // namespace

TEST(Handles, GenusFromEuler) {
  EXPECT_EQ(closedGenus(shapes::icosphere(Vec3::Zero(), 1.0, 2)), 0);
  EXPECT_EQ(closedGenus(shapes::torus(2.0, 1.0, 48, 24)), 1);
  EXPECT_EQ(closedGenus(holedPlate(2)), 2);
  EXPECT_EQ(closedGenus(holedPlate(3)), 3);
}

TEST(Handles, TorusHasOneHandleCutAndTheAnalyticConcavity) {
  const TriMesh torus = normalised(shapes::torus(2.0, 1.0, 96, 48));
  const ConcavityMap c = measure(torus, 0.05);
  ASSERT_EQ(c.handleCuts.size(), 1u);
  EXPECT_EQ(c.sharedPockets, 0);
  EXPECT_EQ(edgeComponents(torus, c.handleCuts), 1) << "a handle cut must not split the model";
  // The hole's wall is measured from the nearer of the two caps: depth r / (R + r) = 1/3,
  // where one cap for the whole wall would give 2r / (R + r).
  EXPECT_GT(c.concavity, 1.0 / 3.0 - 0.02);
  EXPECT_LT(c.concavity, 0.42);
}

TEST(Handles, PlateWithHolesHasOneCutPerHole) {
  for (int holes : {1, 2, 3}) {
    const TriMesh plate = normalised(holedPlate(holes));
    const ConcavityMap c = measure(plate, 0.02);
    EXPECT_EQ(static_cast<int>(c.handleCuts.size()), holes) << holes << " holes";
    EXPECT_EQ(c.sharedPockets, 0) << holes << " holes";
    EXPECT_EQ(edgeComponents(plate, c.handleCuts), 1);
  }
}

TEST(Handles, GenusZeroNeedsNoCuts) {
  const ConcavityMap c = measure(normalised(shapes::uShape()), 0.02);
  EXPECT_TRUE(c.handleCuts.empty());
}

TEST(Handles, CorpusModelsOfPositiveGenusAreReducedToSinglyBridgedPockets) {
  // Full decompositions of these models are checked against every invariant in
  // test_decompose.cpp (DecomposeCorpus); here, the genus reduction itself.
  for (const auto& [model, genus] : std::vector<std::pair<std::string, int>>{{"knot", 1}, {"eight", 2}, {"elephant", 3}}) {
    SCOPED_TRACE(model);
    ReadResult r = readMesh(std::string(ACD_DATA_DIR) + "/meshes/" + model + ".off");
    ASSERT_TRUE(r.status.ok()) << r.status.message << " (scripts/fetch_corpus.sh fetches the corpus)";
    const TriMesh mesh = normalised(r.mesh);
    ASSERT_EQ(closedGenus(mesh), genus);
    for (double epsilon : {0.1, 0.025}) {
      const ConcavityMap c = measure(mesh, epsilon);
      EXPECT_EQ(c.sharedPockets, 0) << "epsilon " << epsilon;
      EXPECT_GE(c.handleCuts.size(), 1u) << "epsilon " << epsilon;
      EXPECT_LE(static_cast<int>(c.handleCuts.size()), genus) << "epsilon " << epsilon;
      EXPECT_EQ(edgeComponents(mesh, c.handleCuts), 1) << "handle cuts split the model";
    }
  }
}

TEST(Handles, PlateWithTwoHolesDecomposesWithinTau) {
  const TriMesh plate = holedPlate(2);
  DecomposeOptions o;
  o.tau = 0.05;
  const Decomposition d = decompose(plate, o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  ASSERT_GE(d.components.size(), 2u);
  double volume = 0;
  for (const Component& c : d.components) {
    EXPECT_TRUE(isClosedOriented(c.mesh));
    EXPECT_FALSE(c.unresolved) << c.note;
    EXPECT_LE(c.concavity, o.tau);
    EXPECT_EQ(closedGenus(c.mesh), 0) << "a convex piece has no handle";
    volume += c.volume;
  }
  EXPECT_NEAR(volume, d.stats.inputVolume, 1e-9 * d.stats.inputVolume);
}
