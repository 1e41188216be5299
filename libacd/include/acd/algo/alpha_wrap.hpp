// The watertight wrap, the last resort for meshes no repair makes a closed, manifold,
// non-self-intersecting solid: CGAL's 3D Alpha Wrapping (CGAL 5.5) shrink-wraps any triangle
// soup into a closed, 2-manifold, self-intersection-free surface at distance `offset` outside
// it, that enters no cavity narrower than about `alpha`. docs/ALGORITHM.md explains how the
// parameters follow from tau, with the measured fidelity and time.
#pragma once

#include <acd/mesh.hpp>
#include <acd/status.hpp>
#include <acd/algo/wrap_report.hpp>

namespace acd {

/// Wrap parameters in normalised units (minimum enclosing sphere radius 1) for a decomposition
/// at `tau`: offset = tau / 10, alpha = tau (alpha at least 0.02 so the wrap of a 2-unit model
/// stays a few hundred cells across; see docs/ALGORITHM.md for the measurements).
struct WrapParameters {
  double alpha = 0.0;
  double offset = 0.0;
};
WrapParameters wrapParametersFor(double tau);

struct Wrap {
  Status status;         // not ok: CGAL failed (never expected) or the wrap is empty
  TriMesh mesh;          // closed, outward, 2-manifold, without self-intersections
  double seconds = 0.0;
};

/// Wraps a triangle soup (any topology; degenerate faces are fine) with CGAL::alpha_wrap_3.
/// `alpha` and `offset` are in the soup's units. Never throws.
Wrap alphaWrap(const TriMesh& soup, double alpha, double offset);

/// Largest distance from the surface of `a` to that of `b` and back, estimated from every
/// vertex (up to `samples`) and `samples` area-weighted points of each side, each measured
/// exactly to the other surface. Lower bounds that converge from below; deterministic.
struct SurfaceDistance {
  double aToB = 0.0;
  double bToA = 0.0;
  double hausdorff() const { return aToB > bToA ? aToB : bToA; }  // two-sided
};
SurfaceDistance surfaceDistance(const TriMesh& a, const TriMesh& b, int samples = 20000);

/// How far the surface of `a` reaches outside the closed surface `solid`: the largest distance to
/// `solid`'s surface of the points sampled as surfaceDistance does that lie outside it (0 when
/// none does). Parts of `a` inside `solid` do not count: a solid's hulls cover them.
double distanceOutside(const TriMesh& a, const TriMesh& solid, int samples = 20000);

/// Two-sided Hausdorff distance: surfaceDistance(a, b).hausdorff().
double hausdorffDistance(const TriMesh& a, const TriMesh& b, int samples = 20000);

}  // namespace acd
