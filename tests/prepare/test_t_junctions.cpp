// T-junctions (libacd/src/prepare/t_junctions.cpp): boundary edges split at the vertices lying on
// them, checked against the shapes' known areas, volumes and edges.
#include <acd/algo/t_junctions.hpp>
#include <acd/diagnosis.hpp>
#include <acd/repair.hpp>

#include <gtest/gtest.h>

#include <set>

#include "bad_meshes.hpp"

using namespace acd;

namespace {

bool hasEdge(const std::vector<Face>& faces, int a, int b) {
  for (const Face& f : faces)
    for (int k = 0; k < 3; ++k)
      if (f[k] == a && f[(k + 1) % 3] == b) return true;
  return false;
}

/// Twice the area vector of a face (its normal times twice its area).
Vec3 areaVector(const std::vector<Vec3>& v, const Face& f) { return (v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]); }

}  // namespace

TEST(TJunctions, BoxWithTopMeshedApartClosesWithoutMovingAPoint) {
  const TriMesh input = badmeshes::byName("t_junctions");
  ASSERT_FALSE(isClosedOriented(input));
  const MeshRepair r = repairMesh(input);
  ASSERT_TRUE(r.status.ok());
  EXPECT_EQ(r.tJunctionEdges, 4);
  EXPECT_EQ(r.tJunctionVertices, 4);
  EXPECT_TRUE(isClosedOriented(r.mesh));
  EXPECT_EQ(diagnose(r.mesh).nonManifoldVertices, 0);
  EXPECT_NEAR(signedVolume(r.mesh), 1.0, 1e-12);
  std::set<std::array<double, 3>> given;
  for (const Vec3& p : input.vertices) given.insert({p.x(), p.y(), p.z()});
  for (const Vec3& p : r.mesh.vertices) EXPECT_TRUE(given.count({p.x(), p.y(), p.z()})) << p.transpose();
  ASSERT_FALSE(r.repairs.empty());
  EXPECT_NE(r.repairs.front().find("T-junctions: split 4 boundary edges at the 4 vertices"), std::string::npos)
      << r.repairs.front();
}

TEST(TJunctions, AFaceWithCracksOnTwoSidesIsSplitOnBoth) {
  // Triangle A B C with P on side A-B and R on side C-A; P and R are corners of faces of their own.
  const std::vector<Vec3> v = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 0, 0}, {0, 1, 0}, {1, -1, 0}, {-1, 1, 0}};
  const int A = 0, B = 1, C = 2, P = 3, R = 4, below = 5, left = 6;
  const std::vector<Face> faces = {{A, B, C}, {A, below, P}, {P, below, B}, {C, left, R}, {R, left, A}};
  const TJunctionSplit s = splitTJunctions(v, faces, 1e-9);
  EXPECT_EQ(s.splitEdges, 2);
  EXPECT_EQ(s.splitVertices, 2);
  ASSERT_EQ(s.faces.size(), 7u);  // A B C in three, the four others unchanged
  Vec3 total = Vec3::Zero();
  for (const Face& f : s.faces) {
    const Vec3 n = areaVector(v, f);
    EXPECT_GT(n.z(), 0.0);  // every face keeps the orientation, none is degenerate
    total += n;
  }
  EXPECT_NEAR(total.z(), 2 * (2.0 + 4 * 0.5), 1e-12);  // twice (area of A B C + the four small faces)
  for (auto [a, b] : {std::pair{A, P}, {P, B}, {C, R}, {R, A}}) EXPECT_TRUE(hasEdge(s.faces, a, b)) << a << "-" << b;
  EXPECT_FALSE(hasEdge(s.faces, A, B));
  EXPECT_FALSE(hasEdge(s.faces, C, A));
}

TEST(TJunctions, OnlyVerticesOnTheEdgeAndAwayFromItsEndsSplitIt) {
  const double tol = 1e-6;
  // Side 0-1 of the first face is a boundary edge; vertex 3 lies 2 tol off it, vertex 4 within
  // tol of its end; both are corners of another face, so both are boundary vertices.
  const std::vector<Vec3> v = {{0, 0, 0},   {1, 0, 0}, {0, 1, 0}, {0.5, -2 * tol, 0}, {1 - 0.5 * tol, 0, 0},
                               {0.5, -1, 0}};
  const std::vector<Face> faces = {{0, 1, 2}, {3, 5, 4}};
  const TJunctionSplit s = splitTJunctions(v, faces, tol);
  EXPECT_EQ(s.splitEdges, 0);
  EXPECT_EQ(s.faces, faces);
}

TEST(TJunctions, AClosedMeshIsLeftAsItIs) {
  const TriMesh box = badmeshes::byName("clean_box");
  const TJunctionSplit s = splitTJunctions(box.vertices, box.faces, 1e-6);
  EXPECT_EQ(s.splitEdges, 0);
  EXPECT_EQ(s.faces, box.faces);
}

TEST(TJunctions, AFlatFaceIsNotSplitAtItsOwnCorner) {
  // Corner 2 of the flat face lies on its side 0-1 (a boundary edge); a fan to it would repeat
  // it. The other face's corner 3 on that side still splits it. (A fuzzer's input whose repeated
  // corner hung CGAL's orient_polygon_soup.)
  const std::vector<Vec3> v = {{0, 0, 0}, {1, 0, 0}, {0.25, 0, 0}, {0.75, 0, 0}, {0.75, -1, 0}, {1.5, -1, 0}};
  const std::vector<Face> faces = {{0, 1, 2}, {3, 4, 5}};
  const TJunctionSplit s = splitTJunctions(v, faces, 1e-6);
  for (const Face& f : s.faces) EXPECT_TRUE(f[0] != f[1] && f[1] != f[2] && f[2] != f[0]) << f[0] << f[1] << f[2];
  EXPECT_TRUE(hasEdge(s.faces, 0, 3));
  EXPECT_TRUE(hasEdge(s.faces, 3, 1));
}

TEST(TJunctions, TheFuzzersFlatFaceEndsRepaired) {
  // fuzz_decompose's input that hung the repair (2026-11-29): a double cone of 1e-6 whose
  // vertices merge into flat faces, and two far vertices.
  const TriMesh m{{
      {0, 0, -1.5e-06},
      {3.487305509109044e-07, 0, -7.5e-07},
      {1.7436527545545221e-07, 3.020095161645857e-07, -7.5e-07},
      {-1.7436527545545208e-07, 3.020095161645857e-07, -7.5e-07},
      {-3.487305509109044e-07, 4.270717529379321e-23, -7.5e-07},
      {-1.7436527545545235e-07, -3.020095161645856e-07, -7.5e-07},
      {1.7436527545545221e-07, -3.020095161645857e-07, -7.5e-07},
      {1e-06, 0, 0},
      {-0.4999995, 0.2734383660254038, -0.015625},
      {-4.999999999999998e-07, 8.660254037844387e-07, 0},
      {-1e-06, 1.2246467991473532e-22, 0},
      {-5.000000000000005e-07, -8.660254037844384e-07, 0},
      {5.000000000000001e-07, -8.660254037844386e-07, 0},
      {-0.1562496512694491, 0.21875, -0.30468675},
      {1.7436527545545221e-07, 3.020095161645857e-07, 7.5e-07},
      {-1.7436527545545208e-07, 3.020095161645857e-07, 7.5e-07},
      {-3.487305509109044e-07, 4.270717529379321e-23, 7.5e-07},
      {-1.7436527545545235e-07, -3.020095161645856e-07, 7.5e-07},
      {1.7436527545545221e-07, -3.020095161645857e-07, 7.5e-07},
      {0, 0, 1.5e-06}},
                  {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 5, 4}, {0, 6, 5}, {0, 1, 6}, {1, 2, 8},
                   {1, 8, 7}, {2, 3, 9}, {2, 9, 8}, {3, 4, 10}, {3, 10, 9}, {4, 5, 11}, {4, 11, 10},
                   {5, 6, 12}, {5, 12, 11}, {6, 1, 7}, {6, 7, 12}, {7, 8, 14}, {7, 14, 13}, {9, 8, 15},
                   {8, 15, 14}, {9, 10, 16}, {10, 11, 17}, {10, 17, 16}, {11, 12, 18}, {11, 18, 17}, {12, 7, 13},
                   {12, 13, 18}, {19, 13, 14}, {19, 14, 15}, {19, 15, 16}, {19, 16, 17}, {19, 17, 18}, {19, 18, 13},
                   {10, 11, 17}}};
  const MeshRepair r = repairMesh(m);
  EXPECT_TRUE(r.status.ok());
}
