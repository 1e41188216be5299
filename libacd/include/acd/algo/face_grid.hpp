// A uniform grid over the faces of some meshes, for the face nearest to a point: a query touches
// the cells around the point, not the whole surface, and the grid costs a few bytes per face.
#pragma once

#include <acd/algo/float_bounds.hpp>
#include <acd/mesh.hpp>

#include <array>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace acd {

class FaceGrid {
 public:
  /// About one face per cell, over the box of all the meshes' vertices. The meshes must outlive it.
  explicit FaceGrid(std::vector<const TriMesh*> meshes);

  struct Nearest {
    int mesh = -1;  // which mesh holds the nearest face; -1 when none was found
    int face = -1;  // which face of it
    double distance = std::numeric_limits<double>::infinity();
  };

  /// The nearest face's mesh and its distance; equal distances go to the lower mesh index. The
  /// search may stop once every face not seen lies farther than `within`: a distance above
  /// `within` only says that the true one is above it too.
  Nearest nearest(const Vec3& p, double within = std::numeric_limits<double>::infinity()) const;

 private:
  /// The cell index along `axis` of coordinate x, clamped to the grid.
  int cellOf(double x, int axis) const;
  /// The squared distance from p to cell (i, j, k)'s box, less rounding's worth (a lower bound).
  double cellDistance2(const Vec3& p, int i, int j, int k) const;
  template <class Visit>
  void forEachFaceCell(const Visit& visit) const;


  std::vector<const TriMesh*> meshes_;
  double cell_ = 1.0;
  Vec3 lo_ = Vec3::Zero();
  std::array<int, 3> dims_{};
  std::vector<int> firstFace_;        // by mesh, its first face's number among all (and the count)
  // by face number, in floats rounded outward (it still holds the face): the test that skips most
  // faces of a cell reads 24 bytes in a row instead of three vertices elsewhere
  std::vector<FloatBox> boxes_;
  std::vector<std::size_t> start_;    // by cell, into entries_
  std::vector<int> entries_;          // face numbers by cell
};

}  // namespace acd
