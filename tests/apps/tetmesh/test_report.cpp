// tetmesh's report and the deformation's files (apps/tetmesh/src/report, deformation_files):
// the summary and the JSON give the mesh's figures, the deformation writes its six files.
#include "deformation_files.hpp"
#include "helpers.hpp"
#include "hull_mesher.hpp"
#include "report.hpp"

#include <appcli/exit_codes.hpp>

#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

using namespace tetmesh;

namespace {

/// An L-shaped solid meshed through the exact complex of its hulls (two components).
HullMeshResult meshedL(Args& a) {
  a.model = "l.off";
  a.options.mesher = Mesher::Complex;
  a.options.simplify = 0;
  a.options.tau = 0.02;
  a.options.threads = 2;
  return meshHulls(acd::shapes::lShape(), a.options);
}

}  // namespace

TEST(TetmeshReport, SummaryAndJsonGiveTheMeshFigures) {
  acdtest::TempDir dir("tetmesh_report");
  Args a;
  const HullMeshResult r = meshedL(a);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  a.json = dir / "report.json";
  const DirectMeshResult direct;
  const DeformationResult deformed;
  testing::internal::CaptureStdout();
  printReport(a, TetFormat::Vtk, r, direct, deformed);
  const std::string summary = testing::internal::GetCapturedStdout();
  EXPECT_EQ(summary.rfind("l.off\n", 0), 0u) << summary;
  EXPECT_NE(summary.find(std::to_string(r.quality.tets)), std::string::npos) << summary;
  ASSERT_EQ(writeJsonReport(a, r, direct, deformed), appcli::kOk);
  const nlohmann::json j = nlohmann::json::parse(acdtest::slurp(a.json));
  EXPECT_EQ(j["model"], "l.off");
  EXPECT_EQ(j["hull_mesh"]["tets"], r.quality.tets);
  EXPECT_EQ(j["components"].size(), r.hulls.size());
  // The L (three unit cubes) cut into boxes: each exact hull is its component, nothing overshoots.
  EXPECT_NE(summary.find("overshoot      tets beyond their component: median +0.0%"), std::string::npos) << summary;
  double components = 0.0;
  for (const auto& c : j["components"]) {
    components += c["component_volume"].get<double>();
    EXPECT_NEAR(c["overshoot"].get<double>(), 0.0, 1e-9) << c;
    EXPECT_NEAR(c["region_volume"].get<double>(), c["component_volume"].get<double>(), 1e-9) << c;
  }
  EXPECT_NEAR(components, 3.0, 1e-9);
  EXPECT_FALSE(j.contains("original_mesh"));
  EXPECT_FALSE(j.contains("deformation"));
  a.json = dir / "missing/report.json";
  testing::internal::CaptureStderr();
  EXPECT_EQ(writeJsonReport(a, r, direct, deformed), appcli::kOutputFailed);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("cannot write"), std::string::npos);
}

TEST(TetmeshReport, TheDeformationWritesItsFilesAndJson) {
  acdtest::TempDir dir("tetmesh_deformation_files");
  Args a;
  const HullMeshResult r = meshedL(a);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  a.deform.dir = dir / "deformed";
  DeformationOptions o;
  ASSERT_EQ(deformOptions(a.deform, o), appcli::kOk);
  DeformationResult deformed;
  ASSERT_EQ(runDeformation(a.deform, o, r.mesh, acd::shapes::lShape(), deformed), appcli::kOk);
  for (const char* f : {"surface_before.off", "surface_after.off", "tets_before.vtk", "tets_after.vtk",
                        "parts_before.obj", "parts_after.obj"})
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(a.deform.dir) / f)) << f;
  const nlohmann::json j = deformationJson(a.deform, deformed);
  EXPECT_EQ(j["directory"], a.deform.dir);
  EXPECT_EQ(j["handle"], deformed.handle);
  EXPECT_EQ(j["arap"]["iterations"], deformed.arap.iterations);
}
