// Generated closed meshes with known answers, for tests, benchmarks and demos.
#pragma once

#include <acd/mesh.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace acd::shapes {

/// Axis-aligned box [lo, hi], 12 triangles.
TriMesh box(const Vec3& lo, const Vec3& hi);

/// Icosahedron subdivided `level` times and projected on the sphere.
TriMesh icosphere(const Vec3& center, double radius, int level);

/// Union of unit cubes: cells[i] = (x, y, z) grid cell. Faces between a filled
/// and an empty cell become two triangles each. Cells must not touch only along
/// an edge or a corner (the result would be non-manifold).
TriMesh voxels(const std::vector<std::array<int, 3>>& cells, double cellSize = 1.0);

/// L: three cells of width `w` in an L in the xy-plane, extruded to depth 1.
TriMesh lShape();
/// U: two arms of height 3 on a base of width 3 (slot 1 wide, 2 deep).
TriMesh uShape();

/// Surface of revolution around z of a profile r(z) > 0 on (z0, z1), closed by poles.
TriMesh revolve(const std::function<double(double)>& radius, double z0, double z1, int rings, int segments);

/// Two balls of radius 1 centred at z = -(1 + gap/2) and z = +(1 + gap/2) joined by a bar of radius `bar`.
TriMesh dumbbell(double gap = 2.0, double bar = 0.15, int rings = 96, int segments = 32);

/// Ring torus around z, radii R > r.
TriMesh torus(double R, double r, int major, int minor);

}  // namespace acd::shapes
