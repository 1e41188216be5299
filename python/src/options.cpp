// Option classes whose attributes are the command line's options: the keyword is the long option
// with '-' turned into '_', the default is the CLI's (both come from the library's structs). The
// Python functions take exactly these attributes as keyword arguments, so a new option of
// `acd decompose` or `acd evaluate` is one line here.
#include "binding.hpp"

#include <acd/decompose.hpp>
#include <acd/evaluate.hpp>
#include <acd/surface_decompose.hpp>

#include <pybind11/stl.h>

#include <optional>

namespace acdpy {

namespace {

/// --no-X: the negation of a library flag.
template <class Options>
void negated(py::class_<Options>& c, const char* keyword, bool Options::*member) {
  c.def_property(
      keyword, [member](const Options& o) { return !(o.*member); }, [member](Options& o, bool v) { o.*member = !v; });
}

/// A length whose default depends on tau (negative in the library): None in Python.
template <class Options>
void tauDerived(py::class_<Options>& c, const char* keyword, double Options::*member) {
  c.def_property(
      keyword,
      [member](const Options& o) { return o.*member < 0 ? std::optional<double>() : std::optional<double>(o.*member); },
      [member](Options& o, std::optional<double> v) { o.*member = v ? *v : -1.0; });
}

}  // namespace

void bindOptions(py::module_& m) {
  using Solid = acd::DecomposeOptions;
  py::class_<Solid> solid(m, "DecomposeOptions", "Options of `acd decompose` (solid ACD)");
  solid.def(py::init<>());
  solid.def_readwrite("tau", &Solid::tau);             // -t, --tau
  tauDerived(solid, "epsilon", &Solid::epsilon);       // --epsilon (None: tau / 2)
  tauDerived(solid, "delta", &Solid::delta);           // --delta (None: tau / 20)
  negated(solid, "no_grouping", &Solid::featureGrouping);
  negated(solid, "no_merge", &Solid::merge);
  negated(solid, "no_fill_holes", &Solid::fillHoles);
  negated(solid, "no_wrap", &Solid::wrap);
  negated(solid, "no_repair", &Solid::repair);
  solid.def_readwrite("threads", &Solid::threads);     // --threads (0: all cores)

  using Surface = acd::SurfaceDecomposeOptions;
  py::class_<Surface> surface(m, "SurfaceDecomposeOptions", "Options of `acd decompose --surface`");
  surface.def(py::init<>());
  surface.def_readwrite("tau", &Surface::tau);
  tauDerived(surface, "epsilon", &Surface::epsilon);
  tauDerived(surface, "delta", &Surface::delta);
  negated(surface, "no_grouping", &Surface::featureGrouping);
  negated(surface, "no_merge", &Surface::merge);
  surface.def_readwrite("threads", &Surface::threads);

  using Eval = acd::EvaluateOptions;
  py::class_<Eval> eval(m, "EvaluateOptions", "Options of `acd evaluate`");
  eval.def(py::init<>());
  eval.def_readwrite("samples", &Eval::volumeSamples);          // --samples
  eval.def_readwrite("surface_samples", &Eval::surfaceSamples); // --surface-samples
  eval.def_readwrite("seed", &Eval::seed);                      // --seed
  eval.def_readwrite("threads", &Eval::threads);                // --threads
}

}  // namespace acdpy
