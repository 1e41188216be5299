// `acd decompose --exact [--surface]`: the files, report.json and exit codes of the exact baselines.
#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/io.hpp>
#include <acd/mesh.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "helpers.hpp"

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

using namespace acd;
namespace fs = std::filesystem;
using json = nlohmann::json;
using acdtest::quote;

namespace {

class ExactCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::make_unique<acdtest::TempDir>(std::string("exact_cli_") + info->name());
  }
  std::string path(const std::string& name) const { return *dir_ / name; }
  acdtest::ToolRun acd(const std::string& args) const { return acdtest::runTool(ACD_CLI, args, *dir_); }
  std::string model(const std::string& name, const TriMesh& mesh) const {
    const std::string p = path(name);
    EXPECT_TRUE(writeMesh(p, mesh).ok());
    return p;
  }
  json report() const {
    std::ifstream in(path("out/report.json"));
    json j;
    in >> j;
    return j;
  }

 private:
  std::unique_ptr<acdtest::TempDir> dir_;
};

double maxFrontDistance(const TriMesh& m) {
  double worst = -1;
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) {
    const Vec3 n = faceNormal(m, f).normalized();
    for (const Vec3& v : m.vertices) worst = std::max(worst, n.dot(v - m.vertices[m.faces[f][0]]));
  }
  return worst;
}

}  // namespace

TEST_F(ExactCli, SolidPiecesAndReport) {
  const TriMesh l = shapes::lShape();
  const auto r = acd("decompose " + quote(model("l.off", l)) + " --exact -o " + quote(path("out")));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("components     2"), std::string::npos) << r.out;
  const ObjObjects pieces = readObjObjects(path("out/pieces.obj"));
  ASSERT_TRUE(pieces.status.ok()) << pieces.status.message;
  ASSERT_EQ(pieces.objects.size(), 2u);
  double volume = 0;
  for (const TriMesh& p : pieces.objects) {
    EXPECT_TRUE(isClosedOriented(p));
    EXPECT_LE(maxFrontDistance(p), 1e-9);
    volume += signedVolume(p);
  }
  EXPECT_NEAR(volume, signedVolume(l), 1e-9);
  const json j = report();
  EXPECT_EQ(j["totals"]["components"], 2);
  EXPECT_EQ(j["totals"]["finished"], true);
  EXPECT_EQ(j["input"]["reflex_edges"], countNotches(l));
  EXPECT_EQ(j["totals"]["output_bytes"].get<std::uintmax_t>(), fs::file_size(path("out/pieces.obj")));
}

TEST_F(ExactCli, SurfacePatchesAndReport) {
  const TriMesh u = shapes::uShape();
  const auto r = acd("decompose " + quote(model("u.off", u)) + " --exact --surface -q -o " + quote(path("out")));
  ASSERT_EQ(r.code, 0) << r.err;
  const ObjObjects patches = readObjObjects(path("out/patches.obj"));
  ASSERT_TRUE(patches.status.ok()) << patches.status.message;
  EXPECT_EQ(patches.objects.size(), 2u);
  std::size_t faces = 0;
  double area = 0;
  for (const TriMesh& p : patches.objects) faces += p.faces.size(), area += surfaceArea(p);
  EXPECT_EQ(faces, u.faces.size());
  EXPECT_NEAR(area, surfaceArea(u), 1e-9);
  EXPECT_EQ(report()["totals"]["components"], 2);
}

TEST_F(ExactCli, TimeCapExitsFourWithNote) {
  const auto r = acd("decompose " + quote(model("t.off", shapes::torus(2.0, 0.5, 64, 32))) +
                     " --exact --exact-time-limit 0.3 -q -o " + quote(path("out")));
  EXPECT_EQ(r.code, 4) << r.err;
  EXPECT_NE(r.err.find("not finished within 0.3 s"), std::string::npos) << r.err;
  const json j = report();
  EXPECT_EQ(j["totals"]["finished"], false);
  EXPECT_EQ(j["totals"]["unfinished_solids"], 1);
}

TEST_F(ExactCli, BadInputAndParameters) {
  TriMesh open = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  open.faces.pop_back();
  auto r = acd("decompose " + quote(model("open.off", open)) + " --exact --no-fill-holes -q -o " + quote(path("out")));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("open"), std::string::npos) << r.err;
  r = acd("decompose " + quote(path("open.off")) + " --exact -q -o " + quote(path("out")));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(report()["input"]["holes_filled"], 1);
  r = acd("decompose " + quote(model("l.off", shapes::lShape())) + " --exact --exact-time-limit -1 -q -o " + quote(path("out")));
  EXPECT_EQ(r.code, 3) << r.err;
  r = acd("decompose " + quote(path("missing.off")) + " --exact --surface -q -o " + quote(path("out")));
  EXPECT_EQ(r.code, 2) << r.err;
}
