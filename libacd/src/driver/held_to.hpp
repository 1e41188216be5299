// decompose() for a watertight wrap: its merge pass measures against the surface it wraps.
#pragma once

#include <acd/decompose.hpp>

namespace acd {

/// decompose() of `mesh`, a watertight wrap of the closed surface `wrapped` (which may pass through
/// itself), whose merge pass held to the model measures a union's hull against `wrapped`, to
/// `mergeTau`, instead of against the wrap to options.tau: where the wrap stands off the input or
/// bridges a gap, a merged hull would otherwise be within tau of the wrap but not of what the user
/// gave. (The wrap itself is decomposed to less than the user's tau; its merges can be held to it.)
Decomposition decomposeHeldTo(const TriMesh& mesh, const TriMesh& wrapped, const DecomposeOptions& options,
                              double mergeTau);

}  // namespace acd
