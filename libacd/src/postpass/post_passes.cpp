#include <acd/post_passes.hpp>

#include <acd/diagnosis.hpp>
#include <acd/algo/hull_budget.hpp>
#include <acd/algo/hull_vertex_cap.hpp>
#include <acd/algo/normalize.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace acd {

namespace {

Status bad(const std::string& message) { return Status::error(StatusCode::InvalidParameter, message); }

/// The status of a pass, its message naming the option (once).
Status within(const std::string& option, Status s) {
  if (s.message.rfind(option, 0) != 0) s.message = option + ": " + s.message;
  return s;
}

std::vector<TriMesh> componentMeshes(const Decomposition& d) {
  std::vector<TriMesh> meshes;
  for (const Component& c : d.components) meshes.push_back(c.mesh);
  return meshes;
}

}  // namespace

Status validate(const PostPassOptions& o) {
  if (o.tauAbs && (!(*o.tauAbs > 0) || !std::isfinite(*o.tauAbs))) return bad("--tau-abs must be a positive length");
  if (o.maxHulls && *o.maxHulls < 1) return bad("--max-hulls must be at least 1, got " + std::to_string(*o.maxHulls));
  if (o.maxHullVertices && *o.maxHullVertices < 4)
    return bad("--max-hull-vertices must be at least 4 (a solid needs 4 corners), got " +
               std::to_string(*o.maxHullVertices));
  if (!(o.density > 0) || !std::isfinite(o.density)) return bad("--density must be positive");
  return Status::success();
}

Status resolveTauAbs(const TriMesh& mesh, const PostPassOptions& post, DecomposeOptions& options) {
  if (!post.tauAbs) return Status::success();
  PrepareOptions po;
  po.openMeshes = options.fillHoles ? OpenMeshPolicy::FillHoles : OpenMeshPolicy::Refuse;
  const PreparedSolid p = prepareSolid(mesh, po);
  if (!p.status.ok()) return Status::success();  // decompose() reports it
  TriMesh all;
  for (const TriMesh& c : p.components) {
    const int base = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), c.vertices.begin(), c.vertices.end());
    for (const Face& f : c.faces) all.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  const double scale = minimumSphereNormalization(all).scale;
  const double tau = *post.tauAbs * scale;
  if (tau < 1e-4 || tau > 2.0) {
    char message[200];
    std::snprintf(message, sizeof message, "--tau-abs %g is tau = %g in normalised units (radius %g), outside [1e-4, 2]",
                  *post.tauAbs, tau, 1.0 / scale);
    return bad(message);
  }
  options.tau = tau;
  return Status::success();
}

PostPassResult applyPostPasses(Decomposition& d, const PostPassOptions& o) {
  PostPassResult r;
  r.status = validate(o);
  if (!r.status.ok()) return r;
  r.tauAbs = o.tauAbs;
  r.density = o.density;

  if (o.maxHulls) {
    HullBudgetOptions bo;
    bo.maxHulls = *o.maxHulls;
    bo.threads = d.options.threads;
    const HullBudgetReport b = limitHullCount(d, bo);
    if (!b.status.ok()) {
      r.status = within("--max-hulls", b.status);
      return r;
    }
    HullBudgetSummary s;
    s.maxHulls = *o.maxHulls;
    s.before = b.before;
    s.after = b.after;
    s.gluedMerges = b.gluedMerges;
    s.joinedMerges = b.joinedMerges;
    s.maxConcavity = b.maxConcavity;
    s.tau = b.tau;
    s.exceedsTau = b.exceedsTau;
    s.seconds = b.seconds;
    r.budget = s;
    r.components.resize(d.components.size());
    for (std::size_t i = 0; i < d.components.size(); ++i) {
      r.components[i].mergedFrom = b.members[i];
      r.components[i].hullGapMeasure = b.hullGapMeasure[i];
    }
  }
  r.components.resize(d.components.size());

  if (o.maxHullVertices) {
    std::vector<TriMesh> hulls;
    for (const Component& c : d.components) hulls.push_back(c.hull);
    HullCapOptions co;
    co.maxVertices = *o.maxHullVertices;
    const CappedHulls capped = capHullVertices(hulls, co);
    if (!capped.status.ok()) {
      r.status = within("--max-hull-vertices", capped.status);
      return r;
    }
    const double cube = std::pow(d.normalization.scale, 3);  // input volume -> normalised volume
    HullVertexCapSummary s;
    s.maxHullVertices = *o.maxHullVertices;
    s.hulls = static_cast<int>(d.components.size());
    s.withinCap = capped.reached;
    s.unchanged = capped.unchanged;
    for (std::size_t i = 0; i < d.components.size(); ++i) {
      Component& c = d.components[i];
      ComponentPostPass& p = r.components[i];
      p.uncappedHullVertices = static_cast<int>(c.hull.vertices.size());
      p.uncappedHullVolume = c.hullVolume;
      p.addedVolume = capped.addedVolume[i] * cube;
      s.uncappedHullVolume += c.hullVolume;
      s.addedVolume += capped.addedVolume[i] * cube;
      c.hull = capped.hulls[i];
      c.hullVolume = capped.hulls[i].empty() ? 0.0 : signedVolume(capped.hulls[i]) * cube;
      s.mostVertices = std::max(s.mostVertices, capped.vertices[i]);
    }
    r.cap = s;
    if (s.withinCap != s.hulls) {  // a bug in the cap: never hand out hulls above it
      r.status = Status::error(StatusCode::InternalError, std::to_string(s.hulls - s.withinCap) + " hulls above " +
                                                              std::to_string(s.maxHullVertices) +
                                                              " vertices after the cap");
      return r;
    }
  }

  r.mass = massProperties(componentMeshes(d), o.density);
  return r;
}

}  // namespace acd
