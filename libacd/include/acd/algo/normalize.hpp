// The paper's units: the model scaled so that its minimum enclosing sphere has radius 1.
#pragma once

#include <acd/mesh.hpp>

namespace acd {

/// x_normalised = rotation * (x - center) * scale.
struct Normalization {
  Vec3 center = Vec3::Zero();
  double scale = 1.0;  // 1 / radius of the minimum enclosing sphere
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // rows: the frame's axes (acd/algo/canonical_frame.hpp)

  Vec3 apply(const Vec3& p) const { return rotation * ((p - center) * scale); }
  Vec3 undo(const Vec3& p) const { return rotation.transpose() * p / scale + center; }
};

/// Minimum enclosing sphere of the vertices (exact, Welzl-style via CGAL).
Normalization minimumSphereNormalization(const TriMesh& mesh);

TriMesh applyNormalization(const TriMesh& mesh, const Normalization& n);
TriMesh undoNormalization(const TriMesh& mesh, const Normalization& n);

}  // namespace acd
