#include "fcl_bvh.hpp"

#include <vector>

namespace planner {

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> bvhOf(const acd::TriMesh& m) {
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Vector3d> points(m.vertices.begin(), m.vertices.end());
  std::vector<fcl::Triangle> triangles;
  triangles.reserve(m.faces.size());
  for (const acd::Face& f : m.faces) triangles.emplace_back(f[0], f[1], f[2]);
  model->beginModel();
  model->addSubModel(points, triangles);
  model->endModel();
  return model;
}

}  // namespace planner
