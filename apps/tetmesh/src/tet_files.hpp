// Writing tetrahedral meshes: VTK legacy unstructured grid (ParaView), Medit .mesh, and
// TetGen's .node/.ele/.face. Labels are the 1-based component numbers.
#pragma once

#include "tet_mesh.hpp"

#include <acd/status.hpp>

#include <string>
#include <vector>

namespace tetmesh {

enum class TetFormat { Vtk, Medit, TetGen };

/// "vtk", "mesh", "tetgen"; false for anything else.
bool parseTetFormat(const std::string& name, TetFormat& format);

/// Files written for OUT in this format (OUT itself, or OUT.node/.ele/.face for TetGen where
/// OUT is the base name without extension).
std::vector<std::string> tetOutputFiles(const std::string& out, TetFormat format);

/// ASCII VTK 2.0 UNSTRUCTURED_GRID, cell type 10, CELL_DATA int array "component".
acd::Status writeVtk(const std::string& path, const TetMesh& mesh);

/// Medit MeshVersionFormatted 2: Vertices, Triangles (reference = facet kind), Tetrahedra
/// (reference = component).
acd::Status writeMedit(const std::string& path, const TetMesh& mesh);

/// TetGen files, numbered from 1: BASE.node, BASE.ele (one attribute: component), BASE.face
/// (boundary marker = facet kind).
acd::Status writeTetGenFiles(const std::string& base, const TetMesh& mesh);

acd::Status writeTetMesh(const std::string& out, TetFormat format, const TetMesh& mesh);

}  // namespace tetmesh

namespace tetmesh {

/// The complex TetGen is given, as a TetGen .poly file (numbered from 1; facet marker = kind,
/// region attribute = component), for inspection with `tetgen -d` or meshing by hand.
acd::Status writePoly(const std::string& path, const Plc& plc);

}  // namespace tetmesh
