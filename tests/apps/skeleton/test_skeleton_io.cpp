// Skeleton files: JSON round trip, OBJ line segments, tube meshes for rendering.
#include "ged.hpp"
#include "skeleton_io.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <unistd.h>

using namespace skeleton;

namespace {

Graph sample() {
  Graph g;
  g.addNode(Vec3(0, 0, 0), NodeKind::Component, 0);
  g.addNode(Vec3(2, 0, 0), NodeKind::Component, 1);
  g.addNode(Vec3(1, 0.5, 0), NodeKind::Cut);
  g.addEdge(0, 2);
  g.addEdge(2, 1);
  return g;
}

}  // namespace

TEST(SkeletonIo, JsonRoundTrip) {
  const Graph g = sample();
  const nlohmann::json j = toJson(g);
  EXPECT_EQ(j["node_count"], 3);
  EXPECT_EQ(j["edge_count"], 2);
  EXPECT_EQ(j["nodes"][2]["kind"], "cut");
  EXPECT_EQ(j["nodes"][2]["degree"], 2);
  EXPECT_EQ(j["nodes"][1]["component"], 1);
  const Graph back = graphFromJson(nlohmann::json::parse(j.dump()));
  ASSERT_EQ(back.nodeCount(), 3);
  EXPECT_EQ(back.edges, g.edges);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(back.nodes[i].position, g.nodes[i].position);
    EXPECT_EQ(back.nodes[i].kind, g.nodes[i].kind);
  }
  nlohmann::json bad = j;
  bad["edges"].push_back({0, 7});
  EXPECT_THROW(graphFromJson(bad), nlohmann::json::exception);
}

TEST(SkeletonIo, ObjHasOneVertexPerNodeAndOneLinePerEdge) {
  const std::string path = testing::TempDir() + "skeleton_io_" + std::to_string(::getpid()) + ".obj";
  ASSERT_TRUE(writeSkeletonObj(path, sample()));
  std::ifstream in(path);
  std::string line;
  int v = 0, l = 0;
  while (std::getline(in, line)) {
    v += line.rfind("v ", 0) == 0;
    if (line.rfind("l ", 0) == 0) {
      ++l;
      std::istringstream s(line.substr(2));
      int a = 0, b = 0;
      s >> a >> b;
      EXPECT_GE(std::min(a, b), 1);  // OBJ indices are 1-based
      EXPECT_LE(std::max(a, b), 3);
    }
  }
  std::remove(path.c_str());
  EXPECT_EQ(v, 3);
  EXPECT_EQ(l, 2);
  EXPECT_FALSE(writeSkeletonObj("/nonexistent/dir/x.obj", sample()));
}

TEST(SkeletonIo, TubesStayCloseToTheSkeleton) {
  const Graph g = sample();
  const double r = 0.01;
  const acd::TriMesh tubes = tubeMesh(g, r, 8);
  EXPECT_EQ(tubes.vertices.size(), 2u * 2 * 8 + 3u * 6);
  EXPECT_EQ(tubes.faces.size(), 2u * 2 * 8 + 3u * 8);
  for (const Vec3& p : tubes.vertices) {
    // Distance to the nearest edge segment is r (prism) or at most 2r (node octahedra).
    double best = 1e9;
    for (const auto& [a, b] : g.edges) {
      const Vec3 u = g.nodes[a].position, w = g.nodes[b].position;
      const double t = std::clamp((p - u).dot(w - u) / (w - u).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (u + t * (w - u) - p).norm());
    }
    EXPECT_LE(best, 2 * r + 1e-12);
  }
  for (int f = 0; f < static_cast<int>(tubes.faces.size()); ++f)
    EXPECT_GT(acd::faceNormal(tubes, f).norm(), 0.0);  // no degenerate triangles
}
