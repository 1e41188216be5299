// The SDF that `acd decompose --format sdf` writes, read and validated by libsdformat (Gazebo's).
#include <sdf/Collision.hh>
#include <sdf/Geometry.hh>
#include <sdf/Link.hh>
#include <sdf/Mesh.hh>
#include <sdf/Model.hh>
#include <sdf/Root.hh>

#include "sim_fixture.hpp"

#include <filesystem>

using SdfOutput = simtest::SimOutput;

TEST_F(SdfOutput, LoadsWithoutErrorsWithOneCollisionPerHull) {
  sdf::Root root;
  const sdf::Errors errors = root.Load(out_ + "/model.sdf");
  for (const sdf::Error& e : errors) ADD_FAILURE() << e.Message();
  ASSERT_NE(root.Model(), nullptr);
  const sdf::Model* model = root.Model();
  EXPECT_EQ(model->Name(), "u_shape");
  ASSERT_EQ(model->LinkCount(), 1u);
  const sdf::Link* link = model->LinkByIndex(0);
  ASSERT_EQ(static_cast<int>(link->CollisionCount()), hulls());
  for (std::uint64_t i = 0; i < link->CollisionCount(); ++i) {
    const sdf::Geometry* g = link->CollisionByIndex(i)->Geom();
    ASSERT_EQ(g->Type(), sdf::GeometryType::MESH);
    EXPECT_TRUE(std::filesystem::exists(out_ + "/" + g->MeshShape()->Uri())) << g->MeshShape()->Uri();
  }
  EXPECT_EQ(link->VisualCount(), 1u);
  const auto inertial = link->Inertial();
  EXPECT_NEAR(inertial.MassMatrix().Mass(), kDensity * kVolume, 1e-6);
  EXPECT_NEAR(inertial.Pose().Pos().X(), centerOfMass().x(), 1e-7);
  EXPECT_NEAR(inertial.Pose().Pos().Y(), centerOfMass().y(), 1e-7);
  EXPECT_NEAR(inertial.Pose().Pos().Z(), centerOfMass().z(), 1e-7);
  EXPECT_TRUE(inertial.MassMatrix().IsValid()) << "sdformat finds the inertia not physical";
}
