#include "soup.hpp"

#include <acd/algo/shapes.hpp>

#include <algorithm>

namespace scenes {

void Soup::add(const std::string& name, acd::TriMesh piece) {
  pieces.push_back(std::move(piece));
  names.push_back(name);
}

acd::TriMesh Soup::merged() const { return join(pieces); }

acd::TriMesh boxSurface(const acd::Vec3& lo, const acd::Vec3& hi) { return acd::shapes::box(lo, hi); }

acd::TriMesh boxSides(const acd::Vec3& lo, const acd::Vec3& hi, const std::vector<std::string>& open) {
  const acd::TriMesh box = acd::shapes::box(lo, hi);
  acd::TriMesh out;
  out.vertices = box.vertices;
  for (int f = 0; f < static_cast<int>(box.faces.size()); ++f) {
    // The side a face lies on: the axis its normal points along, and the sign.
    const acd::Vec3 n = acd::faceNormal(box, f);
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    const std::string side = std::string(n[axis] > 0 ? "+" : "-") + "xyz"[axis];
    if (std::find(open.begin(), open.end(), side) == open.end()) out.faces.push_back(box.faces[f]);
  }
  return out;
}

acd::TriMesh quad(const acd::Vec3& a, const acd::Vec3& b, const acd::Vec3& c, const acd::Vec3& d) {
  acd::TriMesh m;
  m.vertices = {a, b, c, d};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

acd::TriMesh doubleSided(const acd::TriMesh& m) {
  acd::TriMesh out = m;
  for (const acd::Face& f : m.faces) out.faces.push_back({f[0], f[2], f[1]});
  return out;
}

acd::TriMesh join(const std::vector<acd::TriMesh>& parts) {
  acd::TriMesh out;
  for (const acd::TriMesh& p : parts) {
    const int base = static_cast<int>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), p.vertices.begin(), p.vertices.end());
    for (const acd::Face& f : p.faces) out.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
  }
  return out;
}

}  // namespace scenes
