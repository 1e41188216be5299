// CGAL's mean-curvature-flow skeleton (Tagliasacchi et al. 2012, as
// `CGAL::extract_mean_curvature_flow_skeleton`), for comparison with the ACD skeleton.
// Its size is not reproducible: it varies between runs (heap layout) and under rigid motion
// (the default minimum edge length is relative to the bounding box).
#pragma once

#include "graph.hpp"

#include <acd/mesh.hpp>

#include <string>

namespace skeleton {

struct McfSkeleton {
  bool ok = false;
  std::string error;    // why there is no skeleton (not a closed triangle mesh, CGAL failure)
  Graph graph;          // one Curve node per skeleton vertex, at its position
  double seconds = 0.0;
};

/// Skeleton of a closed mesh with CGAL's default parameters. Never throws.
McfSkeleton meanCurvatureSkeleton(const acd::TriMesh& mesh);

}  // namespace skeleton
