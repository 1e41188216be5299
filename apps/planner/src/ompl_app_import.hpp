// A mesh file imported the way OMPL.app imports it (RigidBodyGeometry): assimp with OMPL.app's
// post-processing (generate normals, triangulate, join identical vertices, sort by primitive
// type, optimise the graph), every vertex moved by its node's transformation, and the
// robot's reference point at the mean of those vertices. Flat-shaded files repeat a corner
// once per distinct normal, so that mean is not the mean of the distinct corners.
#pragma once

#include <acd/mesh.hpp>

#include <optional>
#include <string>

namespace planner {

struct OmplAppImport {
  acd::TriMesh triangles;   // the triangles OMPL.app collides with
  acd::Vec3 center;         // OMPL.app's getRobotCenter for this file
};

/// `upAxis`: apply COLLADA's <up_axis> and <unit> as assimp does by default (OMPL.app's
/// frame); false: coordinates as written (libacd's scene reader, the YAML scenarios).
/// Nothing when assimp cannot read the file or finds no triangle. Call only on files the
/// sandboxed reader has accepted (this one runs assimp in this process).
std::optional<OmplAppImport> importAsOmplApp(const std::string& path, bool upAxis);

}  // namespace planner
