// The deformations `skeleton --deform SPEC` makes, and how SPEC is read.
//
//   bend:DIR:AXIS:DEG[:HANDLE[:REGION]]
//       ARAP bend of the limb at the model's extreme along DIR (+x, -x, +y, -y, +z, -z).
//       e = the vertex furthest along DIR; distances are shortest paths along mesh edges from e,
//       in units of the bounding-box diagonal. Handle = vertices within HANDLE (default 0.08)
//       of e, region = vertices within REGION (default 0.25), fixed = the rest. The handle is
//       rotated by DEG degrees about the axis AXIS (x, y or z) through the pivot = mean of the
//       region's outer ring (vertices at path distance in [0.9 REGION, REGION]), where the
//       limb meets the body.
//   twist:DIR:DEG[:HANDLE[:REGION]]
//       The same handle and region, the handle turned by DEG degrees about the limb's own axis:
//       the line from the pivot to e.
//   ids:FILE.json
//       ARAP with given vertex ids: {"handle": [...], "region": [...], "pivot": [x, y, z],
//       "axis": [x, y, z], "angle": degrees}.
//   affine:RX,RY,RZ:SX,SY,SZ[:TX,TY,TZ]
//       Non-uniform scaling by (SX, SY, SZ) about the bounding-box centre, then rotation by
//       RX, RY, RZ degrees about x, then y, then z (through the centre), then translation by
//       (TX, TY, TZ) in model units. A rigid motion when every S is 1.
//   SPEC;SPEC;...
//       Each applied to the result of the one before (a limb chain posed joint by joint).
#pragma once

#include "arap.hpp"

#include <acd/mesh.hpp>

#include <string>

namespace skeleton {

struct DeformResult {
  bool ok = false;
  std::string error;     // names the bad part of the spec or the failure
  acd::TriMesh mesh;
  std::string summary;   // one line: what was done (handle/region sizes, pivot)
  double seconds = 0.0;
};

/// Applies SPEC (grammar above) to a closed mesh. Never throws.
DeformResult applyDeformation(const acd::TriMesh& mesh, const std::string& spec);

/// The affine deformation alone.
acd::TriMesh affineDeform(const acd::TriMesh& mesh, const Vec3& rotationDegrees, const Vec3& scale,
                          const Vec3& translation);

/// The bend rule's handle, region and pivot (see the grammar above).
ArapRequest bendRequest(const acd::TriMesh& mesh, const Vec3& direction, const Vec3& axis, double degrees,
                        double handleRadius = 0.08, double regionRadius = 0.25);

}  // namespace skeleton
