// Triangle soups as modelling tools export them: pieces that overlap, faces that are
// double-sided (each triangle also present reversed), open surfaces. Used to make the
// planner's benchmark scenes (planner_scenes.cpp).
#pragma once

#include <acd/mesh.hpp>

#include <string>
#include <vector>

namespace scenes {

struct Soup {
  std::vector<acd::TriMesh> pieces;  // exported as one COLLADA mesh each
  std::vector<std::string> names;

  void add(const std::string& name, acd::TriMesh piece);
  /// All pieces in one mesh (no vertex shared between pieces).
  acd::TriMesh merged() const;
};

/// The six sides of an axis-aligned box, outward.
acd::TriMesh boxSurface(const acd::Vec3& lo, const acd::Vec3& hi);

/// The box's sides without the ones named in `open` ("-x", "+x", "-y", "+y", "-z", "+z").
acd::TriMesh boxSides(const acd::Vec3& lo, const acd::Vec3& hi, const std::vector<std::string>& open);

/// One quad a-b-c-d (two triangles), facing by the right-hand rule.
acd::TriMesh quad(const acd::Vec3& a, const acd::Vec3& b, const acd::Vec3& c, const acd::Vec3& d);

/// Every triangle also reversed: a face visible from both sides, as exporters write it.
acd::TriMesh doubleSided(const acd::TriMesh& m);

/// Concatenates meshes (no vertex merging).
acd::TriMesh join(const std::vector<acd::TriMesh>& parts);

}  // namespace scenes
