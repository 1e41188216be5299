// tetmesh's report: the summary on standard output (side by side with the model's own mesh
// under --compare) and the same figures as JSON (--json).
#pragma once

#include "command_line.hpp"
#include "deformation_demo.hpp"
#include "hull_mesher.hpp"
#include "tet_files.hpp"

namespace tetmesh {

void printReport(const Args& a, TetFormat format, const HullMeshResult& r, const DirectMeshResult& direct,
                 const DeformationResult& deformed);

/// --json; kOk, or kOutputFailed after a message.
int writeJsonReport(const Args& a, const HullMeshResult& r, const DirectMeshResult& direct,
                    const DeformationResult& deformed);

}  // namespace tetmesh
