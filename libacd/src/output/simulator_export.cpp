// URDF, MJCF and SDF rigid bodies and per-hull mesh files; see simulator_export.hpp.
#include <acd/simulator_export.hpp>

#include <acd/algo/gltf_export.hpp>
#include <acd/io.hpp>

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

namespace acd {

namespace fs = std::filesystem;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

namespace {

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

std::string triple(const Vec3& v) { return number(v.x()) + " " + number(v.y()) + " " + number(v.z()); }

XMLElement* child(XMLElement* parent, const char* name) {
  XMLElement* e = parent->GetDocument()->NewElement(name);
  parent->InsertEndChild(e);
  return e;
}

XMLElement* textChild(XMLElement* parent, const char* name, const std::string& text) {
  XMLElement* e = child(parent, name);
  e->SetText(text.c_str());
  return e;
}

Status save(XMLDocument& doc, const fs::path& path) {
  if (doc.SaveFile(path.string().c_str()) != tinyxml2::XML_SUCCESS)
    return Status::error(StatusCode::FileUnreadable, "cannot write " + path.string());
  return Status::success();
}

std::string hullName(std::size_t i) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "hull_%03zu", i);
  return buf;
}

std::string hullFile(std::size_t i, const char* ext) { return "hulls/" + hullName(i) + "." + ext; }

const Eigen::Matrix3d& inertiaOf(const SimulatorModel& m) { return m.mass.inertia; }

// ---------------------------------------------------------------- URDF
Status writeUrdf(const fs::path& path, const SimulatorModel& m) {
  XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  XMLElement* robot = doc.NewElement("robot");
  doc.InsertEndChild(robot);
  robot->SetAttribute("name", m.name.c_str());
  XMLElement* link = child(robot, "link");
  link->SetAttribute("name", m.name.c_str());
  XMLElement* inertial = child(link, "inertial");
  XMLElement* origin = child(inertial, "origin");
  origin->SetAttribute("xyz", triple(m.mass.centerOfMass).c_str());
  origin->SetAttribute("rpy", "0 0 0");
  child(inertial, "mass")->SetAttribute("value", number(m.mass.mass).c_str());
  XMLElement* inertia = child(inertial, "inertia");
  const Eigen::Matrix3d& I = inertiaOf(m);
  inertia->SetAttribute("ixx", number(I(0, 0)).c_str());
  inertia->SetAttribute("ixy", number(I(0, 1)).c_str());
  inertia->SetAttribute("ixz", number(I(0, 2)).c_str());
  inertia->SetAttribute("iyy", number(I(1, 1)).c_str());
  inertia->SetAttribute("iyz", number(I(1, 2)).c_str());
  inertia->SetAttribute("izz", number(I(2, 2)).c_str());
  XMLElement* visual = child(link, "visual");
  visual->SetAttribute("name", "visual");
  child(child(visual, "geometry"), "mesh")->SetAttribute("filename", "model.stl");
  for (std::size_t i = 0; i < m.hulls.size(); ++i) {
    XMLElement* collision = child(link, "collision");
    collision->SetAttribute("name", hullName(i).c_str());
    child(child(collision, "geometry"), "mesh")->SetAttribute("filename", hullFile(i, "stl").c_str());
  }
  return save(doc, path);
}

// ---------------------------------------------------------------- MJCF
Status writeMjcf(const fs::path& path, const SimulatorModel& m) {
  XMLDocument doc;
  XMLElement* mujoco = doc.NewElement("mujoco");
  doc.InsertEndChild(mujoco);
  mujoco->SetAttribute("model", m.name.c_str());
  XMLElement* compiler = child(mujoco, "compiler");
  compiler->SetAttribute("angle", "radian");
  compiler->SetAttribute("meshdir", ".");
  // Collision geoms in group 3, the visual in group 2 without contacts (MuJoCo's convention).
  XMLElement* defaults = child(mujoco, "default");
  XMLElement* visualClass = child(defaults, "default");
  visualClass->SetAttribute("class", "visual");
  XMLElement* vg = child(visualClass, "geom");
  vg->SetAttribute("contype", 0);
  vg->SetAttribute("conaffinity", 0);
  vg->SetAttribute("group", 2);
  XMLElement* collisionClass = child(defaults, "default");
  collisionClass->SetAttribute("class", "collision");
  child(collisionClass, "geom")->SetAttribute("group", 3);
  XMLElement* asset = child(mujoco, "asset");
  XMLElement* vm = child(asset, "mesh");
  vm->SetAttribute("name", "visual");
  vm->SetAttribute("file", "model.stl");
  for (std::size_t i = 0; i < m.hulls.size(); ++i) {
    XMLElement* mesh = child(asset, "mesh");
    mesh->SetAttribute("name", hullName(i).c_str());
    mesh->SetAttribute("file", hullFile(i, "stl").c_str());
  }
  XMLElement* body = child(child(mujoco, "worldbody"), "body");
  body->SetAttribute("name", m.name.c_str());
  child(body, "freejoint");
  XMLElement* inertial = child(body, "inertial");
  const Eigen::Matrix3d& I = inertiaOf(m);
  inertial->SetAttribute("pos", triple(m.mass.centerOfMass).c_str());
  inertial->SetAttribute("mass", number(m.mass.mass).c_str());
  inertial->SetAttribute("fullinertia", (number(I(0, 0)) + " " + number(I(1, 1)) + " " + number(I(2, 2)) + " " +
                                         number(I(0, 1)) + " " + number(I(0, 2)) + " " + number(I(1, 2)))
                                            .c_str());
  XMLElement* visual = child(body, "geom");
  visual->SetAttribute("name", "visual");
  visual->SetAttribute("class", "visual");
  visual->SetAttribute("type", "mesh");
  visual->SetAttribute("mesh", "visual");
  for (std::size_t i = 0; i < m.hulls.size(); ++i) {
    XMLElement* geom = child(body, "geom");
    geom->SetAttribute("name", hullName(i).c_str());
    geom->SetAttribute("class", "collision");
    geom->SetAttribute("type", "mesh");
    geom->SetAttribute("mesh", hullName(i).c_str());
  }
  return save(doc, path);
}

// ---------------------------------------------------------------- SDF
Status writeSdf(const fs::path& path, const SimulatorModel& m) {
  XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  XMLElement* sdf = doc.NewElement("sdf");
  doc.InsertEndChild(sdf);
  sdf->SetAttribute("version", "1.7");
  XMLElement* model = child(sdf, "model");
  model->SetAttribute("name", m.name.c_str());
  XMLElement* link = child(model, "link");
  link->SetAttribute("name", "body");
  XMLElement* inertial = child(link, "inertial");
  textChild(inertial, "pose", triple(m.mass.centerOfMass) + " 0 0 0");
  textChild(inertial, "mass", number(m.mass.mass));
  XMLElement* inertia = child(inertial, "inertia");
  const Eigen::Matrix3d& I = inertiaOf(m);
  textChild(inertia, "ixx", number(I(0, 0)));
  textChild(inertia, "ixy", number(I(0, 1)));
  textChild(inertia, "ixz", number(I(0, 2)));
  textChild(inertia, "iyy", number(I(1, 1)));
  textChild(inertia, "iyz", number(I(1, 2)));
  textChild(inertia, "izz", number(I(2, 2)));
  XMLElement* visual = child(link, "visual");
  visual->SetAttribute("name", "visual");
  textChild(child(child(visual, "geometry"), "mesh"), "uri", "model.stl");
  for (std::size_t i = 0; i < m.hulls.size(); ++i) {
    XMLElement* collision = child(link, "collision");
    collision->SetAttribute("name", hullName(i).c_str());
    textChild(child(child(collision, "geometry"), "mesh"), "uri", hullFile(i, "stl"));
  }
  return save(doc, path);
}

}  // namespace

bool parseSimFormat(const std::string& name, SimFormat& format) {
  std::string s = name;
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  static const std::pair<const char*, SimFormat> table[] = {{"obj", SimFormat::Obj},   {"stl", SimFormat::Stl},
                                                            {"glb", SimFormat::Glb},   {"gltf", SimFormat::Gltf},
                                                            {"urdf", SimFormat::Urdf}, {"mjcf", SimFormat::Mjcf},
                                                            {"sdf", SimFormat::Sdf}};
  for (const auto& [n, f] : table)
    if (s == n) return format = f, true;
  return false;
}

const char* toString(SimFormat format) {
  switch (format) {
    case SimFormat::Obj: return "obj";
    case SimFormat::Stl: return "stl";
    case SimFormat::Glb: return "glb";
    case SimFormat::Gltf: return "gltf";
    case SimFormat::Urdf: return "urdf";
    case SimFormat::Mjcf: return "mjcf";
    case SimFormat::Sdf: return "sdf";
  }
  return "?";
}

std::string simulatorName(const std::string& raw) {
  std::string s;
  for (unsigned char c : raw) s += (std::isalnum(c) || c == '_' || c == '-' || c == '.') ? static_cast<char>(c) : '_';
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) s = "model_" + s;
  return s;
}

Status writeSimulatorFiles(const std::string& dir, const SimulatorModel& model, const std::vector<SimFormat>& formats,
                           std::vector<std::string>* written) {
  auto wants = [&](SimFormat f) { return std::find(formats.begin(), formats.end(), f) != formats.end(); };
  const bool described = wants(SimFormat::Urdf) || wants(SimFormat::Mjcf) || wants(SimFormat::Sdf);
  const fs::path root(dir);
  std::vector<std::string> files;
  auto note = [&](const std::string& f) { files.push_back(f); };
  const bool perHullObj = wants(SimFormat::Obj), perHullStl = wants(SimFormat::Stl) || described;
  if (perHullObj || perHullStl) {
    std::error_code ec;
    fs::create_directories(root / "hulls", ec);
    if (ec) return Status::error(StatusCode::FileUnreadable, "cannot create " + (root / "hulls").string() + ": " + ec.message());
  }
  for (std::size_t i = 0; i < model.hulls.size(); ++i)
    for (const char* ext : {"obj", "stl"}) {
      if ((ext[0] == 'o' && !perHullObj) || (ext[0] == 's' && !perHullStl)) continue;
      const std::string rel = hullFile(i, ext);
      if (Status s = writeMesh((root / rel).string(), model.hulls[i]); !s.ok()) return s;
      note(rel);
    }
  if (described) {
    if (Status s = writeMesh((root / "model.stl").string(), model.visual); !s.ok()) return s;
    note("model.stl");
  }
  std::vector<std::string> names;
  for (std::size_t i = 0; i < model.hulls.size(); ++i) names.push_back(hullName(i));
  if (wants(SimFormat::Glb)) {
    if (Status s = writeGltf((root / "hulls.glb").string(), model.hulls, names, true); !s.ok()) return s;
    note("hulls.glb");
  }
  if (wants(SimFormat::Gltf)) {
    if (Status s = writeGltf((root / "hulls.gltf").string(), model.hulls, names, false, "hulls.bin"); !s.ok()) return s;
    note("hulls.gltf");
    note("hulls.bin");
  }
  if (wants(SimFormat::Urdf)) {
    if (Status s = writeUrdf(root / "model.urdf", model); !s.ok()) return s;
    note("model.urdf");
  }
  if (wants(SimFormat::Mjcf)) {
    if (Status s = writeMjcf(root / "model.xml", model); !s.ok()) return s;
    note("model.xml");
  }
  if (wants(SimFormat::Sdf)) {
    if (Status s = writeSdf(root / "model.sdf", model); !s.ok()) return s;
    note("model.sdf");
  }
  if (written) *written = std::move(files);
  return Status::success();
}

}  // namespace acd
