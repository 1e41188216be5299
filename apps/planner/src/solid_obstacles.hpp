// Obstacles and robots given as polygon soups (open surfaces, double-sided faces, overlapping
// pieces) made into closed solids for the free space's Boolean difference and for point
// location. Collision checking keeps the original triangles (FCL handles soups); the solids
// only shape the free space that the ACD decomposes.
#pragma once

#include <acd/mesh.hpp>

#include <string>
#include <vector>

namespace planner {

/// CGAL 3D Alpha Wrapping of the pieces no repair closes, in length units.
struct WrapSettings {
  double alpha = 0.0;   // no cavity or passage narrower than about alpha is entered
  double offset = 0.0;  // the wrap lies this far outside the triangles
};

struct SolidObstacle {
  std::vector<acd::TriMesh> pieces;   // closed, outward, free of self-intersections; may overlap
  int soupPieces = 0;                 // vertex-connected pieces of the triangles
  int closedPieces = 0;               // closed as given (after merging identical corners)
  int repairedPieces = 0;             // closed by libacd's repairs (double-sided faces, orientation...)
  int wrappedPieces = 0;              // the rest, wrapped together into one solid
  int wrapFaces = 0;
  WrapSettings wrap;                  // as used, when wrappedPieces > 0
  double seconds = 0.0;
  bool ok = false;
  std::string error;                  // why nothing could be made (the wrap failed)

  /// One line: "3 pieces: 1 closed, 1 repaired, 1 wrapped (alpha 0.1, offset 0.005, 840 faces)".
  std::string summary() const;
};

/// Splits `triangles` into vertex-connected pieces (corners at identical positions joined);
/// each piece that libacd's repairs make a closed solid without dropping any surface is kept
/// exactly, every other piece goes into one alpha wrap. Never throws.
SolidObstacle solidify(const acd::TriMesh& triangles, const WrapSettings& wrap);

/// All pieces in one mesh (the union by winding number, as acd::InsideTest reads it).
acd::TriMesh concatenatedPieces(const SolidObstacle& solid);

/// One vertex of each vertex-connected piece of a soup: a piece wholly inside the robot
/// touches no surface, so the validity test looks for these points inside it.
std::vector<acd::Vec3> pieceProbes(const acd::TriMesh& triangles);

}  // namespace planner
