// acd-table (bench/table/): the Table 1 rows (|e|, notch %, every method's components, size and time), the
// Result 1 summary and the tau sweep, on generated shapes whose exact decompositions are known.
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "helpers.hpp"

#include <fstream>
#include <string>

using namespace acd;
using json = nlohmann::json;
using acdtest::quote;

TEST(Table, RowsSummaryAndSweep) {
  acdtest::TempDir dir("table_rows");
  const TriMesh l = shapes::lShape(), u = shapes::uShape();
  ASSERT_TRUE(writeMesh(dir / "L.off", l).ok());
  ASSERT_TRUE(writeMesh(dir / "U.off", u).ok());
  const auto r = acdtest::runTool(
      ACD_TABLE,
      "--models " + quote(dir / "L.off") + "," + quote(dir / "U.off") + " --taus 0.2 --exact-time-limit 60" +
          " --sweep-models " + quote(dir / "L.off") + " --sweep-taus 0.3,0.1 --json " + quote(dir / "t.json") +
          " --markdown " + quote(dir / "t.md") + " --work " + quote(dir / "work"),
      dir);
  ASSERT_EQ(r.code, 0) << r.err;
  json j;
  std::ifstream(dir / "t.json") >> j;
  ASSERT_EQ(j["models"].size(), 2u);
  const bool surfaceAcd = j["surface_acd_available"];
  const TriMesh* meshes[] = {&l, &u};
  const long solidPieces[] = {2, 3}, surfacePatches[] = {2, 2};
  for (int i = 0; i < 2; ++i) {
    const json& row = j["models"][i];
    EXPECT_EQ(row["edges"], diagnose(*meshes[i]).edges);
    EXPECT_EQ(row["reflex_edges"], countNotches(*meshes[i]));
    const json& runs = row["runs"];
    EXPECT_EQ(runs["solid_ecd"]["status"], "ok");
    EXPECT_EQ(runs["solid_ecd"]["components"], solidPieces[i]);
    EXPECT_GT(runs["solid_ecd"]["bytes"].get<long>(), 0);
    EXPECT_EQ(runs["surface_ecd"]["components"], surfacePatches[i]);
    EXPECT_EQ(runs["solid_acd_0.2"]["status"], "ok");
    EXPECT_GE(runs["solid_acd_0.2"]["components"].get<long>(), 1);
    EXPECT_GT(runs["solid_acd_0.2"]["seconds"].get<double>(), 0.0);
    if (!surfaceAcd) {
      EXPECT_EQ(runs["surface_acd_0.2"]["status"], "n/a");
    }
  }
  EXPECT_EQ(j["summary"]["0.2"]["models_compared"], 2);
  // Two tolerances, grouping on and off, solid (and surface when it exists).
  EXPECT_EQ(j["sweep"].size(), surfaceAcd ? 8u : 4u);
  for (const json& e : j["sweep"]) EXPECT_GE(e["components"].get<long>(), 1) << e.dump();
  const std::string md = acdtest::slurp(dir / "t.md");
  EXPECT_NE(md.find("| L | "), std::string::npos) << md;
  EXPECT_NE(md.find("solid ECD"), std::string::npos);
}

TEST(Table, BadArguments) {
  acdtest::TempDir dir("table_bad");
  auto r = acdtest::runTool(ACD_TABLE, "--models " + quote(dir / "missing.off"), dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("missing.off"), std::string::npos) << r.err;
  ASSERT_TRUE(writeMesh(dir / "L.off", shapes::lShape()).ok());
  r = acdtest::runTool(ACD_TABLE, "--models " + quote(dir / "L.off") + " --taus 0.2,-1", dir);
  EXPECT_EQ(r.code, 3) << r.err;
}
