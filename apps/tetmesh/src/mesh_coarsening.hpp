// Coarsening a labelled tet mesh by edge collapses that keep it well shaped. Delaunay refinement
// samples every surface of the regions densely enough for its own proofs (facet angle, restricted
// Delaunay topology), which is more than a coarse mesh needs: on a model that is itself coarse
// (the eight: 1 536 faces) it ends with more tets than TetGen's unrefined mesh of the model.
//
// An edge ab is collapsed (a moved onto b, the tets around ab removed) only when
//  * a may move there: a vertex inside one region anywhere; a vertex of one surface patch (the
//    boundary of one region, or the interface of two) only along an edge of that patch; vertices
//    where patches meet (the regions' rims and junctions) never, so every patch keeps its outline;
//  * the mesh stays a mesh: the vertices next to both a and b are those of the triangles on ab
//    (the link condition; the outside counts as a vertex next to every boundary vertex), and
//    every tet that a leaves is positive;
//  * it stays well shaped: every tet made has its dihedral angles within [minDihedral,
//    180 - minDihedral];
//  * no label's volume drops below its floor (the component's own volume, say);
//  * the surface stays put: every surface point the mesh started with (its surface vertices)
//    lies within maxDistance of the patch it belongs to after the collapse, and no patch
//    triangle turns by more than maxTurnDegrees.
// Shortest edges first; ties by vertex numbers, so the same mesh gives the same result.
#pragma once

#include "tet_mesh.hpp"

#include <vector>

namespace tetmesh {

struct CoarsenOptions {
  double minDihedral = 10.0;     // degrees; tets made stay within [this, 180 - this]
  double maxDistance = 0.0;      // input units; > 0
  double maxTurnDegrees = 30.0;  // a patch triangle's normal turns by at most this
  /// Per label (index label - 1): no collapse takes the label's tets below this volume (when it
  /// had more); empty: no bound.
  std::vector<double> minVolume;
};

struct CoarsenResult {
  int tetsBefore = 0, tetsAfter = 0;
  int pointsBefore = 0, pointsAfter = 0;
  int collapses = 0;
  double farthest = 0.0;  // the farthest a starting surface vertex ended from its patch
};

/// Coarsens `mesh` in place; its points are renumbered, unused ones dropped, and its faces
/// (boundary and interface triangles) rebuilt from the tets.
CoarsenResult coarsenMesh(TetMesh& mesh, const CoarsenOptions& options);

/// The boundary triangles (one tet) and interface triangles (two tets of different labels) of a
/// labelled tet mesh, with their markers, oriented out of the tet with the lower label.
void rebuildFaces(TetMesh& mesh);

}  // namespace tetmesh
