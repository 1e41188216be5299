// The last slivers of a refined mesh, moved apart. CGAL's exudation leaves a few tets below the
// sliver bound (0 to a few per corpus mesh, down to 3 degrees), mostly flat tets on a rounded
// edge or an interface whose four corners all lie on the surface, where CGAL only moves
// vertices within the surface. Here a corner of each sliver is moved off it
// by a small amount (at most `maxMove`, which the caller ties to how closely the surface follows
// the regions anyway) when that raises the smallest dihedral angle around the vertex; every tet
// stays positive. Deterministic: slivers in index order, a fixed set of trial moves.
#pragma once

#include "tet_mesh.hpp"

namespace tetmesh {

struct SliverRepair {
  int before = 0;  // tets below the bound before
  int after = 0;   // and after
  int moves = 0;   // vertex moves made
};

SliverRepair repairSlivers(TetMesh& mesh, double boundDegrees, double maxMove);

}  // namespace tetmesh
