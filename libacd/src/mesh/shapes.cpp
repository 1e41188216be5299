#include <acd/algo/shapes.hpp>

#include <cmath>
#include <map>
#include <set>

namespace acd::shapes {

TriMesh box(const Vec3& lo, const Vec3& hi) {
  TriMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(), i & 4 ? hi.z() : lo.z());
  // Quads counter-clockwise from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.faces.push_back({q[0], q[1], q[2]});
    m.faces.push_back({q[0], q[2], q[3]});
  }
  return m;
}

TriMesh icosphere(const Vec3& center, double radius, int level) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Face> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                         {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                         {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Vec3& p : v) p.normalize();
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<Face> next;
    for (const Face& tri : f) {
      const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]), c = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    f.swap(next);
  }
  TriMesh m;
  for (const Vec3& p : v) m.vertices.push_back(center + radius * p);
  m.faces = f;
  return m;
}

TriMesh voxels(const std::vector<std::array<int, 3>>& cells, double cellSize) {
  std::set<std::array<int, 3>> filled(cells.begin(), cells.end());
  std::map<std::array<int, 3>, int> corner;
  TriMesh m;
  auto vertex = [&](std::array<int, 3> c) {
    auto [it, inserted] = corner.emplace(c, static_cast<int>(m.vertices.size()));
    if (inserted) m.vertices.emplace_back(c[0] * cellSize, c[1] * cellSize, c[2] * cellSize);
    return it->second;
  };
  for (const auto& c : filled) {
    for (int axis = 0; axis < 3; ++axis) {
      for (int dir = -1; dir <= 1; dir += 2) {
        auto n = c;
        n[axis] += dir;
        if (filled.count(n)) continue;
        // Face on the side `dir` of the cell, perpendicular to `axis`.
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        std::array<int, 3> base = c;
        if (dir > 0) base[axis] += 1;
        auto at = [&](int du, int dw) {
          auto p = base;
          p[u] += du;
          p[w] += dw;
          return vertex(p);
        };
        const int a = at(0, 0), b = at(1, 0), d = at(1, 1), e = at(0, 1);
        // (u, w, axis) is right-handed, so a->b->d is counter-clockwise seen from +axis.
        if (dir > 0) {
          m.faces.push_back({a, b, d});
          m.faces.push_back({a, d, e});
        } else {
          m.faces.push_back({a, d, b});
          m.faces.push_back({a, e, d});
        }
      }
    }
  }
  return m;
}

TriMesh lShape() { return voxels({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}); }

TriMesh uShape() {
  return voxels({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {2, 1, 0}, {0, 2, 0}, {2, 2, 0}});
}

TriMesh revolve(const std::function<double(double)>& radius, double z0, double z1, int rings, int segments) {
  TriMesh m;
  const double pi = std::acos(-1.0);
  m.vertices.emplace_back(0, 0, z0);
  for (int i = 1; i < rings; ++i) {
    const double z = z0 + (z1 - z0) * i / rings;
    const double r = radius(z);
    for (int j = 0; j < segments; ++j) {
      const double a = 2 * pi * j / segments;
      m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), z);
    }
  }
  m.vertices.emplace_back(0, 0, z1);
  const int top = static_cast<int>(m.vertices.size()) - 1;
  auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) m.faces.push_back({0, ring(1, j + 1), ring(1, j)});
  for (int i = 1; i + 1 < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      m.faces.push_back({ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)});
      m.faces.push_back({ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)});
    }
  for (int j = 0; j < segments; ++j) m.faces.push_back({top, ring(rings - 1, j), ring(rings - 1, j + 1)});
  return m;
}

TriMesh dumbbell(double gap, double bar, int rings, int segments) {
  const double c = 1.0 + gap / 2.0;
  auto r = [=](double z) {
    auto ball = [](double d) { return d < 1.0 ? std::sqrt(1.0 - d * d) : 0.0; };
    double rr = std::max(ball(std::abs(z - c)), ball(std::abs(z + c)));
    if (std::abs(z) < c) rr = std::max(rr, bar);
    return std::max(rr, 1e-3);
  };
  return revolve(r, -c - 1.0, c + 1.0, rings, segments);
}

TriMesh torus(double R, double r, int major, int minor) {
  TriMesh m;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      const double u = 2 * pi * i / major, v = 2 * pi * j / minor;
      m.vertices.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto id = [&](int i, int j) { return (i % major) * minor + (j % minor); };
  for (int i = 0; i < major; ++i)
    for (int j = 0; j < minor; ++j) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

}  // namespace acd::shapes
