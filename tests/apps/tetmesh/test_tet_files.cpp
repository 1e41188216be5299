// Output files reload: the VTK and Medit files are parsed back here by independent readers.
#include "hull_mesher.hpp"
#include "tet_files.hpp"

#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace tetmesh;

namespace {

struct Reloaded {
  std::vector<Vec3> points;
  std::vector<std::array<int, 4>> tets;  // 0-based
  std::vector<int> labels;
  std::size_t triangles = 0;
};

/// Legacy VTK unstructured grid with tets only and one int cell array.
Reloaded readVtk(const std::string& path) {
  Reloaded r;
  std::ifstream in(path);
  std::string word;
  std::size_t n = 0, total = 0;
  while (in >> word) {
    if (word == "POINTS") {
      std::string type;
      in >> n >> type;
      EXPECT_EQ(type, "double");
      r.points.resize(n);
      for (auto& p : r.points) in >> p.x() >> p.y() >> p.z();
    } else if (word == "CELLS") {
      in >> n >> total;
      EXPECT_EQ(total, 5 * n);
      r.tets.resize(n);
      for (auto& t : r.tets) {
        int four = 0;
        in >> four >> t[0] >> t[1] >> t[2] >> t[3];
        EXPECT_EQ(four, 4);
      }
    } else if (word == "CELL_TYPES") {
      in >> n;
      for (std::size_t i = 0; i < n; ++i) {
        int type = 0;
        in >> type;
        EXPECT_EQ(type, 10);  // VTK_TETRA
      }
    } else if (word == "LOOKUP_TABLE") {
      in >> word;
      r.labels.resize(r.tets.size());
      for (int& l : r.labels) in >> l;
    }
  }
  EXPECT_FALSE(in.bad());
  return r;
}

/// Medit .mesh: Vertices, Triangles, Tetrahedra sections (1-based, with references).
Reloaded readMedit(const std::string& path) {
  Reloaded r;
  std::ifstream in(path);
  std::string word;
  bool ended = false;
  while (in >> word) {
    std::size_t n = 0;
    if (word == "Vertices") {
      in >> n;
      r.points.resize(n);
      for (auto& p : r.points) {
        int ref = 0;
        in >> p.x() >> p.y() >> p.z() >> ref;
      }
    } else if (word == "Triangles") {
      in >> n;
      r.triangles = n;
      for (std::size_t i = 0; i < n; ++i) {
        int a, b, c, ref;
        in >> a >> b >> c >> ref;
        EXPECT_TRUE(ref == kBoundaryFacet || ref == kInterfaceFacet);
      }
    } else if (word == "Tetrahedra") {
      in >> n;
      r.tets.resize(n);
      r.labels.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        in >> r.tets[i][0] >> r.tets[i][1] >> r.tets[i][2] >> r.tets[i][3] >> r.labels[i];
        for (int& v : r.tets[i]) --v;
      }
    } else if (word == "End") {
      ended = true;
    }
  }
  EXPECT_TRUE(ended);
  return r;
}

void expectSame(const TetMesh& m, const Reloaded& r) {
  ASSERT_EQ(r.points.size(), m.points.size());
  for (std::size_t i = 0; i < m.points.size(); ++i) EXPECT_EQ(r.points[i], m.points[i]);  // %.17g round-trips
  ASSERT_EQ(r.tets.size(), m.tets.size());
  EXPECT_EQ(r.tets, m.tets);
  EXPECT_EQ(r.labels, m.labels);
}

class TetFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    HullMeshOptions o;
    o.tau = 0.05;
    o.threads = 1;
    result_ = meshHulls(acd::shapes::lShape(), o);
    ASSERT_TRUE(result_.status.ok()) << result_.status.message;
    dir_ = std::filesystem::temp_directory_path() / ("tetmesh_files_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  HullMeshResult result_;
  std::filesystem::path dir_;
};

}  // namespace

TEST_F(TetFiles, VtkReloads) {
  const std::string path = (dir_ / "l.vtk").string();
  ASSERT_TRUE(writeVtk(path, result_.mesh).ok());
  expectSame(result_.mesh, readVtk(path));
}

TEST_F(TetFiles, MeditReloads) {
  const std::string path = (dir_ / "l.mesh").string();
  ASSERT_TRUE(writeMedit(path, result_.mesh).ok());
  const Reloaded r = readMedit(path);
  expectSame(result_.mesh, r);
  EXPECT_EQ(r.triangles, result_.mesh.faces.size());
  EXPECT_GT(r.triangles, 0u);
}

TEST_F(TetFiles, TetGenFilesHaveConsistentHeaders) {
  const std::string base = (dir_ / "l").string();
  ASSERT_TRUE(writeTetGenFiles(base, result_.mesh).ok());
  std::ifstream node(base + ".node"), ele(base + ".ele"), face(base + ".face");
  std::size_t n = 0, dim = 0, nt = 0, corners = 0, attributes = 0;
  node >> n >> dim;
  ele >> nt >> corners >> attributes;
  EXPECT_EQ(n, result_.mesh.points.size());
  EXPECT_EQ(dim, 3u);
  EXPECT_EQ(nt, result_.mesh.tets.size());
  EXPECT_EQ(corners, 4u);
  EXPECT_EQ(attributes, 1u);
  // Last tet line: index nt, four 1-based corners, the label.
  std::string line, last;
  while (std::getline(ele, line))
    if (!line.empty()) last = line;
  std::istringstream s(last);
  std::size_t index = 0;
  int a, b, c, d, label;
  s >> index >> a >> b >> c >> d >> label;
  EXPECT_EQ(index, nt);
  EXPECT_EQ(a - 1, result_.mesh.tets.back()[0]);
  EXPECT_EQ(label, result_.mesh.labels.back());
  std::size_t nf = 0;
  face >> nf;
  EXPECT_EQ(nf, result_.mesh.faces.size());
}

TEST_F(TetFiles, UnwritablePathIsAnError) {
  const acd::Status s = writeVtk("/nonexistent-dir/x.vtk", result_.mesh);
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message.find("/nonexistent-dir/x.vtk"), std::string::npos);
}
