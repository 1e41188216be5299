// decompose() of a shell the repairs have already made a clean solid.
#pragma once

#include <acd/decompose.hpp>

namespace acd {

/// decompose() with repair off of `shell`, one of prepareModel's shells as prepareSolid made it
/// (PreparedModel::isClean: closed, outward, edge-connected, every repair done): the same
/// decomposition without checking and repairing it a second time, which on a million faces costs
/// seconds. A face of zero area at the shell's own scale (prepareModel measures at the whole
/// model's) sends it through prepareSolid after all, as decompose() would.
Decomposition decomposeCleanShell(const TriMesh& shell, const DecomposeOptions& options);

}  // namespace acd
