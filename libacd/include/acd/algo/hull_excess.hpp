// How far a mesh's convex hull sticks out of the mesh: the largest distance from a point of the
// hull's surface to the mesh's surface. It bounds how far the hull can stick out of the model, the
// quantity users measure, so a piece is final only when it is within tau.
#pragma once

#include <acd/mesh.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace acd {

struct HullExcess {
  double distance = 0.0;  // the largest distance found: a lower bound of the excess
  double bound = 0.0;     // an upper bound of the excess (at most distance + resolution unless stopped early)
  Vec3 hullPoint = Vec3::Zero();     // where on the hull `distance` was found
  Vec3 surfacePoint = Vec3::Zero();  // its nearest point on the mesh
  int hullFace = -1;                 // the hull face holding hullPoint
  bool exceeds = false;              // distance > limit (the search stops there)
  int probes = 0;                    // distance queries made: the search's cost
};

/// Branch and bound over the hull's faces: each face is split in four while a bound on its points'
/// distances could still exceed `limit` and the face is wider than `resolution`. The bound is the
/// smaller of the distance at its centroid plus its radius (distance is 1-Lipschitz) and its
/// corners' largest distance to the surface triangle nearest to the centroid. Stops at the first
/// point farther than `limit`.
HullExcess measureHullExcess(const TriMesh& mesh, const TriMesh& hull, double limit, double resolution);

/// How far a hull sticks out of a closed model (its solid, not its surface): hull points inside the
/// model count zero, points outside their distance to the model's surface. Built once per model;
/// `measure` is thread-safe. A merged component's hull may reach into its neighbours, which are
/// model too: only what leaves the model is what users measure.
/// What counts as inside the model: its whole surface as one closed, oriented mesh (a repaired
/// model), or any of its closed shells, each on its own (the input as read: ShellsInside).
enum class ModelSolid { Whole, AnyClosedShell };

class ModelExcess {
 public:
  /// Built on at most `threads` threads (0: those of the caller's task arena), its inside test and
  /// distance tree side by side.
  explicit ModelExcess(const TriMesh& model, ModelSolid solid = ModelSolid::Whole, int threads = 0);
  ~ModelExcess();
  ModelExcess(const ModelExcess&) = delete;
  ModelExcess& operator=(const ModelExcess&) = delete;

  /// The same branch and bound as measureHullExcess, with the distance to the solid; hull face
  /// `firstFace`, when given, is searched first (where another measure found the largest distance:
  /// a hull beyond the limit is then found so at once).
  HullExcess measure(const TriMesh& hull, double limit, double resolution, int firstFace = -1) const;

  /// With ModelSolid::AnyClosedShell, the shells that bound no solid (0 otherwise).
  int openShells() const;

  /// The volume of `hull` outside the model and outside every hull in `covered` (what a merge
  /// that replaces those hulls by `hull` adds to the union of hulls beyond the model), estimated
  /// from `samples` points spread uniformly in `hull` by a counter-based stream keyed by `key`.
  /// Sampling stops as soon as the estimate must exceed `stopAbove`; the value returned is then
  /// some value above it.
  double addedVolume(const TriMesh& hull, const std::vector<const TriMesh*>& covered, int samples,
                     std::uint64_t key, double stopAbove = std::numeric_limits<double>::infinity()) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// How far a hull sticks out of a dense closed input, with no structure of the input's size but a
/// grid of its faces (a few bytes a face, where ModelExcess's trees take hundreds): distances to
/// the input come from the grid, and which side of it a point lies on from a coarse closed stand-in
/// whose surface lies within `standOff` of the input's, both ways (the working model,
/// acd/algo/working_mesh.hpp): a point farther than that from the stand-in's surface lies on the
/// same side of both. Nearer, the side is left open and only the distance bounds the excess there.
/// `measure` is thread-safe.
class InputExcess {
 public:
  InputExcess(TriMesh input, TriMesh standIn, double standOff);
  ~InputExcess();
  InputExcess(const InputExcess&) = delete;
  InputExcess& operator=(const InputExcess&) = delete;

  /// The same branch and bound as ModelExcess::measure, `firstFace` as there. `cornerExcess`, when
  /// given, bounds how far any vertex of the hull stands off the input: faces short enough to be
  /// within the limit by that bound alone are not searched.
  HullExcess measure(const TriMesh& hull, double limit, double resolution, int firstFace = -1,
                     double cornerExcess = std::numeric_limits<double>::infinity()) const;

 private:
  HullExcess searchFrom(const TriMesh& hull, double limit, double resolution, int firstFace) const;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace acd
