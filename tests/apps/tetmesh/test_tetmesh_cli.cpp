// The tetmesh command: files, report, exit codes and error messages.
#include "helpers.hpp"

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using acdtest::runTool;
using acdtest::TempDir;

TEST(TetmeshCli, BoxToEveryFormat) {
  TempDir dir("tetmesh_cli_box");
  ASSERT_TRUE(acd::writeMesh(dir / "box.off", acd::shapes::box(acd::Vec3(0, 0, 0), acd::Vec3(1, 2, 3))).ok());
  auto r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " -o " + acdtest::quote(dir / "box.vtk") + " --compare --json " +
                                    acdtest::quote(dir / "report.json"),
                   dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("original model"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("+0.00%"), std::string::npos) << r.out;
  EXPECT_NE(acdtest::slurp(dir / "box.vtk").find("UNSTRUCTURED_GRID"), std::string::npos);
  EXPECT_NE(acdtest::slurp(dir / "report.json").find("\"hull_mesh\""), std::string::npos);
  // The regions as an OBJ: one object, the box itself (within the vertex budget).
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " --regions " + acdtest::quote(dir / "regions.obj"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const acd::ObjObjects regions = acd::readObjObjects(dir / "regions.obj");
  ASSERT_TRUE(regions.status.ok()) << regions.status.message;
  ASSERT_EQ(regions.objects.size(), 1u);
  EXPECT_NEAR(acd::signedVolume(regions.objects[0]), 6.0, 1e-12);
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " -o " + acdtest::quote(dir / "box.mesh"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(acdtest::slurp(dir / "box.mesh").find("Tetrahedra"), std::string::npos);
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " --format tetgen -o " + acdtest::quote(dir / "box"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(acdtest::slurp(dir / "box.ele").empty());
  EXPECT_FALSE(acdtest::slurp(dir / "box.node").empty());
  EXPECT_FALSE(acdtest::slurp(dir / "box.face").empty());
}

TEST(TetmeshCli, BadInputIsAClearError) {
  TempDir dir("tetmesh_cli_bad");
  // Missing file.
  auto r = runTool(TETMESH_CLI, acdtest::quote(dir / "missing.off"), dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("missing.off"), std::string::npos) << r.err;
  // No faces at all.
  {
    std::ofstream(dir / "empty.off") << "OFF\n0 0 0\n";
  }
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "empty.off"), dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("tetmesh: "), std::string::npos) << r.err;
  // Garbage file.
  {
    std::ofstream(dir / "junk.off") << "OFF\n3 1 0\n0 0 nan\n";
  }
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "junk.off"), dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_FALSE(r.err.empty());
  // Bad parameters.
  ASSERT_TRUE(acd::writeMesh(dir / "box.off", acd::shapes::box(acd::Vec3(0, 0, 0), acd::Vec3(1, 1, 1))).ok());
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " --simplify 3", dir);
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("--simplify"), std::string::npos) << r.err;
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " --quality 0.5", dir);
  EXPECT_EQ(r.code, 3);
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " --surface-distance 0", dir);
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("--surface-distance"), std::string::npos) << r.err;
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " --format stl -o x.stl", dir);
  EXPECT_EQ(r.code, 3);
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " -o /nonexistent-dir/x.vtk", dir);
  EXPECT_EQ(r.code, 5);
  EXPECT_NE(r.err.find("/nonexistent-dir/x.vtk"), std::string::npos) << r.err;
}

TEST(TetmeshCli, TheCoarseningReachesTheReport) {
  // A sphere (curved hulls: the refinement): coarsened by default, not with --no-coarsen, nor in
  // the quality mode; --keep-volume is recorded.
  TempDir dir("tetmesh_cli_coarsen");
  ASSERT_TRUE(acd::writeMesh(dir / "ball.off", acd::shapes::icosphere(acd::Vec3(0, 0, 0), 1.0, 3)).ok());
  auto json = [&](const std::string& flags) {
    const auto r = runTool(TETMESH_CLI, acdtest::quote(dir / "ball.off") + " " + flags + " --json " + acdtest::quote(dir / "r.json"), dir);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(acdtest::slurp(dir / "r.json"));
  };
  const nlohmann::json coarse = json("");
  EXPECT_TRUE(coarse["coarsening"]["done"].get<bool>());
  EXPECT_LT(coarse["coarsening"]["tets_after"].get<int>(), coarse["coarsening"]["tets_before"].get<int>());
  EXPECT_EQ(coarse["coarsening"]["tets_after"], coarse["hull_mesh"]["tets"]);
  EXPECT_LE(coarse["coarsening"]["farthest"].get<double>(), coarse["coarsening"]["max_distance"].get<double>());
  EXPECT_EQ(coarse["hull_mesh"]["tets_below_5_deg"], 0);
  EXPECT_FALSE(json("--no-coarsen")["coarsening"]["done"].get<bool>());
  EXPECT_FALSE(json("--quality 1.5")["coarsening"]["done"].get<bool>());
  EXPECT_TRUE(json("--keep-volume")["coarsening"]["keep_volume"].get<bool>());
}

TEST(TetmeshCli, SelfIntersectingModelIsNotGivenToTetGen) {
  // Two boxes through each other as one surface: the hulls are meshed; the direct mesh is refused.
  TempDir dir("tetmesh_cli_cross");
  acd::TriMesh a = acd::shapes::box(acd::Vec3(0, 0, 0), acd::Vec3(2, 2, 2));
  const acd::TriMesh b = acd::shapes::box(acd::Vec3(1, 1, 1), acd::Vec3(3, 3, 3));
  const int base = static_cast<int>(a.vertices.size());
  a.vertices.insert(a.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (const acd::Face& f : b.faces) a.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  ASSERT_TRUE(acd::writeMesh(dir / "cross.off", a).ok());
  auto r = runTool(TETMESH_CLI, acdtest::quote(dir / "cross.off") + " --compare", dir);
  EXPECT_NE(r.code, -1);  // no crash whatever the outcome
  EXPECT_NE(r.out.find("original model not meshed: the surface intersects itself"), std::string::npos) << r.out << r.err;
}

TEST(TetmeshCli, SharpEdgesAndClippingReachTheReport) {
  // A 1 x 2 x 3 box: with its edges kept the hull mesh has the box's volume exactly (rounded,
  // it would not); the JSON says how many edges were kept and which mesher ran.
  TempDir dir("tetmesh_cli_sharp");
  ASSERT_TRUE(acd::writeMesh(dir / "box.off", acd::shapes::box(acd::Vec3(0, 0, 0), acd::Vec3(1, 2, 3))).ok());
  auto r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " --sharp 30 --json " + acdtest::quote(dir / "sharp.json"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("sharp edges (turning > 30 deg) kept: 12 segments"), std::string::npos) << r.out;
  const nlohmann::json sharp = nlohmann::json::parse(acdtest::slurp(dir / "sharp.json"));
  EXPECT_EQ(sharp["mesher"], "refine");
  EXPECT_EQ(sharp["refinement"]["sharp_segments"], 12);
  EXPECT_NEAR(sharp["hull_mesh"]["volume"].get<double>(), 6.0, 1e-5 * 6.0);
  EXPECT_EQ(sharp["hull_mesh"]["tets_below_5_deg"], 0);
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " --clip --json " + acdtest::quote(dir / "clip.json"), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("the components (hull regions clipped to the model)"), std::string::npos) << r.out;
  const nlohmann::json clip = nlohmann::json::parse(acdtest::slurp(dir / "clip.json"));
  EXPECT_TRUE(clip["clip"].get<bool>());
  EXPECT_LE(clip["hull_mesh"]["volume"].get<double>(), 6.0 * (1 + 1e-9));
  EXPECT_GT(clip["hull_mesh"]["volume"].get<double>(), 0.9 * 6.0);
  r = runTool(TETMESH_CLI, acdtest::quote(dir / "box.off") + " --mesher complex --clip", dir);
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("--clip and --sharp need the refinement"), std::string::npos) << r.err;
}
