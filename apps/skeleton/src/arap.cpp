// The only translation unit that instantiates CGAL's Surface_mesh_deformation (slow to compile).
#include "arap.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/algo/surface_mesh_copy.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_deformation.h>

#include <Eigen/Geometry>

#include <cmath>
#include <exception>

namespace skeleton {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Deformation = CGAL::Surface_mesh_deformation<Mesh>;
}  // namespace

ArapResult arapDeform(const acd::TriMesh& input, const ArapRequest& request) {
  const auto start = acd::Clock::now();
  ArapResult out;
  const int n = static_cast<int>(input.vertices.size());
  for (const std::vector<int>* list : {&request.handle, &request.region})
    for (int v : *list)
      if (v < 0 || v >= n) {
        out.error = "vertex id " + std::to_string(v) + " out of range (the mesh has " + std::to_string(n) + " vertices)";
        return out;
      }
  if (request.handle.empty()) {
    out.error = "the handle is empty";
    return out;
  }
  if (!(request.axis.norm() > 0.0) || !std::isfinite(request.angleDegrees) || !request.pivot.allFinite()) {
    out.error = "the rotation needs a non-zero axis and finite angle and pivot";
    return out;
  }
  Mesh mesh;
  if (acd::copyToSurfaceMesh(input, mesh) >= 0) {
    out.error = "the mesh is not an oriented 2-manifold (CGAL refused a face)";
    return out;
  }
  try {
    Deformation deformation(mesh);
    for (int v : request.region) deformation.insert_roi_vertex(Mesh::Vertex_index(v));
    for (int v : request.handle) deformation.insert_control_vertex(Mesh::Vertex_index(v));  // also joins the region
    if (!deformation.preprocess()) {
      out.error = "ARAP preprocessing failed (singular system: is every free vertex connected to a fixed one?)";
      return out;
    }
    const Eigen::AngleAxisd rotation(request.angleDegrees * M_PI / 180.0, request.axis.normalized());
    for (int v : request.handle) {
      const Vec3 q = request.pivot + rotation * (input.vertices[v] - request.pivot);
      deformation.set_target_position(Mesh::Vertex_index(v), Kernel::Point_3(q.x(), q.y(), q.z()));
    }
    deformation.deform(static_cast<unsigned int>(std::max(1, request.iterations)), 0.0);
    out.mesh = input;
    for (int v = 0; v < n; ++v) {
      const auto& p = mesh.point(Mesh::Vertex_index(v));
      out.mesh.vertices[v] = Vec3(p.x(), p.y(), p.z());
      if (!out.mesh.vertices[v].allFinite()) {
        out.error = "ARAP produced a non-finite vertex";
        return out;
      }
    }
    out.ok = true;
  } catch (const std::exception& e) {
    out.error = std::string("CGAL deformation failed: ") + e.what();
  }
  out.seconds = acd::secondsSince(start);
  return out;
}

}  // namespace skeleton
