#include "deform.hpp"

#include <acd/algo/stopwatch.hpp>

#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <queue>
#include <sstream>

namespace skeleton {

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) parts.push_back(part);
  if (!s.empty() && s.back() == sep) parts.emplace_back();
  return parts;
}

bool parseNumber(const std::string& s, double& value) {
  try {
    std::size_t used = 0;
    value = std::stod(s, &used);
    return used == s.size() && std::isfinite(value);
  } catch (const std::exception&) {
    return false;
  }
}

bool parseTriple(const std::string& s, Vec3& v) {
  const std::vector<std::string> parts = split(s, ',');
  if (parts.size() != 3) return false;
  for (int i = 0; i < 3; ++i)
    if (!parseNumber(parts[i], v[i])) return false;
  return true;
}

bool parseDirection(const std::string& s, Vec3& d) {
  if (s.size() != 2 || (s[0] != '+' && s[0] != '-') || s[1] < 'x' || s[1] > 'z') return false;
  d = Vec3::Zero();
  d[s[1] - 'x'] = s[0] == '+' ? 1.0 : -1.0;
  return true;
}

bool parseAxis(const std::string& s, Vec3& a) {
  if (s.size() != 1 || s[0] < 'x' || s[0] > 'z') return false;
  a = Vec3::Zero();
  a[s[0] - 'x'] = 1.0;
  return true;
}

/// Shortest-path distances along mesh edges from one vertex.
std::vector<double> edgeDistances(const acd::TriMesh& mesh, int source) {
  const int n = static_cast<int>(mesh.vertices.size());
  std::vector<std::vector<int>> adj(n);
  for (const acd::Face& f : mesh.faces)
    for (int k = 0; k < 3; ++k) adj[f[k]].push_back(f[(k + 1) % 3]), adj[f[(k + 1) % 3]].push_back(f[k]);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  dist[source] = 0.0;
  queue.push({0.0, source});
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    for (int w : adj[v]) {
      const double nd = d + (mesh.vertices[w] - mesh.vertices[v]).norm();
      if (nd < dist[w]) dist[w] = nd, queue.push({nd, w});
    }
  }
  return dist;
}

std::string describe(const ArapRequest& r) {
  std::ostringstream s;
  s << "ARAP: handle " << r.handle.size() << " vertices, region " << r.region.size() << " vertices, "
    << r.angleDegrees << " deg about (" << r.axis.x() << ", " << r.axis.y() << ", " << r.axis.z()
    << ") through (" << r.pivot.x() << ", " << r.pivot.y() << ", " << r.pivot.z() << ")";
  return s.str();
}

DeformResult runArap(const acd::TriMesh& mesh, const ArapRequest& request) {
  DeformResult out;
  ArapResult arap = arapDeform(mesh, request);
  out.ok = arap.ok;
  out.error = arap.error;
  out.mesh = std::move(arap.mesh);
  out.summary = describe(request);
  return out;
}

/// The first vertex furthest along `direction`.
int extremeVertex(const acd::TriMesh& mesh, const Vec3& direction) {
  int extreme = 0;
  for (int v = 1; v < static_cast<int>(mesh.vertices.size()); ++v)
    if (mesh.vertices[v].dot(direction) > mesh.vertices[extreme].dot(direction)) extreme = v;
  return extreme;
}

DeformResult failure(const std::string& message) {
  DeformResult out;
  out.error = message;
  return out;
}

}  // namespace

acd::TriMesh affineDeform(const acd::TriMesh& mesh, const Vec3& rotationDegrees, const Vec3& scale,
                          const Vec3& translation) {
  const Vec3 centre = acd::boundingBox(mesh).center();
  const double k = M_PI / 180.0;
  const Eigen::Matrix3d rotation = (Eigen::AngleAxisd(rotationDegrees.z() * k, Vec3::UnitZ()) *
                                    Eigen::AngleAxisd(rotationDegrees.y() * k, Vec3::UnitY()) *
                                    Eigen::AngleAxisd(rotationDegrees.x() * k, Vec3::UnitX()))
                                       .toRotationMatrix();
  acd::TriMesh out = mesh;
  for (Vec3& p : out.vertices) p = centre + rotation * (scale.cwiseProduct(p - centre)) + translation;
  // A mirror (odd number of negative scales) would turn the surface inside out.
  if (scale.x() * scale.y() * scale.z() < 0)
    for (acd::Face& f : out.faces) std::swap(f[1], f[2]);
  return out;
}

ArapRequest bendRequest(const acd::TriMesh& mesh, const Vec3& direction, const Vec3& axis, double degrees,
                        double handleRadius, double regionRadius) {
  ArapRequest r;
  r.axis = axis;
  r.angleDegrees = degrees;
  if (mesh.vertices.empty()) return r;
  const int extreme = extremeVertex(mesh, direction);
  const double diagonal = acd::boundingBox(mesh).size().norm();
  const std::vector<double> dist = edgeDistances(mesh, extreme);
  Vec3 ring = Vec3::Zero();
  int ringCount = 0;
  for (int v = 0; v < static_cast<int>(mesh.vertices.size()); ++v) {
    const double d = dist[v] / diagonal;
    if (d <= handleRadius) r.handle.push_back(v);
    if (d <= regionRadius) r.region.push_back(v);
    if (d <= regionRadius && d >= 0.9 * regionRadius) ring += mesh.vertices[v], ++ringCount;
  }
  r.pivot = ringCount > 0 ? Vec3(ring / ringCount)
                          : Vec3(mesh.vertices[extreme] - regionRadius * diagonal * direction);
  return r;
}

DeformResult applyDeformation(const acd::TriMesh& mesh, const std::string& spec) {
  if (spec.find(';') != std::string::npos) {  // a sequence: each step applied to the last one's result
    DeformResult out;
    out.ok = true;
    out.mesh = mesh;
    std::vector<std::string> summaries;
    for (const std::string& step : split(spec, ';')) {
      DeformResult r = applyDeformation(out.mesh, step);
      if (!r.ok) return r;
      out.mesh = std::move(r.mesh);
      out.seconds += r.seconds;
      summaries.push_back(r.summary);
    }
    for (std::size_t i = 0; i < summaries.size(); ++i) out.summary += (i ? "; then " : "") + summaries[i];
    return out;
  }
  const auto start = acd::Clock::now();
  const std::vector<std::string> parts = split(spec, ':');
  const std::string kind = parts.empty() ? "" : parts[0];
  DeformResult out;
  if (kind == "bend") {
    if (parts.size() < 4 || parts.size() > 6)
      return failure("bend needs DIR:AXIS:DEG[:HANDLE[:REGION]], got '" + spec + "'");
    Vec3 direction, axis;
    double degrees = 0, handle = 0.08, region = 0.25;
    if (!parseDirection(parts[1], direction)) return failure("bend direction must be +x, -x, +y, -y, +z or -z, got '" + parts[1] + "'");
    if (!parseAxis(parts[2], axis)) return failure("bend axis must be x, y or z, got '" + parts[2] + "'");
    if (!parseNumber(parts[3], degrees)) return failure("bend angle is not a number: '" + parts[3] + "'");
    if (parts.size() > 4 && (!parseNumber(parts[4], handle) || handle <= 0 || handle >= 1))
      return failure("bend handle radius must lie in (0, 1), got '" + parts[4] + "'");
    if (parts.size() > 5 && (!parseNumber(parts[5], region) || region <= handle || region >= 1))
      return failure("bend region radius must lie in (handle radius, 1), got '" + parts[5] + "'");
    out = runArap(mesh, bendRequest(mesh, direction, axis, degrees, handle, region));
  } else if (kind == "twist") {
    if (parts.size() < 3 || parts.size() > 5)
      return failure("twist needs DIR:DEG[:HANDLE[:REGION]], got '" + spec + "'");
    Vec3 direction;
    double degrees = 0, handle = 0.08, region = 0.25;
    if (!parseDirection(parts[1], direction)) return failure("twist direction must be +x, -x, +y, -y, +z or -z, got '" + parts[1] + "'");
    if (!parseNumber(parts[2], degrees)) return failure("twist angle is not a number: '" + parts[2] + "'");
    if (parts.size() > 3 && (!parseNumber(parts[3], handle) || handle <= 0 || handle >= 1))
      return failure("twist handle radius must lie in (0, 1), got '" + parts[3] + "'");
    if (parts.size() > 4 && (!parseNumber(parts[4], region) || region <= handle || region >= 1))
      return failure("twist region radius must lie in (handle radius, 1), got '" + parts[4] + "'");
    ArapRequest r = bendRequest(mesh, direction, Vec3::UnitZ(), degrees, handle, region);
    // About the limb's own axis: from where it meets the body to its tip.
    const Vec3 along = mesh.vertices[extremeVertex(mesh, direction)] - r.pivot;
    if (!(along.norm() > 0)) return failure("twist: the limb along " + parts[1] + " has no length");
    r.axis = along.normalized();
    out = runArap(mesh, r);
  } else if (kind == "ids") {
    if (parts.size() != 2) return failure("ids needs one file name: ids:FILE.json, got '" + spec + "'");
    std::ifstream in(parts[1]);
    if (!in) return failure("cannot open '" + parts[1] + "'");
    ArapRequest r;
    try {
      const nlohmann::json j = nlohmann::json::parse(in);
      r.handle = j.at("handle").get<std::vector<int>>();
      r.region = j.at("region").get<std::vector<int>>();
      const auto pivot = j.at("pivot").get<std::vector<double>>();
      const auto axis = j.at("axis").get<std::vector<double>>();
      if (pivot.size() != 3 || axis.size() != 3) return failure(parts[1] + ": pivot and axis need three numbers each");
      r.pivot = Vec3(pivot[0], pivot[1], pivot[2]);
      r.axis = Vec3(axis[0], axis[1], axis[2]);
      r.angleDegrees = j.at("angle").get<double>();
    } catch (const std::exception& e) {
      return failure(parts[1] + ": " + e.what());
    }
    out = runArap(mesh, r);
  } else if (kind == "affine") {
    if (parts.size() < 3 || parts.size() > 4)
      return failure("affine needs RX,RY,RZ:SX,SY,SZ[:TX,TY,TZ], got '" + spec + "'");
    Vec3 rotation, scale, translation = Vec3::Zero();
    if (!parseTriple(parts[1], rotation)) return failure("affine rotation needs three numbers RX,RY,RZ, got '" + parts[1] + "'");
    if (!parseTriple(parts[2], scale)) return failure("affine scale needs three numbers SX,SY,SZ, got '" + parts[2] + "'");
    if (scale.cwiseAbs().minCoeff() < 1e-6) return failure("affine scale factors must not be zero, got '" + parts[2] + "'");
    if (parts.size() == 4 && !parseTriple(parts[3], translation))
      return failure("affine translation needs three numbers TX,TY,TZ, got '" + parts[3] + "'");
    out.ok = true;
    out.mesh = affineDeform(mesh, rotation, scale, translation);
    std::ostringstream s;
    s << "affine: scale (" << scale.x() << ", " << scale.y() << ", " << scale.z() << "), rotation (" << rotation.x()
      << ", " << rotation.y() << ", " << rotation.z() << ") deg, translation (" << translation.x() << ", "
      << translation.y() << ", " << translation.z() << ")";
    out.summary = s.str();
  } else {
    return failure("unknown deformation '" + kind + "' (expected bend, twist, ids or affine)");
  }
  out.seconds = acd::secondsSince(start);
  return out;
}

}  // namespace skeleton
