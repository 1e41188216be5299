// acd::HullSet (libacd/src/measure/hull_set.cpp): hulls as half-spaces with a cell grid; the
// grid's answers are those of testing every hull, and a hull given as box and facets is the
// same hull as its mesh.
#include <acd/algo/hull_set.hpp>
#include <acd/algo/parallel.hpp>
#include <acd/algo/hull.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include "helpers.hpp"

#include <random>
#include <vector>

using namespace acd;

namespace {

std::vector<TriMesh> someHulls() {
  return {shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), hullMesh(shapes::icosphere(Vec3(1.2, 0.5, 0.5), 0.6, 2).vertices),
          shapes::box(Vec3(-1, -1, 0.2), Vec3(0.1, 0.1, 0.4))};
}

}  // namespace

TEST(HullSet, TheGridAnswersAsTestingEveryHull) {
  HullSet set(1e-10);
  for (const TriMesh& h : someHulls()) ASSERT_TRUE(set.add(h));
  ASSERT_EQ(set.size(), 3);
  const Box3 box{Vec3(-1.5, -1.5, -0.5), Vec3(2.0, 1.5, 1.5)};
  tbb::task_arena arena = workerArena(2);
  set.buildIndex(box, 4096, arena);
  EXPECT_GT(set.boundaryCells(), 0u);
  EXPECT_GT(set.insideCells(), 0u);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < 20000; ++i)
    points.push_back(box.lo + box.size().cwiseProduct(acdtest::drawPoint([&] { return u(rng); })));
  points.push_back(Vec3(5, 5, 5));  // off the grid: the scan answers
  std::uint64_t direct = 0;
  for (const Vec3& p : points) {
    ASSERT_EQ(set.inside(p), set.insideDirect(p)) << p.transpose();
    direct += set.insideDirect(p) ? 1 : 0;
  }
  EXPECT_EQ(set.countInside([&](std::uint64_t i) { return points[i]; }, 0, points.size()), direct);
  EXPECT_GT(direct, 0u);
  EXPECT_LT(direct, points.size());
}

TEST(HullSet, ABoxAndItsFacetsAreTheHullsMesh) {
  const TriMesh cube = shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  HullSet fromMesh(1e-10), fromPlanes(1e-10);
  ASSERT_TRUE(fromMesh.add(cube));
  fromPlanes.add(Box3{Vec3(0, 0, 0), Vec3(1, 2, 3)},
                 {{Vec3(1, 0, 0), 1}, {Vec3(-1, 0, 0), 0}, {Vec3(0, 1, 0), 2}, {Vec3(0, -1, 0), 0},
                  {Vec3(0, 0, 1), 3}, {Vec3(0, 0, -1), 0}});
  for (const Vec3& p : {Vec3(0.5, 1, 1.5), Vec3(1.1, 1, 1), Vec3(0, 0, 0), Vec3(1 + 1e-11, 2, 3), Vec3(-1e-9, 1, 1)}) {
    EXPECT_EQ(fromMesh.contains(0, p), fromPlanes.contains(0, p)) << p.transpose();
    EXPECT_EQ(fromMesh.firstContaining(p), fromPlanes.firstContaining(p)) << p.transpose();
  }
  EXPECT_TRUE(fromPlanes.contains(0, Vec3(1 + 1e-11, 2, 3)));  // within the slack
  EXPECT_FALSE(fromPlanes.contains(0, Vec3(-1e-9, 1, 1)));
}

TEST(HullSet, AMeshWithoutAFaceAddsNothing) {
  HullSet set(0.0);
  TriMesh flat;
  flat.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  flat.faces = {{0, 1, 2}};
  EXPECT_FALSE(set.add(flat));
  EXPECT_EQ(set.size(), 0);
  EXPECT_EQ(set.planeCount(), 0u);
  EXPECT_FALSE(set.insideDirect(Vec3(0.5, 0, 0)));
}

// Cells are classified block by block (4 x 4 x 4 cells); a grid whose sides are not multiples
// of the block, and hulls of many small facets whose planes cross many cells, must still answer
// as testing every plane, also for points on and just beside the facets.
TEST(HullSet, ManyFacetedHullsOnAGridOfPartBlocks) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  HullSet set(1e-10);
  std::vector<TriMesh> hulls;
  for (int h = 0; h < 6; ++h) {
    std::vector<Vec3> points;
    const Vec3 centre(0.7 * h, 0.3 * (h % 2), 0.2 * (h % 3));
    for (int i = 0; i < 400; ++i) points.push_back(centre + 0.5 * Vec3(g(rng), g(rng), 0.6 * g(rng)).normalized());
    hulls.push_back(hullMesh(points));
    ASSERT_TRUE(set.add(hulls.back()));
  }
  const Box3 box{Vec3(-0.7, -0.65, -0.45), Vec3(4.3, 1.0, 0.95)};
  tbb::task_arena arena = workerArena(2);
  set.buildIndex(box, 2000, arena);
  ASSERT_TRUE(set.gridX() % 4 != 0 || set.gridY() % 4 != 0 || set.gridZ() % 4 != 0);
  EXPECT_GT(set.boundaryCells(), 0u);
  EXPECT_GT(set.insideCells(), 0u);
  std::vector<Vec3> points;
  for (int i = 0; i < 40000; ++i)
    points.push_back(box.lo + box.size().cwiseProduct(acdtest::drawPoint([&] { return u(rng); })));
  for (const TriMesh& hull : hulls)  // on each facet's plane at its centroid, and 1e-9 either side of it
    for (const Face& f : hull.faces) {
      const Vec3 &a = hull.vertices[f[0]], &b = hull.vertices[f[1]], &c = hull.vertices[f[2]];
      const Vec3 n = (b - a).cross(c - a).normalized(), centroid = (a + b + c) / 3;
      for (double off : {-1e-9, 0.0, 1e-9}) points.push_back(centroid + off * n);
    }
  std::uint64_t direct = 0;
  for (const Vec3& p : points) {
    ASSERT_EQ(set.inside(p), set.insideDirect(p)) << p.transpose();
    direct += set.insideDirect(p) ? 1 : 0;
  }
  EXPECT_EQ(set.countInside([&](std::uint64_t i) { return points[i]; }, 0, points.size()), direct);
  EXPECT_GT(direct, 1000u);
  EXPECT_LT(direct, points.size() - 1000);
}
