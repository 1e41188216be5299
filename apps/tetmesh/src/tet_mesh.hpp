// The two geometry types of tetmesh: a piecewise linear complex (TetGen's input) and a
// labelled tetrahedral mesh (its output).
#pragma once

#include <acd/mesh.hpp>

#include <array>
#include <vector>

namespace tetmesh {

using acd::Vec3;

/// Facet markers: where a facet lies in the union of the regions.
enum FacetKind : int { kBoundaryFacet = 1, kInterfaceFacet = 2 };

/// Piecewise linear complex: planar polygons (vertex indices, in order around the polygon)
/// that meet only along shared edges and vertices, and one seed point per region.
struct Plc {
  struct Facet {
    std::vector<int> polygon;
    int marker = kBoundaryFacet;
  };
  struct Region {
    Vec3 seed = Vec3::Zero();  // strictly inside the region
    int label = 0;             // 1-based component number
  };
  std::vector<Vec3> points;
  std::vector<Facet> facets;
  std::vector<Region> regions;
};

/// Tetrahedra with positive volume ((b-a) x (c-a)) . (d-a) > 0, each with a region label.
struct TetMesh {
  std::vector<Vec3> points;
  std::vector<std::array<int, 4>> tets;
  std::vector<int> labels;                 // per tet; 0 when the mesh has no regions
  std::vector<std::array<int, 3>> faces;   // boundary and interface triangles
  std::vector<int> faceMarkers;            // FacetKind per face
};

/// Signed volume of tetrahedron t.
double tetVolume(const TetMesh& mesh, int t);

}  // namespace tetmesh
