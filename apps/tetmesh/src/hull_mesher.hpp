// The tetmesh pipeline: solid ACD, a convex hull per component (optionally simplified), then
// either Delaunay refinement of the hull regions (the default) or one conforming complex of the
// hulls given to TetGen; and, for comparison, TetGen on the model itself.
#pragma once

#include "hull_complex.hpp"
#include "mesh_coarsening.hpp"
#include "mesh_quality.hpp"
#include "region_refiner.hpp"
#include "tetgen_run.hpp"

#include <acd/decompose.hpp>

#include <string>
#include <vector>

namespace tetmesh {

/// How the hull regions become tets.
enum class Mesher {
  Auto,     // Complex where every hull has few corners and its mesh has no sliver, else Refine
  Refine,   // Delaunay refinement of the regions (region_refiner.hpp): no slivers, coarse by tau
  Complex,  // the regions' exact complex (hull_complex.hpp) given to TetGen: their faces kept exactly
};

struct HullMeshOptions {
  double tau = 0.2;          // concavity tolerance of the decomposition, normalised units
  Mesher mesher = Mesher::Auto;
  int simplify = -1;         // > 0: hulls with at most this many vertices (>= 4); 0: exact; -1: the mesher's default
  bool clip = false;         // Refine only: mesh the components themselves (the regions clipped to the model)
  double sharpAngle = 0.0;   // Refine only, degrees: the regions' edges turning more are kept exactly; 0: all rounded
  bool coarsen = true;       // Refine, coarse mode only: edge collapses that keep the tets well shaped
  bool keepVolume = false;   // the collapses keep each component's tets at or above its own volume
  double surfaceDistance = -1;  // Refine only, share of tau: the surface follows the regions within it; < 0: the default
  bool merge = false;        // the decomposition's merge pass; off keeps hulls apart along cut planes
  int threads = 0;           // decomposition threads, 0 = all cores
  double tolerance = 1e-8;   // complex snapping tolerance (relative); raised 10x if TetGen refuses
  TetGenOptions tetgen = coarse();  // radiusEdge and maxVolume also steer the refinement
  /// No quality refinement: the constrained Delaunay mesh of the complex, as coarse as it gets.
  static TetGenOptions coarse() {
    TetGenOptions o;
    o.radiusEdge = 0;
    return o;
  }
};

struct HullMeshTimes {
  double decompose = 0, hulls = 0, complex = 0, tetgen = 0, refine = 0, coarsen = 0, quality = 0;  // wall seconds
};

struct HullMeshResult {
  acd::Status status;                    // not ok: nothing was meshed; message says why
  acd::Decomposition decomposition;
  std::vector<acd::TriMesh> hulls;       // per component, as meshed (simplified if asked)
  std::vector<int> hullVertices;         // per component, before simplification
  int simplifyMissed = 0;                // hulls that could not get down to `simplify` vertices
  int simplifyUsed = 0;                  // the vertex budget of the meshed hulls (below `simplify` after refusals)
  int separatingPlanes = 0;              // planes keeping the simplified hulls apart
  int overlappingHulls = 0;              // pairs of exact hulls that overlap (a plane cuts them)
  bool simplifyFallback = false;         // TetGen refused the simplified hulls: the exact ones were meshed
  double maxOutside = 0.0;               // largest distance of a component vertex outside its hull
  std::vector<acd::TriMesh> regions;     // per component, the region meshed for it (empty if it vanished)
  double maxOutsideRegion = 0.0;         // same, against the meshed region (after clipping)
  Mesher used = Mesher::Refine;          // the mesher that made `mesh` (Refine or Complex)
  bool complexTried = false;             // Auto: the complex of the exact hulls was tried
  int complexSlivers = -1;               // and had this many tets below kSliverDegrees; -1: TetGen refused it
  TetMesh mesh;                          // the result, labels 1..n as the components
  std::vector<double> meshedVolume;      // per component: volume of its tets
  MeshQuality quality;
  // Mesher::Complex
  HullComplex complex;
  double toleranceUsed = 0.0;                  // snapping tolerance of the complex TetGen meshed
  std::vector<std::string> refusedComplexes;   // TetGen's errors on complexes with smaller tolerances
  TetGenResult tetgen;                         // its mesh moved to `mesh`
  // Mesher::Refine
  RefineOptions refineOptions;           // as used (input units)
  RefineResult refine;                   // its mesh moved to `mesh`
  bool coarsened = false;                // the refined mesh was coarsened
  CoarsenOptions coarsenOptions;
  CoarsenResult coarsening;
  double modelVolume = 0.0;              // input units
  double hullsVolume = 0.0;              // volume of the union of the hull regions
  HullMeshTimes times;
};

HullMeshResult meshHulls(const acd::TriMesh& model, const HullMeshOptions& options);

struct DirectMeshResult {
  acd::Status status;        // not ok: the model cannot be given to TetGen (or TetGen failed)
  TetGenResult tetgen;
  MeshQuality quality;
  int selfIntersections = 0;
  double seconds = 0.0;      // validation + TetGen
};

/// TetGen on the model's own surface (after the same checks and safe repairs as `acd`).
/// Refuses self-intersecting surfaces before TetGen sees them.
DirectMeshResult meshModelDirectly(const acd::TriMesh& model, const TetGenOptions& options);

}  // namespace tetmesh
