// Shells that pass through, touch or nest in one another, united into the solid they bound
// together: an assembly exported from CAD (screws, covers, ribs, bosses as shells of their own)
// is then decomposed as one solid, and one hull may span several shells.
#pragma once

#include <acd/mesh.hpp>

#include <string>
#include <vector>

namespace acd {

struct ShellUnion {
  std::vector<TriMesh> shells;  // the united solids first, then every shell left as it was
  int united = 0;               // input shells that went into a union
  int solids = 0;               // the closed shells those became
  int leftAlone = 0;            // shells that meet another but that the union could not take
  std::string firstFailure;     // why the first of those was left alone
  double seconds = 0.0;
};

/// Unites the closed, outward-oriented `shells` whose surfaces meet (or of which one lies inside
/// another) with CGAL's corefinement in exact arithmetic; the union's surface is made of pieces of
/// the shells' own surfaces, so a hull within tau of it is within tau of the input. Shells that
/// cross themselves, or a union that would not be a manifold (two shells touching along an edge
/// only), are left alone and counted. Shells that meet no other come back unchanged. With
/// `invariant` the work is done on the shells rounded to the canonical grid in the canonical frame
/// turned onto their largest planes (faceAlignedFrame), in canonical order, so that the result
/// does not follow the pose or the order of faces and shells; the vertices of the input come back
/// with their exact coordinates, the points where shells cross within a grid step of theirs.
ShellUnion uniteMeetingShells(const std::vector<TriMesh>& shells, bool invariant);

}  // namespace acd
