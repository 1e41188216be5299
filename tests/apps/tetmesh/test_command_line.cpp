// tetmesh's options and their checks (apps/tetmesh/src/command_line): the format from -o, and
// every range refused with exit code 3 and one line.
#include "command_line.hpp"

#include <appcli/exit_codes.hpp>

#include <gtest/gtest.h>

#include <string>

using namespace tetmesh;

TEST(TetmeshCommandLine, TheFormatComesFromTheOptionElseTheExtension) {
  Args a;
  TetFormat f = TetFormat::Vtk;
  a.out = "out.mesh";
  ASSERT_EQ(checkArgs(a, f), appcli::kOk);
  EXPECT_EQ(f, TetFormat::Medit);
  a.out = "base";
  ASSERT_EQ(checkArgs(a, f), appcli::kOk);
  EXPECT_EQ(f, TetFormat::TetGen);
  a.format = "vtk";
  ASSERT_EQ(checkArgs(a, f), appcli::kOk);
  EXPECT_EQ(f, TetFormat::Vtk);
  a.format = "stl";
  testing::internal::CaptureStderr();
  EXPECT_EQ(checkArgs(a, f), appcli::kBadParameter);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "tetmesh: unknown --format 'stl' (vtk, mesh or tetgen)\n");
}

TEST(TetmeshCommandLine, RangesAreChecked) {
  const auto refused = [](void (*change)(Args&), const std::string& said) {
    Args a;
    change(a);
    TetFormat f = TetFormat::Vtk;
    testing::internal::CaptureStderr();
    EXPECT_EQ(checkArgs(a, f), appcli::kBadParameter) << said;
    EXPECT_EQ(testing::internal::GetCapturedStderr().rfind("tetmesh: " + said, 0), 0u) << said;
  };
  refused([](Args& a) { a.options.tau = -1; }, "--tau must be positive");
  refused([](Args& a) { a.options.simplify = 3; }, "--simplify must be at least 4");
  refused([](Args& a) { a.options.tetgen.radiusEdge = 0.5; }, "--quality must be at least 1.5 with --mesher auto");
  refused([](Args& a) { a.mesher = "refine", a.options.tetgen.radiusEdge = 1.2; }, "--quality must be at least 1.5 with --mesher refine");
  refused([](Args& a) { a.mesher = "complex", a.options.tetgen.radiusEdge = 0.5; }, "--quality must be at least 1 with --mesher complex");
  refused([](Args& a) { a.options.tetgen.maxVolume = -1; }, "--max-volume must be positive");
  refused([](Args& a) { a.mesher = "delaunay"; }, "unknown --mesher 'delaunay' (auto, refine or complex)");
  refused([](Args& a) { a.mesher = "complex", a.options.clip = true; }, "--clip and --sharp need the refinement");
  refused([](Args& a) { a.mesher = "complex", a.options.sharpAngle = 40; }, "--clip and --sharp need the refinement");
  refused([](Args& a) { a.options.sharpAngle = 200; }, "--sharp must be an angle in degrees in [0, 180)");
  refused([](Args& a) { a.poly = "c.poly"; }, "--poly writes the complex given to TetGen: it needs --mesher complex");
}

TEST(TetmeshCommandLine, TheMesherIsAutomaticUnlessAskedFor) {
  Args a;
  TetFormat f = TetFormat::Vtk;
  ASSERT_EQ(checkArgs(a, f), appcli::kOk);
  EXPECT_EQ(a.options.mesher, Mesher::Auto);
  a.mesher = "refine";
  ASSERT_EQ(checkArgs(a, f), appcli::kOk);
  EXPECT_EQ(a.options.mesher, Mesher::Refine);
  a.mesher = "complex";
  a.poly = "c.poly";
  a.options.tetgen.radiusEdge = 1.2;
  ASSERT_EQ(checkArgs(a, f), appcli::kOk);
  EXPECT_EQ(a.options.mesher, Mesher::Complex);
}

TEST(TetmeshCommandLine, DeformationOptions) {
  DeformArgs d;
  DeformationOptions o;
  ASSERT_EQ(deformOptions(d, o), appcli::kOk);
  EXPECT_FALSE(o.translate);
  EXPECT_FALSE(o.rotate);
  d.move = {1, 0, 0};
  ASSERT_EQ(deformOptions(d, o), appcli::kOk);
  EXPECT_TRUE(o.translate);
  d.angle = 30;
  testing::internal::CaptureStderr();
  EXPECT_EQ(deformOptions(d, o), appcli::kBadParameter);
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "tetmesh: --deform-move and --deform-angle cannot be used together\n");
  DeformArgs same;
  same.handle = same.anchor = 2;
  testing::internal::CaptureStderr();
  EXPECT_EQ(deformOptions(same, o), appcli::kBadParameter);
  EXPECT_NE(testing::internal::GetCapturedStderr().find("are the same component (2)"), std::string::npos);
}
