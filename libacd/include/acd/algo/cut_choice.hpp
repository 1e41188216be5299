// Which plane cuts a piece (Sections 3.2, 4.2 and 4.3): the candidates at its notch, and the
// choice among them, by the first that cuts cleanly or by one step of lookahead.
#pragma once

#include <acd/algo/concavity.hpp>
#include <acd/algo/cut.hpp>
#include <acd/algo/surface_graph.hpp>
#include <acd/decompose.hpp>

#include <vector>

namespace acd {

/// A piece is final when its hull stands at most this share of tau off its surface, measured to
/// within kExcessResolution * tau: 0.96 + 1/32 < 1, so a final hull is within tau of its piece.
constexpr double kExcessLimit = 0.96;
constexpr double kExcessResolution = 1.0 / 32;

/// Where and why a piece is cut: its notch, the normal of the bridge (or hull face) above it, and
/// how it came to be cut.
struct CutSite {
  int notch = -1;                  // mesh vertex
  Vec3 bridgeNormal = Vec3::Zero();
  int stalls = 0;                  // consecutive cuts that left this notch as it was
  bool fromExcess = false;         // cut because its hull stands off it, not for a pocket
  bool atNotchOnly = true;         // cut only the section region at the notch
};

/// The planes that compete to cut `mesh` at the site: the global cuts of feature grouping
/// (Section 4.2) first, then the bisector, the plane through the notch parallel to the bridge and a
/// fan of planes through the notch that contain the bridge normal. After stalls the fan widens.
/// Adds the time spent grouping to `groupingSeconds`.
std::vector<Plane> candidatePlanes(const TriMesh& mesh, const SurfaceGraph& graph, const ConcavityMap& map,
                                   const DecomposeOptions& o, const CutSite& site, double& groupingSeconds);

/// Figure 13: a plane through the notch that contains the bridge normal, across the pocket's longest
/// extent (principal axis of the pocket's vertices projected on the bridge plane).
Plane splitCupPlane(const TriMesh& mesh, const ConcavityMap& map, int notch);

/// Cuts `mesh` by `plane`, nudged along its normal if the section is degenerate, into pieces on
/// both sides, each with more than 1e-7 of the mesh's volume. `used` is the plane that cut. With
/// `near`, the section region nearest that point is cut and most others are not (cutByPlane).
bool cutCleanly(const TriMesh& mesh, const Plane& plane, std::vector<TriMesh>& pieces, Plane& used,
                const Vec3* near = nullptr);

struct CutChoice {
  bool ok = false;            // some candidate cut cleanly
  std::size_t index = 0;      // the chosen candidate
  Plane plane;                // the plane that cut (the candidate, perhaps nudged)
  std::vector<TriMesh> pieces;
  int failed = 0;             // candidates that did not cut cleanly (before the chosen one, for the first-plane rule)
};

/// The paper's baseline: the first candidate that cuts cleanly.
CutChoice cutByFirstPlane(const TriMesh& mesh, const std::vector<Plane>& candidates);

/// One step of lookahead: cut with every candidate (in parallel; with site.atNotchOnly at the
/// notch's section region, cutByPlane) and keep the one whose children
/// are best approximated by their hulls (least hull volume beyond the children's own volume); after
/// a stall, the one whose children are least concave; for a site from hull excess, first the one
/// that leaves fewest children whose hull stands more than the limit off them. Ties go to the
/// earlier candidate; an exact repeat of an earlier plane is not cut again.
CutChoice cutByLookahead(const TriMesh& mesh, const std::vector<Plane>& candidates, const CutSite& site,
                         const ConcavityOptions& co, double tau);

/// The hull the lookahead scores a child of a cut by `plane` with: its vertices off the plane and
/// the corners of the convex outline of those on it (within 1e-9), computed in the plane's frame
/// with the cap at height exactly 0. The hull's vertices are the child's, in place; it is the
/// child's convex hull up to rounding, found without the exact arithmetic that near-coplanar cap
/// points cost.
TriMesh lookaheadHull(const TriMesh& child, const Plane& plane);

}  // namespace acd
