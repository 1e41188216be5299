// Exact point-in-solid test for closed, consistently oriented meshes.
#pragma once

#include <acd/mesh.hpp>
#include <memory>

namespace acd {

/// Inside a closed, oriented mesh by the winding number of a +z ray, with exact predicates and
/// a symbolic perturbation of the query point. Thread-safe after construction. Only points
/// exactly on the surface get an arbitrary (but deterministic) answer.
class InsideTest {
 public:
  explicit InsideTest(const TriMesh& mesh);
  ~InsideTest();
  InsideTest(const InsideTest&) = delete;
  InsideTest& operator=(const InsideTest&) = delete;

  bool inside(const Vec3& q) const;
  /// The winding number itself (outward-oriented shells count +1 inside): exact for any mesh
  /// whose every edge is used as often in one direction as in the other, self-crossing or not.
  int winding(const Vec3& q) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace acd
