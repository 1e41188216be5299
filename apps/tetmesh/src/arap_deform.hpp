// Volumetric as-rigid-as-possible deformation of a tetrahedral mesh with positional constraints
// (Sorkine & Alexa 2007, "As-rigid-as-possible surface modeling", carried to linear tets with
// the per-element energy of Chao et al. 2010, "A simple geometric model for elastic
// deformations").
//
// Energy: E(x, R) = sum over tets t of w_t * ||F_t(x) - R_t||_F^2, with F_t the deformation
// gradient of the linear tet (constant per tet), R_t a rotation and w_t the rest volume of the
// tet, raised to a floor (minWeight x the mean tet volume) so that slivers of a coarse mesh,
// which have almost no volume, do not invert for free. Per-element rotations keep every weight
// positive (unlike per-vertex cotangent weights, which go negative on obtuse tets).
//
// Solver (local/global alternation): the local step sets each R_t to the rotation of the polar
// decomposition of F_t (SVD, reflections flipped on the smallest singular value); the global
// step minimises E over the free positions for fixed rotations, a sparse symmetric positive
// definite system with the linear-FEM stiffness matrix sum w_t G_t^T G_t (constrained
// vertices eliminated), factored once (Eigen SimplicialLDLT) and reused for the three
// coordinates and every iteration. Each step minimises E over its own variables, so E never
// increases. The start is the linear solve with every R_t = I (harmonic deformation, the first
// step of a linear elastic model), which is kept for comparison.
#pragma once

#include "tet_mesh.hpp"

#include <acd/status.hpp>

#include <functional>
#include <vector>

namespace tetmesh {

struct ArapOptions {
  int maxIterations = 200;       // local/global iterations after the linear start
  double tolerance = 1e-5;       // stop when an iteration lowers the energy by less than this fraction
  double minWeight = 0.1;        // weight floor, fraction of the mean tet volume; 0: pure volume weights
  int threads = 0;               // local step threads, 0 = all cores (the result is the same)
  bool linearStart = true;       // start from the linear solve; false: from rest with the constrained vertices moved
  std::function<void(int iteration, double energy)> progress;  // called after each iteration when set
};

struct ArapResult {
  acd::Status status;                 // not ok: nothing solved (bad constraints, singular system)
  std::vector<Vec3> positions;        // deformed mesh points (constrained ones exactly at their targets)
  std::vector<Vec3> linearPositions;  // the linear solve (all rotations the identity), start or not
  /// Energy divided by the sum of the weights (weighted mean squared distance of F to a
  /// rotation): [0] at the start, then after every iteration. Never increases.
  std::vector<double> energy;
  int iterations = 0;
  bool converged = false;             // stopped on the tolerance, not on maxIterations
  int freeVertices = 0;               // solved for
  int pinnedVertices = 0;             // kept at rest because no constraint reaches their part of the mesh
  int invertedTets = 0;               // tets of non-positive volume after the solve
  double invertedRestVolume = 0.0;    // their volume at rest (slivers of a coarse mesh invert cheaply)
  int linearInvertedTets = 0;         // same for the linear start
  double restVolume = 0.0, volume = 0.0, linearVolume = 0.0;  // sum of signed tet volumes
  double maxConstraintError = 0.0;    // largest distance of a constrained vertex from its target
  double factorSeconds = 0.0, solveSeconds = 0.0;  // factorisation; all iterations
};

/// Deforms `mesh` so that vertex constrained[i] goes to targets[i] (rest positions are
/// mesh.points). Vertices in no tet stay where they are. A part of the mesh (tets connected
/// through shared vertices) without any constrained vertex is kept at rest (it has no energy
/// there and would otherwise be free to float).
ArapResult arapDeform(const TetMesh& mesh, const std::vector<int>& constrained, const std::vector<Vec3>& targets,
                      const ArapOptions& options = {});

/// Signed volume of every tet with the points replaced by `positions`.
double meshVolume(const TetMesh& mesh, const std::vector<Vec3>& positions);

/// Number of tets whose volume with these positions is <= 0.
int countInverted(const TetMesh& mesh, const std::vector<Vec3>& positions);

}  // namespace tetmesh
