// Faces given twice (libacd/src/prepare/duplicate_faces.cpp): copies, double-sided sheets and the
// inner walls between cells, each with the faces that must stay.
#include <acd/algo/duplicate_faces.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

using namespace acd;

namespace {

Face reversed(const Face& f) { return {f[0], f[2], f[1]}; }

/// Two unit cells side by side sharing the four vertices of the wall between them, each closed on
/// its own: the wall's two triangles come once per cell, in opposite orientations.
TriMesh twoCells() {
  const TriMesh a = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1)), b = shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1));
  TriMesh m = a;
  std::vector<int> index(b.vertices.size());
  for (std::size_t v = 0; v < b.vertices.size(); ++v) {
    index[v] = -1;
    for (std::size_t w = 0; w < a.vertices.size(); ++w)
      if (a.vertices[w] == b.vertices[v]) index[v] = static_cast<int>(w);
    if (index[v] < 0) index[v] = static_cast<int>(m.vertices.size()), m.vertices.push_back(b.vertices[v]);
  }
  for (const Face& f : b.faces) m.faces.push_back({index[f[0]], index[f[1]], index[f[2]]});
  return m;
}

}  // namespace

TEST(DuplicateFaces, AnExactCopyGoes) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::vector<Face> faces = box.faces;
  faces.push_back({box.faces[3][1], box.faces[3][2], box.faces[3][0]});  // face 3 again, rotated
  const DuplicateOutcome d = resolveDuplicates(faces);
  EXPECT_EQ(d.exactCopies, 1);
  EXPECT_EQ(d.faces, box.faces);
}

TEST(DuplicateFaces, AShellGivenOnBothSidesKeepsTheSideGivenFirst) {
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  std::vector<Face> faces;
  for (const Face& f : box.faces) faces.push_back(reversed(f));  // the inner side first
  faces.insert(faces.end(), box.faces.begin(), box.faces.end());
  const DuplicateOutcome d = resolveDuplicates(faces);
  EXPECT_EQ(d.keptOne, 12);
  EXPECT_EQ(d.droppedBoth, 0);
  ASSERT_EQ(d.faces.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i) EXPECT_EQ(d.faces[i], reversed(box.faces[i]));
}

TEST(DuplicateFaces, TheWallBetweenTwoCellsGoesOnBothSides) {
  const TriMesh cells = twoCells();
  ASSERT_EQ(cells.faces.size(), 24u);
  const DuplicateOutcome d = resolveDuplicates(cells.faces);
  EXPECT_EQ(d.droppedBoth, 2);  // the wall's two triangles, each given once per cell
  EXPECT_EQ(d.keptOne, 0);
  EXPECT_EQ(d.faces.size(), 20u);
  for (const Face& f : d.faces) {
    const bool onWall = cells.vertices[f[0]].x() == 1 && cells.vertices[f[1]].x() == 1 && cells.vertices[f[2]].x() == 1;
    EXPECT_FALSE(onWall);
  }
}
