// apps/cli: every program's messages are one line starting with its name, and a Status maps to
// the same exit code in every program.
#include <appcli/console.hpp>
#include <appcli/exit_codes.hpp>

#include <gtest/gtest.h>

#include <string>

using appcli::Console;

TEST(AppCli, FailPrintsOneLineAndReturnsTheCode) {
  const Console console("tetmesh");
  testing::internal::CaptureStderr();
  const int code = console.fail(appcli::kBadParameter, "--tau must be positive, got -1");
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "tetmesh: --tau must be positive, got -1\n");
  EXPECT_EQ(code, appcli::kBadParameter);
}

TEST(AppCli, FormattedMessagesAreAsPrintfWritesThem) {
  const Console console("pointloc");
  testing::internal::CaptureStderr();
  const int code = console.failf(appcli::kBadParameter, "--grid-cells %zu must be in [1, %d]; %g%%", std::size_t{0}, 16, 0.5);
  console.sayf("decomposing at tau %g", 0.05);
  console.say("a line with 100% in it");
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "pointloc: --grid-cells 0 must be in [1, 16]; 0.5%\n"
            "pointloc: decomposing at tau 0.05\n"
            "pointloc: a line with 100% in it\n");
  EXPECT_EQ(code, appcli::kBadParameter);
  // longer than any fixed buffer
  const std::string longText(5000, 'x');
  testing::internal::CaptureStderr();
  console.sayf("%s", longText.c_str());
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "pointloc: " + longText + "\n");
}

TEST(AppCli, AStatusNamesWhereOnce) {
  const Console console("acd");
  testing::internal::CaptureStderr();
  const int a = console.fail("m.off", acd::Status::error(acd::StatusCode::FileUnreadable, "m.off: cannot open"));
  const int b = console.fail("m.off", acd::Status::error(acd::StatusCode::InvalidParameter, "tau must be positive"));
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "acd: m.off: cannot open\nacd: m.off: tau must be positive\n");
  EXPECT_EQ(a, appcli::kBadInput);
  EXPECT_EQ(b, appcli::kBadParameter);
}

TEST(AppCli, ExitCodes) {
  EXPECT_EQ(appcli::exitFor(acd::Status{}), appcli::kOk);
  EXPECT_EQ(appcli::exitFor(acd::Status::error(acd::StatusCode::InternalError, "bug")), appcli::kInternal);
  EXPECT_EQ(appcli::exitFor(acd::Status::error(acd::StatusCode::DegenerateFace, "flat")), appcli::kBadInput);
  EXPECT_EQ(appcli::usageExit(0), appcli::kOk);  // --help
  EXPECT_EQ(appcli::usageExit(106), appcli::kUsage);
}
