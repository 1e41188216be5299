#include "deformation_demo.hpp"

#include <acd/algo/stopwatch.hpp>
#include <acd/diagnosis.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace tetmesh {

namespace {

template <typename... Args>
std::string format(const char* f, Args... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, args...);
  return buf;
}

struct LabelStats {
  double volume = 0.0;
  Vec3 moment = Vec3::Zero();  // sum of volume x tet centroid
  Vec3 centroid() const { return volume > 0 ? Vec3(moment / volume) : moment; }
};

/// Handle and anchor vertex sets of the one-component fallback: first and last fifth of the
/// longest side of the bounding box.
void splitByPosition(const TetMesh& tets, std::vector<bool>& handle, std::vector<bool>& anchor) {
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (const auto& t : tets.tets)
    for (int v : t) lo = lo.cwiseMin(tets.points[v]), hi = hi.cwiseMax(tets.points[v]);
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const double fifth = (hi[axis] - lo[axis]) / 5.0;
  for (const auto& t : tets.tets)
    for (int v : t) {
      const double c = tets.points[v][axis];
      if (c >= hi[axis] - fifth) handle[v] = true;
      if (c <= lo[axis] + fifth) anchor[v] = true;
    }
}

/// Per label: volume and centroid; the whole mesh's in `all`; the half-diagonal of its box.
std::map<int, LabelStats> labelStats(const TetMesh& tets, LabelStats& all, double& halfDiagonal) {
  std::map<int, LabelStats> labels;
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (std::size_t t = 0; t < tets.tets.size(); ++t) {
    const auto& v = tets.tets[t];
    const double vol = tetVolume(tets, static_cast<int>(t));
    const Vec3 c = (tets.points[v[0]] + tets.points[v[1]] + tets.points[v[2]] + tets.points[v[3]]) / 4.0;
    LabelStats& s = labels[tets.labels.empty() ? 0 : tets.labels[t]];
    s.volume += vol, s.moment += vol * c;
    all.volume += vol, all.moment += vol * c;
    for (int k : v) lo = lo.cwiseMin(tets.points[k]), hi = hi.cwiseMax(tets.points[k]);
  }
  halfDiagonal = 0.5 * (hi - lo).norm();
  return labels;
}

/// The handle and the anchor components: as given, else the handle farthest from the centroid
/// and the anchor the largest other component. Returns why they cannot be, or "".
std::string chooseComponents(const std::map<int, LabelStats>& labels, const LabelStats& all,
                             const DeformationOptions& options, DeformationResult& r) {
  auto known = [&](int label) { return labels.count(label) > 0 && label > 0; };
  std::string names;
  for (const auto& [label, s] : labels) names += (names.empty() ? "" : ", ") + std::to_string(label);
  if (options.handle != 0 && !known(options.handle))
    return "there is no component " + std::to_string(options.handle) + " (labels: " + names + ")";
  if (options.anchor != 0 && !known(options.anchor))
    return "there is no component " + std::to_string(options.anchor) + " (labels: " + names + ")";
  if (options.handle != 0 && options.handle == options.anchor)
    return "the handle and the anchor are the same component (" + std::to_string(options.handle) + ")";

  const Vec3 centre = all.centroid();
  r.handle = options.handle, r.anchor = options.anchor;
  if (labels.size() >= 2) {
    if (r.handle == 0) {
      double best = -1;
      for (const auto& [label, s] : labels)
        if (label != r.anchor && (s.centroid() - centre).norm() > best) best = (s.centroid() - centre).norm(), r.handle = label;
    }
    if (r.anchor == 0) {
      double best = -1;
      for (const auto& [label, s] : labels)
        if (label != r.handle && s.volume > best) best = s.volume, r.anchor = label;
    }
  } else if (options.handle != 0 || options.anchor != 0) {
    return "the mesh has one component only: leave the handle and the anchor to the default split";
  }
  return {};
}

/// The vertices of the handle and of the anchor (a vertex in both is the anchor's).
struct VertexSets {
  std::vector<bool> inHandle, inAnchor;
  std::vector<int> handleVertices, anchorVertices;
};

VertexSets vertexSets(const TetMesh& tets, std::size_t components, DeformationResult& r) {
  const int n = static_cast<int>(tets.points.size());
  VertexSets sets;
  std::vector<bool>& inHandle = sets.inHandle;
  std::vector<bool>& inAnchor = sets.inAnchor;
  inHandle.assign(n, false), inAnchor.assign(n, false);
  if (components >= 2) {
    for (std::size_t t = 0; t < tets.tets.size(); ++t)
      for (int v : tets.tets[t]) {
        if (tets.labels[t] == r.handle) inHandle[v] = true;
        if (tets.labels[t] == r.anchor) inAnchor[v] = true;
      }
  } else {
    splitByPosition(tets, inHandle, inAnchor);
  }
  for (int v = 0; v < n; ++v) {
    if (inAnchor[v]) sets.anchorVertices.push_back(v);
    if (inHandle[v] && inAnchor[v]) ++r.sharedVertices;
    if (inHandle[v] && !inAnchor[v]) sets.handleVertices.push_back(v);
  }
  r.handleVertices = static_cast<int>(sets.handleVertices.size());
  r.anchorVertices = static_cast<int>(sets.anchorVertices.size());
  return sets;
}

/// The handle's rigid motion: a turn about an axis through the anchor's point nearest the
/// handle, or a translation (given, else across the handle-anchor direction). Fills the
/// result's description of it and returns the rotation (identity for a translation).
Eigen::Matrix3d chooseMotion(const TetMesh& tets, const std::map<int, LabelStats>& labels, const VertexSets& sets,
                             const DeformationOptions& options, DeformationResult& r) {
  const std::vector<int>& handleVertices = sets.handleVertices;
  const std::vector<int>& anchorVertices = sets.anchorVertices;
  Vec3 handleCentre = Vec3::Zero(), anchorCentre = Vec3::Zero();
  for (int v : handleVertices) handleCentre += tets.points[v] / handleVertices.size();
  for (int v : anchorVertices) anchorCentre += tets.points[v] / anchorVertices.size();
  if (labels.size() >= 2) handleCentre = labels.at(r.handle).centroid(), anchorCentre = labels.at(r.anchor).centroid();
  Vec3 d = handleCentre - anchorCentre;
  d = d.norm() > 0 ? Vec3(d.normalized()) : Vec3::UnitX();
  int leastAligned = 0;
  d.cwiseAbs().minCoeff(&leastAligned);
  const Vec3 e = Vec3::Unit(leastAligned);
  const Vec3 u = (e - e.dot(d) * d).normalized();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (options.rotate) {
    r.angleDegrees = options.angleDegrees;
    r.axis = d.cross(u).normalized();
    // The anchor's vertex nearest the handle: the handle swings about the side of the anchor
    // that faces it, as a limb about its joint.
    r.pivot = tets.points[anchorVertices.front()];
    for (int v : anchorVertices)
      if ((tets.points[v] - handleCentre).squaredNorm() < (r.pivot - handleCentre).squaredNorm()) r.pivot = tets.points[v];
    rotation = Eigen::AngleAxisd(r.angleDegrees * M_PI / 180.0, r.axis).toRotationMatrix();
    r.motion = format("turned by %g deg about the axis (%.3g, %.3g, %.3g)", r.angleDegrees, r.axis.x(), r.axis.y(), r.axis.z()) +
               format(" through (%.4g, %.4g, %.4g), the anchor's point nearest the handle", r.pivot.x(), r.pivot.y(), r.pivot.z());
  } else {
    r.translation = options.translate ? options.move : Vec3(0.2 * r.halfDiagonal * u);
    r.motion = format("translated by (%.4g, %.4g, %.4g)", r.translation.x(), r.translation.y(), r.translation.z()) +
               (options.translate ? "" : format(", 0.2 x half-diagonal %.4g", r.halfDiagonal));
  }
  return rotation;
}

/// The surface's faces as handle, anchor or rest (for pictures), and the end-to-end check: a
/// surface vertex in a tet whose corners all belong to the handle must have followed the
/// handle's rigid motion exactly (up to rounding).
template <class Motion>
void checkSurfaceParts(const TetMesh& tets, const acd::TriMesh& surface, std::size_t components, const VertexSets& sets,
                       const Motion& motion, DeformationResult& r) {
  const std::vector<bool>& inHandle = sets.inHandle;
  const std::vector<bool>& inAnchor = sets.inAnchor;
  // A face is the handle's (anchor's) when all three of its vertices lie in tets of the handle (anchor).
  std::vector<int> tetPart(tets.tets.size(), kRest);
  for (std::size_t t = 0; t < tets.tets.size(); ++t) {
    if (components >= 2) {
      tetPart[t] = tets.labels[t] == r.handle ? kHandle : tets.labels[t] == r.anchor ? kAnchor : kRest;
    } else {
      bool h = true, a = true;
      for (int v : tets.tets[t]) h = h && inHandle[v], a = a && inAnchor[v];
      tetPart[t] = h ? kHandle : a ? kAnchor : kRest;
    }
  }
  for (const acd::Face& f : surface.faces) {
    const int p0 = tetPart[r.embedding.tet[f[0]]];
    r.facePart.push_back(p0 == tetPart[r.embedding.tet[f[1]]] && p0 == tetPart[r.embedding.tet[f[2]]] ? p0 : kRest);
  }
  for (std::size_t i = 0; i < surface.vertices.size(); ++i) {
    const auto& v = tets.tets[r.embedding.tet[i]];
    bool all = true;
    for (int k : v) all = all && inHandle[k] && !inAnchor[k];
    if (!all) continue;
    ++r.surfaceOnHandle;
    r.surfaceHandleError = std::max(r.surfaceHandleError, (r.surfaceAfter.vertices[i] - motion(surface.vertices[i])).norm());
  }
}

}  // namespace

DeformationResult deformSurface(const TetMesh& tets, const acd::TriMesh& surface, const DeformationOptions& options) {
  const auto start = acd::Clock::now();
  DeformationResult r;
  auto fail = [&](const std::string& message) {
    r.status = acd::Status::error(acd::StatusCode::InvalidParameter, "deformation: " + message);
    return r;
  };
  if (tets.tets.empty()) return fail("the tet mesh is empty");
  if (options.rotate && options.translate) return fail("give either a translation or an angle, not both");
  if ((options.rotate && !std::isfinite(options.angleDegrees)) || (options.translate && !options.move.allFinite()))
    return fail("the motion of the handle must be finite");

  LabelStats all;
  const std::map<int, LabelStats> labels = labelStats(tets, all, r.halfDiagonal);
  if (const std::string why = chooseComponents(labels, all, options, r); !why.empty()) return fail(why);
  const std::size_t components = labels.size();
  const VertexSets sets = vertexSets(tets, components, r);
  if (sets.handleVertices.empty()) return fail("the handle has no vertex that is not also in the anchor");

  const Eigen::Matrix3d rotation = chooseMotion(tets, labels, sets, options, r);
  auto motion = [&](const Vec3& p) { return options.rotate ? Vec3(r.pivot + rotation * (p - r.pivot)) : Vec3(p + r.translation); };
  std::vector<int> constrained;
  std::vector<Vec3> targets;
  for (int v : sets.handleVertices) {
    constrained.push_back(v);
    targets.push_back(motion(tets.points[v]));
  }
  for (int v : sets.anchorVertices) constrained.push_back(v), targets.push_back(tets.points[v]);

  // Embed, solve, carry the surface along.
  r.embedding = embedPoints(tets, surface.vertices);
  r.arap = arapDeform(tets, constrained, targets, options.arap);
  if (!r.arap.status.ok()) {
    r.status = r.arap.status;
    return r;
  }
  r.tetPositionsAfter = r.arap.positions;
  r.surfaceAfter = r.surfaceLinear = surface;
  r.surfaceAfter.vertices = interpolate(r.embedding, tets, r.arap.positions);
  r.surfaceLinear.vertices = interpolate(r.embedding, tets, r.arap.linearPositions);
  r.surfaceVolumeBefore = acd::signedVolume(surface);
  r.surfaceVolumeAfter = acd::signedVolume(r.surfaceAfter);
  r.surfaceVolumeLinear = acd::signedVolume(r.surfaceLinear);
  for (std::size_t i = 0; i < surface.vertices.size(); ++i)
    r.maxSurfaceDisplacement = std::max(r.maxSurfaceDisplacement, (r.surfaceAfter.vertices[i] - surface.vertices[i]).norm());
  checkSurfaceParts(tets, surface, components, sets, motion, r);
  for (int t : r.embedding.tet) {
    const auto& v = tets.tets[t];
    const auto& x = r.arap.positions;
    if ((x[v[1]] - x[v[0]]).cross(x[v[2]] - x[v[0]]).dot(x[v[3]] - x[v[0]]) <= 0) ++r.surfaceInInverted;
  }
  // Nothing in the energy keeps parts of the surface apart: say whether it now passes through
  // itself (and whether it did before).
  r.selfIntersectionsBefore = acd::countSelfIntersections(surface);
  r.selfIntersectionsAfter = acd::countSelfIntersections(r.surfaceAfter);
  r.seconds = acd::secondsSince(start);
  return r;
}

void splitByPart(const acd::TriMesh& surface, const std::vector<int>& facePart, std::vector<acd::TriMesh>& parts,
                 std::vector<std::string>& names) {
  const char* partNames[] = {"rest", "handle", "anchor"};
  parts.clear(), names.clear();
  for (int part : {kRest, kHandle, kAnchor}) {
    acd::TriMesh m;
    std::vector<int> index(surface.vertices.size(), -1);
    for (std::size_t f = 0; f < surface.faces.size(); ++f) {
      if (facePart[f] != part) continue;
      acd::Face g;
      for (int k = 0; k < 3; ++k) {
        int& i = index[surface.faces[f][k]];
        if (i < 0) i = static_cast<int>(m.vertices.size()), m.vertices.push_back(surface.vertices[surface.faces[f][k]]);
        g[k] = i;
      }
      m.faces.push_back(g);
    }
    if (m.faces.empty()) continue;
    parts.push_back(std::move(m));
    names.push_back(partNames[part]);
  }
}

std::vector<std::string> deformationSummary(const DeformationResult& r) {
  const ArapResult& a = r.arap;
  auto change = [](double after, double before) { return before != 0 ? 100.0 * (after - before) / before : 0.0; };
  std::vector<std::string> lines;
  lines.push_back(r.handle > 0 ? format("  deformation    handle component %d (%d vertices), anchor component %d (%d vertices)",
                                        r.handle, r.handleVertices, r.anchor, r.anchorVertices)
                               : format("  deformation    one component: handle = last fifth (%d vertices), anchor = first fifth (%d vertices)",
                                        r.handleVertices, r.anchorVertices));
  if (r.sharedVertices > 0) lines.back() += format(", %d shared kept with the anchor", r.sharedVertices);
  lines.push_back("                 handle " + r.motion);
  lines.push_back(format("  embedding      %zu surface vertices located, %d outside every tet (farthest %.3g), %.3f s",
                         r.embedding.tet.size(), r.embedding.outside, r.embedding.maxOutsideDistance,
                         r.embedding.seconds));
  lines.push_back(format("  ARAP           %d iterations (%s), energy %.4g -> %.4g (weighted mean ||F - R||^2)",
                         a.iterations, a.converged ? "converged" : "stopped at the limit",
                         a.energy.empty() ? 0.0 : a.energy.front(), a.energy.empty() ? 0.0 : a.energy.back()));
  lines.push_back(format("                 inverted tets %d (linear start %d; %.2g of the volume at rest, %d surface vertices in them)",
                         a.invertedTets, a.linearInvertedTets, a.restVolume > 0 ? a.invertedRestVolume / a.restVolume : 0.0,
                         r.surfaceInInverted));
  lines.push_back(format("                 constraint error %.3g (surface on the handle: %d vertices, off its motion by %.3g)",
                         a.maxConstraintError, r.surfaceOnHandle, r.surfaceHandleError));
  lines.push_back(format("                 %d vertices solved, %d kept at rest (no constraint reaches them)", a.freeVertices,
                         a.pinnedVertices));
  lines.push_back(format("  volume change  tets %+.2f%% (linear start %+.2f%%), surface %+.2f%% (linear start %+.2f%%)",
                         change(a.volume, a.restVolume), change(a.linearVolume, a.restVolume),
                         change(r.surfaceVolumeAfter, r.surfaceVolumeBefore), change(r.surfaceVolumeLinear, r.surfaceVolumeBefore)));
  lines.push_back(format("  surface        %d intersecting face pairs after (%d before)", r.selfIntersectionsAfter,
                         r.selfIntersectionsBefore));
  lines.push_back(format("  time (s)       factor %.3f, iterations %.3f, all %.3f; surface moved up to %.4g", a.factorSeconds,
                         a.solveSeconds, r.seconds, r.maxSurfaceDisplacement));
  return lines;
}

}  // namespace tetmesh
