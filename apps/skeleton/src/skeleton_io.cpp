#include "skeleton_io.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>

namespace skeleton {

nlohmann::json toJson(const Graph& g) {
  const std::vector<int> deg = degrees(g);
  nlohmann::json nodes = nlohmann::json::array(), edges = nlohmann::json::array();
  for (int i = 0; i < g.nodeCount(); ++i) {
    const Node& n = g.nodes[i];
    nlohmann::json node = {{"id", i}, {"kind", toString(n.kind)},
                           {"position", {n.position.x(), n.position.y(), n.position.z()}}, {"degree", deg[i]}};
    if (n.kind == NodeKind::Component) node["component"] = n.source;
    nodes.push_back(node);
  }
  for (const auto& [a, b] : g.edges) edges.push_back({a, b});
  return {{"node_count", g.nodeCount()}, {"edge_count", g.edgeCount()}, {"nodes", nodes}, {"edges", edges}};
}

Graph graphFromJson(const nlohmann::json& j) {
  Graph g;
  for (const auto& node : j.at("nodes")) {
    const auto p = node.at("position").get<std::vector<double>>();
    const std::string kind = node.value("kind", "curve");
    g.addNode(Vec3(p.at(0), p.at(1), p.at(2)),
              kind == "component" ? NodeKind::Component : kind == "cut" ? NodeKind::Cut : NodeKind::Curve,
              node.value("component", -1));
  }
  for (const auto& e : j.at("edges")) {
    const int a = e.at(0).get<int>(), b = e.at(1).get<int>();
    if (a < 0 || b < 0 || a >= g.nodeCount() || b >= g.nodeCount())
      throw nlohmann::json::out_of_range::create(401, "edge names a node that does not exist", &e);
    g.addEdge(a, b);
  }
  return g;
}

nlohmann::json toJson(const GedResult& r) {
  nlohmann::json j = {{"distance", r.distance}, {"lower_bound", r.lowerBound}, {"exact", r.exact},
                      {"method", r.method},     {"expansions", r.expansions},  {"seconds", r.seconds}};
  if (r.method == "bipartite") j["assignment_distance"] = r.assignmentCost;  // before local search
  return j;
}

bool writeSkeletonObj(const std::string& path, const Graph& g) {
  std::ofstream out(path);
  if (!out) return false;
  out << "# skeleton: " << g.nodeCount() << " nodes, " << g.edgeCount() << " edges\n" << std::setprecision(9);
  for (const Node& n : g.nodes) out << "v " << n.position.x() << ' ' << n.position.y() << ' ' << n.position.z() << '\n';
  for (const auto& [a, b] : g.edges) out << "l " << a + 1 << ' ' << b + 1 << '\n';
  return static_cast<bool>(out);
}

acd::TriMesh tubeMesh(const Graph& g, double radius, int sides) {
  acd::TriMesh m;
  sides = std::max(3, sides);
  for (const auto& [a, b] : g.edges) {
    const Vec3 p = g.nodes[a].position, q = g.nodes[b].position, d = q - p;
    if (!(d.norm() > 0)) continue;
    const Vec3 axis = d.normalized();
    const Vec3 u = axis.unitOrthogonal(), w = axis.cross(u);
    const int base = static_cast<int>(m.vertices.size());
    for (int k = 0; k < sides; ++k) {
      const double t = 2.0 * M_PI * k / sides;
      const Vec3 r = radius * (std::cos(t) * u + std::sin(t) * w);
      m.vertices.push_back(p + r);
      m.vertices.push_back(q + r);
    }
    for (int k = 0; k < sides; ++k) {
      const int k2 = (k + 1) % sides;
      const int p0 = base + 2 * k, q0 = p0 + 1, p1 = base + 2 * k2, q1 = p1 + 1;
      m.faces.push_back({p0, p1, q1});
      m.faces.push_back({p0, q1, q0});
    }
  }
  for (const Node& n : g.nodes) {
    const double r = 2.0 * radius;
    const int base = static_cast<int>(m.vertices.size());
    for (int axis = 0; axis < 3; ++axis)
      for (double s : {1.0, -1.0}) {
        Vec3 v = n.position;
        v[axis] += s * r;
        m.vertices.push_back(v);
      }
    // Octahedron: +x,-x,+y,-y,+z,-z = base+0..5, faces outward.
    const int px = base, nx = base + 1, py = base + 2, ny = base + 3, pz = base + 4, nz = base + 5;
    for (const acd::Face& f : std::vector<acd::Face>{{px, py, pz}, {py, nx, pz}, {nx, ny, pz}, {ny, px, pz},
                                                     {py, px, nz}, {nx, py, nz}, {ny, nx, nz}, {px, ny, nz}})
      m.faces.push_back(f);
  }
  return m;
}

}  // namespace skeleton
