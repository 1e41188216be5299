// TetGen in its own process: bad input is an error message, never a crash; quality measures.
#include "mesh_quality.hpp"
#include "tetgen_run.hpp"

#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace tetmesh;

namespace {

Plc plcOf(const std::vector<acd::TriMesh>& meshes) {
  Plc plc;
  for (const acd::TriMesh& m : meshes) {
    const int base = static_cast<int>(plc.points.size());
    plc.points.insert(plc.points.end(), m.vertices.begin(), m.vertices.end());
    for (const acd::Face& f : m.faces) plc.facets.push_back({{base + f[0], base + f[1], base + f[2]}, kBoundaryFacet});
  }
  return plc;
}

}  // namespace

TEST(TetGenRun, OverlappingBoxesEndInAnErrorNotACrash) {
  // Two boxes through each other given as one PLC: TetGen 1.5 crashes on this in-process.
  const Plc plc = plcOf({acd::shapes::box(Vec3(0, 0, 0), Vec3(2, 2, 2)), acd::shapes::box(Vec3(1, 1, 1), Vec3(3, 3, 3))});
  const TetGenResult r = runTetGen(plc, TetGenOptions{});
  EXPECT_FALSE(r.ok);
  EXPECT_FALSE(r.error.empty());
  EXPECT_NE(r.error.find("TetGen"), std::string::npos) << r.error;
  // And we are still here to run it again: the check mode names the problem.
  TetGenOptions check;
  check.checkIntersections = true;
  const TetGenResult d = runTetGen(plc, check);
  EXPECT_FALSE(d.ok);
  EXPECT_NE(d.error.find("ntersect"), std::string::npos) << d.error;
}

TEST(TetGenRun, FacetWithAnOutOfRangeIndexIsRefused) {
  Plc plc = plcOf({acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1))});
  plc.facets[3].polygon[1] = 99;
  const TetGenResult r = runTetGen(plc, TetGenOptions{});
  EXPECT_FALSE(r.ok);
  EXPECT_FALSE(r.error.empty());
}

TEST(TetGenRun, OpenSurfaceIsAnErrorOrEmpty) {
  Plc plc = plcOf({acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1))});
  plc.facets.pop_back();  // a hole: TetGen carves everything from outside
  const TetGenResult r = runTetGen(plc, TetGenOptions{});
  EXPECT_TRUE(!r.ok || r.mesh.tets.empty());
}

TEST(TetGenRun, SwitchesFollowTheOptions) {
  TetGenOptions o;
  EXPECT_EQ(tetgenSwitches(o), "pq2AQz");
  o.radiusEdge = 1.5;
  o.minDihedral = 10;
  o.maxVolume = 0.25;
  EXPECT_EQ(tetgenSwitches(o), "pq1.5/10a0.25AQz");
  o.radiusEdge = 0;
  o.regions = false;
  EXPECT_EQ(tetgenSwitches(o), "pa0.25Qz");
}

TEST(MeshQuality, RegularTetrahedron) {
  const Vec3 a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);
  for (double angle : dihedralAngles(a, b, c, d)) EXPECT_NEAR(angle, std::acos(1.0 / 3.0) * 180 / M_PI, 1e-9);
  EXPECT_NEAR(radiusEdgeRatio(a, b, c, d), std::sqrt(6.0) / 4.0, 1e-12);
}

TEST(MeshQuality, CornerTetrahedron) {
  // Right corner: three 90-degree dihedral angles at the corner edges, three of acos(1/sqrt(3)).
  auto angles = dihedralAngles(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
  std::sort(angles.begin(), angles.end());
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(angles[k], std::acos(1 / std::sqrt(3.0)) * 180 / M_PI, 1e-9);
  for (int k = 3; k < 6; ++k) EXPECT_NEAR(angles[k], 90.0, 1e-9);
  TetMesh m;
  m.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.tets = {{0, 1, 2, 3}};
  const MeshQuality q = measureQuality(m);
  EXPECT_NEAR(q.volume, 1.0 / 6.0, 1e-15);
  EXPECT_EQ(q.nonPositiveTets, 0);
  EXPECT_NEAR(q.maxRadiusEdge, std::sqrt(3.0) / 2.0, 1e-12);  // circumradius sqrt(3)/2, shortest edge 1
}
