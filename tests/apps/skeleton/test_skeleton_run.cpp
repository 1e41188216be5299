// The steps of a skeleton run (apps/skeleton/src/skeleton_run) and its output (run_report):
// parameters checked, models loaded and deformed, skeletons and distances, the files written.
#include "run_report.hpp"
#include "skeleton_run.hpp"

#include "helpers.hpp"

#include <appcli/exit_codes.hpp>

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

using namespace skeleton;

TEST(SkeletonRun, ParametersAreChecked) {
  RunParameters p;
  EXPECT_EQ(checkParameters(p), appcli::kOk);
  const auto refused = [](void (*change)(RunParameters&), const std::string& said) {
    RunParameters q;
    change(q);
    testing::internal::CaptureStderr();
    EXPECT_EQ(checkParameters(q), appcli::kBadParameter) << said;
    EXPECT_EQ(testing::internal::GetCapturedStderr().rfind("skeleton: " + said, 0), 0u) << said;
  };
  refused([](RunParameters& q) { q.tau = 3; }, "--tau must lie in [1e-4, 2]");
  refused([](RunParameters& q) { q.exactMaxNodes = 41; }, "--exact-max-nodes must lie in [0, 40]");
  refused([](RunParameters& q) { q.maxExpansions = 0; }, "--max-expansions must be positive");
  refused([](RunParameters& q) { q.mcfRuns = 0; }, "--mcf-runs must lie in [1, 100]");
  refused([](RunParameters& q) { q.threads = -1; }, "--threads must be >= 0");
  refused([](RunParameters& q) { q.tubeRadius = 1; }, "--tubes must lie in [0, 0.1]");
}

TEST(SkeletonRun, AnUnknownDeformationIsRefusedBeforeTheWork) {
  acdtest::TempDir dir("skeleton_run_spec");
  RunParameters p;
  p.modelPath = dir / "l.off";
  ASSERT_TRUE(acd::writeMesh(p.modelPath, acd::shapes::lShape()).ok());
  p.deformSpecs = {"bend:+x:z:30;shear:1"};
  std::vector<Model> models;
  testing::internal::CaptureStderr();
  EXPECT_EQ(loadModels(p, models), appcli::kBadParameter);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("unknown deformation 'shear'"), std::string::npos);
  p.modelPath = dir / "missing.off";
  testing::internal::CaptureStderr();
  EXPECT_EQ(loadModels(p, models), appcli::kBadInput);
  testing::internal::GetCapturedStderr();
}

TEST(SkeletonRun, ARigidMotionKeepsTheAcdSkeleton) {
  acdtest::TempDir dir("skeleton_run");
  RunParameters p;
  p.modelPath = dir / "u.off";
  ASSERT_TRUE(acd::writeMesh(p.modelPath, acd::shapes::uShape()).ok());
  p.outDir = dir / "out";
  p.deformSpecs = {"affine:0,0,30:1,1,1"};
  p.noMcf = true;
  p.threads = 2;
  p.tau = 0.05;
  std::vector<Model> models;
  ASSERT_EQ(loadModels(p, models), appcli::kOk);
  ASSERT_EQ(makeDeformations(p, models), appcli::kOk);
  ASSERT_EQ(models.size(), 2u);
  EXPECT_TRUE(std::filesystem::exists(p.outDir + "/deformed_1.off"));
  ASSERT_EQ(decomposeModels(p, models), appcli::kOk);
  compareSkeletons(p, models);
  EXPECT_GT(models[0].acd.nodeCount(), 1);
  EXPECT_EQ(models[1].d.distance, 0);  // invariant decomposition: the same skeleton after a turn

  bool unresolved = true;
  ASSERT_EQ(writeRunFiles(p, models, unresolved), appcli::kOk);
  EXPECT_FALSE(unresolved);
  const nlohmann::json report = nlohmann::json::parse(acdtest::slurp(p.outDir + "/report.json"));
  ASSERT_EQ(report["models"].size(), 2u);
  EXPECT_EQ(report["models"][1]["acd"]["D"]["distance"], 0);
  EXPECT_TRUE(std::filesystem::exists(p.outDir + "/original.acd_skeleton.obj"));
  testing::internal::CaptureStdout();
  printTable(models);
  const std::string table = testing::internal::GetCapturedStdout();
  EXPECT_NE(table.find("deformed_1"), std::string::npos) << table;
}
