// Simulator files: per-hull meshes read back equal to the hulls, glTF/GLB read back with
// tinygltf, MJCF checked against the elements and attributes MuJoCo's XML reference documents,
// URDF/SDF well-formed (their own parsers read them in tests/simulators/).
#include <acd/decompose.hpp>
#include <acd/io.hpp>
#include <acd/algo/mass_properties.hpp>
#include <acd/algo/shapes.hpp>
#include <acd/simulator_export.hpp>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <tinyxml2.h>

#include "helpers.hpp"

#include <Eigen/Eigenvalues>

#include <filesystem>
#include <map>
#include <set>
#include <sstream>

using namespace acd;
namespace fs = std::filesystem;

namespace {

SimulatorModel lModel() {
  DecomposeOptions o;
  o.tau = 0.01;
  const TriMesh l = shapes::lShape();
  const Decomposition d = decompose(l, o);
  EXPECT_TRUE(d.status.ok());
  SimulatorModel m;
  m.name = simulatorName("L shape");
  m.visual = l;
  for (const Component& c : d.components) m.hulls.push_back(c.hull);
  m.mass = massProperties(l, 1000.0);
  return m;
}

const std::vector<SimFormat> kAll = {SimFormat::Obj,  SimFormat::Stl,  SimFormat::Glb, SimFormat::Gltf,
                                     SimFormat::Urdf, SimFormat::Mjcf, SimFormat::Sdf};

/// Elements and attributes of MJCF that MuJoCo's XML reference documents (the ones a rigid
/// body with mesh geoms may use), by parent element.
const std::map<std::string, std::set<std::string>> kMjcfChildren = {
    {"mujoco", {"compiler", "option", "size", "visual", "statistic", "default", "extension", "custom", "asset",
                "worldbody", "contact", "equality", "tendon", "actuator", "sensor", "keyframe"}},
    {"default", {"default", "mesh", "material", "joint", "geom", "site", "camera", "light", "pair", "equality",
                 "tendon", "general", "motor", "position", "velocity"}},
    {"asset", {"mesh", "hfield", "skin", "texture", "material"}},
    {"worldbody", {"body", "geom", "site", "camera", "light", "frame"}},
    {"body", {"inertial", "joint", "freejoint", "geom", "site", "camera", "light", "body", "frame"}},
};
const std::map<std::string, std::set<std::string>> kMjcfAttributes = {
    {"mujoco", {"model"}},
    {"compiler", {"autolimits", "boundmass", "boundinertia", "settotalmass", "balanceinertia", "strippath",
                  "coordinate", "angle", "fitaabb", "eulerseq", "meshdir", "texturedir", "assetdir",
                  "discardvisual", "convexhull", "usethread", "fusestatic", "inertiafromgeom",
                  "inertiagrouprange", "exactmeshinertia"}},
    {"default", {"class"}},
    {"asset", {}},
    {"worldbody", {}},
    {"mesh", {"name", "class", "content_type", "file", "vertex", "normal", "texcoord", "face", "refpos", "refquat",
              "scale", "smoothnormal", "maxhullvert", "inertia"}},
    {"body", {"name", "childclass", "pos", "quat", "mocap", "axisangle", "xyaxes", "zaxis", "euler", "gravcomp", "user"}},
    {"freejoint", {"name", "group", "align"}},
    {"inertial", {"pos", "quat", "mass", "diaginertia", "axisangle", "xyaxes", "zaxis", "euler", "fullinertia"}},
    {"geom", {"name", "class", "type", "contype", "conaffinity", "condim", "group", "priority", "size", "material",
              "friction", "mass", "density", "shellinertia", "solmix", "solref", "solimp", "margin", "gap",
              "fromto", "pos", "quat", "axisangle", "xyaxes", "zaxis", "euler", "hfield", "mesh", "fitscale",
              "rgba", "fluidshape", "fluidcoef", "user"}},
};

void checkMjcfElement(const tinyxml2::XMLElement* e, std::vector<std::string>& problems) {
  const std::string name = e->Name();
  const auto attrs = kMjcfAttributes.find(name);
  if (attrs == kMjcfAttributes.end()) {
    problems.push_back("element <" + name + "> not expected here");
  } else {
    for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a; a = a->Next())
      if (!attrs->second.count(a->Name())) problems.push_back("<" + name + "> has undocumented attribute " + a->Name());
  }
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const auto kids = kMjcfChildren.find(name);
    if (kids == kMjcfChildren.end() || !kids->second.count(c->Name()))
      problems.push_back("<" + std::string(c->Name()) + "> is not a documented child of <" + name + ">");
    checkMjcfElement(c, problems);
  }
}

std::vector<double> numbers(const char* text) {
  std::vector<double> v;
  std::istringstream in(text ? text : "");
  for (double x; in >> x;) v.push_back(x);
  return v;
}

}  // namespace

TEST(SimulatorExport, WritesEveryFormatAndTheMeshesReadBack) {
  acdtest::TempDir dir("simexport_all");
  const SimulatorModel m = lModel();
  ASSERT_GE(m.hulls.size(), 2u);
  std::vector<std::string> written;
  const Status s = writeSimulatorFiles(dir.path().string(), m, kAll, &written);
  ASSERT_TRUE(s.ok()) << s.message;
  for (const std::string& f : written) EXPECT_TRUE(fs::exists(dir.path() / f)) << f;
  for (const char* f : {"model.urdf", "model.xml", "model.sdf", "model.stl", "hulls.glb", "hulls.gltf", "hulls.bin"})
    EXPECT_NE(std::find(written.begin(), written.end(), f), written.end()) << f;
  for (std::size_t i = 0; i < m.hulls.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "hulls/hull_%03zu", i);
    const ReadResult obj = readMesh(dir / (std::string(name) + ".obj"));
    ASSERT_TRUE(obj.status.ok()) << obj.status.message;
    EXPECT_EQ(obj.mesh.faces.size(), m.hulls[i].faces.size());
    EXPECT_NEAR(signedVolume(obj.mesh), signedVolume(m.hulls[i]), 1e-12);
    const ReadResult stl = readMesh(dir / (std::string(name) + ".stl"));
    ASSERT_TRUE(stl.status.ok()) << stl.status.message;
    EXPECT_NEAR(signedVolume(stl.mesh), signedVolume(m.hulls[i]), 1e-6);  // float coordinates
  }
}

TEST(SimulatorExport, GltfAndGlbReadBackWithOneNodePerHull) {
  acdtest::TempDir dir("simexport_gltf");
  const SimulatorModel m = lModel();
  ASSERT_TRUE(writeSimulatorFiles(dir.path().string(), m, {SimFormat::Glb, SimFormat::Gltf}).ok());
  for (bool binary : {true, false}) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model g;
    std::string err, warn;
    const bool ok = binary ? loader.LoadBinaryFromFile(&g, &err, &warn, dir / "hulls.glb")
                           : loader.LoadASCIIFromFile(&g, &err, &warn, dir / "hulls.gltf");
    ASSERT_TRUE(ok) << err;
    ASSERT_EQ(g.nodes.size(), m.hulls.size());
    ASSERT_EQ(g.scenes.size(), 1u);
    EXPECT_EQ(g.scenes[0].nodes.size(), m.hulls.size());
    for (std::size_t i = 0; i < m.hulls.size(); ++i) {
      const tinygltf::Node& node = g.nodes[i];
      ASSERT_GE(node.mesh, 0);
      const tinygltf::Primitive& p = g.meshes[node.mesh].primitives.at(0);
      const tinygltf::Accessor& pos = g.accessors[p.attributes.at("POSITION")];
      const tinygltf::Accessor& idx = g.accessors[p.indices];
      ASSERT_EQ(pos.count, m.hulls[i].vertices.size());
      ASSERT_EQ(idx.count, 3 * m.hulls[i].faces.size());
      const tinygltf::BufferView& pv = g.bufferViews[pos.bufferView];
      const tinygltf::BufferView& iv = g.bufferViews[idx.bufferView];
      const auto* xyz = reinterpret_cast<const float*>(g.buffers[pv.buffer].data.data() + pv.byteOffset + pos.byteOffset);
      const auto* ids = reinterpret_cast<const std::uint32_t*>(g.buffers[iv.buffer].data.data() + iv.byteOffset + idx.byteOffset);
      TriMesh back;
      for (std::size_t v = 0; v < pos.count; ++v) back.vertices.emplace_back(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
      for (std::size_t f = 0; f < idx.count / 3; ++f)
        back.faces.push_back({static_cast<int>(ids[3 * f]), static_cast<int>(ids[3 * f + 1]), static_cast<int>(ids[3 * f + 2])});
      EXPECT_NEAR(signedVolume(back), signedVolume(m.hulls[i]), 1e-6);
      EXPECT_EQ(node.name, g.meshes[node.mesh].name);
    }
  }
}

TEST(SimulatorExport, MjcfUsesOnlyDocumentedElementsAndItsReferencesResolve) {
  acdtest::TempDir dir("simexport_mjcf");
  const SimulatorModel m = lModel();
  ASSERT_TRUE(writeSimulatorFiles(dir.path().string(), m, {SimFormat::Mjcf}).ok());
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile((dir / "model.xml").c_str()), tinyxml2::XML_SUCCESS);
  const tinyxml2::XMLElement* root = doc.RootElement();
  ASSERT_STREQ(root->Name(), "mujoco");
  std::vector<std::string> problems;
  checkMjcfElement(root, problems);
  for (const std::string& p : problems) ADD_FAILURE() << p;
  // Every mesh asset names an existing file; every mesh geom names an asset; one collision geom per hull.
  const char* meshdir = root->FirstChildElement("compiler")->Attribute("meshdir");
  std::set<std::string> assets;
  for (const auto* a = root->FirstChildElement("asset")->FirstChildElement("mesh"); a; a = a->NextSiblingElement("mesh")) {
    EXPECT_TRUE(fs::exists(dir.path() / (meshdir ? meshdir : ".") / a->Attribute("file"))) << a->Attribute("file");
    EXPECT_TRUE(assets.insert(a->Attribute("name")).second) << "duplicate asset " << a->Attribute("name");
  }
  const auto* body = root->FirstChildElement("worldbody")->FirstChildElement("body");
  ASSERT_NE(body, nullptr);
  int collision = 0;
  for (const auto* g = body->FirstChildElement("geom"); g; g = g->NextSiblingElement("geom")) {
    EXPECT_STREQ(g->Attribute("type"), "mesh");
    EXPECT_TRUE(assets.count(g->Attribute("mesh"))) << g->Attribute("mesh");
    collision += std::string(g->Attribute("class")) == "collision";
  }
  EXPECT_EQ(collision, static_cast<int>(m.hulls.size()));
  // Inertial: the mass and full inertia of the model (positive definite, triangle inequality).
  const auto* inertial = body->FirstChildElement("inertial");
  ASSERT_NE(inertial, nullptr);
  EXPECT_NEAR(inertial->DoubleAttribute("mass"), 3000.0, 1e-6);  // three unit cells at 1000
  const std::vector<double> fi = numbers(inertial->Attribute("fullinertia"));
  ASSERT_EQ(fi.size(), 6u);
  Eigen::Matrix3d I;
  I << fi[0], fi[3], fi[4], fi[3], fi[1], fi[5], fi[4], fi[5], fi[2];
  const Vec3 ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  EXPECT_GT(ev[0], 0.0);
  EXPECT_LE(ev[2], ev[0] + ev[1] + 1e-9);
  EXPECT_EQ(numbers(inertial->Attribute("pos")).size(), 3u);
}

TEST(SimulatorExport, NamesAreMadeSafe) {
  EXPECT_EQ(simulatorName("bunny00"), "bunny00");
  EXPECT_EQ(simulatorName("my model<1>"), "my_model_1_");
  EXPECT_EQ(simulatorName("3dmodel"), "model_3dmodel");
  EXPECT_EQ(simulatorName(""), "model_");
  SimFormat f;
  EXPECT_TRUE(parseSimFormat("URDF", f));
  EXPECT_EQ(f, SimFormat::Urdf);
  EXPECT_FALSE(parseSimFormat("dae", f));
}

TEST(SimulatorExport, UnwritableFolderIsAStatus) {
  const SimulatorModel m = lModel();
  const Status s = writeSimulatorFiles("/proc/acd-no-such-dir", m, kAll);
  EXPECT_FALSE(s.ok());
  EXPECT_FALSE(s.message.empty());
}
