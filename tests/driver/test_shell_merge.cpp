// mergeAcrossShells (libacd/src/driver/shell_merge.cpp), through decompose(): an assembly's shells
// are decomposed one by one, then components of different shells are joined where the union's
// hull stays within tau of the solid the shells bound. Oracles: the parts as boxes, distances to
// them computed here.
#include <acd/decompose.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <algorithm>
#include <limits>
#include <random>
#include <utility>

using namespace acd;

namespace {

using Boxes = std::vector<std::pair<Vec3, Vec3>>;

TriMesh assembly(const Boxes& boxes) {
  std::vector<TriMesh> parts;
  for (const auto& [lo, hi] : boxes) parts.push_back(shapes::box(lo, hi));
  return concatenate(parts);
}

/// The largest distance from a point of the hulls (vertices and points spread over their faces) to
/// the union of the boxes, in tau's units.
double hullsOffBoxes(const Decomposition& d, const Boxes& boxes) {
  std::mt19937_64 rng(11);
  double worst = 0.0;
  for (const Component& c : d.components)
    for (const Vec3& p : acdtest::sampleSurface(c.hull, 3000, rng)) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& [lo, hi] : boxes) best = std::min(best, (p.cwiseMax(lo).cwiseMin(hi) - p).norm());
      worst = std::max(worst, best);
    }
  return worst * d.normalization.scale;
}

/// The shells decomposed one by one, then merged across: the pass under test (by default the
/// union route runs too and may win without any merge across shells).
DecomposeOptions shellsApart() {
  DecomposeOptions o;
  o.uniteShells = false;
  return o;
}

}  // namespace

TEST(MergeAcrossShells, HeadsLyingOnAPlateShareItsHull) {
  // Four heads 0.03 proud of a plate (about half of tau after normalisation), each its own shell.
  Boxes boxes{{Vec3(0, 0, 0), Vec3(4, 1, 0.2)}};
  for (double x : {0.5, 1.5, 2.5, 3.5}) boxes.push_back({Vec3(x, 0.35, 0.2), Vec3(x + 0.3, 0.65, 0.23)});
  const Decomposition d = decompose(assembly(boxes), shellsApart());
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_EQ(d.components.size(), 1u);
  EXPECT_LE(hullsOffBoxes(d, boxes), d.options.tau * (1 + 1.0 / 32));
  EXPECT_EQ(d.stats.merges, 4);
}

TEST(MergeAcrossShells, ShellsFarApartKeepTheirOwnHulls) {
  // A hull across the gap would stand half the gap off both boxes.
  const Boxes boxes{{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(2, 0, 0), Vec3(3, 1, 1)}};
  const Decomposition d = decompose(assembly(boxes), DecomposeOptions{});
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_EQ(d.components.size(), 2u);
  EXPECT_LE(hullsOffBoxes(d, boxes), 1e-9);
}

TEST(MergeAcrossShells, HeldToEachComponentNothingMergesAcrossShells) {
  Boxes boxes{{Vec3(0, 0, 0), Vec3(4, 1, 0.2)}};
  for (double x : {0.5, 1.5, 2.5, 3.5}) boxes.push_back({Vec3(x, 0.35, 0.2), Vec3(x + 0.3, 0.65, 0.23)});
  DecomposeOptions o = shellsApart();
  o.mergeScope = MergeScope::Component;
  const Decomposition d = decompose(assembly(boxes), o);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  EXPECT_EQ(d.components.size(), 5u);
}

TEST(MergeAcrossShells, TheSameMergesInAnyPose) {
  // Flat faces meshed finely (as CAD exports are): each hull keeps or drops the points lying on
  // its facets as rounding in the pose decides. The merges must not follow: twelve heads of
  // random sizes on a finely meshed U, turned at random and moved. (A guard: the generated
  // assembly where this was seen, 24_plate_with_bolts of bench/assemblies, matched in 2 of 10
  // motions before; this smaller scene did not show it.)
  Boxes heads;
  std::mt19937_64 place(17);
  std::uniform_real_distribution<double> unit;
  for (int k = 0; k < 12; ++k) {
    const double x = 0.05 + 0.24 * k, y = 0.05 + 0.4 * unit(place), w = 0.1 + 0.1 * unit(place), h = 0.05 + 0.2 * unit(place);
    heads.push_back({Vec3(x, y, 1), Vec3(x + w, y + 0.3, 1 + h)});
  }
  // A U of unit cells (cut, then merged back), its faces split at every cell's corners.
  const TriMesh plate = acdtest::midpointSubdivided(shapes::uShape());
  const TriMesh input = concatenate({plate, assembly(heads)});
  const Decomposition original = decompose(input, DecomposeOptions{});
  ASSERT_TRUE(original.status.ok()) << original.status.message;
  std::vector<double> expected;
  for (const Component& c : original.components) expected.push_back(c.volume);
  std::sort(expected.begin(), expected.end());
  std::mt19937_64 rng(5);
  for (int motion = 0; motion < 4; ++motion) {
    const Eigen::Matrix3d r = acdtest::randomRotation(rng);
    const Decomposition turned = decompose(acdtest::moved(input, r, Vec3(3.7, -12.1, 0.9)), DecomposeOptions{});
    ASSERT_TRUE(turned.status.ok()) << turned.status.message;
    std::vector<double> volumes;
    for (const Component& c : turned.components) volumes.push_back(c.volume);
    std::sort(volumes.begin(), volumes.end());
    ASSERT_EQ(volumes.size(), expected.size()) << "motion " << motion;
    for (std::size_t i = 0; i < volumes.size(); ++i) EXPECT_NEAR(volumes[i], expected[i], 1e-9) << "motion " << motion;
  }
}
