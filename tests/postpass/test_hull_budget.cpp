// The hull budget: at most N components, every input component in exactly one, volume kept,
// N = 1 gives the convex hull of the model, separate pieces joined only when needed.
#include <acd/algo/hull.hpp>
#include <acd/algo/hull_budget.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <algorithm>
#include <numeric>

using namespace acd;
using acdtest::decomposed;

namespace {

TriMesh together(const std::vector<TriMesh>& parts) {
  TriMesh all;
  for (const TriMesh& m : parts) {
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), m.vertices.begin(), m.vertices.end());
    for (const Face& f : m.faces) all.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  return all;
}

double totalVolume(const Decomposition& d) {
  double v = 0;
  for (const Component& c : d.components) v += c.volume;
  return v;
}

}  // namespace

TEST(HullBudget, MergesDownToTheBudgetKeepingEveryComponentOnce) {
  const TriMesh torus = shapes::torus(2.0, 0.6, 48, 16);
  // Merged to the paper's promise only, so that the budget has neighbours left to glue.
  DecomposeOptions paper;
  paper.tau = 0.05;
  paper.mergeScope = MergeScope::Component;
  Decomposition d = decompose(torus, paper);
  ASSERT_TRUE(d.status.ok()) << d.status.message;
  const int before = static_cast<int>(d.components.size());
  ASSERT_GE(before, 5) << "the test needs a decomposition with several components";
  const double volume = totalVolume(d);
  double maxBefore = 0;
  for (const Component& c : d.components) maxBefore = std::max(maxBefore, c.concavity);
  HullBudgetOptions o;
  o.maxHulls = 3;
  const HullBudgetReport r = limitHullCount(d, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.before, before);
  EXPECT_EQ(static_cast<int>(d.components.size()), 3);
  EXPECT_EQ(r.after, 3);
  // Neighbours are glued while any share faces; pieces whose shared cut was split again on one
  // side only (a T-junction) cannot be glued and are joined.
  EXPECT_EQ(r.gluedMerges + r.joinedMerges, before - 3);
  EXPECT_GE(r.gluedMerges, 1);
  std::vector<int> all;
  for (const auto& m : r.members) all.insert(all.end(), m.begin(), m.end());
  std::sort(all.begin(), all.end());
  std::vector<int> expected(before);
  std::iota(expected.begin(), expected.end(), 0);
  EXPECT_EQ(all, expected);
  EXPECT_NEAR(totalVolume(d), volume, 1e-9 * volume);
  double reached = 0;
  for (const Component& c : d.components) {
    EXPECT_TRUE(isClosedOriented(c.mesh));
    reached = std::max(reached, c.concavity);
    // Each hull is the hull of its component.
    EXPECT_NEAR(signedVolume(c.hull), signedVolume(hullMesh(c.mesh.vertices)), 1e-12);
  }
  EXPECT_DOUBLE_EQ(r.maxConcavity, reached);
  EXPECT_GE(r.maxConcavity, maxBefore);  // merging never makes a piece more convex than its parts
  EXPECT_EQ(r.exceedsTau, r.maxConcavity > d.options.tau);
  EXPECT_TRUE(r.exceedsTau) << "a third of a torus is far from convex at tau 0.02";
}

TEST(HullBudget, OneHullIsTheConvexHullOfTheModel) {
  const TriMesh u = shapes::uShape();
  Decomposition d = decomposed(u, 0.02);
  ASSERT_GE(d.components.size(), 2u);
  HullBudgetOptions o;
  o.maxHulls = 1;
  const HullBudgetReport r = limitHullCount(d, o);
  ASSERT_TRUE(r.status.ok());
  ASSERT_EQ(d.components.size(), 1u);
  const TriMesh hull = hullMesh(u.vertices);
  EXPECT_NEAR(signedVolume(d.components[0].hull), signedVolume(hull), 1e-12 * signedVolume(hull));
  EXPECT_EQ(d.components[0].hull.vertices.size(), hull.vertices.size());
  EXPECT_NEAR(signedVolume(d.components[0].mesh), signedVolume(u), 1e-12);
  EXPECT_TRUE(r.exceedsTau);  // the U's slot is 2 deep
}

TEST(HullBudget, SeparatePiecesAreJoinedOnlyWhenNoNeighboursAreLeft) {
  // Two L-shapes far apart: each decomposes into pieces; with N = 2 every merge glues
  // neighbours, with N = 1 the last merge must join the two pieces.
  TriMesh l2 = shapes::lShape();
  for (Vec3& v : l2.vertices) v += Vec3(10, 0, 0);
  const TriMesh both = together({shapes::lShape(), l2});
  Decomposition d2 = decomposed(both, 0.01);
  ASSERT_GE(d2.components.size(), 4u);
  Decomposition d1 = d2;
  HullBudgetOptions o;
  o.maxHulls = 2;
  const HullBudgetReport r2 = limitHullCount(d2, o);
  EXPECT_EQ(r2.joinedMerges, 0);
  ASSERT_EQ(d2.components.size(), 2u);
  EXPECT_NE(d2.components[0].source, d2.components[1].source);
  o.maxHulls = 1;
  const HullBudgetReport r1 = limitHullCount(d1, o);
  EXPECT_EQ(r1.joinedMerges, 1);
  ASSERT_EQ(r1.hullGapMeasure.size(), 1u);
  EXPECT_TRUE(r1.hullGapMeasure[0]);
  // The hull gap spans the space between the two L's (a gap of about 8 along x, in normalised units
  // about 8 / 6): far above tau.
  EXPECT_GT(r1.maxConcavity, 0.3);
  EXPECT_NEAR(signedVolume(d1.components[0].hull), signedVolume(hullMesh(both.vertices)), 1e-9);
}

TEST(HullBudget, NothingToDoWithinTheBudgetAndBadBudgetsRefused) {
  Decomposition d = decomposed(shapes::lShape(), 0.01);
  const std::size_t n = d.components.size();
  const Decomposition copy = d;
  HullBudgetOptions o;
  o.maxHulls = static_cast<int>(n);
  const HullBudgetReport r = limitHullCount(d, o);
  EXPECT_TRUE(r.status.ok());
  EXPECT_EQ(d.components.size(), n);
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(d.components[i].hull.vertices, copy.components[i].hull.vertices);
  o.maxHulls = 0;
  EXPECT_EQ(limitHullCount(d, o).status.code, StatusCode::InvalidParameter);
}

TEST(HullBudget, ResultDoesNotDependOnThreads) {
  const TriMesh torus = shapes::torus(2.0, 0.6, 48, 16);
  Decomposition a = decomposed(torus, 0.1), b = a;
  HullBudgetOptions o;
  o.maxHulls = 4;
  o.threads = 1;
  const HullBudgetReport ra = limitHullCount(a, o);
  o.threads = 2;
  const HullBudgetReport rb = limitHullCount(b, o);
  EXPECT_EQ(ra.members, rb.members);
  EXPECT_EQ(ra.maxConcavity, rb.maxConcavity);
}
