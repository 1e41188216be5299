// Genus reduction by handle cuts (Lien & Amato 2007, Section 5).
//
// On a surface of genus > 0 several bridges can share one pocket: the hull is a ball,
// so the surface under a handle (the inside of a cup's handle, the hole of a torus)
// is enclosed only by the projected boundaries of two or more bridges together.
// Those bridges are the pocket's "handle caps". Flooding the pocket from the caps'
// projected boundaries, the fronts meet along closed loops around the handles; those
// loops are the handle cuts. With them as barriers, every part of the old pocket is
// enclosed by one cap again, and each cap measures only the surface on its side.
#pragma once

#include <acd/algo/surface_graph.hpp>
#include <acd/mesh.hpp>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace acd {

/// A pocket ringed by several bridges: a region of the surface whose border has two or
/// more closed loops traced by projected bridge boundaries (a region merely enclosed by
/// crossing projections has one loop). Each loop's vertices and the bridge that traced it.
struct SharedPocket {
  std::vector<int> faces;
  std::vector<std::vector<int>> loops;         // border vertices of each loop
  std::vector<int> loopBridge;                 // bridge (handle cap) of each loop
};

/// One handle cut: mesh edges (edgeKey) forming a closed curve where the pocket parts
/// nearest to two of its loops meet.
struct HandleCut {
  int capA = -1, capB = -1;                    // bridges of the two loops, capA <= capB
  std::vector<std::uint64_t> edges;
  double length = 0.0;
};

/// Directed mesh edge a->b, for maps keyed by the side of an edge.
inline std::uint64_t directedKey(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// The pockets ringed by several loops. `faceRegion` labels every face with its region
/// (regions do not cross projected paths or barriers); `bridgeOnLeft` maps a directed
/// edge a->b of a projected path to the bridge on the side of the face left of a->b.
std::vector<SharedPocket> findSharedPockets(const TriMesh& mesh, const SurfaceGraph& graph,
                                            const std::vector<int>& faceRegion,
                                            const std::unordered_map<std::uint64_t, int>& bridgeOnLeft);

/// Handle cuts for the given shared pockets, shortest first. A cut is kept only if the
/// surface stays edge-connected once all kept cuts (and `existing`) are removed: the
/// model is never split. (Section 5 keeps the handle-cut graph G_h acyclic for the same
/// reason; connectivity is the exact condition, and it does not reject two loops around
/// two different handles that join the same two caps.)
std::vector<HandleCut> findHandleCuts(const TriMesh& mesh, const SurfaceGraph& graph,
                                      const std::vector<SharedPocket>& pockets,
                                      const std::vector<std::uint64_t>& existing = {});

/// Once no handle cut is left (the genus is spent, or a handle hides under one bridge), a
/// pocket can still be ringed by loops of different bridges: where a knotted tube winds
/// under its caps, say. Such a pocket is divided the same way, at the curves where the
/// floods from its loops meet, although each divide splits the surface (they are
/// barriers for pockets, not genus reduction). Only curves between different bridges.
std::vector<HandleCut> findPocketDivides(const TriMesh& mesh, const SurfaceGraph& graph,
                                         const std::vector<SharedPocket>& pockets,
                                         const std::vector<std::uint64_t>& existing = {});

/// Number of different bridges among a shared pocket's loops.
int distinctBridges(const SharedPocket& pocket);

/// Euler-characteristic genus of a closed, edge-connected triangle mesh (0 for a sphere).
int closedGenus(const TriMesh& mesh);

}  // namespace acd
