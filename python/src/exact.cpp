// acd.decompose_exact: the exact baselines of `acd decompose --exact [--surface]`, with the
// report.json the command writes (apps/acd/exact.cpp builds the same fields).
#include "binding.hpp"
#include "progress.hpp"

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/exact_decomposition.hpp>
#include <acd/hull.hpp>
#include <acd/io.hpp>
#include <acd/surface_exact.hpp>
#include <acd/version.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace acdpy {

namespace {

using json = nlohmann::json;

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

json inputJson(const acd::MeshDiagnosis& d, int notches) {
  return {{"vertices", d.vertices},
          {"faces", d.faces},
          {"edges", d.edges},
          {"boundary_edges", d.boundaryEdges},
          {"reflex_edges", notches},
          {"notch_fraction", notches >= 0 && d.edges > 0 ? double(notches) / d.edges : 0.0},
          {"genus", d.genus},
          {"volume", d.closed ? d.volume : 0.0}};
}

std::string solidReport(const std::string& model, const acd::TriMesh& mesh, const acd::ExactDecomposition& d,
                        const ExactSettings& settings) {
  const acd::MeshDiagnosis diagnosis = acd::diagnose(mesh);
  double volume = 0;
  json pieces = json::array();
  for (std::size_t i = 0; i < d.pieces.size(); ++i) {
    const double v = acd::signedVolume(d.pieces[i]);
    volume += v;
    pieces.push_back({{"id", i},
                      {"vertices", d.pieces[i].vertices.size()},
                      {"faces", d.pieces[i].faces.size()},
                      {"volume", v}});
  }
  const double inputVolume = diagnosis.volume;
  json j;
  j["model"] = model;
  j["version"] = ACD_VERSION;
  j["method"] = "solid ECD (CGAL convex_decomposition_3 on an exact Nef polyhedron)";
  j["parameters"] = {{"time_limit_seconds", settings.timeLimitSeconds}, {"memory_limit_gib", settings.memoryGiB}};
  j["input"] = inputJson(diagnosis, d.reflexEdges);
  j["input"]["holes_filled"] = d.holesFilled;
  j["input"]["repairs"] = d.repairs;
  j["pieces"] = pieces;
  const std::size_t bytes = acd::objObjectsText(d.pieces, objectNames("piece", d.pieces.size())).size();
  j["totals"] = {{"finished", d.finished},
                 {"components", d.pieceCount},
                 {"components_written", d.pieces.size()},
                 {"solids", d.solids},
                 {"unfinished_solids", d.unfinishedSolids},
                 {"volume", volume},
                 {"volume_relative_error",
                  d.finished && inputVolume > 0 ? std::abs(volume - inputVolume) / inputVolume : 0.0},
                 {"output_bytes", bytes},
                 {"note", d.note}};
  j["timing"] = {{"total_seconds", d.seconds}};
  return j.dump();
}

std::string surfaceReport(const std::string& model, const acd::TriMesh& mesh, const acd::SurfaceExactDecomposition& d,
                          const std::vector<acd::TriMesh>& patches, const ExactSettings& settings) {
  const acd::MeshDiagnosis diagnosis = acd::diagnose(mesh);
  json list = json::array();
  std::size_t largest = 0, singles = 0;
  double area = 0;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    const double a = acd::surfaceArea(patches[i]);
    area += a;
    largest = std::max(largest, d.patches[i].size());
    singles += d.patches[i].size() == 1;
    list.push_back({{"id", i}, {"faces", d.patches[i].size()}, {"vertices", patches[i].vertices.size()}, {"area", a}});
  }
  json j;
  j["model"] = model;
  j["version"] = ACD_VERSION;
  j["method"] = "surface ECD (flood-and-retract convex patches)";
  j["parameters"] = {{"tolerance", settings.tolerance}, {"units", "normalised: minimum enclosing sphere radius 1"}};
  j["input"] = inputJson(diagnosis, diagnosis.closed ? acd::countNotches(mesh) : -1);
  j["patches"] = list;
  j["totals"] = {{"finished", true},
                 {"components", d.patches.size()},
                 {"single_face_patches", singles},
                 {"largest_patch_faces", largest},
                 {"area", area},
                 {"input_area", diagnosis.area},
                 {"output_bytes", acd::objObjectsText(patches, objectNames("patch", patches.size())).size()}};
  j["timing"] = {{"total_seconds", d.seconds}};
  return j.dump();
}

/// (pieces [(V, F)], report.json text), for settings that passed validate(). The library runs
/// CGAL in a forked worker that only runs C++ (never Python), so forking from the interpreter is
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
    d = acd::exactSolidDecomposition(mesh, options);
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
