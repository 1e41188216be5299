// The `acd` command: help, decompose outputs (files, report.json), errors with exit codes, info, evaluate.
#include <acd/io.hpp>
#include <acd/mesh.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bad_meshes.hpp"
#include "helpers.hpp"


#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>

using namespace acd;
namespace fs = std::filesystem;
using json = nlohmann::json;
using acdtest::quote;
using acdtest::slurp;

namespace {

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::make_unique<acdtest::TempDir>(std::string("cli_") + info->name());
    if (!fs::exists(ACD_CLI)) GTEST_SKIP() << "CLI not built: " << ACD_CLI;
  }

  std::string path(const std::string& name) const { return *dir_ / name; }

  /// Runs `acd ARGS` with stdout and stderr captured.
  acdtest::ToolRun acd(const std::string& args) const { return acdtest::runTool(ACD_CLI, args, *dir_); }

  std::string writeModel(const std::string& name, const TriMesh& mesh) const {
    const std::string p = path(name);
    const Status s = writeMesh(p, mesh);
    EXPECT_TRUE(s.ok()) << s.message;
    return p;
  }

  std::string writeText(const std::string& name, const std::string& text) const {
    const std::string p = path(name);
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

  /// decompose must refuse with `code` and say something containing every word of `words` on stderr.
  void expectRefused(const std::string& args, int code, std::initializer_list<const char*> words) const {
    const acdtest::ToolRun r = acd("decompose " + args + " -o " + quote(path("out")) + " -q");
    EXPECT_EQ(r.code, code) << "stderr: " << r.err;
    EXPECT_FALSE(r.err.empty());
    std::string lower = r.err;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    for (const char* w : words) EXPECT_NE(lower.find(w), std::string::npos) << "'" << w << "' not in: " << r.err;
    EXPECT_FALSE(fs::exists(path("out") + "/report.json")) << "no output on failure";
  }

  std::unique_ptr<acdtest::TempDir> dir_;
};

}  // namespace

TEST_F(Cli, TopLevelHelp) {
  const acdtest::ToolRun r = acd("--help");
  EXPECT_EQ(r.code, 0);
  for (const char* word : {"decompose", "info", "evaluate", "Exit codes"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
}

TEST_F(Cli, DecomposeHelpMentionsEveryOption) {
  const acdtest::ToolRun r = acd("decompose --help");
  EXPECT_EQ(r.code, 0);
  for (const char* opt : {"--tau", "-t", "--epsilon", "--delta", "--no-grouping", "--threads", "--out", "-o", "--quiet",
                          "-q", "model", "Exit codes"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt << " missing from:\n" << r.out;
}

TEST_F(Cli, EvaluateHelpMentionsEveryOption) {
  const acdtest::ToolRun r = acd("evaluate --help");
  EXPECT_EQ(r.code, 0);
  for (const char* opt : {"--samples", "--surface-samples", "--seed", "--threads", "--json"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt << " missing from:\n" << r.out;
}

TEST_F(Cli, NoSubcommandIsAUsageError) {
  const acdtest::ToolRun r = acd("");
  EXPECT_EQ(r.code, 1);
  EXPECT_FALSE(r.err.empty() && r.out.empty());
}

TEST_F(Cli, DecomposeLShapeWritesComponentsHullsAndReport) {
  const std::string model = writeModel("L.off", shapes::lShape());
  const std::string out = path("out");
  // --no-invariant: the L's corners come back bit for bit, so its two boxes are exact.
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -t 0.05 --no-invariant --threads 0 -o " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("components"), std::string::npos);  // the summary table

  ASSERT_TRUE(fs::exists(out + "/report.json"));
  const json report = json::parse(slurp(out + "/report.json"));
  // Parameters, resolved.
  ASSERT_TRUE(report.contains("parameters"));
  const json& p = report["parameters"];
  EXPECT_DOUBLE_EQ(p.at("tau").get<double>(), 0.05);
  EXPECT_DOUBLE_EQ(p.at("epsilon").get<double>(), 0.025);
  EXPECT_DOUBLE_EQ(p.at("delta").get<double>(), 0.0025);
  EXPECT_TRUE(p.at("feature_grouping").get<bool>());
  EXPECT_TRUE(p.contains("threads"));
  // Components.
  ASSERT_TRUE(report.contains("components"));
  const json& comps = report["components"];
  ASSERT_TRUE(comps.is_array());
  ASSERT_EQ(comps.size(), 2u);
  double volume = 0;
  for (std::size_t i = 0; i < comps.size(); ++i) {
    const json& c = comps[i];
    SCOPED_TRACE(i);
    for (const char* key : {"volume", "hull_volume", "concavity", "vertices", "faces", "hull_vertices", "hull_faces", "unresolved"})
      EXPECT_TRUE(c.contains(key)) << key;
    EXPECT_GT(c.at("volume").get<double>(), 0.0);
    EXPECT_GE(c.at("hull_volume").get<double>(), c.at("volume").get<double>() * (1 - 1e-9));
    EXPECT_LE(c.at("concavity").get<double>(), 0.05);
    EXPECT_FALSE(c.at("unresolved").get<bool>());
    volume += c.at("volume").get<double>();
    // The component file matches its entry.
    char name[32];
    std::snprintf(name, sizeof name, "/component_%03zu.off", i);
    const ReadResult m = readMesh(out + name);
    ASSERT_TRUE(m.status.ok()) << m.status.message;
    EXPECT_TRUE(isClosedOriented(m.mesh));
    EXPECT_EQ(static_cast<std::size_t>(c.at("vertices").get<int>()), m.mesh.vertices.size());
    EXPECT_EQ(static_cast<std::size_t>(c.at("faces").get<int>()), m.mesh.faces.size());
  }
  EXPECT_FALSE(fs::exists(out + "/component_002.off"));
  // Totals.
  ASSERT_TRUE(report.contains("totals"));
  const json& t = report["totals"];
  EXPECT_EQ(t.at("components").get<int>(), 2);
  EXPECT_EQ(t.at("unresolved").get<int>(), 0);
  EXPECT_NEAR(t.at("volume").get<double>(), volume, 1e-12);
  EXPECT_LE(t.at("volume_relative_error").get<double>(), 1e-9);
  EXPECT_LE(t.at("max_concavity").get<double>(), 0.05);
  EXPECT_TRUE(t.contains("hull_volume"));
  EXPECT_TRUE(t.contains("cuts"));
  EXPECT_NEAR(report.at("input").at("volume").get<double>(), volume, 1e-9 * volume);
  // Timing.
  ASSERT_TRUE(report.contains("timing"));
  EXPECT_GE(report["timing"].at("total_seconds").get<double>(), 0.0);
  for (const char* key : {"prepare_seconds", "concavity_cpu_seconds", "grouping_cpu_seconds", "cutting_cpu_seconds", "hulls_seconds"})
    EXPECT_TRUE(report["timing"].contains(key)) << key;
  // Hulls: one object per component, convex, each enclosing its component.
  const ObjObjects hulls = readObjObjects(out + "/hulls.obj");
  ASSERT_TRUE(hulls.status.ok()) << hulls.status.message;
  EXPECT_EQ(hulls.objects.size(), comps.size());
  double hullVolume = 0;
  for (const TriMesh& h : hulls.objects) {
    EXPECT_TRUE(isClosedOriented(h));
    hullVolume += signedVolume(h);
  }
  // The L is two boxes: hull volume = volume = 3 in input units.
  EXPECT_NEAR(hullVolume, 3.0, 1e-9);
}

TEST_F(Cli, TheSummaryShowsTheFigureThatCarriesThePromise) {
  const std::string model = writeModel("L.off", shapes::lShape());
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -t 0.05 -o " + quote(path("out")));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("hull excess"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("within tau, as promised"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("beyond tau"), std::string::npos) << r.out;
}

// A cloud of loose triangles (tests/bad_meshes.hpp) can only be decomposed through its watertight
// wrap, which bridges the gaps between the triangles: measured against the input, not the wrap,
// a hull stands more than tau off it at tau 0.1. The command must say so, naming the component
// and the distance of report.json, and end with its own code, not 0.
TEST_F(Cli, AHullBeyondTauEndsWithItsOwnCodeAndNamesIt) {
  const std::string model = path("cloud.off");
  ASSERT_TRUE(acd::writeMesh(model, badmeshes::byName("triangle_cloud")).ok());
  const std::string out = path("out");
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -t 0.1 -o " + quote(out));
  const json report = json::parse(slurp(out + "/report.json"));
  int worst = -1;
  double excess = 0;
  for (std::size_t i = 0; i < report["components"].size(); ++i) {
    const double e = report["components"][i].at("hull_excess").get<double>();
    if (worst < 0 || e > excess) worst = static_cast<int>(i), excess = e;
  }
  if (excess <= 0.1) {  // the day the wrap keeps tau here, this test has nothing to show
    EXPECT_EQ(r.code, 0) << r.err;
    GTEST_SKIP() << "every hull within tau now (largest " << excess << ")";
  }
  EXPECT_EQ(r.code, 8) << r.err;
  EXPECT_NE(r.err.find("tau not kept: the hull of component " + std::to_string(worst) + " stands"), std::string::npos) << r.err;
  char distance[32];
  std::snprintf(distance, sizeof distance, "%.4g", excess);
  EXPECT_NE(r.err.find(distance), std::string::npos) << distance << " not in: " << r.err;
  EXPECT_NE(r.out.find("(beyond tau)"), std::string::npos);
  EXPECT_NE(r.out.find("BEYOND tau"), std::string::npos);
}

TEST_F(Cli, ConvertWritesTheMeshAsRead) {
  const TriMesh l = shapes::lShape();
  const std::string model = writeModel("L.off", l);
  const acdtest::ToolRun r = acd("convert " + quote(model) + " " + quote(path("L.obj")));
  ASSERT_EQ(r.code, 0) << r.err;
  const ReadResult back = readMesh(path("L.obj"));
  ASSERT_TRUE(back.status.ok()) << back.status.message;
  ASSERT_EQ(back.mesh.vertices.size(), l.vertices.size());
  ASSERT_EQ(back.mesh.faces.size(), l.faces.size());
  for (std::size_t i = 0; i < l.vertices.size(); ++i) EXPECT_EQ(back.mesh.vertices[i], l.vertices[i]) << i;
  EXPECT_EQ(acd("convert " + quote(path("nowhere.off")) + " " + quote(path("x.obj"))).code, 2);
}

TEST_F(Cli, QuietPrintsNoSummary) {
  const std::string model = writeModel("L.off", shapes::lShape());
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -t 0.05 -q -o " + quote(path("out")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_TRUE(fs::exists(path("out") + "/component_000.off"));
}

TEST_F(Cli, NoGroupingIsRecordedInTheReport) {
  const std::string model = writeModel("U.obj", shapes::uShape());
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -t 0.05 --no-grouping --threads 1 -q -o " + quote(path("out")));
  ASSERT_EQ(r.code, 0) << r.err;
  const json report = json::parse(slurp(path("out") + "/report.json"));
  EXPECT_FALSE(report["parameters"].at("feature_grouping").get<bool>());
  EXPECT_GE(report["totals"].at("components").get<int>(), 3);
}

TEST_F(Cli, CutEveryRegionIsRecordedInTheReport) {
  const std::string model = writeModel("U.obj", shapes::uShape());
  for (const bool every : {false, true}) {
    const std::string out = path(every ? "every" : "default");
    const acdtest::ToolRun r =
        acd("decompose " + quote(model) + " -t 0.05 --threads 1 -q -o " + quote(out) + (every ? " --cut-every-region" : ""));
    ASSERT_EQ(r.code, 0) << r.err;
    const json report = json::parse(slurp(out + "/report.json"));
    EXPECT_EQ(report["parameters"].at("cut_at_notch_only").get<bool>(), !every);
    EXPECT_LT(report["totals"].at("volume_relative_error").get<double>(), 1e-9);
  }
}

// ------------------------------------------------------------------ bad input: exit 2, stderr names the problem

TEST_F(Cli, MissingFile) { expectRefused(quote(path("nowhere.off")), 2, {"nowhere.off", "cannot open"}); }

TEST_F(Cli, UnsupportedExtension) {
  writeText("model.xyz", "0 0 0\n1 0 0\n");
  expectRefused(quote(path("model.xyz")), 2, {"unsupported", ".xyz"});
}

TEST_F(Cli, GarbageFile) {
  writeText("garbage.off", "hello world\nthis is not a mesh\n");
  expectRefused(quote(path("garbage.off")), 2, {"garbage.off", "off"});
}

TEST_F(Cli, NaNCoordinate) {
  writeText("nan.off", "OFF\n4 4 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  expectRefused(quote(path("nan.off")), 2, {"vertex 2", "non-finite"});
}

TEST_F(Cli, EmptyMesh) {
  writeText("empty.off", "OFF\n0 0 0\n");
  expectRefused(quote(path("empty.off")), 2, {"no faces"});
}

TEST_F(Cli, OpenMeshIsRefusedWithoutHoleFilling) {
  TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  box.faces.pop_back();
  const std::string model = writeModel("open.off", box);
  expectRefused(quote(model) + " --no-fill-holes --no-wrap", 2, {"open", "boundary"});
}

TEST_F(Cli, OpenMeshHolesAreFilledAndReported) {
  TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  box.faces.pop_back();
  const std::string model = writeModel("open.off", box);
  const std::string out = path("out");
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -q -o " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  const json report = json::parse(slurp(out + "/report.json"));
  EXPECT_EQ(report["input"]["holes_filled"].get<int>(), 1);
  EXPECT_EQ(report["totals"]["components"].get<int>(), 1);  // the closed box is convex
  // The closed result has the box's volume (normalised units: the box's half diagonal is 1).
  EXPECT_NEAR(report["input"]["volume"].get<double>(), std::pow(2.0 / std::sqrt(3.0), 3), 1e-9);
  bool said = false;
  for (const auto& line : report["input"]["repairs"]) said |= line.get<std::string>().find("filled 1 hole") != std::string::npos;
  EXPECT_TRUE(said) << report["input"]["repairs"].dump();
}

TEST_F(Cli, SelfIntersectingInputIsReportedAndDecomposed) {
  // Two boxes that pass through each other, written as one mesh.
  TriMesh both = shapes::box(Vec3(0, 0, 0), Vec3(2, 1, 1));
  const TriMesh other = shapes::box(Vec3(1, 0.25, 0.25), Vec3(3, 0.75, 0.75));
  const int base = static_cast<int>(both.vertices.size());
  both.vertices.insert(both.vertices.end(), other.vertices.begin(), other.vertices.end());
  for (Face f : other.faces) both.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  const std::string model = writeModel("crossing.off", both);
  const std::string out = path("out");
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -q -o " + quote(out));
  EXPECT_TRUE(r.code == 0 || r.code == 4) << r.code << " " << r.err;
  EXPECT_NE(r.err.find("intersects itself"), std::string::npos) << r.err;
  const json report = json::parse(slurp(out + "/report.json"));
  EXPECT_GT(report["input"]["self_intersecting_face_pairs"].get<int>(), 0);
}

TEST_F(Cli, NonManifoldEdge) {
  const TriMesh twoCubes = shapes::voxels({{0, 0, 0}, {1, 1, 0}});  // share the edge x = y = 1
  const std::string model = writeModel("nme.off", twoCubes);
  expectRefused(quote(model) + " --no-repair", 2, {"non-manifold edge"});
  // By default the edge is split: two cubes, each convex, each said on stderr as one line.
  const std::string out = path("split");
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -q -o " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("repaired: split non-manifold edges and vertices: 2 vertices copied"), std::string::npos) << r.err;
  const json report = json::parse(slurp(out + "/report.json"));
  EXPECT_EQ(report["totals"]["components"].get<int>(), 2);
  EXPECT_FALSE(report["input"]["wrap"]["used"].get<bool>());
  for (const auto& c : report["components"]) EXPECT_EQ(c["of"].get<std::string>(), "input");
}

TEST_F(Cli, UnclosableMeshIsDecomposedThroughItsWrap) {
  // A box with a fin on an edge: the fin is split off and, being a sheet, wrapped.
  TriMesh m = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  m.vertices.emplace_back(-0.6, -0.6, 0.5);
  m.faces.push_back({m.faces[0][0], m.faces[0][1], 8});
  const std::string model = writeModel("fin.off", m);
  const std::string out = path("fin");
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -q -t 0.1 -o " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("decomposed through a watertight wrap"), std::string::npos) << r.err;
  const json report = json::parse(slurp(out + "/report.json"));
  EXPECT_TRUE(report["input"]["wrap"]["used"].get<bool>());
  EXPECT_GT(report["input"]["wrap"]["hausdorff"].get<double>(), 0.0);
  int ofWrap = 0, ofInput = 0;
  for (const auto& c : report["components"]) (c["of"].get<std::string>() == "wrap" ? ofWrap : ofInput) += 1;
  EXPECT_GE(ofWrap, 1);
  EXPECT_GE(ofInput, 1);  // the box itself stays exact
  expectRefused(quote(model) + " --no-wrap", 2, {"open mesh"});
  const acdtest::ToolRun info = acd("info " + quote(model));
  EXPECT_NE(info.out.find("through a watertight wrap"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("split non-manifold edges"), std::string::npos) << info.out;
}

TEST_F(Cli, TauZero) {
  const std::string model = writeModel("L.off", shapes::lShape());
  expectRefused(quote(model) + " -t 0", 3, {"tau"});
}

TEST_F(Cli, TauNegative) {
  const std::string model = writeModel("L.off", shapes::lShape());
  expectRefused(quote(model) + " -t -1", 3, {"tau"});
}

TEST_F(Cli, TauNaN) {
  const std::string model = writeModel("L.off", shapes::lShape());
  expectRefused(quote(model) + " -t nan", 3, {"tau", "nan"});
}

TEST_F(Cli, TauHuge) {
  const std::string model = writeModel("L.off", shapes::lShape());
  expectRefused(quote(model) + " -t 1e9", 3, {"tau", "exceeds"});
}

TEST_F(Cli, NegativeThreads) {
  const std::string model = writeModel("L.off", shapes::lShape());
  expectRefused(quote(model) + " --threads -3", 3, {"threads"});
}

TEST_F(Cli, EpsilonAboveTau) {
  const std::string model = writeModel("L.off", shapes::lShape());
  expectRefused(quote(model) + " -t 0.05 --epsilon 0.5", 3, {"epsilon"});
}

TEST_F(Cli, UnknownOption) {
  const std::string model = writeModel("L.off", shapes::lShape());
  expectRefused(quote(model) + " --bogus", 1, {"--bogus"});
}

TEST_F(Cli, MissingModelArgument) {
  const acdtest::ToolRun r = acd("decompose -t 0.1");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("model"), std::string::npos) << r.err;
}

// ------------------------------------------------------------------ info and evaluate

TEST_F(Cli, InfoOnTheL) {
  const std::string model = writeModel("L.off", shapes::lShape());
  const acdtest::ToolRun r = acd("info " + quote(model));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(genus\s+0\b)"))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(closed\s+yes\b)"))) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(volume\s+3\b)"))) << r.out;
}

TEST_F(Cli, InfoSaysAModelOnlyTheWrapCanCloseIsDecomposedThroughIt) {
  // An open terrain sheet: no patch closes it; decompose wraps it, and info must say so, not
  // that the solid decomposition is refused.
  const std::string model = writeModel("terrain.off", badmeshes::byName("hole_unpatchable"));
  const acdtest::ToolRun r = acd("info " + quote(model));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("solid decomposition   possible, through a watertight wrap"), std::string::npos) << r.out;
  const acdtest::ToolRun d = acd("decompose " + quote(model) + " -q -o " + quote(path("terrain")));
  EXPECT_TRUE(d.code == 0 || d.code == 8) << d.err;  // decomposed (8: a hull beyond tau, said)
  EXPECT_TRUE(std::filesystem::exists(path("terrain") + "/report.json"));
}

TEST_F(Cli, InfoOnATorusAndAnOpenMesh) {
  const acdtest::ToolRun t = acd("info " + quote(writeModel("torus.off", shapes::torus(2.0, 0.5, 24, 12))));
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_TRUE(std::regex_search(t.out, std::regex(R"(genus\s+1\b)"))) << t.out;
  TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  box.faces.pop_back();
  const acdtest::ToolRun o = acd("info " + quote(writeModel("open.off", box)));
  ASSERT_EQ(o.code, 0) << o.err;  // diagnosing a broken mesh is not an error
  EXPECT_TRUE(std::regex_search(o.out, std::regex(R"(closed\s+no\b)"))) << o.out;
  EXPECT_TRUE(std::regex_search(o.out, std::regex(R"(boundary edges\s+3\b)"))) << o.out;
  // decompose closes the hole first, and info says so.
  EXPECT_TRUE(std::regex_search(o.out, std::regex(R"(solid decomposition\s+possible)"))) << o.out;
  EXPECT_NE(o.out.find("filled 1 hole"), std::string::npos) << o.out;
}

TEST_F(Cli, InfoOnAMissingFile) {
  const acdtest::ToolRun r = acd("info " + quote(path("nowhere.off")));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("nowhere.off"), std::string::npos) << r.err;
}

TEST_F(Cli, EvaluateTheLAgainstItsDecomposition) {
  const std::string model = writeModel("L.off", shapes::lShape());
  const std::string out = path("out");
  ASSERT_EQ(acd("decompose " + quote(model) + " -t 0.05 --no-invariant -q -o " + quote(out)).code, 0);  // exact boxes
  const acdtest::ToolRun r = acd("evaluate " + quote(model) + " " + quote(out + "/hulls.obj") +
                    " --samples 200000 --surface-samples 20000 --threads 0");
  ASSERT_EQ(r.code, 0) << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(r.out, m, std::regex(R"(IoU\s+([0-9.]+))"))) << r.out;
  EXPECT_GT(std::stod(m[1].str()), 0.999);  // two boxes that are exactly the L
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(\(2 hulls\))"))) << r.out;

  const acdtest::ToolRun j = acd("evaluate " + quote(model) + " " + quote(out + "/hulls.obj") +
                    " --samples 200000 --surface-samples 20000 --json");
  ASSERT_EQ(j.code, 0) << j.err;
  const json e = json::parse(j.out);
  EXPECT_EQ(e.at("hulls").get<int>(), 2);
  EXPECT_GT(e.at("iou").get<double>(), 0.999);
  EXPECT_LT(e.at("hull_outside_max").get<double>(), 1e-9);
}

TEST_F(Cli, EvaluateWithAMissingHullFile) {
  const std::string model = writeModel("L.off", shapes::lShape());
  const acdtest::ToolRun r = acd("evaluate " + quote(model) + " " + quote(path("nohulls.obj")));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("nohulls.obj"), std::string::npos) << r.err;
}

TEST_F(Cli, PerMeshIsRefusedWithSurfaceOrExact) {
  // --per-mesh decomposes each mesh of a scene as a solid; with --surface or --exact it would be
  // silently ignored, so it is refused with one line (exit 1, a usage error).
  const std::string l = writeModel("l.off", shapes::lShape());
  expectRefused(quote(l) + " --per-mesh --surface", 1, {"--per-mesh", "solid"});
  expectRefused(quote(l) + " --per-mesh --exact", 1, {"--per-mesh", "solid"});
}

namespace {

/// Unit cubes as a closed, outward surface, each square split along one diagonal or the other;
/// vertices numbered through `ids` so that several parts can share them where they touch, as an
/// assembly's export welds them.
void addVoxels(const std::vector<std::array<int, 3>>& cells, bool otherDiagonal, TriMesh& into,
               std::map<std::array<int, 3>, int>& ids) {
  const std::set<std::array<int, 3>> filled(cells.begin(), cells.end());
  auto id = [&](const std::array<int, 3>& p) {
    auto [it, added] = ids.try_emplace(p, static_cast<int>(into.vertices.size()));
    if (added) into.vertices.emplace_back(p[0], p[1], p[2]);
    return it->second;
  };
  // Per face direction, its square's corners counter-clockwise seen from outside.
  const std::array<std::pair<std::array<int, 3>, std::array<std::array<int, 3>, 4>>, 6> sides{{
      {{1, 0, 0}, {{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}}},
      {{-1, 0, 0}, {{{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}}},
      {{0, 1, 0}, {{{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}}}},
      {{0, -1, 0}, {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}}},
      {{0, 0, 1}, {{{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}}},
      {{0, 0, -1}, {{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}}},
  }};
  for (const auto& c : filled)
    for (const auto& [d, square] : sides) {
      if (filled.count({c[0] + d[0], c[1] + d[1], c[2] + d[2]})) continue;
      std::array<int, 4> q;
      for (int k = 0; k < 4; ++k) q[k] = id({c[0] + square[k][0], c[1] + square[k][1], c[2] + square[k][2]});
      const std::array<Face, 2> t = otherDiagonal ? std::array<Face, 2>{Face{q[1], q[2], q[3]}, Face{q[1], q[3], q[0]}}
                                            : std::array<Face, 2>{Face{q[0], q[1], q[2]}, Face{q[0], q[2], q[3]}};
      into.faces.insert(into.faces.end(), t.begin(), t.end());
    }
}

/// A box of 3 x 3 x 2 cells with a pocket in the top's middle, and a lid of 3 x 3 x 1 cells lying
/// on it: welded along the box's top edges (four faces on each), their squares split along
/// different diagonals, so that no face is repeated. Between them, a sealed cavity [1,2]^3.
TriMesh boxAndLid() {
  std::vector<std::array<int, 3>> box, lid;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y) {
      for (int z = 0; z < 2; ++z)
        if (!(x == 1 && y == 1 && z == 1)) box.push_back({x, y, z});
      lid.push_back({x, y, 2});
    }
  TriMesh m;
  std::map<std::array<int, 3>, int> ids;
  addVoxels(box, false, m, ids);
  addVoxels(lid, true, m, ids);
  return m;
}

/// Distance from p to the solid of boxAndLid (the union of these boxes), 0 inside.
double distanceToBoxAndLid(const Vec3& p) {
  const std::array<std::pair<Vec3, Vec3>, 6> parts{{{Vec3(0, 0, 0), Vec3(3, 3, 1)},
                                                    {Vec3(0, 0, 1), Vec3(1, 3, 2)},
                                                    {Vec3(2, 0, 1), Vec3(3, 3, 2)},
                                                    {Vec3(1, 0, 1), Vec3(2, 1, 2)},
                                                    {Vec3(1, 2, 1), Vec3(2, 3, 2)},
                                                    {Vec3(0, 0, 2), Vec3(3, 3, 3)}}};
  double best = std::numeric_limits<double>::infinity();
  for (const auto& [lo, hi] : parts) best = std::min(best, (p.cwiseMax(lo).cwiseMin(hi) - p).norm());
  return best;
}

}  // namespace

// An assembly welded where its parts touch: the box and its lid come apart whole (no wrap), and
// no hull crosses the cavity between them (checked here on the hulls' vertices and points spread
// over their faces, against the parts as boxes).
TEST_F(Cli, ABoxAndItsLidWeldedAlongTheirEdgesComeApart) {
  const std::string model = writeModel("box_and_lid.off", boxAndLid());
  const std::string out = path("out");
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -q -o " + quote(out));
  ASSERT_EQ(r.code, 0) << r.err;
  const json report = json::parse(slurp(out + "/report.json"));
  EXPECT_FALSE(report["input"]["wrap"]["used"].get<bool>()) << report["input"]["repairs"].dump();
  const ObjObjects hulls = readObjObjects(out + "/hulls.obj");
  ASSERT_TRUE(hulls.status.ok());
  const double tau = 0.05 * 1.5 * std::sqrt(3.0);  // in the box's units: its enclosing sphere has radius 1.5 sqrt 3
  std::mt19937_64 rng(5);
  double worst = 0.0;
  for (const TriMesh& h : hulls.objects)
    for (const Vec3& p : acdtest::sampleSurface(h, 2000, rng)) worst = std::max(worst, distanceToBoxAndLid(p));
  EXPECT_LE(worst, tau * (1 + 1.0 / 32));
  EXPECT_LE(report["totals"]["max_hull_excess_input"].get<double>(), 0.05 * (1 + 1.0 / 32));
}

// A sphere without its top (the faces above z = 0.5): the repair fills the hole with a dome that
// follows the sphere, and the hull over it stands far off the input as given (the top of the dome
// lies outside the bowl, a winding number below 1/2, and away from every face of it). That is
// said, with the distinct exit code; the figure agrees with this test's own distances.
TEST_F(Cli, AHullOverAFilledHoleFarFromTheInputIsSaid) {
  TriMesh bowl = shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  bowl.faces.erase(std::remove_if(bowl.faces.begin(), bowl.faces.end(), [&](const Face& f) {
    return bowl.vertices[f[0]].z() > 0.5 && bowl.vertices[f[1]].z() > 0.5 && bowl.vertices[f[2]].z() > 0.5;
  }), bowl.faces.end());
  const std::string model = writeModel("bowl.off", bowl);
  const std::string out = path("out");
  const acdtest::ToolRun r = acd("decompose " + quote(model) + " -q -o " + quote(out));
  ASSERT_EQ(r.code, 8) << r.err;
  EXPECT_NE(r.err.find("tau not kept: the hull of component"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("off the input as read"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--surface"), std::string::npos) << r.err;
  const json report = json::parse(slurp(out + "/report.json"));
  const ObjObjects hulls = readObjObjects(out + "/hulls.obj");
  ASSERT_TRUE(hulls.status.ok());
  // Hull vertices above the rim's plane by more than a tenth are outside the bowl.
  const acdtest::MeshIndex faces(bowl);
  double worst = 0.0;
  for (const TriMesh& h : hulls.objects)
    for (const Vec3& p : h.vertices)
      if (p.z() > 0.6) worst = std::max(worst, faces.distance(p));
  const double scale = report["input"]["normalization"]["scale"].get<double>();
  EXPECT_GT(worst * scale, 0.05);
  EXPECT_GE(report["totals"]["max_hull_excess_input"].get<double>(), 0.95 * worst * scale);
}
