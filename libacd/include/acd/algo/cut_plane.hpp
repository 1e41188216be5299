// Choosing the cut plane (Lien & Amato 2007, Sections 3.2 and 4.3).
#pragma once

#include <acd/algo/cut.hpp>
#include <acd/algo/features.hpp>
#include <acd/algo/surface_graph.hpp>

namespace acd {

/// Best-fit plane of a global cut (Eq. 5 approximated by concavity-weighted PCA),
/// then pushed toward the cut vertices it misrepresents (Figure 15): vertices
/// farther than `tolerance` from the plane get heavier and the plane is refit.
Plane fitCutPlane(const TriMesh& mesh, const GlobalCut& cut, const Vec3& bridgeNormal, double tolerance);

/// Without feature grouping: the plane through the most concave edge at `notch`
/// that bisects its (reflex) dihedral angle (Figure 6a).
Plane bisectorPlane(const TriMesh& mesh, const SurfaceGraph& graph, int notch, const Vec3& bridgeNormal);

}  // namespace acd
