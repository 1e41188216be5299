// acd._core: libacd for Python. The pure-Python package acd (python/acd/) checks arguments and
// shapes results; this file only moves arrays in and out and runs the library without the GIL.
#include "binding.hpp"
#include "model_reader.hpp"
#include "progress.hpp"

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/evaluate.hpp>
#include <acd/io.hpp>
#include <acd/report.hpp>
#include <acd/simulator_export.hpp>
#include <acd/surface_decompose.hpp>
#include <acd/version.hpp>

#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace acdpy {

namespace {

py::list arraysOf(const std::vector<acd::TriMesh>& meshes) {
  py::list out;
  for (const auto& mesh : meshes) out.append(toArrays(mesh));
  return out;
}

acd::TriMesh meshOf(const py::handle& pair) {
  const auto t = pair.cast<py::tuple>();
  return toMesh(t[0].cast<Vertices>(), t[1].cast<Faces>());
}

py::tuple readMesh(const std::string& path) {
  acd::ReadResult r;
  {
    py::gil_scoped_release free;
    r = acdpy::readModel(path);
  }
  check(r.status);
  return toArrays(r.mesh);
}

void writeMesh(const std::string& path, const Vertices& vertices, const Faces& faces) {
  const acd::TriMesh mesh = toMesh(vertices, faces);
  py::gil_scoped_release free;
  check(acd::writeMesh(path, mesh));
}

py::list readObjObjects(const std::string& path) {
  acd::ObjObjects r;
  {
    py::gil_scoped_release free;
    r = acd::readObjObjects(path);
  }
  check(r.status);
  return arraysOf(r.objects);
}

/// (components [(V, F)], hulls [(V, F)], report.json text): the decomposition and its
/// post-passes, as `acd decompose` runs them. `sceneMesh` names the mesh of a scene decomposed on
/// its own (report["mesh"], as with --per-mesh); empty for a whole model.
py::tuple decompose(const Vertices& vertices, const Faces& faces, const SolidOptions& settings,
                    const std::string& model, const std::string& sceneMesh, py::object progress) {
  const acd::TriMesh mesh = toMesh(vertices, faces);
  ProgressRelay relay(std::move(progress));
  acd::DecomposeOptions options = settings.decompose;
  options.progress = relay.function<int, int>();
  acd::Status parameters;
  acd::Decomposition d;
  acd::PostPassResult post;
  std::string report;
  {
    py::gil_scoped_release free;
    parameters = acd::resolveTauAbs(mesh, settings.post, options);  // tau from tau_abs, then checked
    if (parameters.ok()) parameters = acd::validate(options);
    if (parameters.ok()) d = acd::decompose(mesh, options);
    if (parameters.ok() && d.status.ok()) post = acd::applyPostPasses(d, settings.post);
    if (parameters.ok() && d.status.ok() && post.status.ok()) {
      acd::ReportInput input = acd::describeInput(model, mesh, options.threads);
      input.mesh = sceneMesh;
      input.inputOutside = acd::inputOutsideHulls(mesh, d).max;
      input.hullOffInput =
          acd::hullsOffInput(mesh, d, !settings.post.maxHulls && !settings.post.maxHullVertices).excess;
      report = acd::reportJson(input, d, post);
    }
  }
  relay.raiseIfFailed();
  check(parameters);
  check(d.status);
  check(post.status);
  py::list components, hulls;
  for (const auto& c : d.components) {
    components.append(toArrays(c.mesh));
    hulls.append(toArrays(c.hull));
  }
  return py::make_tuple(components, hulls, report);
}

/// `acd decompose --format`: the files a simulator loads, written into `folder` (which exists);
/// their paths relative to it. The mass properties are the components' at `density`.
std::vector<std::string> writeSimulatorFiles(const std::string& folder, const std::string& name,
                                             const py::tuple& visual, const py::list& hullPairs,
                                             const py::list& componentPairs, double density,
                                             const std::vector<std::string>& formatNames) {
  std::vector<acd::SimFormat> formats;
  for (const std::string& f : formatNames) {
    acd::SimFormat format;
    if (!acd::parseSimFormat(f, format))
      check(acd::Status::error(acd::StatusCode::InvalidParameter,
                               "unknown format '" + f + "' (expected obj, stl, glb, gltf, urdf, mjcf or sdf)"));
    if (std::find(formats.begin(), formats.end(), format) == formats.end()) formats.push_back(format);
  }
  if (!(density > 0) || !std::isfinite(density))
    check(acd::Status::error(acd::StatusCode::InvalidParameter, "density must be positive"));
  acd::SimulatorModel model;
  model.name = acd::simulatorName(name);
  model.visual = meshOf(visual);
  for (const auto& pair : hullPairs) model.hulls.push_back(meshOf(pair));
  std::vector<acd::TriMesh> components;
  for (const auto& pair : componentPairs) components.push_back(meshOf(pair));
  std::vector<std::string> written;
  py::gil_scoped_release free;
  model.mass = acd::massProperties(components, density);
  check(acd::writeSimulatorFiles(folder, model, formats, &written));
  return written;
}

/// (patches [(V, F)], hulls [(V, F)] with empty arrays for flat patches, report.json text,
///  the repaired surface (V, F), each patch's faces of it [int64 array])
py::tuple decomposeSurface(const Vertices& vertices, const Faces& faces, acd::SurfaceDecomposeOptions options,
                           const std::string& model, py::object progress) {
  const acd::TriMesh mesh = toMesh(vertices, faces);
  ProgressRelay relay(std::move(progress));
  options.progress = relay.function<int, int>();
  acd::SurfaceDecomposition d;
  std::string report;
  {
    py::gil_scoped_release free;
    d = acd::decomposeSurface(mesh, options);
    if (d.status.ok()) {
      // output_bytes: the size patches.obj has when `acd decompose --surface` writes it.
      std::vector<acd::TriMesh> patches;
      std::vector<std::string> names;
      char name[32];
      for (std::size_t i = 0; i < d.patches.size(); ++i) {
        std::snprintf(name, sizeof name, "patch_%05zu", i);
        patches.push_back(d.patches[i].mesh);
        names.emplace_back(name);
      }
      report = acd::reportJson(acd::describeInput(model, mesh, options.threads), d, acd::objObjectsText(patches, names).size());
    }
  }
  relay.raiseIfFailed();
  check(d.status);
  py::list patches, hulls, patchFaces;
  for (const auto& p : d.patches) {
    patches.append(toArrays(p.mesh));
    hulls.append(toArrays(p.hull));
    patchFaces.append(py::array_t<std::int64_t>(static_cast<py::ssize_t>(p.faces.size()),
                                                std::vector<std::int64_t>(p.faces.begin(), p.faces.end()).data()));
  }
  return py::make_tuple(patches, hulls, report, toArrays(d.surface), patchFaces);
}

/// `acd evaluate --json` text.
std::string evaluate(const Vertices& vertices, const Faces& faces, const py::list& hullPairs,
                     const acd::EvaluateOptions& options, const std::string& model, const std::string& hullsFile) {
  const acd::TriMesh mesh = toMesh(vertices, faces);
  std::vector<acd::TriMesh> hulls;
  for (const auto& pair : hullPairs) hulls.push_back(meshOf(pair));
  py::gil_scoped_release free;
  const acd::Evaluation e = acd::evaluateModel(mesh, hulls, options);
  check(e.status);
  return acd::evaluationJson(model, hullsFile, e);
}

/// What `acd info` prints, as a dict.
py::dict diagnose(const Vertices& vertices, const Faces& faces) {
  const acd::TriMesh mesh = toMesh(vertices, faces);
  acd::MeshDiagnosis d;
  std::optional<int> selfIntersections;
  acd::PreparedSolid prepared;
  {
    py::gil_scoped_release free;
    d = acd::diagnose(mesh);
    if (d.closed && d.nonManifoldEdges == 0 && d.indexOutOfRange == 0 && d.nonFiniteVertices == 0) {
      const int pairs = acd::countSelfIntersections(mesh);
      if (pairs >= 0) selfIntersections = pairs;
    }
    acd::PrepareOptions fill;  // as `acd decompose` does: holes are closed first
    fill.openMeshes = acd::OpenMeshPolicy::FillHoles;
    prepared = acd::prepareSolid(mesh, fill);
  }
  py::dict out;
  out["vertices"] = d.vertices;
  out["faces"] = d.faces;
  out["edges"] = d.edges;
  out["boundary_edges"] = d.boundaryEdges;
  out["non_manifold_edges"] = d.nonManifoldEdges;
  out["non_manifold_vertices"] = d.nonManifoldVertices;
  out["components"] = d.components;
  out["degenerate_faces"] = d.degenerateFaces;
  out["duplicate_faces"] = d.duplicateFaces;
  out["duplicate_vertices"] = d.duplicateVertices;
  out["unreferenced_vertices"] = d.unreferencedVertices;
  out["non_finite_vertices"] = d.nonFiniteVertices;
  out["index_out_of_range"] = d.indexOutOfRange;
  out["orientation_consistent"] = d.orientationConsistent;
  out["closed"] = d.closed;
  out["genus"] = d.genus >= 0 ? py::object(py::int_(d.genus)) : py::object(py::none());
  out["volume"] = d.volume;
  out["area"] = d.area;
  out["bbox"] = py::make_tuple(py::make_tuple(d.bbox.lo.x(), d.bbox.lo.y(), d.bbox.lo.z()),
                               py::make_tuple(d.bbox.hi.x(), d.bbox.hi.y(), d.bbox.hi.z()));
  out["first_problem"] = d.firstProblem.empty() ? py::object(py::none()) : py::object(py::str(d.firstProblem));
  out["self_intersections"] = selfIntersections;
  out["solid_decomposition"] = prepared.status.ok();
  out["solid_problem"] = prepared.status.ok() ? py::object(py::none()) : py::object(py::str(prepared.status.message));
  out["repairs"] = prepared.repairs;
  return out;
}

}  // namespace

}  // namespace acdpy

PYBIND11_MODULE(_core, m) {
  using namespace acdpy;
  m.doc() = "libacd, the approximate convex decomposition library, for the Python package acd";
  m.attr("__version__") = ACD_VERSION;
  bindErrors(m);
  bindOptions(m);
  bindExact(m);
  bindScene(m);
  // Parameters are checked before the model is read, as the command does.
  m.def("validate", [](const SolidOptions& o) { check(validate(o)); }, py::arg("options"));
  m.def("validate", [](const acd::SurfaceDecomposeOptions& o) { check(acd::validate(o)); }, py::arg("options"));
  m.def("read_mesh", &readMesh, py::arg("path"));
  m.def("write_mesh", &writeMesh, py::arg("path"), py::arg("vertices"), py::arg("faces"));
  m.def("read_obj_objects", &readObjObjects, py::arg("path"));
  m.def("decompose", &decompose, py::arg("vertices"), py::arg("faces"), py::arg("options"), py::arg("model"),
        py::arg("scene_mesh"), py::arg("progress"));
  m.def("write_simulator_files", &writeSimulatorFiles, py::arg("folder"), py::arg("name"), py::arg("visual"),
        py::arg("hulls"), py::arg("components"), py::arg("density"), py::arg("formats"));
  m.def("decompose_surface", &decomposeSurface, py::arg("vertices"), py::arg("faces"), py::arg("options"),
        py::arg("model"), py::arg("progress"));
  m.def("evaluate", &evaluate, py::arg("vertices"), py::arg("faces"), py::arg("hulls"), py::arg("options"),
        py::arg("model"), py::arg("hulls_file"));
  m.def("diagnose", &diagnose, py::arg("vertices"), py::arg("faces"));
}
