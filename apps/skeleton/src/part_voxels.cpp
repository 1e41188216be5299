#include "part_voxels.hpp"

#include <acd/algo/canonical_frame.hpp>
#include <acd/algo/union_find.hpp>
#include "graph.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <unordered_set>

namespace skeleton {

namespace {

/// Signed twice-area of (p, q, (x, y)) projected on xy; computed from the lower end of the edge,
/// so that the edge's two triangles get exactly opposite values and no column slips between them.
double edgeFunction(const Vec3& p, const Vec3& q, double x, double y) {
  const bool flip = std::make_pair(q.x(), q.y()) < std::make_pair(p.x(), p.y());
  const Vec3& s = flip ? q : p;
  const Vec3& t = flip ? p : q;
  const double w = (t.x() - s.x()) * (y - s.y()) - (t.y() - s.y()) * (x - s.x());
  return flip ? -w : w;
}

/// Whether a point on the edge p->q of a counter-clockwise triangle belongs to it: top and left
/// edges do, so that a column through an edge shared by two triangles meets exactly one.
bool topLeft(const Vec3& p, const Vec3& q) {
  const double dx = q.x() - p.x(), dy = q.y() - p.y();
  return dy < 0 || (dy == 0 && dx > 0);
}

// Cells of the grid's lattice: a vertex, an edge along an axis, a face across an axis.
enum CellType { kVertex = 0, kEdgeX = 1, kFaceX = 4, kCellTypes = 7 };

}  // namespace

PartVoxels::PartVoxels(const std::vector<acd::TriMesh>& components, const std::vector<int>& partOf, int cellsAcross) {
  const acd::Normalization frame = acd::canonicalFrame(components);
  const double h = 2.0 / cellsAcross;
  std::vector<std::vector<Vec3>> points(components.size());
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t c = 0; c < components.size(); ++c)
    for (const Vec3& v : components[c].vertices) {
      points[c].push_back(frame.apply(v));
      lo = lo.cwiseMin(points[c].back());
      hi = hi.cwiseMax(points[c].back());
    }
  if (!(lo.x() <= hi.x())) return;
  int first[3];
  for (int d = 0; d < 3; ++d) {
    first[d] = static_cast<int>(std::floor(lo[d] / h)) - 1;  // one empty layer round the solid
    n_[d] = static_cast<int>(std::ceil(hi[d] / h)) + 1 - first[d];
  }
  label_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2], -1);
  const auto centre = [&](int d, int i) { return (first[d] + i + 0.5) * h; };

  // Columns along z through the cube centres: a component's crossings in a column, paired in
  // height order, bound the cubes inside it.
  for (std::size_t c = 0; c < components.size(); ++c) {
    std::unordered_map<std::int64_t, std::vector<double>> crossings;
    for (const acd::Face& f : components[c].faces) {
      Vec3 p = points[c][f[0]], q = points[c][f[1]], r = points[c][f[2]];
      const double area = edgeFunction(p, q, r.x(), r.y());
      if (area == 0) continue;  // seen edge-on: the neighbours count the column
      if (area < 0) std::swap(q, r);
      const double a = std::abs(area);
      const int x0 = std::max(0, static_cast<int>(std::floor(std::min({p.x(), q.x(), r.x()}) / h - first[0] - 0.5)));
      const int x1 = std::min(n_[0] - 1, static_cast<int>(std::ceil(std::max({p.x(), q.x(), r.x()}) / h - first[0] - 0.5)));
      const int y0 = std::max(0, static_cast<int>(std::floor(std::min({p.y(), q.y(), r.y()}) / h - first[1] - 0.5)));
      const int y1 = std::min(n_[1] - 1, static_cast<int>(std::ceil(std::max({p.y(), q.y(), r.y()}) / h - first[1] - 0.5)));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const double cx = centre(0, x), cy = centre(1, y);
          const double wp = edgeFunction(q, r, cx, cy), wq = edgeFunction(r, p, cx, cy), wr = edgeFunction(p, q, cx, cy);
          const bool inside = (wp > 0 || (wp == 0 && topLeft(q, r))) && (wq > 0 || (wq == 0 && topLeft(r, p))) &&
                              (wr > 0 || (wr == 0 && topLeft(p, q)));
          if (!inside) continue;
          crossings[static_cast<std::int64_t>(y) * n_[0] + x].push_back((wp * p.z() + wq * q.z() + wr * r.z()) / a);
        }
    }
    for (auto& [column, zs] : crossings) {
      std::sort(zs.begin(), zs.end());
      const int x = static_cast<int>(column % n_[0]), y = static_cast<int>(column / n_[0]);
      for (std::size_t k = 0; k + 1 < zs.size(); k += 2) {
        const int z0 = std::max(0, static_cast<int>(std::ceil(zs[k] / h - first[2] - 0.5)));
        const int z1 = std::min(n_[2] - 1, static_cast<int>(std::floor(zs[k + 1] / h - first[2] - 0.5)));
        for (int z = z0; z <= z1; ++z) label_[index(x, y, z)] = partOf[c];
      }
    }
  }
}

long long PartVoxels::eulerCharacteristic(int only) const {
  long long chi = 0;
  const auto in = [this, only](int x, int y, int z) { return filled(x, y, z, only); };
  for (int z = 0; z <= n_[2]; ++z)
    for (int y = 0; y <= n_[1]; ++y)
      for (int x = 0; x <= n_[0]; ++x) {
        // Each lattice point owns the vertex there, the edges and faces leaving it upwards, and the cube above.
        const bool c000 = in(x, y, z), c100 = in(x - 1, y, z), c010 = in(x, y - 1, z), c110 = in(x - 1, y - 1, z);
        const bool c001 = in(x, y, z - 1), c101 = in(x - 1, y, z - 1), c011 = in(x, y - 1, z - 1),
                   c111 = in(x - 1, y - 1, z - 1);
        chi += c000 || c100 || c010 || c110 || c001 || c101 || c011 || c111;  // vertex
        chi -= c000 || c010 || c001 || c011;                                    // edge along x
        chi -= c000 || c100 || c001 || c101;                                    // edge along y
        chi -= c000 || c100 || c010 || c110;                                    // edge along z
        chi += c000 || c100;                                                    // face across x
        chi += c000 || c010;                                                    // face across y
        chi += c000 || c001;                                                    // face across z
        chi -= c000;                                                            // cube
      }
  return chi;
}

int PartVoxels::loops(int only) const {
  if (label_.empty()) return 0;
  // Pieces: cubes joined through any common corner (closed cubes); cavities: empty cubes joined
  // through faces, less the one outside (the empty layer round the grid holds it).
  const auto count = [this, only](bool solid) {
    std::vector<char> seen(label_.size(), 0);
    std::vector<std::array<int, 3>> stack;
    int groups = 0;
    for (int z = 0; z < n_[2]; ++z)
      for (int y = 0; y < n_[1]; ++y)
        for (int x = 0; x < n_[0]; ++x) {
          if (filled(x, y, z, only) != solid || seen[index(x, y, z)]) continue;
          ++groups;
          seen[index(x, y, z)] = 1;
          stack.push_back({x, y, z});
          while (!stack.empty()) {
            const auto [cx, cy, cz] = stack.back();
            stack.pop_back();
            for (int dz = -1; dz <= 1; ++dz)
              for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                  if (!solid && std::abs(dx) + std::abs(dy) + std::abs(dz) != 1) continue;
                  const int nx = cx + dx, ny = cy + dy, nz = cz + dz;
                  if (nx < 0 || ny < 0 || nz < 0 || nx >= n_[0] || ny >= n_[1] || nz >= n_[2]) continue;
                  if (filled(nx, ny, nz, only) != solid || seen[index(nx, ny, nz)]) continue;
                  seen[index(nx, ny, nz)] = 1;
                  stack.push_back({nx, ny, nz});
                }
          }
        }
    return groups;
  };
  const long long pieces = count(true), cavities = count(false) - 1;
  return static_cast<int>(pieces + cavities - eulerCharacteristic(only));
}

int PartVoxels::loopsThrough(int a, int b, bool joinedElsewhere) const {
  // Lattice cells by (point, type); a cell's cubes by type.
  const auto key = [this](int x, int y, int z, int type) {
    return ((static_cast<std::int64_t>(z) * (n_[1] + 1) + y) * (n_[0] + 1) + x) * kCellTypes + type;
  };
  // The cubes a cell bounds, into `cubes`; returns how many (8, 4 or 2).
  const auto cubesOf = [](int x, int y, int z, int type, std::array<std::array<int, 3>, 8>& cubes) {
    if (type == kVertex) {
      for (int k = 0; k < 8; ++k) cubes[k] = {x - (k & 1), y - ((k >> 1) & 1), z - ((k >> 2) & 1)};
      return 8;
    }
    if (type < kFaceX) {  // an edge along axis d: the four cubes round it
      const int d = type - kEdgeX, u = (d + 1) % 3, v = (d + 2) % 3;
      for (int k = 0; k < 4; ++k) {
        cubes[k] = {x, y, z};
        cubes[k][u] -= k & 1;
        cubes[k][v] -= (k >> 1) & 1;
      }
      return 4;
    }
    const int d = type - kFaceX;  // a face across axis d: the cubes on both sides
    cubes[0] = cubes[1] = {x, y, z};
    cubes[1][d] -= 1;
    return 2;
  };
  std::array<std::array<int, 3>, 8> cubes;
  std::unordered_set<std::int64_t> visited;
  long long change = 0;
  std::vector<std::int64_t> contactFaces;
  std::unordered_map<std::int64_t, std::vector<int>> facesOfEdge;
  for (int z = 0; z < n_[2]; ++z)
    for (int y = 0; y < n_[1]; ++y)
      for (int x = 0; x < n_[0]; ++x) {
        if (at(x, y, z) != a) continue;
        // The cube's closure: its 8 corners, 12 edges, 6 faces.
        for (int k = 0; k < 8; ++k) {
          const int cx = x + (k & 1), cy = y + ((k >> 1) & 1), cz = z + ((k >> 2) & 1);
          for (int type = 0; type < kCellTypes; ++type) {
            // From corner k, the cell of this type whose lowest point it is, when it is in the cube.
            if (type >= kEdgeX && type < kFaceX) {
              const int d = type - kEdgeX;
              if ((k >> d) & 1) continue;
            } else if (type >= kFaceX) {
              const int d = type - kFaceX, u = (d + 1) % 3, v = (d + 2) % 3;
              if (((k >> u) & 1) || ((k >> v) & 1)) continue;
            }
            const std::int64_t id = key(cx, cy, cz, type);
            if (!visited.insert(id).second) continue;
            bool seenA = false, seenB = false, other = false;
            const int count = cubesOf(cx, cy, cz, type, cubes);
            for (int i = 0; i < count; ++i) {
              const int l = at(cubes[i][0], cubes[i][1], cubes[i][2]);
              seenA |= l == a;
              seenB |= l == b;
              other |= l >= 0 && l != a && l != b;
            }
            if (!seenA || !seenB || other) continue;
            const int dimension = type == kVertex ? 0 : type < kFaceX ? 1 : 2;
            change += dimension == 1 ? -1 : 1;
            if (dimension == 2) {
              const int d = type - kFaceX, u = (d + 1) % 3, v = (d + 2) % 3;
              const int face = static_cast<int>(contactFaces.size());
              contactFaces.push_back(id);
              for (int e = 0; e < 4; ++e) {  // the face's four edges, along u and v
                std::array<int, 3> p{cx, cy, cz};
                const int along = e < 2 ? u : v, across = e < 2 ? v : u;
                p[across] += e & 1;
                facesOfEdge[key(p[0], p[1], p[2], kEdgeX + along)].push_back(face);
              }
            }
          }
        }
      }
  acd::UnionFind patches(static_cast<int>(contactFaces.size()));
  for (const auto& [edge, faces] : facesOfEdge)
    for (std::size_t i = 1; i < faces.size(); ++i) patches.join(patches.find(faces[i]), patches.find(faces[0]));
  int k = 0;
  for (int f = 0; f < static_cast<int>(contactFaces.size()); ++f) k += patches.find(f) == f;
  return static_cast<int>(change) - std::max(0, k - 1) - (joinedElsewhere ? 0 : 1);
}

}  // namespace skeleton
