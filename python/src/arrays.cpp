#include "binding.hpp"

#include <climits>
#include <cstring>

namespace acdpy {

acd::TriMesh toMesh(const Vertices& vertices, const Faces& faces) {
  if (vertices.ndim() != 2 || vertices.shape(1) != 3 || faces.ndim() != 2 || faces.shape(1) != 3)
    throw py::value_error("vertices and faces must have shapes (n, 3) and (m, 3)");
  acd::TriMesh mesh;
  const auto nv = static_cast<std::size_t>(vertices.shape(0));
  const auto nf = static_cast<std::size_t>(faces.shape(0));
  mesh.vertices.resize(nv);
  const double* v = vertices.data();
  for (std::size_t i = 0; i < nv; ++i) mesh.vertices[i] = acd::Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
  mesh.faces.resize(nf);
  const std::int64_t* f = faces.data();
  for (std::size_t i = 0; i < nf; ++i)
    for (int k = 0; k < 3; ++k) {
      const std::int64_t index = f[3 * i + k];
      if (index < INT_MIN || index > INT_MAX)
        check(acd::Status::error(acd::StatusCode::IndexOutOfRange, "face " + std::to_string(i) + " refers to vertex " +
                                                                      std::to_string(index) + ", which does not exist"));
      mesh.faces[i][k] = static_cast<int>(index);
    }
  return mesh;
}

py::tuple toArrays(const acd::TriMesh& mesh) {
  const auto nv = static_cast<py::ssize_t>(mesh.vertices.size());
  const auto nf = static_cast<py::ssize_t>(mesh.faces.size());
  py::array_t<double> vertices({nv, py::ssize_t(3)});
  py::array_t<std::int64_t> faces({nf, py::ssize_t(3)});
  double* v = vertices.mutable_data();
  for (py::ssize_t i = 0; i < nv; ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = mesh.vertices[i][k];
  std::int64_t* f = faces.mutable_data();
  for (py::ssize_t i = 0; i < nf; ++i)
    for (int k = 0; k < 3; ++k) f[3 * i + k] = mesh.faces[i][k];
  return py::make_tuple(vertices, faces);
}

}  // namespace acdpy
