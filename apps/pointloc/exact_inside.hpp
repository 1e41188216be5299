// Exact point-in-model test (winding number of a +z ray, exact predicates).
#pragma once
#include <acd/mesh.hpp>

#include <memory>

namespace pointloc {

/// Inside a closed, oriented mesh. Thread-safe after construction. Only points exactly on
/// the surface get an arbitrary (but deterministic) answer.
class ExactInside {
 public:
  explicit ExactInside(const acd::TriMesh& mesh);
  ~ExactInside();
  bool inside(const acd::Vec3& q) const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pointloc
