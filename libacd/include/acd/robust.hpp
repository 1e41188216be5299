// Any mesh people bring, decomposed: repairs (acd/repair.hpp), hole filling, several shells
// (acd/algo/shells.hpp) and, as the last resort, the watertight wrap (acd/algo/alpha_wrap.hpp). This is
// what acd::decompose does when DecomposeOptions::repair is on (the default).
#pragma once

#include <acd/algo/alpha_wrap.hpp>
#include <acd/decompose.hpp>
#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>
#include <vector>

namespace acd {

/// The input made into closed shells ready for the solid decomposition.
struct PreparedModel {
  Status status;                      // not ok: refused (only with options.wrap off, or unusable data)
  std::vector<TriMesh> shells;        // closed, outward, apart; input coordinates
  std::vector<char> isWrap;           // per shell: it is (part of) the wrap
  std::vector<char> isClean;          // per shell: prepareSolid's own output (no union, no wrap)
  std::vector<TriMesh> wrappedInput;  // the repaired pieces the wrap replaced (for its fidelity)
  std::vector<std::string> repairs;   // one line each, in the order done
  int holesFilled = 0;
  int cavitiesDropped = 0;
  int overlappingShells = 0;
  int unitedShells = 0;               // shells that went into a union (acd/algo/shell_union.hpp)
  WrapReport wrap;                    // hausdorff is filled in by decomposeRepaired
  std::string wrapReason;             // with buildWrap off: why the wrap would be used
  double seconds = 0.0;
};

/// Repairs the mesh, closes holes (options.fillHoles), classifies shells, drops cavities (a shell
/// at odd nesting depth: the hulls of the shell around it cover it), unites the shells that pass
/// through, touch or lie in another (options.uniteShells; acd/algo/shell_union.hpp) and wraps the pieces that
/// still are not clean solids (options.wrap; otherwise refuses them as prepareSolid does). Wrap
/// parameters follow options.tau (wrapParametersFor). With `buildWrap` off only the reason is
/// given (acd info), and the status is ok when the wrap would make the solid. Never throws.
PreparedModel prepareModel(const TriMesh& mesh, const DecomposeOptions& options, bool buildWrap = true);

/// prepareModel (which unites the shells that meet, unless options.uniteShells is off), then each
/// remaining shell decomposed on its own at tau in the model's normalised units (where shells were
/// united, the shells apart too, and the route with fewer hulls kept); then, when options.wrap is on,
/// every shell left with a component above tau (a surface passing through itself, typically) is
/// replaced by its wrap and decomposed again. Volumes and concavities are in the model's units;
/// Component::source is the shell.
Decomposition decomposeRepaired(const TriMesh& mesh, const DecomposeOptions& options);

}  // namespace acd
