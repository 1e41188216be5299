// The face grid's nearest face against every face tried one by one, near the surface, inside it,
// far outside the grid, and with a search radius.
#include <acd/algo/closest_point.hpp>
#include <acd/algo/face_grid.hpp>
#include <acd/algo/shapes.hpp>

#include "helpers.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace {

using acd::TriMesh;
using acd::Vec3;

/// The distance to the nearest face of the meshes, and which mesh (the lower on a tie).
std::pair<int, double> everyFace(const std::vector<const TriMesh*>& meshes, const Vec3& p) {
  std::pair<int, double> best{-1, std::numeric_limits<double>::infinity()};
  for (std::size_t m = 0; m < meshes.size(); ++m)
    for (const acd::Face& f : meshes[m]->faces) {
      const TriMesh& t = *meshes[m];
      const double d = (acd::closestPointOnTriangle(p, t.vertices[f[0]], t.vertices[f[1]], t.vertices[f[2]]) - p).norm();
      if (d < best.second) best = {static_cast<int>(m), d};
    }
  return best;
}

TEST(FaceGrid, NearestFaceIsTheOneEveryFaceTriedGives) {
  const TriMesh sphere = acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, 3);
  const TriMesh box = acd::shapes::box(Vec3(1.2, -0.3, -0.3), Vec3(1.8, 0.3, 0.3));
  const std::vector<const TriMesh*> meshes{&sphere, &box};
  const acd::FaceGrid grid(meshes);
  // Points in a ball of radius 3: inside the sphere, between the two, and well outside the grid.
  for (const Vec3& u : acdtest::randomPoints(400, 5, true)) {
    const Vec3 p = 3.0 * u;
    const auto [mesh, distance] = everyFace(meshes, p);
    const acd::FaceGrid::Nearest n = grid.nearest(p);
    EXPECT_EQ(n.mesh, mesh) << p.transpose();
    EXPECT_NEAR(n.distance, distance, 1e-12) << p.transpose();
    ASSERT_GE(n.face, 0);
    const TriMesh& t = *meshes[n.mesh];
    const acd::Face& f = t.faces[n.face];
    EXPECT_NEAR((acd::closestPointOnTriangle(p, t.vertices[f[0]], t.vertices[f[1]], t.vertices[f[2]]) - p).norm(),
                distance, 1e-12);
  }
}

TEST(FaceGrid, ASearchRadiusKeepsWhatIsWithinAndSaysBeyondOfTheRest) {
  const TriMesh sphere = acd::shapes::icosphere(Vec3(0, 0, 0), 1.0, 4);
  const acd::FaceGrid grid({&sphere});
  for (const double within : {0.0, 0.01, 0.1, 0.4}) {
    for (const Vec3& u : acdtest::randomPoints(300, 9, true)) {
      const Vec3 p = 2.0 * u;
      const double distance = everyFace({&sphere}, p).second;
      const double found = grid.nearest(p, within).distance;
      if (distance <= within) EXPECT_NEAR(found, distance, 1e-12) << p.transpose();
      else EXPECT_GT(found, within) << p.transpose();
    }
  }
}

TEST(FaceGrid, PointsFarOffTheGridFindTheirNearestFace) {
  const TriMesh box = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const acd::FaceGrid grid({&box});
  for (const Vec3& p : {Vec3(1e150, 0.5, 0.5), Vec3(-1e150, -1e150, 0.5), Vec3(0.5, 0.5, 1e15)}) {
    const acd::FaceGrid::Nearest n = grid.nearest(p);
    EXPECT_EQ(n.mesh, 0);
    EXPECT_NEAR(n.distance, everyFace({&box}, p).second, 1e-9 * everyFace({&box}, p).second);
  }
}

// A plate a nanometre thick and two units wide: cells of the faces' own size would number
// billions; the grid stays about the size of the mesh and still finds the nearest face.
TEST(FaceGrid, AFlatBoxGivesAGridAboutTheSizeOfTheMesh) {
  const TriMesh plate = acd::shapes::box(Vec3(-1, -1, 0), Vec3(1, 1, 1e-9));
  const acd::FaceGrid grid({&plate});
  for (const Vec3& p : {Vec3(0.3, 0.2, 0.5), Vec3(2, 2, 0), Vec3(0, 0, 5e-10)}) {
    const acd::FaceGrid::Nearest n = grid.nearest(p);
    EXPECT_NEAR(n.distance, everyFace({&plate}, p).second, 1e-12) << p.transpose();
  }
}

// Faces are numbered across the meshes (empty ones among them): the face found must be the
// found mesh's own, the one every face tried gives, also for points on a wall two boxes share.
TEST(FaceGrid, ManyMeshesGiveBackTheirOwnFaces) {
  const TriMesh empty;
  const TriMesh left = acd::shapes::box(Vec3(0, 0, 0), Vec3(1, 1, 1));
  const TriMesh right = acd::shapes::box(Vec3(1, 0, 0), Vec3(2, 1, 1));
  const TriMesh ball = acd::shapes::icosphere(Vec3(1, 0.5, 2.5), 0.8, 2);
  const std::vector<const TriMesh*> meshes{&empty, &left, &empty, &right, &empty, &ball, &empty};
  const acd::FaceGrid grid(meshes);
  std::vector<Vec3> points;
  for (const Vec3& u : acdtest::randomPoints(300, 17, true)) points.push_back(Vec3(1, 0.5, 1.2) + 2.5 * u);
  for (double y : {0.1, 0.5, 0.9}) points.push_back(Vec3(1, y, 0.5));  // on the shared wall
  for (const Vec3& p : points) {
    const auto [mesh, distance] = everyFace(meshes, p);
    const acd::FaceGrid::Nearest n = grid.nearest(p);
    ASSERT_EQ(n.mesh, mesh) << p.transpose();
    ASSERT_GE(n.face, 0);
    ASSERT_LT(n.face, static_cast<int>(meshes[n.mesh]->faces.size())) << p.transpose();
    const TriMesh& t = *meshes[n.mesh];
    const acd::Face& f = t.faces[n.face];
    EXPECT_NEAR((acd::closestPointOnTriangle(p, t.vertices[f[0]], t.vertices[f[1]], t.vertices[f[2]]) - p).norm(),
                distance, 1e-12) << p.transpose();
  }
}

TEST(FaceGrid, NoFacesFindNothing) {
  const TriMesh empty;
  const acd::FaceGrid grid({&empty});
  EXPECT_EQ(grid.nearest(Vec3(0, 0, 0)).mesh, -1);
}

}  // namespace
