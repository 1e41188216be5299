// Sharp edges of the hull regions, kept only where clean; see region_features.hpp.
#include "region_features.hpp"

#include "region_labels.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace tetmesh {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Closest points of segments pq and rs: parameters s, t in [0, 1] and the distance.
double segmentDistance(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s, double& sp, double& tr) {
  const Vec3 d1 = q - p, d2 = s - r, w = p - r;
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(w);
  double u = 0.0, v = 0.0;
  if (a <= 0 && e <= 0) {
    u = v = 0.0;
  } else if (a <= 0) {
    v = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = d1.dot(w);
    if (e <= 0) {
      u = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = d1.dot(d2), denom = a * e - b * b;
      u = denom > 0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      v = (b * u + f) / e;
      if (v < 0) v = 0, u = std::clamp(-c / a, 0.0, 1.0);
      else if (v > 1) v = 1, u = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  sp = u, tr = v;
  return (p + u * d1 - (r + v * d2)).norm();
}

/// Points, welded within `weld` (a grid of that cell size; neighbours checked).
class Welder {
 public:
  explicit Welder(double weld) : weld_(weld) {}
  int add(const Vec3& p) {
    const std::array<long, 3> c = cell(p);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = grid_.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid_.end()) continue;
          for (int id : it->second)
            if ((points[id] - p).norm() <= weld_) return id;
        }
    points.push_back(p);
    grid_[c].push_back(static_cast<int>(points.size()) - 1);
    return static_cast<int>(points.size()) - 1;
  }
  std::vector<Vec3> points;

 private:
  std::array<long, 3> cell(const Vec3& p) const {
    return {std::lround(std::floor(p.x() / weld_)), std::lround(std::floor(p.y() / weld_)), std::lround(std::floor(p.z() / weld_))};
  }
  double weld_;
  std::map<std::array<long, 3>, std::vector<int>> grid_;
};

/// Whether the labels change around the edge ab of a region whose faces there have normals n1, n2.
bool labelsChangeAround(const RegionLabels& labels, const Vec3& a, const Vec3& b, const Vec3& n1, const Vec3& n2, double eps) {
  const Vec3 m = 0.5 * (a + b);
  const Vec3 out = (n1 + n2).normalized(), across = (n1 - n2).normalized();
  const int first = labels(m + eps * out);
  for (const Vec3& d : {Vec3(-out), across, Vec3(-across)})
    if (labels(m + eps * d) != first) return true;
  return false;
}

}  // namespace

RegionFeatures regionFeatures(const std::vector<acd::TriMesh>& regions, const RegionLabels& labels, double minTurnDegrees,
                              double clearance) {
  RegionFeatures out;
  const double size = (labels.upper() - labels.lower()).norm();
  const double weld = 1e-9 * size;
  const double cosTurn = std::cos(minTurnDegrees * kPi / 180.0);
  Welder points(weld);
  std::set<std::pair<int, int>> segments;
  for (const acd::TriMesh& region : regions) {
    std::map<std::pair<int, int>, std::vector<int>> edgeFaces;
    for (int f = 0; f < static_cast<int>(region.faces.size()); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = region.faces[f][k], b = region.faces[f][(k + 1) % 3];
        edgeFaces[{std::min(a, b), std::max(a, b)}].push_back(f);
      }
    auto normal = [&](int f) {
      const auto& v = region.vertices;
      const auto& t = region.faces[f];
      return Vec3((v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized());
    };
    for (const auto& [edge, faces] : edgeFaces) {
      if (faces.size() != 2) continue;
      const Vec3 n1 = normal(faces[0]), n2 = normal(faces[1]);
      if (!n1.allFinite() || !n2.allFinite() || n1.dot(n2) > cosTurn) continue;
      const Vec3 &a = region.vertices[edge.first], &b = region.vertices[edge.second];
      ++out.candidates;
      if (!labelsChangeAround(labels, a, b, n1, n2, 0.25 * clearance)) continue;
      const int i = points.add(a), j = points.add(b);
      if (i != j) segments.insert({std::min(i, j), std::max(i, j)});
    }
  }
  const std::vector<Vec3>& p = points.points;
  // Split at corners lying on other segments and at crossings: every pair once, the points
  // where each segment must be split gathered first (splitting makes no new crossings).
  const std::vector<std::pair<int, int>> whole(segments.begin(), segments.end());
  std::vector<std::vector<int>> splitAt(whole.size());
  for (std::size_t s = 0; s < whole.size(); ++s)
    for (std::size_t t = s + 1; t < whole.size(); ++t) {
      const auto [a, b] = whole[s];
      const auto [c, d] = whole[t];
      if (a == c || a == d || b == c || b == d) continue;
      double u = 0, v = 0;
      if (segmentDistance(p[a], p[b], p[c], p[d], u, v) > 10 * weld) continue;
      const bool uEnd = u <= 0 || u >= 1, vEnd = v <= 0 || v >= 1;
      if (uEnd && vEnd) continue;  // ends within the weld: the welder has made them one
      // Where they meet: an end of one on the other, or a crossing inside both.
      const int at = uEnd ? (u <= 0 ? a : b) : vEnd ? (v <= 0 ? c : d) : points.add(p[a] + u * (p[b] - p[a]));
      if (!uEnd) splitAt[s].push_back(at);
      if (!vEnd) splitAt[t].push_back(at);
    }
  std::vector<std::pair<int, int>> list;
  for (std::size_t s = 0; s < whole.size(); ++s) {
    const auto [a, b] = whole[s];
    std::vector<int> chain = splitAt[s];
    const Vec3 d = p[b] - p[a];
    std::sort(chain.begin(), chain.end(), [&](int x, int y) { return (p[x] - p[a]).dot(d) < (p[y] - p[a]).dot(d); });
    chain.erase(std::unique(chain.begin(), chain.end()), chain.end());
    chain.insert(chain.begin(), a);
    chain.push_back(b);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k)
      if (chain[k] != chain[k + 1]) list.push_back({std::min(chain[k], chain[k + 1]), std::max(chain[k], chain[k + 1])});
  }
  std::sort(list.begin(), list.end());
  list.erase(std::unique(list.begin(), list.end()), list.end());
  // Drop what comes too close: short segments, near misses, segments meeting at a small angle.
  std::sort(list.begin(), list.end(), [&](const auto& x, const auto& y) {
    const double lx = (p[x.second] - p[x.first]).norm(), ly = (p[y.second] - p[y.first]).norm();
    return lx != ly ? lx > ly : x < y;  // longest first: the shorter of a conflicting pair goes
  });
  std::vector<std::pair<int, int>> kept;
  for (const auto& [a, b] : list) {
    bool clear = (p[b] - p[a]).norm() >= clearance;
    for (std::size_t k = 0; k < kept.size() && clear; ++k) {
      const auto [c, d] = kept[k];
      const int shared = (a == c || a == d) + (b == c || b == d);
      if (shared == 0) {
        double u = 0, v = 0;
        clear = segmentDistance(p[a], p[b], p[c], p[d], u, v) >= clearance;
      } else {
        const int common = (a == c || a == d) ? a : b;
        const Vec3 x = (p[a == common ? b : a] - p[common]).normalized(), y = (p[c == common ? d : c] - p[common]).normalized();
        clear = x.dot(y) < std::cos(30.0 * kPi / 180.0);
      }
    }
    if (clear) kept.push_back({a, b});
    else ++out.dropped;
  }
  std::sort(kept.begin(), kept.end());
  for (const auto& [a, b] : kept) out.segments.push_back({p[a], p[b]});
  return out;
}

std::vector<std::vector<Vec3>> chainSegments(const std::vector<std::array<Vec3, 2>>& segments) {
  // Segments share their ends exactly (regionFeatures welds them).
  std::map<std::array<double, 3>, std::vector<int>> at;
  auto key = [](const Vec3& v) { return std::array<double, 3>{v.x(), v.y(), v.z()}; };
  for (int s = 0; s < static_cast<int>(segments.size()); ++s)
    for (const Vec3& end : segments[s]) at[key(end)].push_back(s);
  std::vector<char> used(segments.size(), 0);
  std::vector<std::vector<Vec3>> lines;
  auto walk = [&](int s, const Vec3& from) {
    std::vector<Vec3> line{from};
    Vec3 here = from;
    while (s >= 0 && !used[s]) {
      used[s] = 1;
      here = segments[s][0] == here ? segments[s][1] : segments[s][0];
      line.push_back(here);
      const std::vector<int>& next = at[key(here)];
      s = -1;
      if (next.size() == 2)
        for (int n : next)
          if (!used[n]) s = n;
    }
    lines.push_back(std::move(line));
  };
  // Open chains from their ends (points where other than two segments meet), then closed loops.
  for (const auto& [point, touching] : at)
    if (touching.size() != 2)
      for (int s : touching)
        if (!used[s]) walk(s, Vec3(point[0], point[1], point[2]));
  for (int s = 0; s < static_cast<int>(segments.size()); ++s)
    if (!used[s]) walk(s, segments[s][0]);
  return lines;
}

}  // namespace tetmesh
