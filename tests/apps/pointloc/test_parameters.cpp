// pointloc's parameters (apps/pointloc/src/parameters): counts written as doubles, and every
// range refused with exit code 3 before any model is read.
#include "parameters.hpp"

#include <appcli/exit_codes.hpp>

#include <gtest/gtest.h>

#include <cstdint>

using pointloc::Parameters;

TEST(PointlocParameters, CountsAreIntegersWrittenAnyWay) {
  std::uint64_t n = 0;
  EXPECT_TRUE(pointloc::parseCount("1e8", 1e10, false, n));
  EXPECT_EQ(n, 100000000u);
  EXPECT_TRUE(pointloc::parseCount("250", 1e10, false, n));
  EXPECT_EQ(n, 250u);
  EXPECT_TRUE(pointloc::parseCount("0", 1e10, true, n));
  EXPECT_FALSE(pointloc::parseCount("0", 1e10, false, n));
  EXPECT_FALSE(pointloc::parseCount("1.5", 1e10, false, n));
  EXPECT_FALSE(pointloc::parseCount("2e10", 1e10, false, n));
  EXPECT_FALSE(pointloc::parseCount("12x", 1e10, false, n));
  EXPECT_FALSE(pointloc::parseCount("", 1e10, true, n));
}

TEST(PointlocParameters, DefaultsAreCheckedAndDerived) {
  Parameters p;
  testing::internal::CaptureStderr();
  EXPECT_EQ(pointloc::checkParameters(p), appcli::kOk);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(p.samples, 100000000u);
  EXPECT_EQ(p.exactSamples, 2000000u);   // min(N, 2e6)
  EXPECT_EQ(p.compareSamples, 1000000u);  // min(N, 1e6)
  EXPECT_DOUBLE_EQ(p.tau, 0.02);
  p.samplesText = "1000";
  ASSERT_EQ(pointloc::checkParameters(p), appcli::kOk);
  EXPECT_EQ(p.exactSamples, 1000u);
  EXPECT_EQ(p.compareSamples, 1000u);
}

TEST(PointlocParameters, EveryRangeIsRefusedWithOneLine) {
  const auto refused = [](void (*change)(Parameters&), const char* said) {
    Parameters p;
    change(p);
    testing::internal::CaptureStderr();
    EXPECT_EQ(pointloc::checkParameters(p), appcli::kBadParameter) << said;
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(err.rfind("pointloc: " + std::string(said), 0), 0u) << err;
    EXPECT_EQ(err.find('\n'), err.size() - 1) << err;
  };
  refused([](Parameters& p) { p.samplesText = "0"; }, "--samples '0'");
  refused([](Parameters& p) { p.tauText = "3"; }, "--tau '3'");
  refused([](Parameters& p) { p.threads = -1; }, "--threads -1");
  refused([](Parameters& p) { p.exactText = "-2"; }, "--exact-samples '-2'");
  refused([](Parameters& p) { p.compareText = "2e8"; }, "--compare-samples '2e8'");
  refused([](Parameters& p) { p.ecdTimeLimit = 0; }, "--ecd-time-limit 0");
  refused([](Parameters& p) { p.repeat = 101; }, "--repeat 101");
  refused([](Parameters& p) { p.gridCells = 0; }, "--grid-cells 0");
}

TEST(PointlocParameters, AnUnwritableOutputIsRefusedBeforeTheWork) {
  Parameters p;
  p.jsonPath = "/nonexistent-folder/report.json";
  testing::internal::CaptureStderr();
  EXPECT_EQ(pointloc::checkParameters(p), appcli::kOutputFailed);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "pointloc: cannot write /nonexistent-folder/report.json\n");
}
