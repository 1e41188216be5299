// Parts of a shape from its convex components: the level of the decomposition a skeleton is made
// from, so that the skeleton stays put when the shape bends (paper, Section 7, Figure 21).
//
// A cut across the middle of a tube (a limb cut where it bends, a trunk cut in two, a rounded tip
// cut off) has about the area of the mean cross-section of the pieces on both sides; a cut where a
// limb meets the body, or through a neck, is small against the mean section of the wider side.
// Bending a limb makes and moves cuts of the first kind; cuts of the second kind stay where the
// shape narrows. So neighbouring components are merged across every cut of the first kind, the
// most tube-like first, and a part is a limb, a trunk, a head.
//
//   section ratio = shared area / max(mean section of either side along the cut's normal),
//   mean section  = volume / extent along that normal;  merged while the ratio >= kTubeRatio.
//
// Then the stubs (kStubElongation): wedges where two parts meet and bumps, which come and go with
// small changes of the surface, go into the neighbour they share most with; so do the specks, parts
// of less than tau^3 of the volume (leastPartShare), detail below what a decomposition at tau resolves.
//
// The graph of parts is a tree: a maximum spanning forest of their adjacencies by shared area.
// A solid's handles are counted on a voxel grid (part_voxels.hpp), per part and per adjacency a
// loop passes through, but by default not drawn as cycles: whether a handle lies inside one part
// or runs through the contacts of several depends on where the cuts fall, which a bend changes
// (the elephant, genus 3: 2, 3, 0, 3, 2 and 2 handles inside single parts on the original and its
// five deformations; docs/SKELETON.md), so cycles would make the graph change with the pose.
// `handleCycles` keeps them: the non-tree adjacencies a loop passes through, largest first, at
// most the genus. Without a cycle test
// three parts that meet along one old cut would make a triangle the shape does not have.
#pragma once

#include <acd/mesh.hpp>
#include <vector>

#include "graph.hpp"

namespace skeleton {

/// A cut across a tube has ratio about 1 (a cylinder cut square: exactly 1; a hemispherical tip:
/// 1.5); a limb of half the body's width meeting the body about 0.25 or less. Half way between,
/// on the ratio's log scale.
constexpr double kTubeRatio = 0.5;

/// A limb is longer than it is wide: a part no longer along its largest contact's normal than the
/// square root of the contact's area (a hemispherical cap: 1/sqrt(pi) = 0.56; a limb twice as long
/// as wide: 1.1 or more), and smaller than the part on the other side, is a stub: a wedge in the
/// crease where two parts meet, or a bump. It goes into that neighbour.
constexpr double kStubElongation = 1.0;

/// A part of less than this share of the solid's volume is a speck: about the volume of a cube of
/// side tau against the cube the whole shape fills, the scale below which a decomposition at tau
/// resolves nothing (whether it cuts a thin tail off can change with a bend elsewhere). It goes
/// into the neighbour it shares the most area with.
inline double leastPartShare(double tau) { return tau * tau * tau; }

struct Joint {
  int a = -1, b = -1;          // the two parts, a < b
  double area = 0.0;           // of all cut patches between them
  Vec3 centre = Vec3::Zero();  // area-weighted centre of those patches
};

struct Parts {
  std::vector<int> partOf;                // component -> part
  std::vector<std::vector<int>> members;  // part -> its components, ascending; parts ordered by first member
  std::vector<double> volume;             // per part
  std::vector<Vec3> centroid;             // per part: of the solid it bounds
  std::vector<Joint> joints;              // the adjacencies the skeleton keeps
  int merges = 0;                         // cuts merged across
  int droppedAdjacencies = 0;             // adjacencies not kept as joints
  int loopGrid = 0;                       // cubes across the grid that shows all handles (0: none does)
  std::vector<int> handles;               // per part: its own handles on that grid (empty: no grid)
  std::vector<Joint> loopJoints;          // adjacencies a loop of the solid passes through
};

/// Groups closed, outward components (pieces of one decomposition) into parts (above).
/// `genus` = handles of the solid they make up (genusOf). Depends only on the components' shapes
/// and order: an invariant decomposition gives the same parts in every pose.
Parts groupIntoParts(const std::vector<acd::TriMesh>& components, int genus, bool handleCycles = false,
                     double tubeRatio = kTubeRatio, double leastVolumeShare = 0.0);

/// A Component node per part (at its centroid; `source` = part index), then a Cut node per joint
/// joined to its two parts.
Graph skeletonFromParts(const Parts& parts);

/// Handles of the solid a closed mesh bounds: the sum over its connected shells of (2 - Euler
/// characteristic) / 2.
int genusOf(const acd::TriMesh& closedMesh);

}  // namespace skeleton
