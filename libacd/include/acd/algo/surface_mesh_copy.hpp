// A TriMesh copied into a CGAL::Surface_mesh of any kernel and back: the one place where mesh
// vertices and faces become CGAL's and return. Templates on the CGAL type, so that this header
// needs no CGAL include.
#pragma once

#include <acd/mesh.hpp>

#include <vector>

namespace acd {

/// What to do with a face CGAL refuses (it does not fit an oriented manifold surface there).
enum class RefusedFace {
  Stop,  // stop copying: the caller reports the face and gives up
  Skip,  // leave it out and copy the others
};

/// Appends `mesh` to `out`: vertex i becomes the i-th vertex added, faces follow in order.
/// Returns the index of the first face CGAL refused, or -1 when every face was added.
template <class SurfaceMesh>
long copyToSurfaceMesh(const TriMesh& mesh, SurfaceMesh& out, RefusedFace onRefused = RefusedFace::Stop) {
  using Point = typename SurfaceMesh::Point;
  using Vertex = typename SurfaceMesh::Vertex_index;
  std::vector<Vertex> ids;
  ids.reserve(mesh.vertices.size());
  for (const Vec3& p : mesh.vertices) ids.push_back(out.add_vertex(Point(p.x(), p.y(), p.z())));
  long refused = -1;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const Face& t = mesh.faces[f];
    if (out.add_face(ids[t[0]], ids[t[1]], ids[t[2]]) != SurfaceMesh::null_face()) continue;
    if (refused < 0) refused = static_cast<long>(f);
    if (onRefused == RefusedFace::Stop) break;
  }
  return refused;
}

/// The surface as a TriMesh: vertex i is the i-th vertex, each face from its halfedge's source.
/// `in` must have no garbage (call collect_garbage() after removing elements).
template <class SurfaceMesh>
TriMesh copyFromSurfaceMesh(const SurfaceMesh& in) {
  TriMesh out;
  out.vertices.reserve(in.number_of_vertices());
  for (auto v : in.vertices()) {
    const auto& p = in.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());  // a kernel with double coordinates
  }
  out.faces.reserve(in.number_of_faces());
  for (auto f : in.faces()) {
    const auto h = in.halfedge(f);
    out.faces.push_back({static_cast<int>(in.source(h)), static_cast<int>(in.target(h)),
                         static_cast<int>(in.target(in.next(h)))});
  }
  return out;
}

}  // namespace acd
