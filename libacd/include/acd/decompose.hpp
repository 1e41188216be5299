// Solid approximate convex decomposition (Lien & Amato 2007, Algorithm 1).
#pragma once

#include <acd/mesh.hpp>
#include <acd/algo/normalize.hpp>
#include <acd/status.hpp>
#include <acd/algo/wrap_report.hpp>

#include <functional>
#include <string>
#include <vector>

namespace acd {

/// What the merge pass must keep when it glues two neighbours back together.
enum class MergeScope {
  /// The union's own concavity within tau (the paper's promise for every component), its hull within
  /// tau of it and at most 3 % of its volume beyond the two hulls it replaces.
  Component,
  /// The union's hull within tau of the model, and at most 25 % of the union's volume added outside
  /// the model and the two hulls: a component may be more concave than tau where its pockets are
  /// filled by other components. Touching pieces that do not glue into one solid may share one
  /// hull too: a component may then have several shells. Fewer parts for the same hulls-to-model fidelity.
  Model,
};

struct DecomposeOptions {
  double tau = 0.05;             // concavity tolerance, normalised units (min enclosing sphere radius 1)
  double epsilon = -1.0;         // bridge clustering tolerance; < 0 means tau / 2
  double delta = -1.0;           // Douglas-Peucker knot tolerance; < 0 means tau / 20
  bool featureGrouping = true;   // false: bisect the notch's dihedral angle (Section 3.2)
  /// Cut only the section region at the notch (docs/ALGORITHM.md section 10). false: every region
  /// the plane meets, so that each piece lies on one side of every plane that cut its ancestors.
  bool cutAtNotchOnly = true;
  bool merge = true;             // glue neighbours back while their union stays within tau
  MergeScope mergeScope = MergeScope::Model;  // what "within tau" means for a union (above)
  bool fillHoles = true;         // close an open mesh's holes first (false: refuse open meshes)
  bool repair = true;            // repairs, shells and the wrap (acd/robust.hpp); false: strict checks only
  bool wrap = true;              // with repair: wrap what cannot be made a clean solid (false: refuse it)
  /// With repair: shells that pass through, touch or lie in another are also decomposed as the solid
  /// they bound together, their union (acd/algo/shell_union.hpp), and the route with fewer hulls is
  /// kept (docs/ALGORITHM.md). false: each shell on its own only, which is faster where shells meet.
  bool uniteShells = true;
  /// Decompose in a frame computed from the shape (acd/algo/canonical_frame.hpp): the same parts for any
  /// rotation, translation or order of faces. Input vertices come back exactly; the cuts are computed
  /// on coordinates rounded to the frame's grid (2.4e-7 of the model's radius), so a cut face through
  /// input vertices and points a cut made is planar to within that.
  bool invariant = true;
  /// Detail far below tau cannot change the parts: a solid of at least `workingFromFaces` faces is
  /// first simplified to a working mesh that stands at most this share of tau off it
  /// (acd/algo/working_mesh.hpp), the recursion runs on that at tau less the share, and each hull
  /// is built from the working piece and the input vertices it stands for, and unions of the merge
  /// pass and the hulls' distance to the model are held to tau against the input
  /// (docs/ALGORITHM.md, "The working mesh"): a dense scan's cost follows tau, not its face count.
  /// 0: always the input's own triangles. A piece whose working mesh would pass through itself is
  /// simplified within less, or not at all.
  double workingShare = 0.1;
  /// With a working share, the working mesh is made for solids of at least this many faces. Below, the input's own
  /// triangles cost about as little (the two cross between 8k and 16k faces on the meshes timed in
  /// docs/ALGORITHM.md) and give fewer parts: the working mesh decomposes at tau less its share.
  int workingFromFaces = 20000;
  int threads = 0;               // 0: all cores. The output never depends on it.
  int maxComponents = 10000;     // safety net against runaway recursion
  int maxDepth = 64;
  /// Called from the calling thread after each round: components done, components pending.
  std::function<void(int done, int pending)> progress;
};

/// The defaults above are what the `acd` command and the Python module decompose with: the
/// shape's own frame (invariant) and the merge held to the model (MergeScope::Model), for the
/// same parts in every pose and fewer parts at the same fidelity. Programs that need the
/// paper's promise for every component, or the input's coordinates bit for bit, ask for them
/// (mergeScope = MergeScope::Component, invariant = false), as the planner, tetmesh and
/// pointloc do. recommendedOptions() returns the defaults (kept for callers that used it).
DecomposeOptions recommendedOptions();

/// Parameters after defaults are applied; `validate` rejects nonsense with a message.
DecomposeOptions resolvedOptions(const DecomposeOptions& options);
Status validate(const DecomposeOptions& options);

struct Component {
  TriMesh mesh;            // closed, outward; input coordinates. With MergeScope::Model it may have
                           // several shells (touching pieces that do not glue into one solid)
  TriMesh hull;            // its convex hull; input coordinates
  double volume = 0.0;     // normalised units
  double hullVolume = 0.0; // normalised units
  double concavity = 0.0;  // normalised units, by the library's measure
  double hullExcess = 0.0; // how far its hull stands off it (or, merged with MergeScope::Model, off the model)
  int depth = 0;           // cuts from the input to this component
  int source = 0;          // which connected piece of the input it came from
  bool unresolved = false; // concavity > tau but no cut could be made (reported, never hidden)
  std::string note;        // why it is unresolved
  bool ofWrap = false;     // a piece of the watertight wrap, not of the input (acd/robust.hpp)
};

struct PhaseTimes {
  double prepare = 0.0, concavity = 0.0, grouping = 0.0, cutting = 0.0, merging = 0.0, hulls = 0.0, total = 0.0;  // seconds
  // concavity/grouping/cutting are summed over the pieces (a piece's parallel parts by their wall
  // time); prepare, hulls, total are wall.
};

/// Sums the phases (a piece's work into its decomposition, a shell's into the model's); `total`,
/// the wall time of the whole call, is not summed.
PhaseTimes& operator+=(PhaseTimes& into, const PhaseTimes& t);

struct DecomposeStats {
  int cuts = 0;               // successful plane cuts
  int fallbackCuts = 0;       // cuts where the feature plane failed and the bisector was used
  int failedCuts = 0;         // planes rejected (could not cut cleanly or did not split)
  int bridges = 0;            // bridges measured over all rounds
  int refinements = 0;        // bridge patches split to keep Observation 4.1
  int merges = 0;             // neighbours glued back by the merge pass
  int inputEdges = 0;
  int inputNotches = 0;       // concave edges of the input
  int holesFilled = 0;        // boundary loops closed before decomposing an open mesh
  int workingFaces = 0;       // faces of the working meshes decomposed (inputEdges * 2 / 3 without one)
  double workingDistance = 0.0;  // normalised units: how far the working meshes stand off the input (measured)
  double inputVolume = 0.0;   // normalised units
};

/// The one sum of statistics: every count and the input's volume. `holesFilled` is the
/// preparation's, set once, not summed.
DecomposeStats& operator+=(DecomposeStats& into, const DecomposeStats& s);

struct Decomposition {
  Status status;
  std::vector<Component> components;
  Normalization normalization;
  std::vector<std::string> repairs;   // what the repairs and prepareSolid changed
  WrapReport wrap;                    // whether (part of) the input was decomposed through its wrap
  double repairSeconds = 0.0;         // repairs, hole filling and shell nesting (wall)
  DecomposeStats stats;
  PhaseTimes times;
  DecomposeOptions options;           // as resolved
};

/// Decomposes a mesh: with options.repair (the default) any mesh, through the repairs and the
/// wrap of acd/robust.hpp; without, a closed mesh (several closed pieces are decomposed separately).
/// Invalid input or parameters come back in `status`; nothing throws.
Decomposition decompose(const TriMesh& mesh, const DecomposeOptions& options = {});

/// Number of concave (reflex) edges of a closed mesh: dihedral turn below -angle radians.
int countNotches(const TriMesh& mesh, double angle = 1e-6);

}  // namespace acd
