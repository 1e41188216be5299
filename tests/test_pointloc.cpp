// The `pointloc` command: point location in the union of the ACD hulls against the exact answer.
#include <acd/io.hpp>
#include <acd/mesh.hpp>
#include <acd/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "helpers.hpp"


#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace acd;
namespace fs = std::filesystem;
using json = nlohmann::json;
using acdtest::quote;
using acdtest::slurp;

#ifdef ACD_POINTLOC

namespace {

class PointLoc : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::make_unique<acdtest::TempDir>(std::string("pointloc_") + info->name());
    if (!fs::exists(ACD_POINTLOC)) GTEST_SKIP() << "pointloc not built: " << ACD_POINTLOC;
  }

  std::string path(const std::string& name) const { return *dir_ / name; }

  acdtest::ToolRun run(const std::string& args) const { return acdtest::runTool(ACD_POINTLOC, args, *dir_); }

  std::string writeModel(const std::string& name, const TriMesh& mesh) const {
    const std::string p = path(name);
    const Status s = writeMesh(p, mesh);
    EXPECT_TRUE(s.ok()) << s.message;
    return p;
  }

  /// Runs with --json and returns the parsed report (empty on failure).
  json report(const std::string& args) const {
    const std::string j = path("report.json");
    fs::remove(j);
    const acdtest::ToolRun r = run(args + " --json " + quote(j));
    EXPECT_EQ(r.code, 0) << r.err;
    if (r.code != 0) return {};
    return json::parse(slurp(j));
  }

  std::unique_ptr<acdtest::TempDir> dir_;
};

TEST_F(PointLoc, ConvexModelHasNoError) {
  const std::string model = writeModel("sphere.off", shapes::icosphere(Vec3(0.3, -0.2, 1.0), 2.0, 2));
  const json j = report(quote(model) + " --samples 200000 --tau 0.05");
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j["components"], 1);
  EXPECT_EQ(j["exact"]["samples"], 200000);
  EXPECT_EQ(j["exact"]["false_inside"], 0);
  EXPECT_EQ(j["exact"]["false_outside"], 0);
  EXPECT_EQ(j["exact"]["error_rate"], 0.0);
  // A sphere fills pi/6 of its bounding box.
  const double share = j["points_inside"].get<double>() / 200000.0;
  EXPECT_NEAR(share, 0.5236, 0.02);
}

TEST_F(PointLoc, LShapeIsTwoBoxesWithNoError) {
  const std::string model = writeModel("l.off", shapes::lShape());
  const json j = report(quote(model) + " --samples 300000 --tau 0.02");
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j["components"], 2);
  EXPECT_EQ(j["exact"]["false_inside"], 0);
  EXPECT_EQ(j["exact"]["false_outside"], 0);
  EXPECT_EQ(j["points_inside"], j["exact"]["points_inside"]);  // every point was checked
  EXPECT_GT(j["points_inside"].get<int>(), 0);
  EXPECT_LT(j["points_inside"].get<int>(), 300000);
}

TEST_F(PointLoc, SameSeedSameCountsForAnyThreads) {
  const std::string model = writeModel("l.off", shapes::lShape());
  const std::string args = quote(model) + " --samples 1e5 --exact-samples 50000 --seed 7";
  const json one = report(args + " --threads 1");
  const json two = report(args + " --threads 2");
  ASSERT_FALSE(one.empty());
  ASSERT_FALSE(two.empty());
  EXPECT_EQ(one["threads"], 1);
  EXPECT_EQ(two["threads"], 2);
  EXPECT_EQ(one["points_inside"], two["points_inside"]);
  EXPECT_EQ(one["exact"]["points_inside"], two["exact"]["points_inside"]);
  EXPECT_EQ(one["exact"]["false_inside"], two["exact"]["false_inside"]);
  EXPECT_EQ(one["exact"]["false_outside"], two["exact"]["false_outside"]);
  const json other = report(quote(model) + " --samples 1e5 --exact-samples 50000 --seed 8 --threads 2");
  EXPECT_NE(other["points_inside"], one["points_inside"]);  // the seed matters
}

TEST_F(PointLoc, GridGivesTheSameCountsAsTestingEveryHull) {
  const std::string model = writeModel("u.off", shapes::uShape());
  const std::string args = quote(model) + " --samples 2e5 --exact-samples 50000 --tau 0.02";
  const json grid = report(args + " --grid-cells 64");
  const json plain = report(args + " --no-index");
  ASSERT_FALSE(grid.empty());
  ASSERT_FALSE(plain.empty());
  EXPECT_GE(grid["components"].get<int>(), 3);
  EXPECT_EQ(grid["points_inside"], plain["points_inside"]);
  EXPECT_EQ(grid["exact"]["false_inside"], plain["exact"]["false_inside"]);
  EXPECT_EQ(grid["exact"]["false_outside"], plain["exact"]["false_outside"]);
}

TEST_F(PointLoc, JsonHasTheReportedFields) {
  const std::string model = writeModel("sphere.off", shapes::icosphere(Vec3::Zero(), 1.0, 1));
  const json j = report(quote(model) + " --samples 100000");
  ASSERT_FALSE(j.empty());
  for (const char* k : {"decomposition_seconds", "location_seconds", "total_seconds", "points_per_second",
                        "points_inside", "samples", "tau", "seed", "threads", "components"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j["samples"], 100000);
  EXPECT_GT(j["points_per_second"].get<double>(), 0.0);
  ASSERT_TRUE(j.contains("exact"));
  for (const char* k : {"samples", "false_inside", "false_outside", "false_inside_rate", "false_outside_rate",
                        "false_inside_ci95", "false_outside_ci95", "error_rate", "error_rate_ci95",
                        "top_false_inside", "points_per_second"})
    EXPECT_TRUE(j["exact"].contains(k)) << k;
  EXPECT_EQ(j["exact"]["false_inside_ci95"].size(), 2u);
  EXPECT_EQ(j["exact"]["false_inside_ci95"][0], 0.0);
  EXPECT_GT(j["exact"]["false_inside_ci95"][1].get<double>(), 0.0);
}

TEST_F(PointLoc, BadInputsAreRefusedWithAMessage) {
  const std::string model = writeModel("l.off", shapes::lShape());
  struct Case {
    std::string args;
    int code;
    std::string word;
  };
  const Case cases[] = {
      {quote(path("missing.off")), 2, "missing.off"},
      {quote(model) + " --samples 0", 3, "--samples"},
      {quote(model) + " --samples -5", 3, "--samples"},
      {quote(model) + " --samples 1.5", 3, "--samples"},
      {quote(model) + " --samples 2e10", 3, "--samples"},
      {quote(model) + " --tau 0", 3, "--tau"},
      {quote(model) + " --tau 3", 3, "--tau"},
      {quote(model) + " --tau nan", 3, "--tau"},
  };
  for (const Case& c : cases) {
    const acdtest::ToolRun r = run(c.args);
    EXPECT_EQ(r.code, c.code) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.word), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

TEST_F(PointLoc, AcceptsScientificAndPlainSampleCounts) {
  const std::string model = writeModel("l.off", shapes::lShape());
  const json a = report(quote(model) + " --samples 1e5 --exact-samples 0");
  const json b = report(quote(model) + " --samples 100000 --exact-samples 0");
  ASSERT_FALSE(a.empty());
  ASSERT_FALSE(b.empty());
  EXPECT_EQ(a["samples"], 100000);
  EXPECT_EQ(a["points_inside"], b["points_inside"]);
  EXPECT_EQ(a["exact"]["samples"], 0);
}

TEST_F(PointLoc, HelpNamesTheDefaultModel) {
  const acdtest::ToolRun r = run("--help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("elephant.off"), std::string::npos) << r.out;
}

}  // namespace

#endif  // ACD_POINTLOC
