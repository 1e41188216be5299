// Shared by the consumer tests: the U shape (7 unit cells) decomposed by the built `acd` with
// simulator output, and what the consumers should find in it.
#pragma once

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "helpers.hpp"

#include <fstream>
#include <string>

namespace simtest {

/// Runs `acd decompose` on the U shape, shifted off the origin, into a fresh folder.
class SimOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(ACD_CLI)) GTEST_SKIP() << "CLI not built: " << ACD_CLI;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::make_unique<acdtest::TempDir>(std::string("sim_") + info->name());
    acd::TriMesh u = acd::shapes::uShape();
    for (acd::Vec3& v : u.vertices) v += shift;
    model_ = *dir_ / "u_shape.off";
    ASSERT_TRUE(acd::writeMesh(model_, u).ok());
    out_ = *dir_ / "out";
    const acdtest::ToolRun r = acdtest::runTool(
        ACD_CLI,
        "decompose " + acdtest::quote(model_) + " -t 0.02 --max-hull-vertices 12 --density 500 --format " + formats() +
            " -o " + acdtest::quote(out_) + " -q",
        *dir_);
    ASSERT_EQ(r.code, 0) << r.err;
    std::ifstream in(out_ + "/report.json");
    report_ = nlohmann::json::parse(in);
  }

  virtual std::string formats() const { return "urdf,sdf,mjcf"; }

  // The U: cells (0,0) (1,0) (2,0) (0,1) (2,1) (0,2) (2,2), unit cubes, z in [0, 1].
  const acd::Vec3 shift{3.0, -2.0, 0.5};
  static constexpr double kDensity = 500.0;
  static constexpr double kVolume = 7.0;
  acd::Vec3 centerOfMass() const {
    // x: cells at x-centres 0.5 (3 cells), 1.5 (1), 2.5 (3) -> 1.5; y: 0.5 (3), 1.5 (2), 2.5 (2) -> 9.5 / 7.
    return acd::Vec3(1.5, 9.5 / 7.0, 0.5) + shift;
  }
  int hulls() const { return static_cast<int>(report_["components"].size()); }

  std::unique_ptr<acdtest::TempDir> dir_;
  std::string model_, out_;
  nlohmann::json report_;
};

}  // namespace simtest
