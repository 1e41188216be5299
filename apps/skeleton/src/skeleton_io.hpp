// Writing skeletons: JSON (nodes with positions, edges), OBJ line segments for viewing beside
// the model, and thin tubes (triangles) for renderers that do not draw lines.
#pragma once

#include "ged.hpp"
#include "graph.hpp"

#include <acd/mesh.hpp>

#include <nlohmann/json.hpp>

#include <string>

namespace skeleton {

/// {"nodes": [{"id", "kind", "position": [x, y, z], "degree", "component"?}], "edges": [[a, b]], counts}.
nlohmann::json toJson(const Graph& g);

/// Reads what toJson writes (positions and kinds; extra fields ignored). Throws
/// nlohmann::json::exception on a malformed document.
Graph graphFromJson(const nlohmann::json& j);

nlohmann::json toJson(const GedResult& r);

/// OBJ with one `v` per node and one `l a b` per edge. Returns false when the file cannot be written.
bool writeSkeletonObj(const std::string& path, const Graph& g);

/// Triangle mesh of the skeleton for rendering: a prism of `radius` around each edge and an
/// octahedron of `2 * radius` at each node.
acd::TriMesh tubeMesh(const Graph& g, double radius, int sides = 6);

}  // namespace skeleton
