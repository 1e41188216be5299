// What a simulator asks of a solid decomposition after it is made: tau given as a length in the
// input's units, a budget on the number of hulls (acd/algo/hull_budget.hpp), a vertex cap on every
// hull (acd/algo/hull_vertex_cap.hpp) and the mass properties of the model (acd/algo/mass_properties.hpp).
// `acd decompose --tau-abs --max-hulls --max-hull-vertices --density` and the Python keywords
// tau_abs, max_hulls, max_hull_vertices and density both run them from here, so that their
// results and report.json sections cannot differ.
#pragma once

#include <acd/decompose.hpp>
#include <acd/algo/mass_properties.hpp>
#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <optional>
#include <string>
#include <vector>

namespace acd {

/// Each pass runs only when its option is given (an empty optional is "not given", as an
/// option absent from the command line).
struct PostPassOptions {
  std::optional<double> tauAbs;        // tau as a length in the input's units, instead of tau
  std::optional<int> maxHulls;         // N >= 1: merge components until at most N remain
  std::optional<int> maxHullVertices;  // K >= 4: every hull replaced by a polytope of <= K corners
  double density = 1000.0;             // mass per input unit cubed (kg/m^3 for a model in metres)
};

/// InvalidParameter with the command line's wording for a value out of range.
Status validate(const PostPassOptions& options);

/// With tauAbs given, sets options.tau to that length in the normalised units of `mesh` (as
/// decompose() normalises it: the prepared pieces' minimum enclosing sphere). InvalidParameter
/// when the result lies outside [1e-4, 2]; Ok and options unchanged when the mesh cannot be
/// prepared (decompose() then says why).
Status resolveTauAbs(const TriMesh& mesh, const PostPassOptions& post, DecomposeOptions& options);

/// What the hull budget did (PostPassOptions::maxHulls).
struct HullBudgetSummary {
  int maxHulls = 0;
  int before = 0;  // components on entry
  int after = 0;
  int gluedMerges = 0;
  int joinedMerges = 0;
  double maxConcavity = 0.0;  // normalised units
  double tau = 0.0;
  bool exceedsTau = false;  // maxConcavity > tau
  double seconds = 0.0;
};

/// What the vertex cap did (PostPassOptions::maxHullVertices); volumes in normalised units.
struct HullVertexCapSummary {
  int maxHullVertices = 0;
  int hulls = 0;
  int withinCap = 0;
  int unchanged = 0;   // hulls already within the cap, kept as they were
  int mostVertices = 0;
  double uncappedHullVolume = 0.0;
  double addedVolume = 0.0;
};

/// Per component after the passes; a field is set only when its pass ran.
struct ComponentPostPass {
  std::vector<int> mergedFrom;                 // budget: the components on entry it holds
  std::optional<bool> hullGapMeasure;          // budget: its concavity is the hull gap, not measured
  std::optional<int> uncappedHullVertices;     // cap: the hull's vertices before
  std::optional<double> uncappedHullVolume;    // cap: normalised
  std::optional<double> addedVolume;           // cap: normalised, >= 0
};

struct PostPassResult {
  Status status;
  std::optional<double> tauAbs;          // as given
  std::optional<HullBudgetSummary> budget;
  std::optional<HullVertexCapSummary> cap;
  MassProperties mass;                   // of the components, input units, at options.density
  double density = 0.0;
  std::vector<ComponentPostPass> components;
};

/// After decompose(): the hull budget, then the vertex cap; `d`'s components (budget) and hulls
/// (cap) are replaced in place. The mass properties are always computed. A failed pass comes
/// back as status, its message starting with the option's name (--max-hulls: ...).
PostPassResult applyPostPasses(Decomposition& d, const PostPassOptions& options);

}  // namespace acd
