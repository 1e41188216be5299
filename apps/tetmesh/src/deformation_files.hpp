// The deformation demo's output (--deform): its four file pairs and its part of the JSON report.
#pragma once

#include "command_line.hpp"
#include "deformation_demo.hpp"
#include "tet_mesh.hpp"

#include <acd/mesh.hpp>

#include <nlohmann/json.hpp>

namespace tetmesh {

/// Runs the deformation and writes its four files; the report lines and JSON come from the result.
/// kOk, or the exit code after a message.
int runDeformation(const DeformArgs& d, const DeformationOptions& o, const TetMesh& tets, const acd::TriMesh& surface,
                   DeformationResult& r);

nlohmann::json deformationJson(const DeformArgs& d, const DeformationResult& r);

}  // namespace tetmesh
