// A generated set of the broken meshes people export (Blender, CAD, scans, game assets), one
// per class of problem, each with what acd must do with it. Used by tests/driver/test_robust.cpp and
// written to a folder by the `bad_meshes` program (bench/bad_meshes.sh runs the CLI on them).
// Nothing here is a copy of a real file: every mesh is built from boxes and spheres.
#pragma once

#include <acd/mesh.hpp>
#include <acd/algo/shapes.hpp>
#include <acd/status.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace badmeshes {

using acd::Face;
using acd::TriMesh;
using acd::Vec3;

enum class Outcome {
  Input,    // decomposed; every component is a piece of the (repaired) input
  Wrap,     // decomposed; some components are pieces of the watertight wrap
  Refused,  // refused with a one-line reason (exit 2)
};

struct Case {
  std::string name;
  std::string problem;  // what is wrong, one line
  TriMesh mesh;
  Outcome outcome;
  bool holes = false;   // patches are added: component vertices need not lie on the input surface
};

inline TriMesh box(const Vec3& lo, const Vec3& hi) { return acd::shapes::box(lo, hi); }

inline TriMesh join(const TriMesh& a, const TriMesh& b) { return acd::concatenate({a, b}); }

inline TriMesh reversed(TriMesh m) {
  for (Face& f : m.faces) std::swap(f[1], f[2]);
  return m;
}

/// The faces of `m` as a soup: three vertices of its own per face (STL).
inline TriMesh soup(const TriMesh& m, double noise = 0.0) {
  TriMesh out;
  unsigned state = 7;
  auto jitter = [&]() {
    state = state * 1103515245u + 12345u;
    return noise * ((static_cast<double>((state >> 8) & 0xffff) / 65536.0) - 0.5);
  };
  for (const Face& f : m.faces) {
    const int base = static_cast<int>(out.vertices.size());
    for (int v : f) out.vertices.push_back(m.vertices[v] + Vec3(jitter(), jitter(), jitter()));
    out.faces.push_back({base, base + 1, base + 2});
  }
  return out;
}

/// The unit box with edge 0-1 (from (0,0,0) to (1,0,0)) split at `t` by a vertex, the two faces
/// on that edge split accordingly; `degenerate` adds the zero-area face (M, A, B) instead of
/// splitting the second face, which keeps the mesh closed and consistently oriented.
inline TriMesh boxWithSplitEdge(double t, bool degenerate) {
  TriMesh m = box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const int a = 0, b = 1;
  const int mid = static_cast<int>(m.vertices.size());
  m.vertices.push_back((1 - t) * m.vertices[a] + t * m.vertices[b]);
  std::vector<Face> faces;
  bool firstSplit = false;
  for (const Face& f : m.faces) {
    int k = -1;
    for (int i = 0; i < 3; ++i)
      if ((f[i] == a && f[(i + 1) % 3] == b) || (f[i] == b && f[(i + 1) % 3] == a)) k = i;
    if (k < 0) {
      faces.push_back(f);
      continue;
    }
    const int u = f[k], v = f[(k + 1) % 3], w = f[(k + 2) % 3];
    if (degenerate && firstSplit) {
      faces.push_back(f);  // keeps edge u-v; the zero-area face below closes the gap
      faces.push_back({mid, v, u});
      continue;
    }
    faces.push_back({u, mid, w});
    faces.push_back({mid, v, w});
    firstSplit = true;
  }
  m.faces = faces;
  return m;
}

/// The unit box with its top face meshed apart from the sides, as CAD exporters mesh each face on
/// its own: the top has a vertex in the middle of each of its four edges (and a centre), the side
/// faces have those edges whole. Four cracks of zero width (T-junctions).
inline TriMesh boxWithMeshedApartTop() {
  TriMesh m = box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::vector<Face> faces;
  for (const Face& f : m.faces)
    if (!(m.vertices[f[0]].z() == 1 && m.vertices[f[1]].z() == 1 && m.vertices[f[2]].z() == 1)) faces.push_back(f);
  auto index = [&](const Vec3& p) {
    for (int v = 0; v < static_cast<int>(m.vertices.size()); ++v)
      if (m.vertices[v] == p) return v;
    m.vertices.push_back(p);
    return static_cast<int>(m.vertices.size()) - 1;
  };
  const double ring[8][2] = {{0, 0}, {0.5, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0.5, 1}, {0, 1}, {0, 0.5}};  // counter-clockwise from above
  const int centre = index(Vec3(0.5, 0.5, 1));
  for (int i = 0; i < 8; ++i)
    faces.push_back({centre, index(Vec3(ring[i][0], ring[i][1], 1)), index(Vec3(ring[(i + 1) % 8][0], ring[(i + 1) % 8][1], 1))});
  m.faces = faces;
  return m;
}

/// A box [0,1]^3 with a triangle fin hanging off the edge from vertex 0 to vertex 2.
inline TriMesh boxWithFin() {
  TriMesh m = box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const int apex = static_cast<int>(m.vertices.size());
  m.vertices.emplace_back(-0.6, -0.6, 0.5);
  m.faces.push_back({m.faces[0][0], m.faces[0][1], apex});
  return m;
}

/// Two boxes given as one vertex set, glued along one edge (4 faces on it) or one corner.
inline TriMesh boxesSharing(bool edge) {
  TriMesh a = box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  TriMesh b = box(edge ? Vec3(1, 1, 0) : Vec3(1, 1, 1), edge ? Vec3(2, 2, 1) : Vec3(2, 2, 2));
  return join(a, b);  // shared positions, separate indices: the merge of close vertices joins them
}

/// A flat square sheet in both orientations: a double-sided plane with no volume.
inline TriMesh doubleSidedSheet() {
  TriMesh m{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}, {{0, 1, 2}, {0, 2, 3}}};
  return join(m, reversed(m));
}

/// Two unit cells side by side, each closed on its own: the wall between them is given twice,
/// once per cell, in opposite orientations (an inner wall that closes nothing).
inline TriMesh twoCellsWithInnerWall() {
  return join(box(Vec3(0, 0, 0), Vec3(1, 1, 1)), box(Vec3(1, 0, 0), Vec3(2, 1, 1)));
}

/// A heightfield: an open, bumpy terrain sheet whose boundary loop is not planar.
inline TriMesh terrain(int n = 12) {
  TriMesh m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = double(i) / n, y = double(j) / n;
      m.vertices.emplace_back(x, y, 0.15 * std::sin(6 * x) * std::cos(5 * y));
    }
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

/// A sphere with one vertex pulled through to the far side: a single shell crossing itself.
inline TriMesh foldedSphere() {
  TriMesh m = acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, 2);
  m.vertices[0] = -1.6 * m.vertices[0];
  return m;
}

/// A point from three draws in x, y, z order (in Vec3(random(), random(), random()) the order is
/// the compiler's: GCC and clang would build different meshes).
template <class Draw>
Vec3 point(Draw& draw) {
  const double x = draw();
  const double y = draw();
  const double z = draw();
  return Vec3(x, y, z);
}

/// Scattered, disconnected triangles: what is left of a game asset's decals and cards.
inline TriMesh triangleSoupCloud(int count = 40) {
  TriMesh m;
  unsigned state = 99;
  auto random = [&]() {
    state = state * 1103515245u + 12345u;
    return static_cast<double>((state >> 8) & 0xffff) / 65536.0;
  };
  for (int i = 0; i < count; ++i) {
    const Vec3 c = point(random);
    const int base = static_cast<int>(m.vertices.size());
    for (int k = 0; k < 3; ++k) m.vertices.push_back(c + 0.15 * (point(random) - Vec3(0.5, 0.5, 0.5)));
    m.faces.push_back({base, base + 1, base + 2});
  }
  return m;
}

/// Every class of problem, in a fixed order.
inline std::vector<Case> all() {
  std::vector<Case> c;
  const TriMesh unit = box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  c.push_back({"clean_box", "nothing wrong (control)", unit, Outcome::Input});
  c.push_back({"zero_area_face", "a zero-area face (three collinear corners) in a closed box",
               boxWithSplitEdge(0.5, true), Outcome::Input});
  c.push_back({"needle_faces", "two needle faces: a vertex 3e-6 from a corner on an edge",
               boxWithSplitEdge(3e-6, false), Outcome::Input});
  c.push_back({"stl_soup", "every face with its own three vertices (STL)", soup(unit), Outcome::Input});
  c.push_back({"float_noise_soup", "a soup whose copies of a corner differ by float rounding (1e-8)",
               soup(acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, 2), 1e-8), Outcome::Input});
  {
    TriMesh m = unit;
    m.faces.push_back({m.faces[4][0], m.faces[4][2], m.faces[4][1]});
    c.push_back({"double_sided_face", "a face duplicated in the opposite orientation", m, Outcome::Input});
  }
  {
    TriMesh m = unit;
    m.faces.push_back(m.faces[5]);
    c.push_back({"duplicate_face", "a face given twice", m, Outcome::Input});
  }
  c.push_back({"inner_wall", "two cells whose shared wall is given once per cell (both orientations)",
               twoCellsWithInnerWall(), Outcome::Input});
  {
    TriMesh m = unit;
    for (int f : {1, 4, 7}) std::swap(m.faces[f][1], m.faces[f][2]);
    c.push_back({"inconsistent_orientation", "three faces turned against their neighbours", m, Outcome::Input});
  }
  c.push_back({"inside_out", "every face turned inward", reversed(unit), Outcome::Input});
  c.push_back({"non_manifold_edge_3", "an edge shared by 3 faces (a fin on a box)", boxWithFin(), Outcome::Wrap});
  c.push_back({"non_manifold_edge_4", "two boxes sharing an edge (4 faces on it)", boxesSharing(true), Outcome::Input});
  c.push_back({"non_manifold_vertex", "two boxes sharing a corner", boxesSharing(false), Outcome::Input});
  {
    TriMesh m = unit;
    m.faces.erase(m.faces.begin() + 2);
    c.push_back({"hole_patchable", "a missing face (a hole a patch closes)", m, Outcome::Input, true});
  }
  c.push_back({"t_junctions", "a box whose top face was meshed apart: its edges split on one side of the seam only",
               boxWithMeshedApartTop(), Outcome::Input});
  c.push_back({"hole_unpatchable", "an open terrain sheet: no patch closes it into a solid", terrain(), Outcome::Wrap});
  c.push_back({"double_sided_sheet", "a flat sheet given in both orientations", doubleSidedSheet(), Outcome::Wrap});
  c.push_back({"self_intersecting", "a sphere with a vertex pulled through its far side", foldedSphere(),
               Outcome::Wrap});  // a component stays above tau on the input: its shell is wrapped
  c.push_back({"triangle_cloud", "40 scattered, disconnected triangles", triangleSoupCloud(), Outcome::Wrap});
  c.push_back({"shells_disjoint", "two separate boxes",
               join(unit, box(Vec3(3, 0, 0), Vec3(4, 1, 1))), Outcome::Input});
  c.push_back({"nested_cavity", "a box with a cavity (inner shell facing inward)",
               join(box(Vec3(0, 0, 0), Vec3(3, 3, 3)), reversed(box(Vec3(1, 1, 1), Vec3(2, 2, 2)))), Outcome::Input});
  c.push_back({"nested_cavity_outward", "a box with a cavity whose shell faces outward (common export error)",
               join(box(Vec3(0, 0, 0), Vec3(3, 3, 3)), box(Vec3(1, 1, 1), Vec3(2, 2, 2))), Outcome::Input});
  c.push_back({"solid_in_cavity", "a hollow box with a loose box inside its cavity",
               join(join(box(Vec3(0, 0, 0), Vec3(5, 5, 5)), reversed(box(Vec3(1, 1, 1), Vec3(4, 4, 4)))),
                    box(Vec3(2, 2, 2), Vec3(3, 3, 3))),
               Outcome::Input});
  c.push_back({"shells_touching", "two boxes touching face to face, vertices not shared",
               join(unit, box(Vec3(1, 0.25, 0.25), Vec3(2, 0.75, 0.75))), Outcome::Input});
  c.push_back({"shells_overlapping", "two boxes passing through each other",
               join(box(Vec3(0, 0, 0), Vec3(2, 2, 2)), box(Vec3(1, 1, 1), Vec3(3, 3, 3))), Outcome::Input});
  {
    TriMesh m = unit;
    m.vertices[3].y() = std::numeric_limits<double>::quiet_NaN();
    c.push_back({"non_finite_vertex", "a vertex with a NaN coordinate", m, Outcome::Refused});
  }
  {
    TriMesh m = unit;
    m.faces[0][1] = 42;
    c.push_back({"index_out_of_range", "a face referring to a vertex that does not exist", m, Outcome::Refused});
  }
  return c;
}

/// The mesh of the case called `name` (throws for an unknown name).
inline TriMesh byName(const std::string& name) {
  static const std::vector<Case> cases = all();
  for (const Case& c : cases)
    if (c.name == name) return c.mesh;
  throw std::runtime_error("no bad-mesh case " + name);
}

}  // namespace badmeshes
