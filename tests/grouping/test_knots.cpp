// Douglas-Peucker and knot detection on hand-made profiles (Section 4.2.1).
#include <acd/algo/knots.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace acd;

namespace {

std::vector<Vec2> polyline(std::initializer_list<std::pair<double, double>> points) {
  std::vector<Vec2> out;
  for (auto [x, y] : points) out.emplace_back(x, y);
  return out;
}

}  // namespace

TEST(DouglasPeucker, TrivialInputsKeepEverything) {
  EXPECT_EQ(douglasPeucker({}, 0.1), std::vector<int>{});
  EXPECT_EQ(douglasPeucker(polyline({{0, 0}}), 0.1), std::vector<int>({0}));
  EXPECT_EQ(douglasPeucker(polyline({{0, 0}, {1, 5}}), 0.1), std::vector<int>({0, 1}));
}

TEST(DouglasPeucker, StraightLineKeepsOnlyEndpoints) {
  std::vector<Vec2> line;
  for (int i = 0; i <= 50; ++i) line.emplace_back(0.1 * i, 0.3 + 0.02 * i);
  EXPECT_EQ(douglasPeucker(line, 1e-9), std::vector<int>({0, 50}));
  EXPECT_EQ(douglasPeucker(line, 1e-12), std::vector<int>({0, 50}));
}

TEST(DouglasPeucker, NearlyStraightLineWithinToleranceKeepsOnlyEndpoints) {
  std::vector<Vec2> line;
  for (int i = 0; i <= 40; ++i) line.emplace_back(i, 0.01 * std::sin(1.7 * i));
  EXPECT_EQ(douglasPeucker(line, 0.02), std::vector<int>({0, 40}));
  EXPECT_GT(douglasPeucker(line, 0.001).size(), 2u);
}

TEST(DouglasPeucker, SingleSpikeIsKept) {
  const auto p = polyline({{0, 0}, {1, 0}, {2, 0}, {3, 1.0}, {4, 0}, {5, 0}, {6, 0}});
  const std::vector<int> kept = douglasPeucker(p, 0.1);
  // The spike apex and the two feet that bound it; the flat runs collapse.
  EXPECT_EQ(kept, std::vector<int>({0, 2, 3, 4, 6}));
}

TEST(DouglasPeucker, ToleranceLargerThanTheSpikeRemovesIt) {
  const auto p = polyline({{0, 0}, {1, 0}, {2, 0}, {3, 1.0}, {4, 0}, {5, 0}, {6, 0}});
  EXPECT_EQ(douglasPeucker(p, 1.5), std::vector<int>({0, 6}));
  // Just below and just above the spike height (distance 1 from the chord y = 0).
  EXPECT_EQ(douglasPeucker(p, 1.0 + 1e-9), std::vector<int>({0, 6}));
  EXPECT_NE(douglasPeucker(p, 1.0 - 1e-9), std::vector<int>({0, 6}));
}

TEST(DouglasPeucker, KeptIndicesAreSortedAndWithinToleranceOfTheSimplification) {
  std::vector<Vec2> p;
  for (int i = 0; i <= 200; ++i) p.emplace_back(0.05 * i, std::sin(0.05 * i) + 0.3 * std::sin(0.37 * i));
  const double tol = 0.05;
  const std::vector<int> kept = douglasPeucker(p, tol);
  ASSERT_GE(kept.size(), 2u);
  EXPECT_EQ(kept.front(), 0);
  EXPECT_EQ(kept.back(), 200);
  for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
    ASSERT_LT(kept[k], kept[k + 1]);
    const Vec2 a = p[kept[k]], b = p[kept[k + 1]];
    for (int i = kept[k] + 1; i < kept[k + 1]; ++i) {
      const Vec2 ab = b - a;
      const double t = std::clamp((p[i] - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      EXPECT_LE((p[i] - (a + t * ab)).norm(), tol + 1e-12) << i;
    }
  }
}

TEST(Knots, TwoPeaksAboveDeltaAreExactlyTheKnots) {
  // Concavity profile along a boundary: zero at the ends, peaks at x = 2 (0.3) and x = 7 (0.5),
  // a valley (0.05) between them.
  const auto p = polyline({{0, 0.0}, {1, 0.15}, {2, 0.3}, {3, 0.2}, {4, 0.1}, {5, 0.05},
                           {6, 0.25}, {7, 0.5}, {8, 0.25}, {9, 0.0}});
  EXPECT_EQ(findKnots(p, 0.01), std::vector<int>({2, 7}));
}

TEST(Knots, AValleyIsNotAKnot) {
  // High at both ends, a dip in the middle: the dip is a turn to the left (counter-clockwise).
  const auto p = polyline({{0, 0.6}, {1, 0.4}, {2, 0.2}, {3, 0.4}, {4, 0.6}});
  EXPECT_TRUE(findKnots(p, 0.01).empty());
  // The same profile upside down (a peak at 2) has its knot.
  const auto q = polyline({{0, 0.0}, {1, 0.2}, {2, 0.4}, {3, 0.2}, {4, 0.0}});
  EXPECT_EQ(findKnots(q, 0.01), std::vector<int>({2}));
}

TEST(Knots, APeakBelowDeltaIsNotAKnot) {
  // One clear peak (0.5 at x = 6) and a small one (0.04 at x = 2): with delta = 0.1 only the clear one.
  const auto p = polyline({{0, 0.0}, {1, 0.02}, {2, 0.04}, {3, 0.02}, {4, 0.0}, {5, 0.25},
                           {6, 0.5}, {7, 0.25}, {8, 0.0}});
  EXPECT_EQ(findKnots(p, 0.1), std::vector<int>({6}));
  // With a smaller delta the small peak is a knot too.
  EXPECT_EQ(findKnots(p, 0.005), std::vector<int>({2, 6}));
}

TEST(Knots, FlatAndMonotoneProfilesHaveNoKnots) {
  std::vector<Vec2> flat, rising;
  for (int i = 0; i <= 20; ++i) {
    flat.emplace_back(i, 0.3);
    rising.emplace_back(i, 0.02 * i);
  }
  EXPECT_TRUE(findKnots(flat, 0.01).empty());
  EXPECT_TRUE(findKnots(rising, 0.01).empty());
}
