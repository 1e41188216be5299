// The hulls in a physics engine (Bullet): a box decomposes to one hull whose btConvexHullShape is
// the box, and the hulls of a model, as a compound of btConvexHullShapes dropped onto a plane,
// come to rest with the model's lowest point on the plane.
#include <btBulletDynamicsCommon.h>

#include "sim_fixture.hpp"

#include <acd/mesh.hpp>

#include <cmath>
#include <filesystem>
#include <memory>

namespace fs = std::filesystem;
using acd::Vec3;

namespace {

/// Runs `acd decompose MODEL ARGS --format stl` and returns the report (empty on failure).
nlohmann::json decompose(const std::string& model, const std::string& args, const acdtest::TempDir& dir,
                         const std::string& out) {
  const acdtest::ToolRun r = acdtest::runTool(
      ACD_CLI, "decompose " + acdtest::quote(model) + " " + args + " --format stl -o " + acdtest::quote(out) + " -q", dir);
  EXPECT_EQ(r.code, 0) << r.err;
  if (r.code != 0) return {};
  std::ifstream in(out + "/report.json");
  return nlohmann::json::parse(in);
}

std::vector<acd::TriMesh> readHulls(const std::string& out, int count) {
  std::vector<acd::TriMesh> hulls;
  for (int i = 0; i < count; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "/hulls/hull_%03d.stl", i);
    const acd::ReadResult r = acd::readMesh(out + name);
    EXPECT_TRUE(r.status.ok()) << r.status.message;
    hulls.push_back(r.mesh);
  }
  return hulls;
}

std::unique_ptr<btConvexHullShape> hullShape(const acd::TriMesh& hull, const Vec3& offset, double margin) {
  auto shape = std::make_unique<btConvexHullShape>();
  for (const Vec3& v : hull.vertices) shape->addPoint(btVector3(v.x() - offset.x(), v.y() - offset.y(), v.z() - offset.z()), false);
  shape->setMargin(static_cast<btScalar>(margin));
  shape->recalcLocalAabb();  // after the margin: the cached box includes it
  return shape;
}

struct Rest {
  double lowest = 0.0;  // the model's lowest point above the plane
  double speed = 0.0;   // linear + angular speed at the end
};

/// Drops the hulls (as one rigid compound about the centre of mass) from `height` above the
/// plane z = 0, tilted, and simulates until rest; measures the model's vertices.
Rest drop(const acd::TriMesh& model, const std::vector<acd::TriMesh>& hulls, const Vec3& com, double mass,
          double height, double margin) {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, 0, -9.81));

  btStaticPlaneShape plane(btVector3(0, 0, 1), 0);
  btDefaultMotionState planeState;
  btRigidBody ground(btRigidBody::btRigidBodyConstructionInfo(0, &planeState, &plane));
  ground.setFriction(0.8);
  world.addRigidBody(&ground);

  std::vector<std::unique_ptr<btConvexHullShape>> parts;
  btCompoundShape compound;
  for (const acd::TriMesh& h : hulls) {
    parts.push_back(hullShape(h, com, margin));
    btTransform t;
    t.setIdentity();
    compound.addChildShape(t, parts.back().get());
  }
  btVector3 inertia;
  compound.calculateLocalInertia(static_cast<btScalar>(mass), inertia);
  btTransform start;
  start.setIdentity();
  start.setRotation(btQuaternion(btVector3(1, 0.3, 0).normalized(), 0.35));
  acd::Box3 box = acd::boundingBox(model);
  start.setOrigin(btVector3(0, 0, static_cast<btScalar>(height + (box.hi - box.lo).norm())));
  btDefaultMotionState state(start);
  btRigidBody body(btRigidBody::btRigidBodyConstructionInfo(static_cast<btScalar>(mass), &state, &compound, inertia));
  body.setFriction(0.8);
  body.setDamping(0.05, 0.3);
  world.addRigidBody(&body);
  for (int step = 0; step < 6000; ++step) world.stepSimulation(1.0f / 240.0f, 1, 1.0f / 240.0f);

  btTransform end;
  body.getMotionState()->getWorldTransform(end);
  Rest r;
  r.lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& v : model.vertices) {
    const btVector3 w = end * btVector3(v.x() - com.x(), v.y() - com.y(), v.z() - com.z());
    r.lowest = std::min(r.lowest, static_cast<double>(w.z()));
  }
  r.speed = body.getLinearVelocity().length() + body.getAngularVelocity().length();
  world.removeRigidBody(&body);
  world.removeRigidBody(&ground);
  return r;
}

Vec3 vec(const nlohmann::json& a) { return Vec3(a[0].get<double>(), a[1].get<double>(), a[2].get<double>()); }

}  // namespace

TEST(BulletRest, BoxIsOneHullWhoseShapeIsTheBox) {
  if (!fs::exists(ACD_CLI)) GTEST_SKIP() << "CLI not built";
  acdtest::TempDir dir("bullet_box");
  const Vec3 lo(-0.4, 1.0, 2.0), hi(0.6, 1.5, 4.0);
  ASSERT_TRUE(acd::writeMesh(dir / "box.off", acd::shapes::box(lo, hi)).ok());
  const nlohmann::json report = decompose(dir / "box.off", "--max-hull-vertices 8", dir, dir / "out");
  ASSERT_EQ(report["components"].size(), 1u);
  const std::vector<acd::TriMesh> hulls = readHulls(dir / "out", 1);
  const auto shape = hullShape(hulls[0], Vec3::Zero(), 0.0);
  EXPECT_EQ(shape->getNumPoints(), 8);
  // Same support in every direction of a cube's faces, edges and corners.
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z) {
        if (!x && !y && !z) continue;
        const Vec3 d(x, y, z);
        const btVector3 s = shape->localGetSupportingVertexWithoutMargin(btVector3(x, y, z));
        const double expected = (d.array() > 0).select(hi, lo).dot(d);  // the box's support
        EXPECT_NEAR(s.dot(btVector3(x, y, z)), expected, 1e-5) << x << y << z;
      }
  btVector3 aabbMin, aabbMax;
  btTransform id;
  id.setIdentity();
  shape->getAabb(id, aabbMin, aabbMax);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(aabbMin[k], lo[k], 1e-5);
    EXPECT_NEAR(aabbMax[k], hi[k], 1e-5);
  }
}

TEST(BulletRest, DroppedUShapeRestsOnItsLowestPoint) {
  if (!fs::exists(ACD_CLI)) GTEST_SKIP() << "CLI not built";
  acdtest::TempDir dir("bullet_u");
  const acd::TriMesh u = acd::shapes::uShape();
  ASSERT_TRUE(acd::writeMesh(dir / "u.off", u).ok());
  const nlohmann::json report = decompose(dir / "u.off", "-t 0.02 --max-hull-vertices 12", dir, dir / "out");
  ASSERT_FALSE(report.empty());
  const int n = static_cast<int>(report["components"].size());
  ASSERT_GE(n, 2);
  const auto& mp = report["mass_properties"];
  const Rest r = drop(u, readHulls(dir / "out", n), vec(mp["center_of_mass"]), mp["mass"].get<double>(), 1.0, 1e-3);
  EXPECT_LT(r.speed, 1e-2);
  EXPECT_NEAR(r.lowest, 0.0, 0.02) << "size 3: within 2 % of a cell";
}

TEST(BulletRest, DroppedElephantRestsOnItsLowestPoint) {
  if (!fs::exists(ACD_CLI)) GTEST_SKIP() << "CLI not built";
  const std::string model = std::string(ACD_DATA_DIR) + "/meshes/elephant.off";
  if (!fs::exists(model)) GTEST_SKIP() << "corpus not fetched: " << model;
  acdtest::TempDir dir("bullet_elephant");
  const nlohmann::json report = decompose(model, "--max-hull-vertices 60 --max-hulls 64", dir, dir / "out");
  ASSERT_FALSE(report.empty());
  const int n = static_cast<int>(report["components"].size());
  ASSERT_LE(n, 64);
  const acd::ReadResult m = acd::readMesh(model);
  ASSERT_TRUE(m.status.ok());
  const acd::Box3 box = acd::boundingBox(m.mesh);
  const double size = (box.hi - box.lo).norm();
  const auto& mp = report["mass_properties"];
  const Rest r = drop(m.mesh, readHulls(dir / "out", n), vec(mp["center_of_mass"]), mp["mass"].get<double>(),
                      0.2 * size, 1e-3 * size);
  EXPECT_LT(r.speed, 1e-2 * size);
  EXPECT_NEAR(r.lowest, 0.0, 0.01 * size);
}
