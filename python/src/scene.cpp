// The meshes `acd decompose --per-mesh` decomposes one by one: every mesh placed in a scene file
// (glTF, GLB, COLLADA, 3MF, FBX), every object of an OBJ, or the one mesh of any other file.
#include "binding.hpp"
#include "model_reader.hpp"

#include <acd/io.hpp>
#include <acd/scene_io.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace acdpy {

namespace {

struct NamedMeshes {
  acd::Status status;
  std::vector<acd::TriMesh> meshes;
  std::vector<std::string> names;
};

/// Read as the command's runPerMesh reads them (apps/acd/main.cpp).
NamedMeshes readMeshes(const std::string& path) {
  NamedMeshes out;
  const std::string extension = std::filesystem::path(path).extension().string();
  if (acd::isSceneFormat(path)) {
    acd::SceneMeshes scene = acdpy::readSceneModel(path);
    out.status = scene.status;
    out.meshes = std::move(scene.meshes);
    out.names = std::move(scene.names);
  } else if (extension == ".obj" || extension == ".OBJ") {
    acd::ObjObjects objects = acd::readObjObjects(path);
    out.status = objects.status;
    out.meshes = std::move(objects.objects);
    out.names = std::move(objects.names);
  } else {
    acd::ReadResult r = acdpy::readModel(path);
    out.status = r.status;
    out.meshes.push_back(std::move(r.mesh));
    out.names.push_back(std::filesystem::path(path).stem().string());
  }
  return out;
}

/// [(name, (V, F))], in the order the command numbers its NNN_NAME folders.
py::list readSceneMeshes(const std::string& path) {
  NamedMeshes r;
  {
    py::gil_scoped_release free;
    r = readMeshes(path);
  }
  check(r.status);
  py::list out;
  for (std::size_t k = 0; k < r.meshes.size(); ++k) out.append(py::make_tuple(r.names[k], toArrays(r.meshes[k])));
  return out;
}

}  // namespace

void bindScene(py::module_& m) { m.def("read_scene_meshes", &readSceneMeshes, py::arg("path")); }

}  // namespace acdpy
