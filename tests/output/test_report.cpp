// report.json (libacd/src/output/report.cpp) of a solid decomposition, read back and checked
// against what the test measures itself: the input's counts, each component's size and volume
// (the divergence theorem here, scaled by the reported normalisation), the totals as sums, sorted
// keys and one trailing newline.
#include <acd/decompose.hpp>
#include <acd/report.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "helpers.hpp"

#include <cmath>

using namespace acd;
using json = nlohmann::json;

namespace {

double volumeOf(const TriMesh& m) {
  double v = 0;
  for (const Face& f : m.faces)
    v += m.vertices[f[0]].dot(m.vertices[f[1]].cross(m.vertices[f[2]])) / 6.0;
  return v;
}

}  // namespace

TEST(Report, SolidReportAgreesWithTheDecomposition) {
  TriMesh u = shapes::uShape();
  for (Vec3& v : u.vertices) v = 3.0 * v + Vec3(10, -4, 2);  // not already in normalised units
  const Decomposition d = acdtest::decomposed(u, 0.05);
  ASSERT_GT(d.components.size(), 1u);
  const std::string text = reportJson(describeInput("u.off", u), d);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  EXPECT_NE(text[text.size() - 2], '\n');
  const json j = json::parse(text);
  // nlohmann::json sorts keys itself when parsing: the order is checked in the text.
  std::size_t last = 0;
  for (const char* key : {"\"components\"", "\"input\"", "\"model\"", "\"parameters\"", "\"totals\""}) {
    const std::size_t at = text.find(std::string("\n  ") + key);
    ASSERT_NE(at, std::string::npos) << key;
    EXPECT_GT(at, last) << key << " out of order";
    last = at;
  }
  EXPECT_EQ(j["model"], "u.off");
  EXPECT_EQ(j["input"]["vertices"].get<std::size_t>(), u.vertices.size());
  EXPECT_EQ(j["input"]["faces"].get<std::size_t>(), u.faces.size());
  EXPECT_EQ(j["input"]["genus"].get<int>(), 0);
  const double scale = j["input"]["normalization"]["scale"].get<double>();
  EXPECT_NEAR(scale, d.normalization.scale, 1e-15 * scale);
  EXPECT_NEAR(j["input"]["volume"].get<double>(), volumeOf(u) * std::pow(scale, 3), 1e-9);
  ASSERT_EQ(j["components"].size(), d.components.size());
  double sum = 0;
  for (std::size_t i = 0; i < d.components.size(); ++i) {
    const json& c = j["components"][i];
    const Component& k = d.components[i];
    EXPECT_EQ(c["vertices"].get<std::size_t>(), k.mesh.vertices.size());
    EXPECT_EQ(c["faces"].get<std::size_t>(), k.mesh.faces.size());
    EXPECT_EQ(c["hull_vertices"].get<std::size_t>(), k.hull.vertices.size());
    EXPECT_NEAR(c["volume"].get<double>(), volumeOf(k.mesh) * std::pow(scale, 3), 1e-9) << "component " << i;
    EXPECT_NEAR(c["hull_volume"].get<double>(), volumeOf(k.hull) * std::pow(scale, 3), 1e-9) << "component " << i;
    EXPECT_FALSE(c["unresolved"].get<bool>());
    sum += c["volume"].get<double>();
  }
  EXPECT_EQ(j["totals"]["components"].get<std::size_t>(), d.components.size());
  EXPECT_NEAR(j["totals"]["volume"].get<double>(), sum, 1e-12);
  EXPECT_EQ(j["totals"]["unresolved"].get<int>(), 0);
  EXPECT_DOUBLE_EQ(j["parameters"]["tau"].get<double>(), 0.05);
}
