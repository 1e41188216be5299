// The exact solid decomposition (acd::baselines, <acd/exact_decomposition.hpp>) under a time and
// a memory cap: CGAL's call cannot be interrupted, so it runs in a capped child process that
// streams its stages and the pieces of each finished solid back; what the programs (acd
// decompose --exact, pointloc) and the Python module call.
#pragma once

#include <acd/exact_decomposition.hpp>

namespace acdsandbox {

/// Decomposes a closed (or, with fillHoles, hole-filled), non-self-intersecting mesh into
/// interior-disjoint convex pieces whose union is the input. The input's checks and the pieces'
/// hulls run in the calling process, the decomposition in a child under options' caps.
/// Input problems come back in `status`; hitting a cap is not an error (`finished` is false and
/// `note` says which cap, where it stopped and how many reflex edges the input has; the pieces of
/// the solids finished before are kept). `progress` is called from the calling thread about
/// once a second and whenever the child reports. Nothing throws.
///
/// The child runs C++ only (CGAL), never returns into the caller, and dies with it.
acd::ExactDecomposition exactSolidDecomposition(const acd::TriMesh& closedMesh, const acd::ExactOptions& options = {});

}  // namespace acdsandbox
