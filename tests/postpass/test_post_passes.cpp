// The post-passes as the command and the Python module run them: options given or not, the
// budget before the cap, tau as a length, the report's sections only for the passes that ran.
#include <acd/post_passes.hpp>
#include <acd/report.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "helpers.hpp"

#include <cmath>

using namespace acd;
using json = nlohmann::json;
using acdtest::decomposed;

TEST(PostPasses, OnlyTheOptionsGivenAreChecked) {
  EXPECT_TRUE(validate(PostPassOptions{}).ok());
  PostPassOptions o;
  o.maxHulls = 0;  // given as 0: refused, where absent means no budget
  EXPECT_EQ(validate(o).code, StatusCode::InvalidParameter);
  EXPECT_NE(validate(o).message.find("--max-hulls must be at least 1"), std::string::npos);
  o = {};
  o.maxHullVertices = 3;
  EXPECT_NE(validate(o).message.find("at least 4"), std::string::npos);
  o = {};
  o.tauAbs = -1.0;
  EXPECT_NE(validate(o).message.find("--tau-abs must be a positive length"), std::string::npos);
  o = {};
  o.density = 0.0;
  EXPECT_FALSE(validate(o).ok());
}

TEST(PostPasses, NothingGivenLeavesTheDecompositionAndAddsTheMassProperties) {
  Decomposition d = decomposed(shapes::lShape(), 0.05);
  const std::size_t parts = d.components.size();
  const PostPassResult r = applyPostPasses(d, PostPassOptions{});
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(d.components.size(), parts);
  EXPECT_FALSE(r.budget || r.cap || r.tauAbs);
  const json j = json::parse(reportJson(describeInput("L", shapes::lShape()), d, r));
  EXPECT_FALSE(j.contains("hull_budget") || j.contains("hull_vertex_cap") || j.contains("tau_abs"));
  EXPECT_NEAR(j["mass_properties"]["mass"].get<double>(), 1000.0 * j["mass_properties"]["volume"].get<double>(), 1e-9);
  EXPECT_FALSE(j["components"][0].contains("merged_from"));
}

TEST(PostPasses, BudgetThenCapWithTheirSections) {
  Decomposition d = decomposed(shapes::torus(2.0, 0.6, 48, 16), 0.02);
  ASSERT_GT(d.components.size(), 3u);
  PostPassOptions o;
  o.maxHulls = 3;
  o.maxHullVertices = 8;
  const PostPassResult r = applyPostPasses(d, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(d.components.size(), 3u);
  for (const Component& c : d.components) EXPECT_LE(c.hull.vertices.size(), 8u);
  ASSERT_TRUE(r.budget && r.cap);
  EXPECT_EQ(r.cap->hulls, 3);
  EXPECT_EQ(r.cap->withinCap, 3);
  const json j = json::parse(reportJson(describeInput("torus", shapes::torus(2.0, 0.6, 48, 16)), d, r));
  EXPECT_EQ(j["hull_budget"]["components_after"], 3);
  EXPECT_EQ(j["hull_vertex_cap"]["max_hull_vertices"], 8);
  for (const json& c : j["components"]) {
    EXPECT_TRUE(c.contains("merged_from") && c.contains("uncapped_hull_vertices"));
    EXPECT_LE(c["hull_vertices"].get<int>(), 8);
    EXPECT_GE(c["added_volume"].get<double>(), 0.0);
  }
}

TEST(PostPasses, TauAbsIsTheLengthInNormalisedUnits) {
  // A box 4 x 2 x 2: its minimum enclosing sphere has radius sqrt(6), so 0.1 units is tau 0.1 / sqrt(6).
  const TriMesh box = shapes::box(Vec3(0, 0, 0), Vec3(4, 2, 2));
  PostPassOptions post;
  post.tauAbs = 0.1;
  DecomposeOptions options;
  ASSERT_TRUE(resolveTauAbs(box, post, options).ok());
  EXPECT_NEAR(options.tau, 0.1 / std::sqrt(6.0), 1e-5);
  post.tauAbs = 100.0;  // tau 40: above 2, the normalised model's diameter
  const Status far = resolveTauAbs(box, post, options);
  EXPECT_EQ(far.code, StatusCode::InvalidParameter);
  EXPECT_NE(far.message.find("outside [1e-4, 2]"), std::string::npos) << far.message;
}
