// The URDF that `acd decompose --format urdf` writes, read by urdfdom (ROS's URDF parser).
#include <urdf_parser/urdf_parser.h>

#include "sim_fixture.hpp"

#include <filesystem>

namespace fs = std::filesystem;

using UrdfOutput = simtest::SimOutput;

TEST_F(UrdfOutput, ParsesWithOneCollisionPerHullAndTheModelsInertial) {
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDFFile(out_ + "/model.urdf");
  ASSERT_TRUE(model) << "urdfdom refused model.urdf";
  EXPECT_EQ(model->getName(), "u_shape");
  ASSERT_EQ(model->links_.size(), 1u);
  const urdf::LinkConstSharedPtr link = model->getRoot();
  ASSERT_TRUE(link);
  ASSERT_EQ(static_cast<int>(link->collision_array.size()), hulls());
  for (const auto& c : link->collision_array) {
    ASSERT_TRUE(c->geometry);
    ASSERT_EQ(c->geometry->type, urdf::Geometry::MESH);
    const auto mesh = std::dynamic_pointer_cast<urdf::Mesh>(c->geometry);
    const acd::ReadResult r = acd::readMesh(out_ + "/" + mesh->filename);
    ASSERT_TRUE(r.status.ok()) << mesh->filename;
    std::vector<acd::Vec3> unique = r.mesh.vertices;  // STL: corners merged by position on reading
    EXPECT_LE(unique.size(), 12u) << mesh->filename;
  }
  ASSERT_TRUE(link->visual);
  EXPECT_EQ(std::dynamic_pointer_cast<urdf::Mesh>(link->visual->geometry)->filename, "model.stl");
  EXPECT_TRUE(fs::exists(out_ + "/model.stl"));
  ASSERT_TRUE(link->inertial);
  EXPECT_NEAR(link->inertial->mass, kDensity * kVolume, 1e-6);
  const urdf::Vector3& p = link->inertial->origin.position;
  EXPECT_NEAR(p.x, centerOfMass().x(), 1e-7);
  EXPECT_NEAR(p.y, centerOfMass().y(), 1e-7);
  EXPECT_NEAR(p.z, centerOfMass().z(), 1e-7);
  // Symmetric about x = 1.5 + shift and z = 0.5 + shift: those products of inertia vanish.
  EXPECT_NEAR(link->inertial->ixy, 0.0, 1e-6);
  EXPECT_NEAR(link->inertial->ixz, 0.0, 1e-6);
  EXPECT_NEAR(link->inertial->iyz, 0.0, 1e-6);
  EXPECT_GT(link->inertial->ixx, 0.0);
  EXPECT_GT(link->inertial->iyy, 0.0);
  EXPECT_GT(link->inertial->izz, 0.0);
  // izz = ixx + iyy for a... not a plate; but izz >= each and the triangle inequality holds.
  EXPECT_LE(link->inertial->izz, link->inertial->ixx + link->inertial->iyy + 1e-6);
}
