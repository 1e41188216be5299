// `acd` on scene files (assimp formats): read in a capped child process (sandbox/scene_reader),
// so that a file on which assimp misbehaves costs seconds and ends in a one-line refusal.
#include "helpers.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

/// A unit cube as COLLADA; `indices` is the text of the <p> element.
std::string colladaCube(const std::string& indices) {
  return R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<library_geometries><geometry id="g"><mesh>
<source id="p"><float_array id="pa" count="24">0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1</float_array>
<technique_common><accessor source="#pa" count="8" stride="3">
<param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
</accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="12"><input semantic="VERTEX" source="#v" offset="0"/><p>)" +
         indices + R"(</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"/></node></visual_scene>
</library_visual_scenes><scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";
}

const char* kCubeIndices = "0 2 3 0 3 1 4 5 7 4 7 6 0 1 5 0 5 4 2 6 7 2 7 3 0 4 6 0 6 2 1 3 7 1 7 5";

class CliScene : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(ACD_CLI)) GTEST_SKIP() << "CLI not built: " << ACD_CLI;
    dir_ = std::make_unique<acdtest::TempDir>(std::string("cli_scene_") +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string p = *dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  acdtest::ToolRun acd(const std::string& args) const { return acdtest::runTool(ACD_CLI, args, *dir_); }
  std::unique_ptr<acdtest::TempDir> dir_;
};

}  // namespace

TEST_F(CliScene, ACleanSceneIsReadThroughTheChild) {
  const std::string p = write("cube.dae", colladaCube(kCubeIndices));
  const acdtest::ToolRun r = acd("info " + acdtest::quote(p));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("faces                 12"), std::string::npos) << r.out;
  const acdtest::ToolRun d = acd("decompose " + acdtest::quote(p) + " -o " + acdtest::quote(*dir_ / "out") + " -q");
  EXPECT_EQ(d.code, 0) << d.err;
  EXPECT_TRUE(fs::exists(fs::path(*dir_ / "out") / "report.json"));
}

TEST_F(CliScene, AReaderErrorIsOneLine) {
  const std::string p = write("bad.dae", colladaCube("0 1 99 0 3 1"));
  const acdtest::ToolRun r = acd("info " + acdtest::quote(p));
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("bad.dae: cannot read"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
}

// Fuzzing finding: a letter glued to a number in <p> ("1x0") makes Debian's assimp 5.2.5
// allocate about 19 GB over two minutes before it throws. Under the child's memory cap (4 GiB
// for a small file) it is refused in seconds, and the caller never holds that memory.
TEST_F(CliScene, AnAssimpMemoryBombIsCappedAndRefused) {
  const std::string p = write("bomb.dae", colladaCube("0 1x0 3 1 4 5 7 4 7 6 0 1 5 0 5 4 2 6 7 2 7 3 0 4 6 0 6 2 1 3 7 1 7 5"));
  const acdtest::ToolRun r = acd("decompose " + acdtest::quote(p) + " -o " + acdtest::quote(*dir_ / "out") + " -q");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("bomb.dae: cannot read: the scene reader (assimp) needed more than"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
  EXPECT_FALSE(fs::exists(fs::path(*dir_ / "out") / "report.json"));
}
