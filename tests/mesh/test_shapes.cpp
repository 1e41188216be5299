#include <acd/mesh.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

using namespace acd;

TEST(Shapes, GeneratedSolidsAreClosedAndOutward) {
  const double pi = std::acos(-1.0);
  struct Case { const char* name; TriMesh mesh; double volume; double tol; };
  std::vector<Case> cases = {
      {"box", shapes::box(Vec3(0, 0, 0), Vec3(1, 2, 3)), 6.0, 1e-12},
      {"icosphere", shapes::icosphere(Vec3(1, 1, 1), 2.0, 3), 4.0 / 3.0 * pi * 8, 0.05},
      {"L", shapes::lShape(), 3.0, 1e-12},
      {"U", shapes::uShape(), 7.0, 1e-12},
      {"dumbbell", shapes::dumbbell(), 2 * 4.0 / 3.0 * pi, 0.2},
      {"torus", shapes::torus(2.0, 0.5, 64, 32), 2 * pi * pi * 2.0 * 0.25, 0.05},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(isClosedOriented(c.mesh));
    EXPECT_NEAR(signedVolume(c.mesh), c.volume, c.tol * c.volume);
  }
}
