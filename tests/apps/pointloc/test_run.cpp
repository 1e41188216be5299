// pointloc's steps (apps/pointloc/src/run, compare, report) on a small solid: the grid gives the
// answers of testing every hull, the exact subsample finds the hulls' excess, --compare's
// exact methods agree with acd::InsideTest, and the report carries the counts.
#include "compare.hpp"
#include "report.hpp"
#include "run.hpp"

#include "helpers.hpp"

#include <appcli/exit_codes.hpp>

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace {

class PointlocRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::make_unique<acdtest::TempDir>("pointloc_run");
    model_ = *dir_ / "l.off";
    ASSERT_TRUE(acd::writeMesh(model_, acd::shapes::lShape()).ok());
    p_.model = model_;
    p_.samplesText = "20000";
    p_.threads = 2;
    p_.tauText = "0.02";
    p_.gridCells = 4096;
    ASSERT_EQ(pointloc::checkParameters(p_), appcli::kOk);
  }

  /// Runs the steps up to the errors on the exact subsample.
  void runSteps(pointloc::Run& run) {
    ASSERT_EQ(pointloc::readModel(run), appcli::kOk);
    ASSERT_EQ(pointloc::decomposeAndIndex(run), appcli::kOk);
    ASSERT_EQ(pointloc::locateAll(run), appcli::kOk);
    pointloc::measureErrors(run);
  }

  std::unique_ptr<acdtest::TempDir> dir_;
  std::string model_;
  pointloc::Parameters p_;
};

}  // namespace

TEST_F(PointlocRun, TheGridAnswersAsTestingEveryHull) {
  pointloc::Run indexed(p_);
  runSteps(indexed);
  pointloc::Parameters direct = p_;
  direct.noIndex = true;
  pointloc::Run scanned(direct);
  runSteps(scanned);
  EXPECT_EQ(indexed.inside, scanned.inside);
  EXPECT_EQ(indexed.falseIn, scanned.falseIn);
  EXPECT_EQ(indexed.falseOut, scanned.falseOut);
  EXPECT_GT(indexed.inside, 0u);
  EXPECT_LT(indexed.inside, p_.samples);
  EXPECT_EQ(indexed.hullComponent.size(), static_cast<std::size_t>(indexed.hulls.size()));
  // Hulls contain their components: the exact answer never says inside where the hulls say out.
  EXPECT_EQ(indexed.falseOut, 0u);
  EXPECT_EQ(indexed.order.size(), indexed.byHull.size());
}

TEST_F(PointlocRun, DumpWritesOneRowPerExactPoint) {
  p_.exactText = "100";
  p_.dumpPath = *dir_ / "points.csv";
  ASSERT_EQ(pointloc::checkParameters(p_), appcli::kOk);
  pointloc::Run run(p_);
  runSteps(run);
  ASSERT_EQ(pointloc::dumpPoints(run), appcli::kOk);
  std::ifstream in(p_.dumpPath);
  std::string line;
  int rows = 0;
  std::getline(in, line);
  EXPECT_EQ(line, "x,y,z,hulls,direct,exact");
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 100);
}

TEST_F(PointlocRun, AnOpenModelIsRefused) {
  acd::TriMesh open = acd::shapes::box(acd::Vec3::Zero(), acd::Vec3::Ones());
  open.faces.pop_back();
  p_.model = *dir_ / "open.off";
  ASSERT_TRUE(acd::writeMesh(p_.model, open).ok());
  pointloc::Run run(p_);
  testing::internal::CaptureStderr();
  EXPECT_EQ(pointloc::readModel(run), appcli::kBadInput);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("is not a closed surface"), std::string::npos);
}

TEST_F(PointlocRun, CompareTimesEveryMethodAndTheExactOnesAgree) {
  p_.compare = true;
  p_.compareText = "2000";
  p_.ecdTimeLimit = 30;
  ASSERT_EQ(pointloc::checkParameters(p_), appcli::kOk);
  pointloc::Run run(p_);
  runSteps(run);
  const pointloc::Comparison c = pointloc::compareMethods(run);
  ASSERT_GE(c.methods.size(), 4u);
  EXPECT_EQ(c.methods[0].name, "ACD hulls (grid)");
  EXPECT_EQ(c.methods[0].inside, run.inside);
  int checked = 0;
  for (const pointloc::Method& m : c.methods) {
    // (the rows timed on all N points are not checked point by point)
    if (!m.measured() || !m.exact || !m.disagreements) continue;
    EXPECT_EQ(*m.disagreements, 0u) << m.name;
    ++checked;
  }
  EXPECT_GE(checked, 2);  // acd::InsideTest on 1 and on all threads at least
}

TEST_F(PointlocRun, TheReportCarriesTheCounts) {
  p_.jsonPath = *dir_ / "report.json";
  pointloc::Run run(p_);
  runSteps(run);
  testing::internal::CaptureStdout();
  const nlohmann::json top = pointloc::printReport(run);
  const std::string table = testing::internal::GetCapturedStdout();
  EXPECT_NE(table.find("points inside          " + std::to_string(run.inside)), std::string::npos) << table;
  EXPECT_TRUE(top.is_array());
  ASSERT_EQ(pointloc::writeJson(run, top, nullptr, {}, 1.0), appcli::kOk);
  const nlohmann::json j = nlohmann::json::parse(acdtest::slurp(p_.jsonPath));
  EXPECT_EQ(j["points_inside"], run.inside);
  EXPECT_EQ(j["exact"]["false_inside"], run.falseIn);
  EXPECT_FALSE(j.contains("compare"));
}
