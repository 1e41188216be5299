#include "exact_cgal.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/algo/surface_mesh_copy.hpp>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <vector>

namespace pointloc {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using Side = CGAL::Side_of_triangle_mesh<Mesh, Kernel>;
}  // namespace

struct CgalSideOfMesh::Impl {
  Mesh mesh;
  std::unique_ptr<Tree> tree;
  std::unique_ptr<Side> side;
};

CgalSideOfMesh::CgalSideOfMesh(const acd::TriMesh& input) : impl_(std::make_unique<Impl>()) {
  const auto t0 = acd::Clock::now();
  if (const long f = acd::copyToSurfaceMesh(input, impl_->mesh); f >= 0) {
    error_ = "CGAL Surface_mesh refused face " + std::to_string(f) + " (not a manifold surface)";
    return;
  }
  impl_->tree = std::make_unique<Tree>(faces(impl_->mesh).first, faces(impl_->mesh).second, impl_->mesh);
  impl_->tree->build();
  impl_->side = std::make_unique<Side>(*impl_->tree);
  buildSeconds_ = acd::secondsSince(t0);
}

CgalSideOfMesh::~CgalSideOfMesh() = default;

bool CgalSideOfMesh::inside(const acd::Vec3& p) const {
  return (*impl_->side)(Point(p.x(), p.y(), p.z())) != CGAL::ON_UNBOUNDED_SIDE;
}

}  // namespace pointloc
