// acd.decompose_exact: the exact baselines of `acd decompose --exact [--surface]`, with the
// report.json the command writes (both from acd/report.hpp).
#include "binding.hpp"
#include "progress.hpp"

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/exact_decomposition.hpp>
#include <acd/algo/hull.hpp>
#include <acd/io.hpp>
#include <acd/report.hpp>
#include <acd/surface_exact.hpp>
#include <sandbox/exact_solid.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace acdpy {

namespace {

/// Object names of the command's pieces.obj / patches.obj: the report's output_bytes is that file's size.
std::vector<std::string> objectNames(const char* prefix, std::size_t count) {
  std::vector<std::string> names;
  char name[32];
  for (std::size_t i = 0; i < count; ++i) {
    std::snprintf(name, sizeof name, "%s_%05zu", prefix, i);
    names.emplace_back(name);
  }
  return names;
}

std::string solidReport(const std::string& model, const acd::TriMesh& mesh, const acd::ExactDecomposition& d,
                        const ExactSettings& settings) {
  const std::size_t bytes = acd::objObjectsText(d.pieces, objectNames("piece", d.pieces.size())).size();
  return acd::reportJson(model, acd::diagnose(mesh), d, settings.timeLimitSeconds, settings.memoryGiB, bytes);
}

std::string surfaceReport(const std::string& model, const acd::TriMesh& mesh, const acd::SurfaceExactDecomposition& d,
                          const std::vector<acd::TriMesh>& patches, const ExactSettings& settings) {
  const std::size_t bytes = acd::objObjectsText(patches, objectNames("patch", patches.size())).size();
  return acd::reportJson(model, mesh, acd::diagnose(mesh), d, patches, settings.tolerance, bytes);
}

/// (pieces [(V, F)], report.json text), for settings that passed validate(). The sandbox runs
/// CGAL in a forked child that only runs C++ (never Python), so forking from the interpreter is
/// safe; the GIL is released meanwhile and `progress(stage, seconds)` is called about once a second.
py::tuple decomposeExact(const Vertices& vertices, const Faces& faces, const ExactSettings& settings,
                         const std::string& model, py::object progress) {
  const acd::TriMesh mesh = toMesh(vertices, faces);
  ProgressRelay relay(std::move(progress));
  acd::ExactOptions options;
  options.timeLimitSeconds = settings.timeLimitSeconds;
  options.memoryLimitBytes = static_cast<std::size_t>(settings.memoryGiB * double(std::size_t(1) << 30));
  options.fillHoles = settings.fillHoles;
  options.progress = relay.function<const std::string&, double>();
  acd::ExactDecomposition d;
  std::string report;
  {
    py::gil_scoped_release free;
    d = acdsandbox::exactSolidDecomposition(mesh, options);
    if (d.status.ok()) report = solidReport(model, mesh, d, settings);
  }
  relay.raiseIfFailed();
  check(d.status);
  py::list pieces;
  for (const auto& piece : d.pieces) pieces.append(toArrays(piece));
  return py::make_tuple(pieces, report);
}

/// (patches [(V, F)], hulls [(V, F)], empty arrays for a flat patch), report.json text, each
/// patch's faces of the input [int64 array]).
py::tuple decomposeExactSurface(const Vertices& vertices, const Faces& faces, const ExactSettings& settings,
                                const std::string& model) {
  const acd::TriMesh mesh = toMesh(vertices, faces);
  acd::SurfaceExactOptions options;
  options.tolerance = settings.tolerance;
  acd::SurfaceExactDecomposition d;
  std::vector<acd::TriMesh> patches, hulls;
  std::string report;
  {
    py::gil_scoped_release free;
    d = acd::exactSurfaceDecomposition(mesh, options);
    if (d.status.ok()) {
      for (const auto& patch : d.patches) {
        patches.push_back(acd::patchMesh(mesh, patch));
        hulls.push_back(acd::hullMesh(patches.back().vertices));
      }
      report = surfaceReport(model, mesh, d, patches, settings);
    }
  }
  check(d.status);
  py::list patchList, hullList, patchFaces;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    patchList.append(toArrays(patches[i]));
    hullList.append(toArrays(hulls[i]));
    const std::vector<std::int64_t> indices(d.patches[i].begin(), d.patches[i].end());
    patchFaces.append(py::array_t<std::int64_t>(static_cast<py::ssize_t>(indices.size()), indices.data()));
  }
  return py::make_tuple(patchList, hullList, report, patchFaces);
}

}  // namespace

void bindExact(py::module_& m) {
  m.def("validate", [](const ExactSettings& o) { check(validate(o)); }, py::arg("options"));
  m.def("decompose_exact", &decomposeExact, py::arg("vertices"), py::arg("faces"), py::arg("options"),
        py::arg("model"), py::arg("progress"));
  m.def("decompose_exact_surface", &decomposeExactSurface, py::arg("vertices"), py::arg("faces"),
        py::arg("options"), py::arg("model"));
}

}  // namespace acdpy
