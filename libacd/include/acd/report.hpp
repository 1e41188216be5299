// report.json: the one description of a decomposition run. `acd decompose` writes it, the Python
// module returns it as a dict; both get it from here, so the two can never disagree.
#pragma once

#include <acd/decompose.hpp>
#include <acd/diagnosis.hpp>
#include <acd/evaluate.hpp>
#include <acd/exact_decomposition.hpp>
#include <acd/post_passes.hpp>
#include <acd/surface_decompose.hpp>
#include <acd/surface_exact.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace acd {

/// What a report says about the input besides what the decomposition measured.
struct ReportInput {
  std::string model;          // the file as named by the caller (or a description of in-memory input)
  std::string mesh;           // the scene mesh decomposed (acd decompose --per-mesh); empty: the whole file
  MeshDiagnosis diagnosis;    // of the mesh as read, before repairs
  int selfIntersections = 0;  // face pairs (countSelfIntersections); explains unresolved components
  double inputOutside = -1.0; // inputOutsideHulls (acd/evaluate.hpp), normalised; < 0: not measured
  std::vector<double> hullOffInput;  // hullsOffInput (acd/evaluate.hpp) per component; empty: not measured
  double promiseSeconds = -1.0;      // both measures on the input as read (wall); < 0: not measured
};

/// Diagnosis and self-intersection count of a mesh as read. Call it once the decomposition has
/// accepted the mesh: counting self-intersections assumes valid indices and finite coordinates.
/// The count runs on `threads` workers (0: all cores), as DecomposeOptions::threads.
ReportInput describeInput(const std::string& model, const TriMesh& mesh, int threads = 0);

/// report.json of a solid decomposition: JSON text, keys sorted, indented by 2, newline at the end.
/// Every number is in normalised units except where the key says otherwise; see README.md.
std::string reportJson(const ReportInput& input, const Decomposition& d);

/// The same with the sections of the post-passes that ran (acd/post_passes.hpp): "tau_abs",
/// "hull_budget", "hull_vertex_cap", "mass_properties", and their fields of each component.
std::string reportJson(const ReportInput& input, const Decomposition& d, const PostPassResult& post);

/// report.json of a surface decomposition; `outputBytes` is the size of patches.obj
/// (objObjectsText(...).size() when nothing is written).
std::string reportJson(const ReportInput& input, const SurfaceDecomposition& d, std::uintmax_t outputBytes);

/// report.json of the exact solid baseline (`acd decompose --exact`): `diagnosis` of the mesh as
/// read, the caps as given (seconds, GiB), `outputBytes` the size of pieces.obj.
std::string reportJson(const std::string& model, const MeshDiagnosis& diagnosis, const ExactDecomposition& d,
                       double timeLimitSeconds, double memoryGiB, std::uintmax_t outputBytes);

/// report.json of the exact surface baseline (`acd decompose --exact --surface`): `patches` are
/// the patches as meshes (patchMesh), `outputBytes` the size of patches.obj.
std::string reportJson(const std::string& model, const TriMesh& mesh, const MeshDiagnosis& diagnosis,
                       const SurfaceExactDecomposition& d, const std::vector<TriMesh>& patches, double tolerance,
                       std::uintmax_t outputBytes);

/// What `acd evaluate --json` prints, same conventions.
std::string evaluationJson(const std::string& model, const std::string& hullsFile, const Evaluation& e);

}  // namespace acd
