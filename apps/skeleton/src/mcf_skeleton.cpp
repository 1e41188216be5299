// The only translation unit that instantiates CGAL's skeletonization (slow to compile).
#include "mcf_skeleton.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/algo/surface_mesh_copy.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>

#include <exception>

namespace skeleton {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<Mesh>;
}  // namespace

McfSkeleton meanCurvatureSkeleton(const acd::TriMesh& input) {
  const auto start = acd::Clock::now();
  McfSkeleton out;
  Mesh mesh;
  if (acd::copyToSurfaceMesh(input, mesh) >= 0) {
    out.error = "the mesh is not an oriented 2-manifold (CGAL refused a face)";
    return out;
  }
  if (!CGAL::is_closed(mesh)) {
    out.error = "the mesh is not closed";
    return out;
  }
  try {
    Skeletonization::Skeleton skel;
    CGAL::extract_mean_curvature_flow_skeleton(mesh, skel);
    std::vector<int> node(boost::num_vertices(skel), -1);
    for (auto v : CGAL::make_range(boost::vertices(skel))) {
      const auto& p = skel[v].point;
      node[v] = out.graph.addNode(Vec3(p.x(), p.y(), p.z()), NodeKind::Curve);
    }
    for (auto e : CGAL::make_range(boost::edges(skel)))
      out.graph.addEdge(node[boost::source(e, skel)], node[boost::target(e, skel)]);
    out.ok = true;
  } catch (const std::exception& e) {
    out.error = std::string("CGAL skeletonization failed: ") + e.what();
  }
  out.seconds = acd::secondsSince(start);
  return out;
}

}  // namespace skeleton
