// The `pointloc` command: point location in the union of the ACD hulls against the exact answer.
#include <acd/io.hpp>
#include <acd/mesh.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "helpers.hpp"


#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

  /// Rows of a --dump file: point, hulls' answer through the grid, every hull tested, exact.
  struct Row {
    Vec3 p;
    int hulls, direct, exact;
  };
  std::vector<Row> readDump(const std::string& file) const {
    std::ifstream in(file);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "x,y,z,hulls,direct,exact");
    std::vector<Row> rows;
    while (std::getline(in, line)) {
      Row r;
      char c;
      std::istringstream ls(line);
      ls >> r.p.x() >> c >> r.p.y() >> c >> r.p.z() >> c >> r.hulls >> c >> r.direct >> c >> r.exact;
      EXPECT_TRUE(static_cast<bool>(ls)) << line;
      rows.push_back(r);
    }
    return rows;
  }

  std::unique_ptr<acdtest::TempDir> dir_;
};

std::string corpus(const std::string& name) { return std::string(ACD_DATA_DIR) + "/meshes/" + name + ".off"; }

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

TEST_F(PointLoc, ConvexModelAgreesWithItsOwnHalfSpacesAtEveryPoint) {
  // The model is convex, so its own faces are the half-spaces: a direct test, independent of
  // the decomposition, the hull code and the grid.
  const TriMesh sphere = shapes::icosphere(Vec3(0.3, -0.2, 1.0), 2.0, 2);
  const std::string model = writeModel("sphere.off", sphere);
  const std::string dump = path("points.csv");
  const json j = report(quote(model) + " --samples 30000 --tau 0.05 --grid-cells 500 --dump " + quote(dump));
  ASSERT_FALSE(j.empty());
  const auto rows = readDump(dump);
  ASSERT_EQ(rows.size(), 30000u);
  int inside = 0, nearSurface = 0;
  for (const Row& r : rows) {
    double worst = -1e300;  // largest signed distance to a face plane
    for (const Face& f : sphere.faces) {
      const Vec3 &a = sphere.vertices[f[0]], &b = sphere.vertices[f[1]], &c = sphere.vertices[f[2]];
      const Vec3 n = (b - a).cross(c - a).normalized();
      worst = std::max(worst, n.dot(r.p - a));
    }
    if (std::abs(worst) < 1e-9) {
      ++nearSurface;
      continue;
    }
    const int direct = worst < 0 ? 1 : 0;
    inside += direct;
    EXPECT_EQ(r.hulls, direct) << r.p.transpose();
    EXPECT_EQ(r.direct, direct) << r.p.transpose();
    EXPECT_EQ(r.exact, direct) << r.p.transpose();
  }
  EXPECT_EQ(nearSurface, 0);
  EXPECT_EQ(inside, j["points_inside"].get<int>());
  EXPECT_GT(inside, 10000);
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

TEST_F(PointLoc, LShapeMatchesTheAnalyticAnswerAtEveryPoint) {
  // shapes::lShape(): unit cells (0,0,0), (1,0,0), (0,1,0); its box is [0,2] x [0,2] x [0,1].
  const std::string model = writeModel("l.off", shapes::lShape());
  const std::string dump = path("points.csv");
  const json j = report(quote(model) + " --samples 40000 --tau 0.02 --dump " + quote(dump));
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j["components"], 2);
  const auto rows = readDump(dump);
  ASSERT_EQ(rows.size(), 40000u);
  int inside = 0;
  for (const Row& r : rows) {
    const Vec3& p = r.p;
    ASSERT_TRUE(p.x() >= 0 && p.x() <= 2 && p.y() >= 0 && p.y() <= 2 && p.z() >= 0 && p.z() <= 1) << p.transpose();
    const int truth = (p.x() < 1 || p.y() < 1) ? 1 : 0;
    inside += truth;
    EXPECT_EQ(r.hulls, truth) << p.transpose();
    EXPECT_EQ(r.direct, truth) << p.transpose();
    EXPECT_EQ(r.exact, truth) << p.transpose();
  }
  EXPECT_EQ(j["points_inside"].get<int>(), inside);
  EXPECT_NEAR(inside / 40000.0, 0.75, 0.01);  // three of the box's four cells
}

TEST_F(PointLoc, ErrorEstimateAgreesWithAnIndependentCount) {
  // A real, non-convex model whose hulls do overlap the outside: the reported false inside and
  // false outside must equal a count made here with the tests' own point-in-mesh test, and the
  // reported rate must be that count over the subsample, inside its interval.
  const std::string model = corpus("eight");
  ASSERT_TRUE(fs::exists(model)) << "corpus missing: scripts/fetch_corpus.sh";
  const ReadResult read = readMesh(model);
  ASSERT_TRUE(read.status.ok()) << read.status.message;
  const acdtest::MeshIndex mesh(read.mesh);
  const std::string dump = path("points.csv");
  const json j = report(quote(model) + " --samples 300000 --exact-samples 60000 --tau 0.05 --dump " + quote(dump));
  ASSERT_FALSE(j.empty());
  const auto rows = readDump(dump);
  ASSERT_EQ(rows.size(), 60000u);
  std::uint64_t falseIn = 0, falseOut = 0, truthIn = 0;
  for (const Row& r : rows) {
    const int truth = mesh.inside(r.p) ? 1 : 0;
    truthIn += truth;
    falseIn += r.hulls == 1 && truth == 0 ? 1 : 0;
    falseOut += r.hulls == 0 && truth == 1 ? 1 : 0;
    EXPECT_EQ(r.hulls, r.direct) << r.p.transpose();
  }
  EXPECT_GT(falseIn, 50u);  // the hulls do stick out: the test is not vacuous
  EXPECT_EQ(j["exact"]["false_inside"].get<std::uint64_t>(), falseIn);
  EXPECT_EQ(j["exact"]["false_outside"].get<std::uint64_t>(), falseOut);
  EXPECT_EQ(j["exact"]["points_inside"].get<std::uint64_t>(), truthIn);
  const double rate = static_cast<double>(falseIn + falseOut) / 60000.0;
  EXPECT_DOUBLE_EQ(j["exact"]["error_rate"].get<double>(), rate);
  EXPECT_LT(j["exact"]["error_rate_ci95"][0].get<double>(), rate);
  EXPECT_GT(j["exact"]["error_rate_ci95"][1].get<double>(), rate);
  // The components said to hold most false-inside volume really contain those points.
  ASSERT_FALSE(j["exact"]["top_false_inside"].empty());
  const json& top = j["exact"]["top_false_inside"][0];
  EXPECT_LE(top["false_inside"].get<std::uint64_t>(), falseIn);
  EXPECT_GT(top["share"].get<double>(), 0.0);
}

TEST_F(PointLoc, ElephantAtTwoHundredthsMisclassifiesUnderOnePercent) {
  // The paper's Figure 20 model and tolerance (it reports 0.99 % errors).
  const std::string model = corpus("elephant");
  ASSERT_TRUE(fs::exists(model)) << "corpus missing: scripts/fetch_corpus.sh";
  const json j = report(quote(model) + " --samples 1e6 --exact-samples 1e6 --tau 0.02");
  ASSERT_FALSE(j.empty());
  EXPECT_EQ(j["exact"]["samples"], 1000000);
  EXPECT_LT(j["exact"]["error_rate_ci95"][1].get<double>(), 0.01);
  EXPECT_GT(j["exact"]["false_inside"].get<int>(), 0);
  EXPECT_EQ(j["exact"]["false_outside"].get<int>(), 0);  // every component lies in its own hull
}

TEST_F(PointLoc, CompareTimesTheExactMethodsOnTheSamePoints) {
  const std::string model = writeModel("l.off", shapes::lShape());
  const json j = report(quote(model) + " --samples 2e5 --compare --compare-samples 50000 --ecd-time-limit 30");
  ASSERT_FALSE(j.empty());
  ASSERT_TRUE(j.contains("compare"));
  const json& c = j["compare"];
  EXPECT_EQ(c["samples"], 50000);
  bool cgal1 = false, insideTest = false, ecdRow = false;
  for (const json& m : c["methods"]) {
    const std::string name = m["method"];
    if (name.find("ECD") != std::string::npos) {
      ecdRow = true;
      if (!m["available"].get<bool>()) {
        // Said explicitly, never left out.
        EXPECT_FALSE(m["note"].get<std::string>().empty());
        continue;
      }
    }
    ASSERT_TRUE(m["available"].get<bool>()) << m.dump();
    EXPECT_GT(m["points_per_second"].get<double>(), 0.0) << name;
    // The L is two boxes: every method, approximate or not, gives the exact answer.
    if (!m["disagreements_with_exact"].is_null()) EXPECT_EQ(m["disagreements_with_exact"], 0) << name;
    if (name.find("CGAL") != std::string::npos && m["threads"] == 1) {
      cgal1 = true;
      EXPECT_EQ(m["points"], 50000);
      EXPECT_TRUE(m["extrapolated"].get<bool>());
      EXPECT_NEAR(m["points_inside"].get<double>() / 50000.0, 0.75, 0.02);
    }
    if (name.find("InsideTest") != std::string::npos) insideTest = true;
  }
  EXPECT_TRUE(cgal1);
  EXPECT_TRUE(insideTest);
  EXPECT_TRUE(ecdRow);
  EXPECT_GT(c["speedup_vs_cgal_1_thread"].get<double>(), 0.0);
  ASSERT_TRUE(c.contains("ecd"));
  if (c["ecd"]["available"].get<bool>()) {
    EXPECT_TRUE(c["ecd"]["finished"].get<bool>()) << c["ecd"].dump();
    EXPECT_GE(c["ecd"]["pieces"].get<int>(), 2);
  } else {
    EXPECT_NE(c["ecd"]["note"].get<std::string>().find("not available"), std::string::npos);
  }
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

  // A real model, whose grid has many boundary cells and overlapping hulls.
  const std::string eight = corpus("eight");
  ASSERT_TRUE(fs::exists(eight)) << "corpus missing: scripts/fetch_corpus.sh";
  const std::string realArgs = quote(eight) + " --tau 0.2 --samples 3e5 --exact-samples 1e5 --seed 3";
  const json a = report(realArgs + " --threads 1");
  const json b = report(realArgs + " --threads 2");
  ASSERT_FALSE(a.empty());
  ASSERT_FALSE(b.empty());
  EXPECT_EQ(a["points_inside"], b["points_inside"]);
  EXPECT_EQ(a["exact"]["false_inside"], b["exact"]["false_inside"]);
  EXPECT_EQ(a["exact"]["top_false_inside"], b["exact"]["top_false_inside"]);
  EXPECT_GT(a["index"]["boundary_cells"].get<int>(), 100);
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
  const std::string garbage = path("garbage.off");
  std::ofstream(garbage) << "OFF\n3 1 0\n0 0 zero\n";
  TriMesh cup = shapes::box(Vec3::Zero(), Vec3::Ones());
  cup.faces.pop_back();  // a hole: not a solid
  const std::string open = writeModel("open.off", cup);
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
      {quote(model) + " --tau -0.1", 3, "--tau"},
      {quote(model) + " --threads -2", 3, "--threads"},
      {quote(model) + " --exact-samples -1", 3, "--exact-samples"},
      {quote(model) + " --compare-samples 0", 3, "--compare-samples"},
      {quote(model) + " --compare-samples 1e9", 3, "--compare-samples"},
      {quote(model) + " --repeat 0", 3, "--repeat"},
      {quote(model) + " --ecd-time-limit 0", 3, "--ecd-time-limit"},
      {quote(model) + " --grid-cells 0", 3, "--grid-cells"},
      {quote(garbage), 2, "garbage.off"},
      {quote(open), 2, "open.off"},
      {quote(model) + " --json " + quote(path("no/such/dir/r.json")), 5, "r.json"},  // before any work
      {quote(model) + " --dump " + quote(path("no/such/dir/d.csv")), 5, "d.csv"},
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
