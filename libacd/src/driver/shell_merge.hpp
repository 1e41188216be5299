// The merge pass across shells: an assembly's shells are decomposed one by one, so a hull never
// spans two of them there; here components of different shells are joined while the union's hull
// stays within tau of the solid all the shells bound (a row of bolt heads, a cover and its bosses).
#pragma once

#include <acd/decompose.hpp>

#include <vector>

namespace acd {

/// Joins components of different sources (shells) in pairs, as the model-scope merge pass joins
/// pieces: a pair whose hulls come within tau of each other is screened by the volume its union's
/// hull adds outside the model and the two hulls (at most kModelMergeGrowth of the union's), then
/// taken in order of that volume (ties by index) when the hull stays within tau of `shells` (their
/// solid: any closed shell, each on its own); rounds repeat until nothing merges. Unresolved
/// components and pieces of a wrap stay as they are. `shells` and the components are in input
/// coordinates, `normalization` takes them to tau's units (with o.invariant the shells' canonical
/// frame is used instead, which has the same unit). Returns the number of merges.
int mergeAcrossShells(std::vector<Component>& components, const TriMesh& shells, const Normalization& normalization,
                      const DecomposeOptions& o);

}  // namespace acd
