// The solid of labelled closed components (the parts of a decomposition) on a voxel grid, to count
// its loops and which contacts between parts they pass through.
//
// Contacts of a decomposition are not conforming where three or more pieces meet (one side's
// corners lie on the other side's edges), so the pieces' own triangles do not give the solid's
// topology; a grid does. The solid is the union of the closed cubes whose centres lie inside a
// component, each cube labelled with its component's part. The grid lies in the components'
// canonical frame, so a rigid motion of the input gives the same cubes.
//
// Euler characteristic chi = vertices - edges + faces - cubes of that union, loops (first Betti
// number) = pieces + cavities - chi. Cutting the solid apart where only parts a and b meet (a cell
// whose cubes are all of a or b, some of each, is doubled; a cell that also bounds a cube of
// another part stays joined) raises chi by the alternating count of those cells. Where other
// parts still join a and b, each unit is a loop cut; otherwise one unit is the solid falling in
// two. A contact of k separate patches carries k - 1 loops between a and b alone, which a graph of
// parts cannot show; the rest go round through other parts:
//   loops through (a, b) = that count - (k - 1) - (0 if joined elsewhere, else 1).
// A free disc between parts joined elsewhere too: 1. Three parts meeting along a line, as the
// slices of a pie: 0 for each pair.
#pragma once

#include <acd/mesh.hpp>
#include <cstdint>
#include <vector>

namespace skeleton {

class PartVoxels {
 public:
  /// `cellsAcross` cubes across the components' enclosing sphere.
  PartVoxels(const std::vector<acd::TriMesh>& components, const std::vector<int>& partOf, int cellsAcross);

  /// First Betti number of the solid on the grid; of part `only`'s cubes alone when given.
  int loops(int only = -1) const;

  /// Loops of the solid through the contact of parts a and b and through other parts (above);
  /// `joinedElsewhere`: other contacts join a and b.
  int loopsThrough(int a, int b, bool joinedElsewhere) const;

 private:
  int at(int x, int y, int z) const {
    return x < 0 || y < 0 || z < 0 || x >= n_[0] || y >= n_[1] || z >= n_[2] ? -1 : label_[index(x, y, z)];
  }
  std::int64_t index(int x, int y, int z) const { return (static_cast<std::int64_t>(z) * n_[1] + y) * n_[0] + x; }
  long long eulerCharacteristic(int only) const;
  bool filled(int x, int y, int z, int only) const {
    const int l = at(x, y, z);
    return only < 0 ? l >= 0 : l == only;
  }

  int n_[3] = {0, 0, 0};
  std::vector<std::int32_t> label_;  // part of each cube, -1: outside
};

/// The grids tried for the loop count, coarsest first: the first whose solid has `genus` loops is
/// taken (finer grids resolve thinner handles and narrower gaps).
constexpr int kPartGridSizes[] = {64, 128, 256};

}  // namespace skeleton
