// A frame that moves with the shape, so that a decomposition depends on the shape only: the
// same cuts, in the same order, whatever rotation, translation or face order the input came in.
#pragma once

#include <acd/mesh.hpp>
#include <acd/algo/normalize.hpp>

#include <unordered_map>
#include <vector>

namespace acd {

/// Origin and unit of the minimum enclosing sphere (the paper's units); axes along the principal
/// axes of the surface's area second moments about its centroid, largest first, right-handed, the
/// two with the larger third moments pointing where those are positive. Shapes whose second
/// moments have equal eigenvalues (a cube, a sphere) or with two vanishing third moments have no
/// unique frame; one of the candidates is taken.
Normalization canonicalFrame(const std::vector<TriMesh>& pieces);

/// `frame` turned so that the planes holding the most surface lie across its axes: the line of
/// face normals (n or -n) with the largest area becomes the first axis, the largest line
/// perpendicular to it the second. Points of such a plane then share one coordinate exactly once
/// rounded to kCanonicalGrid, in every pose, as they did in a CAD part's own axes (in `frame`
/// itself they differ by ulps, and rounding can split them). `frame` itself where no line holds
/// kLeastAlignedArea of the surface. Origin and scale stay `frame`'s.
Normalization faceAlignedFrame(const std::vector<TriMesh>& pieces, const Normalization& frame);
constexpr double kLeastAlignedArea = 0.05;

/// Coordinates are rounded to this grid (normalised units) in the canonical frame, so that a frame
/// computed a few ulps differently after a rigid motion gives bit-identical coordinates.
constexpr double kCanonicalGrid = 1.0 / (1 << 22);

/// A mesh in canonical form and, for each of its vertices, the index it had in the input.
struct CanonicalMesh {
  TriMesh mesh;
  std::vector<int> source;
};

/// The mesh in frame `n`, coordinates rounded to kCanonicalGrid, vertices sorted lexicographically,
/// each face starting at its smallest vertex index (orientation kept), faces sorted.
CanonicalMesh canonicalMesh(const TriMesh& mesh, const Normalization& n);

/// Lexicographic order of two meshes in canonical form (vertex count, coordinates, then faces).
bool canonicalLess(const TriMesh& a, const TriMesh& b);

/// Brings coordinates from the canonical frame back to the input's: a vertex of the input comes
/// back as exactly the input's coordinates, any other point (on a cut) through n.undo.
class CanonicalInverse {
 public:
  explicit CanonicalInverse(const Normalization& n) : frame_(n) {}
  void add(const CanonicalMesh& canonical, const TriMesh& input);
  Vec3 operator()(const Vec3& canonicalPoint) const;
  TriMesh operator()(const TriMesh& canonicalMesh) const;
  /// Through n.undo, whether the point is an input vertex or not.
  Vec3 undo(const Vec3& canonicalPoint) const { return frame_.undo(canonicalPoint); }

 private:
  struct KeyHash {
    std::size_t operator()(const Vec3& p) const;
  };
  struct KeyEqual {
    bool operator()(const Vec3& a, const Vec3& b) const { return a.x() == b.x() && a.y() == b.y() && a.z() == b.z(); }
  };
  Normalization frame_;
  std::unordered_map<Vec3, Vec3, KeyHash, KeyEqual> exact_;
};

}  // namespace acd
