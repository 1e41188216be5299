// Solids that touch along an edge, taken apart there. CAD exports weld an assembly's parts where
// they touch (a lid on its box, a screw head on a plate): an edge of four faces, two of each part.
// A generic repair pairs those faces in whatever order they come and may glue the outside of one
// part to the outside of the other, turning a box and its lid into a closed hull around a cavity.
// Here each face is glued to the face that bounds the same material: the parts come apart.
#pragma once

#include <acd/mesh.hpp>

namespace acd {

struct TouchingSolidsSplit {
  TriMesh mesh;        // the faces in their order, with vertices copied where parts come apart
  int splitEdges = 0;  // edges of four or more faces paired by material
  int copiedVertices = 0;
};

/// At every edge used by four or more faces, as often in one direction as in the other, the faces
/// are sorted around the edge and each is paired with its neighbour on its inner side (opposite
/// its normal); then every vertex is copied once per fan of faces glued through it. Edges whose
/// faces cannot be paired that way (an inner side that meets another inner side) are left as they
/// are. Vertices where nothing is split keep their index.
TouchingSolidsSplit splitTouchingSolids(const TriMesh& mesh);

}  // namespace acd
