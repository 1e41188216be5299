// A triangle mesh as FCL's bounding-volume hierarchy (soups included: FCL needs no closing).
#pragma once

#include <acd/mesh.hpp>

#include <fcl/geometry/bvh/BVH_model.h>

#include <memory>

namespace planner {

std::shared_ptr<fcl::BVHModel<fcl::OBBRSSd>> bvhOf(const acd::TriMesh& m);

}  // namespace planner
