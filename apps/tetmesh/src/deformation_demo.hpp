// The deformation of the paper's Figure 4: the original surface is embedded in the coarse tet
// mesh of the hulls, one component (the handle) is moved rigidly while another (the anchor)
// stays, the tet mesh follows by an as-rigid-as-possible solve, and the surface follows the
// tets through its barycentric coordinates.
//
// Defaults, chosen from the mesh alone so that they work on any model:
//  * handle: the component whose centroid (tet volumes) lies farthest from the mesh's centroid
//    (a limb, a head, a tail);
//  * anchor: the largest other component (by volume; the body), so that the deformation shows
//    between the two rather than as a rigid motion of everything but a held fingertip;
//  * motion: the handle translated by 0.2 x the half-diagonal of the mesh's bounding box along u,
//    the coordinate axis least aligned with the anchor-to-handle direction d (between the
//    centroids), made perpendicular to d. With an angle instead, the handle turns about the
//    axis d x u through the anchor's vertex nearest the handle's centroid, so it swings
//    towards +u.
// A mesh with one component has no second one to hold: its vertices in the first and the last
// fifth of the longest side of the bounding box are the anchor and the handle.
// Vertices shared by the handle and the anchor belong to the anchor.
#pragma once

#include "arap_deform.hpp"
#include "surface_embedding.hpp"

#include <acd/mesh.hpp>
#include <acd/status.hpp>

#include <string>
#include <vector>

namespace tetmesh {

struct DeformationOptions {
  int handle = 0;            // component label (1-based); 0: automatic
  int anchor = 0;            // component label; 0: automatic
  bool rotate = false;       // true: turn by angleDegrees; false: translate
  double angleDegrees = 0.0;
  bool translate = false;    // true: translate by `move`; false (and !rotate): the default translation
  Vec3 move = Vec3::Zero();  // input units
  ArapOptions arap;
};

struct DeformationResult {
  acd::Status status;        // InvalidParameter: unknown label, handle == anchor, nothing to move
  int handle = 0, anchor = 0;  // labels used (0: the one-component split by position)
  std::string motion;        // what was done to the handle, one line
  Vec3 translation = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ(), pivot = Vec3::Zero();
  double angleDegrees = 0.0;
  int handleVertices = 0, anchorVertices = 0, sharedVertices = 0;  // shared ones are anchored
  SurfaceEmbedding embedding;
  ArapResult arap;
  std::vector<Vec3> tetPositionsAfter;  // = arap.positions
  acd::TriMesh surfaceAfter;            // the surface carried by the ARAP solution
  acd::TriMesh surfaceLinear;           // the same carried by the linear start
  double surfaceVolumeBefore = 0.0, surfaceVolumeAfter = 0.0, surfaceVolumeLinear = 0.0;
  double maxSurfaceDisplacement = 0.0;
  int surfaceOnHandle = 0;              // surface vertices in tets whose corners all belong to the handle
  double surfaceHandleError = 0.0;      // their largest distance from the handle's rigid motion
  int selfIntersectionsBefore = 0;      // face pairs of the surface that cross (exact), as given
  int selfIntersectionsAfter = 0;       // and after the deformation
  int surfaceInInverted = 0;            // surface vertices embedded in a tet that inverted
  std::vector<int> facePart;            // per surface face: kRest, kHandle or kAnchor (for pictures)
  double halfDiagonal = 0.0;
  double seconds = 0.0;                 // everything
};

enum SurfacePart : int { kRest = 0, kHandle = 1, kAnchor = 2 };

/// Moves the handle of `tets` (a labelled mesh, the hull mesh) and carries `surface` along.
DeformationResult deformSurface(const TetMesh& tets, const acd::TriMesh& surface, const DeformationOptions& options);

/// The faces of `surface` (before or after) in three objects, rest, handle and anchor (empty
/// ones left out), with their names: to see what was held and what was moved.
void splitByPart(const acd::TriMesh& surface, const std::vector<int>& facePart, std::vector<acd::TriMesh>& parts,
                 std::vector<std::string>& names);

/// Summary lines for the command's report (no trailing newline).
std::vector<std::string> deformationSummary(const DeformationResult& result);

}  // namespace tetmesh
