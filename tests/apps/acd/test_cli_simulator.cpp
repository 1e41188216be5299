// `acd decompose` with simulator options: refusals with exit 3, --tau-abs, --max-hulls 1 as the
// convex hull of the model, a cube capped at 8 vertices staying the cube, mass properties.
#include <acd/algo/hull.hpp>
#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "helpers.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace acd;
namespace fs = std::filesystem;
using json = nlohmann::json;
using acdtest::quote;

namespace {

class CliSimulator : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(ACD_CLI)) GTEST_SKIP() << "CLI not built: " << ACD_CLI;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::make_unique<acdtest::TempDir>(std::string("clisim_") + info->name());
  }
  std::string model(const std::string& name, const TriMesh& mesh) const {
    const std::string p = *dir_ / name;
    EXPECT_TRUE(writeMesh(p, mesh).ok());
    return p;
  }
  acdtest::ToolRun decompose(const std::string& modelPath, const std::string& args) const {
    return acdtest::runTool(ACD_CLI, "decompose " + quote(modelPath) + " " + args + " -o " + quote(out()) + " -q", *dir_);
  }
  std::string out() const { return *dir_ / "out"; }
  json report() const {
    std::ifstream in(out() + "/report.json");
    return json::parse(in);
  }
  std::unique_ptr<acdtest::TempDir> dir_;
};

}  // namespace

TEST_F(CliSimulator, BadValuesAreRefusedWithExitThree) {
  const std::string cube = model("cube.off", shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)));
  struct Case {
    const char* args;
    const char* words;
  };
  for (const Case& c : {Case{"--max-hull-vertices 3", "at least 4"}, Case{"--max-hulls 0", "at least 1"},
                        Case{"--format urdf,dae", "unknown --format 'dae'"}, Case{"--density -1", "--density"},
                        Case{"-t 0.1 --tau-abs 0.2", "not both"}, Case{"--tau-abs 0", "positive"},
                        Case{"--tau-abs 100", "outside"}}) {
    const acdtest::ToolRun r = decompose(cube, c.args);
    EXPECT_EQ(r.code, 3) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.words), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
    EXPECT_FALSE(fs::exists(out() + "/report.json")) << c.args;
  }
  const acdtest::ToolRun s = decompose(cube, "--surface --format urdf");
  EXPECT_EQ(s.code, 1) << s.err;
  EXPECT_NE(s.err.find("solid decomposition only"), std::string::npos) << s.err;
}

TEST_F(CliSimulator, CubeCappedAtEightStaysTheCubeWithItsMassProperties) {
  const std::string cube = model("cube.off", shapes::box(Vec3(1, 2, 3), Vec3(3, 3, 7)));
  const acdtest::ToolRun r = decompose(cube, "--max-hull-vertices 8 --density 2");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = report();
  ASSERT_EQ(j["components"].size(), 1u);
  EXPECT_EQ(j["components"][0]["hull_vertices"], 8);
  EXPECT_EQ(j["components"][0]["added_volume"], 0.0);
  EXPECT_EQ(j["hull_vertex_cap"]["added_volume"], 0.0);
  EXPECT_EQ(j["hull_vertex_cap"]["within_cap"], 1);
  const ObjObjects hulls = readObjObjects(out() + "/hulls.obj");
  ASSERT_TRUE(hulls.status.ok());
  ASSERT_EQ(hulls.objects.size(), 1u);
  EXPECT_EQ(hulls.objects[0].vertices.size(), 8u);
  EXPECT_NEAR(signedVolume(hulls.objects[0]), 8.0, 1e-12);
  const json& mp = j["mass_properties"];
  EXPECT_NEAR(mp["volume"].get<double>(), 8.0, 1e-12);
  EXPECT_NEAR(mp["mass"].get<double>(), 16.0, 1e-12);
  EXPECT_NEAR(mp["center_of_mass"][2].get<double>(), 5.0, 1e-12);
  // A 2 x 1 x 4 box of mass 16: Ixx = 16 (1 + 16) / 12.
  EXPECT_NEAR(mp["inertia_about_center_of_mass"][0][0].get<double>(), 16.0 * 17.0 / 12.0, 1e-9);
}

TEST_F(CliSimulator, TauAbsIsALengthInTheInputsUnits) {
  // A cube of side 20: its minimum enclosing sphere has radius 10 sqrt(3).
  const std::string cube = model("cube.off", shapes::box(Vec3(0, 0, 0), Vec3(20, 20, 20)));
  const acdtest::ToolRun r = decompose(cube, "--tau-abs 1.5");
  ASSERT_EQ(r.code, 0) << r.err;
  const json j = report();
  const double radius = 10.0 * std::sqrt(3.0);
  EXPECT_NEAR(j["parameters"]["tau"].get<double>(), 1.5 / radius, 1e-9);
  EXPECT_NEAR(j["tau_abs"]["given"].get<double>(), 1.5, 1e-15);
  EXPECT_NEAR(j["tau_abs"]["tau_input_units"].get<double>(), 1.5, 1e-9);
  EXPECT_NEAR(j["tau_abs"]["normalised_unit_in_input_units"].get<double>(), radius, 1e-6);
}

TEST_F(CliSimulator, OneHullIsTheConvexHullOfTheModelAndTheReportSaysTauIsExceeded) {
  const TriMesh u = shapes::uShape();
  const std::string path = model("u.off", u);
  const acdtest::ToolRun r = decompose(path, "-t 0.02 --no-invariant --max-hulls 1 --format obj");  // exact corners
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("above tau"), std::string::npos) << r.err;
  const json j = report();
  ASSERT_EQ(j["components"].size(), 1u);
  EXPECT_TRUE(j["hull_budget"]["exceeds_tau"].get<bool>());
  EXPECT_GT(j["hull_budget"]["max_concavity"].get<double>(), 0.02);
  EXPECT_GE(j["hull_budget"]["components_before"].get<int>(), 2);
  const ObjObjects hulls = readObjObjects(out() + "/hulls.obj");
  ASSERT_EQ(hulls.objects.size(), 1u);
  const TriMesh hull = hullMesh(u.vertices);
  EXPECT_NEAR(signedVolume(hulls.objects[0]), signedVolume(hull), 1e-9);
  EXPECT_EQ(hulls.objects[0].vertices.size(), hull.vertices.size());
  const ReadResult single = readMesh(out() + "/hulls/hull_000.obj");
  ASSERT_TRUE(single.status.ok());
  EXPECT_NEAR(signedVolume(single.mesh), signedVolume(hull), 1e-9);
}
