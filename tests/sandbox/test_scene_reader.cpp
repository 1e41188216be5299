// sandbox/scene_reader: a scene read in the child comes back whole through the pipe; what assimp
// cannot read comes back as a one-line refusal naming the file; other formats skip the child.
#include <sandbox/scene_reader.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace {

/// A unit cube as COLLADA, one named node.
const char* kCube = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
<library_geometries><geometry id="g" name="cube"><mesh>
<source id="p"><float_array id="pa" count="24">0 0 0 1 0 0 0 1 0 1 1 0 0 0 1 1 0 1 0 1 1 1 1 1</float_array>
<technique_common><accessor source="#pa" count="8" stride="3">
<param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
</accessor></technique_common></source>
<vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
<triangles count="12"><input semantic="VERTEX" source="#v" offset="0"/>
<p>0 2 3 0 3 1 4 5 7 4 7 6 0 1 5 0 5 4 2 6 7 2 7 3 0 4 6 0 6 2 1 3 7 1 7 5</p></triangles>
</mesh></geometry></library_geometries>
<library_visual_scenes><visual_scene id="s"><node id="n" name="cube"><instance_geometry url="#g"/></node>
</visual_scene></library_visual_scenes><scene><instance_visual_scene url="#s"/></scene>
</COLLADA>
)";

std::string tempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("acd_scene_reader_" + std::to_string(::getpid()) + "_" + name)).string();
}

}  // namespace

TEST(SceneReader, ASceneComesBackWholeFromTheChild) {
  const acd::SceneMeshes scene = acdsandbox::readSceneFromMemoryIsolated(kCube, "cube.dae");
  ASSERT_TRUE(scene.status.ok()) << scene.status.message;
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.names.size(), 1u);
  EXPECT_EQ(scene.meshes[0].faces.size(), 12u);
  EXPECT_FALSE(scene.meshes[0].vertices.empty());
  // the same bytes read in this process give the same mesh
  const acd::SceneMeshes direct = acd::readSceneFromMemory(kCube, "cube.dae");
  ASSERT_TRUE(direct.status.ok());
  EXPECT_EQ(direct.names, scene.names);
  EXPECT_EQ(direct.meshes[0].vertices, scene.meshes[0].vertices);
  EXPECT_EQ(direct.meshes[0].faces, scene.meshes[0].faces);
}

TEST(SceneReader, AnUnreadableSceneIsARefusal) {
  const acd::SceneMeshes scene = acdsandbox::readSceneFromMemoryIsolated("<COLLADA>not a scene", "broken.dae");
  EXPECT_FALSE(scene.status.ok());
  EXPECT_TRUE(scene.meshes.empty());
  EXPECT_EQ(scene.status.message.find('\n'), std::string::npos) << scene.status.message;
}

TEST(SceneReader, ReadModelMergesAScenesMeshesAndReadsOtherFormatsDirectly) {
  const std::string dae = tempPath("cube.dae"), off = tempPath("tri.off");
  std::ofstream(dae) << kCube;
  std::ofstream(off) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const acd::ReadResult fromScene = acdsandbox::readModel(dae);
  ASSERT_TRUE(fromScene.status.ok()) << fromScene.status.message;
  EXPECT_EQ(fromScene.mesh.faces.size(), 12u);
  const acd::ReadResult fromOff = acdsandbox::readModel(off);
  ASSERT_TRUE(fromOff.status.ok()) << fromOff.status.message;
  EXPECT_EQ(fromOff.mesh.faces.size(), 1u);
  fs::remove(dae);
  fs::remove(off);
}

TEST(SceneReader, AMissingFileIsSaidWithoutAChild) {
  const acd::SceneMeshes scene = acdsandbox::readSceneIsolated(tempPath("missing.glb"));
  EXPECT_FALSE(scene.status.ok());
}
