// Shared pieces of the Python extension acd._core: numpy <-> TriMesh, and library Status -> acd.Error.
#pragma once

#include <acd/decompose.hpp>
#include <acd/mesh.hpp>
#include <acd/post_passes.hpp>
#include <acd/status.hpp>
#include <acd/surface_exact.hpp>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <exception>
#include <string>

namespace acdpy {

namespace py = pybind11;

using Vertices = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Faces = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

/// A failed acd::Status on its way to Python, where it becomes acd.Error (a ValueError).
struct StatusError : std::exception {
  acd::Status status;
  explicit StatusError(acd::Status s) : status(std::move(s)) {}
  const char* what() const noexcept override { return status.message.c_str(); }
};

inline void check(const acd::Status& s) {
  if (!s.ok()) throw StatusError(s);
}

/// The keywords of `acd decompose --exact [--surface]`, with the command's defaults (a longer
/// time limit than the library's).
struct ExactSettings {
  bool surface = false;                                    // --surface: convex surface patches
  double timeLimitSeconds = 600.0;                         // --exact-time-limit, 0: none
  double memoryGiB = 8.0;                                  // --exact-memory, 0: none
  double tolerance = acd::SurfaceExactOptions{}.tolerance;  // --exact-tolerance
  bool fillHoles = true;                                   // off with --no-fill-holes
};

/// The checks `acd decompose --exact` makes before reading the model.
acd::Status validate(const ExactSettings& settings);

/// acd.decompose's keywords: the options of the decomposition and of the post-passes that follow
/// it, as `acd decompose` has both, and the modes the command switches to (the Python layer
/// routes them: surface to decompose_surface, exact to decompose_exact, per_mesh mesh by mesh).
struct SolidOptions {
  acd::DecomposeOptions decompose = acd::recommendedOptions();  // as `acd decompose`
  acd::PostPassOptions post;
  bool tauGiven = false;  // tau and tau_abs together are refused, as -t and --tau-abs are
  bool exact = false;
  bool perMesh = false;
  ExactSettings exactSettings;  // surface, exact_time_limit, exact_memory, exact_tolerance
};

/// The checks `acd decompose` makes before reading the model (tau itself waits for tau_abs).
acd::Status validate(const SolidOptions& options);

/// (n,3) float64 and (m,3) int64 arrays (the Python layer checks shapes and dtypes first) to a mesh.
/// An index that does not fit an int raises IndexOutOfRange; other bad indices are the library's to report.
acd::TriMesh toMesh(const Vertices& vertices, const Faces& faces);

/// (vertices (n,3) float64, faces (m,3) int64), the layout trimesh and numpy code expect.
py::tuple toArrays(const acd::TriMesh& mesh);

void bindErrors(py::module_& m);   // acd._core.Error, acd._core.StatusCode
void bindOptions(py::module_& m);  // option classes with the CLI's keywords and defaults
void bindExact(py::module_& m);    // decompose_exact, decompose_exact_surface (exact.cpp)
void bindScene(py::module_& m);    // read_scene_meshes: the meshes --per-mesh decomposes (scene.cpp)

}  // namespace acdpy
