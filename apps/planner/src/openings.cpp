#include "openings.hpp"

#include <acd/algo/inside.hpp>

#include <algorithm>
#include <map>
#include <memory>

namespace planner {

std::vector<Opening> extractOpenings(const acd::TriMesh& whole, const std::vector<acd::TriMesh>& components) {
  std::vector<Opening> openings;
  if (whole.empty() || components.size() < 2) return openings;
  const acd::Box3 box = acd::boundingBox(whole);
  // Far below any feature size of a decomposed free space, far above rounding of coordinates.
  const double nudge = 1e-7 * box.size().norm();
  const acd::InsideTest inWhole(whole);
  std::vector<std::unique_ptr<acd::InsideTest>> inPart;
  std::vector<acd::Box3> boxes;
  for (const acd::TriMesh& c : components) {
    inPart.push_back(std::make_unique<acd::InsideTest>(c));
    boxes.push_back(acd::boundingBox(c));
  }
  std::map<std::pair<int, int>, Opening> byPair;
  for (int i = 0; i < static_cast<int>(components.size()); ++i) {
    const acd::TriMesh& m = components[i];
    for (int f = 0; f < static_cast<int>(m.faces.size()); ++f) {
      const acd::Vec3 n = acd::faceNormal(m, f);
      const double twiceArea = n.norm();
      if (twiceArea <= 0) continue;
      const acd::Vec3& p0 = m.vertices[m.faces[f][0]];
      const acd::Vec3& p1 = m.vertices[m.faces[f][1]];
      const acd::Vec3& p2 = m.vertices[m.faces[f][2]];
      const acd::Vec3 c = (p0 + p1 + p2) / 3.0;
      const acd::Vec3 probe = c + nudge * n / twiceArea;
      if (!inWhole.inside(probe)) continue;  // a face of the free space's own boundary
      int neighbour = -1;
      for (int j = 0; j < static_cast<int>(components.size()); ++j) {
        if (j == i) continue;
        const acd::Box3& b = boxes[j];
        if ((probe.array() < b.lo.array() - nudge).any() || (probe.array() > b.hi.array() + nudge).any()) continue;
        if (inPart[j]->inside(probe)) {
          neighbour = j;
          break;
        }
      }
      if (neighbour < i) continue;  // each region once, from the lower-indexed side (or no neighbour found)
      Opening& o = byPair[{i, neighbour}];
      o.a = i;
      o.b = neighbour;
      const int base = static_cast<int>(o.triangles.vertices.size());
      o.triangles.vertices.insert(o.triangles.vertices.end(), {p0, p1, p2});
      o.triangles.faces.push_back({base, base + 1, base + 2});
      const double area = 0.5 * twiceArea;
      o.area += area;
      o.centroid += area * c;
      o.normal += 0.5 * n;
    }
  }
  for (auto& [pair, o] : byPair) {
    if (o.area <= 0) continue;
    o.centroid /= o.area;
    o.normal.normalize();
    o.extentLo = o.extentHi = o.triangles.vertices.front();
    for (const acd::Vec3& p : o.triangles.vertices) {
      o.radius = std::max(o.radius, (p - o.centroid).norm());
      o.extentLo = o.extentLo.cwiseMin(p);
      o.extentHi = o.extentHi.cwiseMax(p);
    }
    openings.push_back(std::move(o));
  }
  std::stable_sort(openings.begin(), openings.end(), [](const Opening& x, const Opening& y) { return x.area > y.area; });
  return openings;
}

}  // namespace planner
