// The `skeleton` command: files written, report fields, and clear errors on bad input.
#include "helpers.hpp"

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using acdtest::runTool;
using acdtest::TempDir;
using json = nlohmann::json;

TEST(SkeletonCli, DumbbellWithTwoDeformations) {
  TempDir dir("skeleton_cli");
  const std::string model = dir / "dumbbell.off";
  ASSERT_TRUE(acd::writeMesh(model, acd::shapes::dumbbell(2.0, 0.3, 48, 24)).ok());
  const std::string out = dir / "out";
  const auto r = runTool(SKELETON_CLI,
                         acdtest::quote(model) + " --tau 0.1 --deform affine:30,0,60:1,1,1:5,0,0 --deform affine:0,0,0:1,1,1.5"
                         " --deform bend:+z:x:40 --mcf-runs 2 --tubes 0.004 -o " + acdtest::quote(out),
                         dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"report.json", "original.acd_skeleton.json", "original.acd_skeleton.obj",
                        "original.mcf_skeleton.json", "deformed_1.off", "deformed_3.off", "deformed_3.acd_skeleton.obj"})
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(out) / f)) << f;
  const json report = json::parse(acdtest::slurp(out + "/report.json"));
  ASSERT_EQ(report["models"].size(), 4u);
  const json& original = report["models"][0];
  EXPECT_EQ(original["name"], "original");
  EXPECT_GE(original["acd"]["nodes"].get<int>(), 3);
  EXPECT_FALSE(original["acd"].contains("D"));
  EXPECT_EQ(original["mcf"]["run_node_counts"].size(), 2u);
  EXPECT_LE(original["mcf"]["run2_vs_run1_D"]["lower_bound"].get<int>(),
            original["mcf"]["run2_vs_run1_D"]["distance"].get<int>());
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(out) / "deformed_3.mcf_skeleton_tubes.off"));
  // A rigid motion leaves the decomposition, hence the skeleton, unchanged.
  const json& rigid = report["models"][1];
  EXPECT_EQ(rigid["acd"]["nodes"], original["acd"]["nodes"]);
  EXPECT_EQ(rigid["acd"]["D"]["distance"], 0);
  EXPECT_EQ(rigid["acd"]["D2"]["distance"], 0);
  for (const json& m : {report["models"][1], report["models"][2], report["models"][3]}) {
    for (const char* which : {"acd", "mcf"}) {
      for (const char* d : {"D", "D2"}) {
        const json& g = m[which][d];
        EXPECT_LE(g["lower_bound"].get<int>(), g["distance"].get<int>());
        EXPECT_TRUE(g["method"] == "exact" || g["method"] == "mip" || g["method"] == "bipartite");
        EXPECT_EQ(g["exact"].get<bool>(), g["lower_bound"] == g["distance"]);
      }
    }
    // CGAL's D2 for every pair of runs (2 of the original by 2 of this mesh), run 1 by run 1 first.
    const json& pairs = m["mcf"]["run_pairs_D2"];
    ASSERT_EQ(pairs.size(), 4u);
    EXPECT_EQ(pairs[0]["distance"], m["mcf"]["D2"]["distance"]);
    for (const json& g : pairs) EXPECT_LE(g["lower_bound"].get<int>(), g["distance"].get<int>());
  }
  // The written skeleton matches the report.
  const json skel = json::parse(acdtest::slurp(out + "/original.acd_skeleton.json"));
  EXPECT_EQ(skel["nodes"].size(), original["acd"]["nodes"].get<std::size_t>());
  EXPECT_NE(r.out.find("ACD D2"), std::string::npos);  // the summary table
}

TEST(SkeletonCli, ARingsHandleIsCountedInTheReport) {
  // A ring (genus 1): its handle found on the coarsest grid, inside the parts or through their
  // contacts; the skeleton of parts a tree by default, and with --handle-cycles a cycle exactly
  // when the handle runs through contacts.
  TempDir dir("skeleton_cli_ring");
  const std::string model = dir / "ring.off";
  ASSERT_TRUE(acd::writeMesh(model, acd::shapes::torus(2.0, 0.5, 64, 16)).ok());
  for (const bool cycles : {false, true}) {
    const std::string out = dir / (cycles ? "cycles" : "tree");
    const auto r = runTool(SKELETON_CLI,
                           acdtest::quote(model) + " --tau 0.05 --no-mcf -q -o " + acdtest::quote(out) +
                               (cycles ? " --handle-cycles" : ""),
                           dir);
    ASSERT_EQ(r.code, 0) << r.err;
    const json report = json::parse(acdtest::slurp(out + "/report.json"));
    EXPECT_EQ(report["parameters"]["handle_cycles"].get<bool>(), cycles);
    const json& m = report["models"][0];
    EXPECT_EQ(m["genus"], 1);
    EXPECT_EQ(m["loop_grid"], 64);
    int inside = 0;
    for (const json& h : m["part_handles"]) inside += h.get<int>();
    const bool through = !m["loop_adjacencies"].empty();
    EXPECT_EQ(inside + (through ? 1 : 0), 1);  // one handle, in one place
    const int nodes = m["acd"]["nodes"], edges = m["acd"]["edges"], graphs = m["acd"]["connected_components"];
    EXPECT_EQ(edges - nodes + graphs, cycles && through ? 1 : 0);
  }
}

TEST(SkeletonCli, BadInputGivesAClearErrorAndExitCode) {
  TempDir dir("skeleton_cli_bad");
  const std::string model = dir / "box.off";
  ASSERT_TRUE(acd::writeMesh(model, acd::shapes::box(acd::Vec3(0, 0, 0), acd::Vec3(1, 1, 1))).ok());
  const std::string openPath = dir / "broken.off";  // a face names vertex 7 of 4
  {
    std::ofstream f(openPath);
    f << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 7\n";
  }
  const std::string out = " -o " + acdtest::quote(dir / "out");
  const struct {
    std::string args;
    int code;
    const char* words;
  } cases[] = {
      {acdtest::quote(dir / "missing.off") + out, 2, "missing.off"},
      {acdtest::quote(openPath) + out, 2, "broken.off"},
      {acdtest::quote(model) + " --deformed " + acdtest::quote(openPath) + out, 2, "broken.off"},
      {acdtest::quote(model) + " --tau -1" + out, 3, "--tau"},
      {acdtest::quote(model) + " --deform shear:3" + out, 3, "unknown deformation 'shear'"},
      {acdtest::quote(model) + " --deform bend:+x:z:nope" + out, 3, "not a number"},
      {acdtest::quote(model) + " --mcf-runs 0" + out, 3, "--mcf-runs"},
      {acdtest::quote(model) + " --no-such-option" + out, 1, "no-such-option"},
  };
  for (const auto& c : cases) {
    const auto r = runTool(SKELETON_CLI, c.args, dir);
    EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.words), std::string::npos) << c.args << "\n" << r.err;
  }
}
