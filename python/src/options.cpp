// Option classes whose attributes are the command line's options: the keyword is the long option
// with '-' turned into '_', the default is the CLI's (both come from the library's structs). The
// Python functions take exactly these attributes as keyword arguments, so a new option of
// `acd decompose` or `acd evaluate` is one line here.
#include "binding.hpp"

#include <acd/evaluate.hpp>
#include <acd/surface_decompose.hpp>

#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <type_traits>

namespace acdpy {

namespace {

/// An attribute read and written through `field(options)`, a reference into the options.
template <class Options, class Field>
void plain(py::class_<Options>& c, const char* keyword, Field field) {
  using Value = std::decay_t<std::invoke_result_t<Field, Options&>>;
  c.def_property(
      keyword, [field](Options& o) { return Value(field(o)); }, [field](Options& o, Value v) { field(o) = v; });
}

/// --no-X: the negation of a library flag.
template <class Options, class Field>
void negated(py::class_<Options>& c, const char* keyword, Field field) {
  c.def_property(
      keyword, [field](Options& o) { return !field(o); }, [field](Options& o, bool v) { field(o) = !v; });
}

/// A length whose default depends on tau (negative in the library): None in Python.
template <class Options, class Field>
void tauDerived(py::class_<Options>& c, const char* keyword, Field field) {
  c.def_property(
      keyword,
      [field](Options& o) { return field(o) < 0 ? std::optional<double>() : std::optional<double>(field(o)); },
      [field](Options& o, std::optional<double> v) { field(o) = v ? *v : -1.0; });
}

/// The caps and mode of `acd decompose --exact`, reached through `settings(options)`.
template <class Options, class Settings>
void exactKeywords(py::class_<Options>& c, Settings settings) {
  plain(c, "surface", [settings](Options& o) -> bool& { return settings(o).surface; });
  plain(c, "exact_time_limit", [settings](Options& o) -> double& { return settings(o).timeLimitSeconds; });
  plain(c, "exact_memory", [settings](Options& o) -> double& { return settings(o).memoryGiB; });
  plain(c, "exact_tolerance", [settings](Options& o) -> double& { return settings(o).tolerance; });
}

}  // namespace

acd::Status validate(const ExactSettings& o) {
  if (!(o.timeLimitSeconds >= 0) || !(o.memoryGiB >= 0) || !std::isfinite(o.memoryGiB))
    return acd::Status::error(acd::StatusCode::InvalidParameter, "exact_time_limit and exact_memory must be >= 0");
  return acd::Status::success();
}

acd::Status validate(const SolidOptions& o) {
  if (o.post.tauAbs && o.tauGiven)
    return acd::Status::error(acd::StatusCode::InvalidParameter, "give either tau or tau_abs, not both");
  if (const acd::Status s = acd::validate(o.post); !s.ok()) return s;
  // The other modes check their own options (decompose_surface, decompose_exact).
  if (o.exact || o.exactSettings.surface) {
    if (o.post.tauAbs || o.post.maxHulls || o.post.maxHullVertices)
      return acd::Status::error(acd::StatusCode::InvalidParameter,
                                "tau_abs, max_hulls and max_hull_vertices apply to solid decomposition only "
                                "(not surface or exact)");
    if (o.perMesh)
      return acd::Status::error(acd::StatusCode::InvalidParameter,
                                "per_mesh applies to solid decomposition only (not surface or exact)");
    return acd::Status::success();
  }
  return o.post.tauAbs ? acd::Status::success() : acd::validate(o.decompose);
}

void bindOptions(py::module_& m) {
  py::class_<SolidOptions> solid(m, "DecomposeOptions", "Options of `acd decompose` (solid ACD and its post-passes)");
  solid.def(py::init<>());
  solid.def_property(  // -t, --tau
      "tau", [](const SolidOptions& o) { return o.decompose.tau; },
      [](SolidOptions& o, double v) { o.decompose.tau = v, o.tauGiven = true; });
  tauDerived(solid, "epsilon", [](SolidOptions& o) -> double& { return o.decompose.epsilon; });  // None: tau / 2
  tauDerived(solid, "delta", [](SolidOptions& o) -> double& { return o.decompose.delta; });      // None: tau / 20
  negated(solid, "no_grouping", [](SolidOptions& o) -> bool& { return o.decompose.featureGrouping; });
  negated(solid, "cut_every_region", [](SolidOptions& o) -> bool& { return o.decompose.cutAtNotchOnly; });
  negated(solid, "no_merge", [](SolidOptions& o) -> bool& { return o.decompose.merge; });
  negated(solid, "no_fill_holes", [](SolidOptions& o) -> bool& { return o.decompose.fillHoles; });
  negated(solid, "no_wrap", [](SolidOptions& o) -> bool& { return o.decompose.wrap; });
  negated(solid, "no_union", [](SolidOptions& o) -> bool& { return o.decompose.uniteShells; });
  negated(solid, "no_repair", [](SolidOptions& o) -> bool& { return o.decompose.repair; });
  negated(solid, "no_invariant", [](SolidOptions& o) -> bool& { return o.decompose.invariant; });
  solid.def_property(  // --merge-scope
      "merge_scope",
      [](const SolidOptions& o) { return std::string(o.decompose.mergeScope == acd::MergeScope::Model ? "model" : "component"); },
      [](SolidOptions& o, const std::string& v) {
        if (v != "model" && v != "component") throw py::value_error("merge_scope must be 'model' or 'component'");
        o.decompose.mergeScope = v == "model" ? acd::MergeScope::Model : acd::MergeScope::Component;
      });
  plain(solid, "working_share", [](SolidOptions& o) -> double& { return o.decompose.workingShare; });
  plain(solid, "working_from_faces", [](SolidOptions& o) -> int& { return o.decompose.workingFromFaces; });
  plain(solid, "threads", [](SolidOptions& o) -> int& { return o.decompose.threads; });  // 0: all cores
  // The post-passes (acd/post_passes.hpp); None: not given, as an option absent from the command line.
  plain(solid, "tau_abs", [](SolidOptions& o) -> std::optional<double>& { return o.post.tauAbs; });
  plain(solid, "max_hulls", [](SolidOptions& o) -> std::optional<int>& { return o.post.maxHulls; });
  plain(solid, "max_hull_vertices", [](SolidOptions& o) -> std::optional<int>& { return o.post.maxHullVertices; });
  plain(solid, "density", [](SolidOptions& o) -> double& { return o.post.density; });
  // Modes: --per-mesh, --surface (decompose_surface), --exact and its caps (decompose_exact).
  plain(solid, "per_mesh", [](SolidOptions& o) -> bool& { return o.perMesh; });
  plain(solid, "exact", [](SolidOptions& o) -> bool& { return o.exact; });
  exactKeywords(solid, [](SolidOptions& o) -> ExactSettings& { return o.exactSettings; });

  py::class_<ExactSettings> exact(m, "ExactOptions", "Options of `acd decompose --exact`");
  exact.def(py::init<>());
  exactKeywords(exact, [](ExactSettings& o) -> ExactSettings& { return o; });
  negated(exact, "no_fill_holes", [](ExactSettings& o) -> bool& { return o.fillHoles; });

  using Surface = acd::SurfaceDecomposeOptions;
  py::class_<Surface> surface(m, "SurfaceDecomposeOptions", "Options of `acd decompose --surface`");
  surface.def(py::init<>());
  plain(surface, "tau", [](Surface& o) -> double& { return o.tau; });
  tauDerived(surface, "epsilon", [](Surface& o) -> double& { return o.epsilon; });
  tauDerived(surface, "delta", [](Surface& o) -> double& { return o.delta; });
  negated(surface, "no_grouping", [](Surface& o) -> bool& { return o.featureGrouping; });
  negated(surface, "no_merge", [](Surface& o) -> bool& { return o.merge; });
  plain(surface, "threads", [](Surface& o) -> int& { return o.threads; });

  using Eval = acd::EvaluateOptions;
  py::class_<Eval> eval(m, "EvaluateOptions", "Options of `acd evaluate`");
  eval.def(py::init<>());
  eval.def_readwrite("samples", &Eval::volumeSamples);          // --samples
  eval.def_readwrite("surface_samples", &Eval::surfaceSamples); // --surface-samples
  eval.def_readwrite("seed", &Eval::seed);                      // --seed
  eval.def_readwrite("threads", &Eval::threads);                // --threads
}

}  // namespace acdpy
