// The text scanning and number printing the file formats share (libacd/src/mesh/format_text.cpp,
// a private header): lines and comments, tokens, numbers that read back exactly, polygons fanned
// into triangles, and the messages for bad indices.
#include "../../libacd/src/mesh/format_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

using namespace acd;
using namespace acd::format;

TEST(FormatText, LinesCommentsAndTokens) {
  LineReader lines("OFF # header\n\n  # only a comment\n1 2\t3 \r\nlast");
  Tokens tokens;
  ASSERT_TRUE(nextContentLine(lines, tokens));
  std::string_view t;
  ASSERT_TRUE(tokens.next(t));
  EXPECT_EQ(t, "OFF");
  EXPECT_FALSE(tokens.next(t));
  ASSERT_TRUE(nextContentLine(lines, tokens));
  EXPECT_EQ(lines.number(), 4);
  for (const char* expected : {"1", "2", "3"}) {
    ASSERT_TRUE(tokens.next(t));
    EXPECT_EQ(t, expected);
  }
  EXPECT_FALSE(tokens.next(t));
  ASSERT_TRUE(nextContentLine(lines, tokens));
  EXPECT_EQ(lines.number(), 5);
  EXPECT_FALSE(nextContentLine(lines, tokens));
  Tokens named("o   a name with spaces  \t");
  ASSERT_TRUE(named.next(t));
  EXPECT_EQ(named.rest(), "a name with spaces");
  LineReader raw("a # b", false);
  std::string_view line;
  ASSERT_TRUE(raw.next(line));
  EXPECT_EQ(line, "a # b");
}

TEST(FormatText, NumbersParseAndRefuse) {
  double d = 0;
  EXPECT_TRUE(parseDouble("-1.5e-3", d));
  EXPECT_EQ(d, -1.5e-3);
  EXPECT_TRUE(parseDouble("nan", d));
  EXPECT_TRUE(std::isnan(d));
  EXPECT_TRUE(parseDouble("inf", d));
  EXPECT_TRUE(std::isinf(d));
  EXPECT_FALSE(parseDouble("1.5x", d));
  EXPECT_FALSE(parseDouble("", d));
  long long i = 0;
  EXPECT_TRUE(parseInteger("-42", i));
  EXPECT_EQ(i, -42);
  EXPECT_FALSE(parseInteger("4.2", i));
  EXPECT_FALSE(parseInteger("99999999999999999999999", i));
}

// Printed numbers read back to the same double (random bit patterns included).
TEST(FormatText, PrintedNumbersReadBackExactly) {
  std::mt19937_64 rng(9);
  std::vector<double> values{0.0, -0.0, 1.0, 0.1, 1.0 / 3.0, 1e-300, 5e-324, 1.7976931348623157e308, -123456.789};
  for (int k = 0; k < 2000; ++k) {
    const std::uint64_t bits = rng();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
  }
  for (double v : values) {
    std::string s;
    appendNumber(s, v);
    double back = 1;
    ASSERT_TRUE(parseDouble(s, back)) << s;
    EXPECT_EQ(std::signbit(back), std::signbit(v)) << s;
    EXPECT_EQ(back, v) << s;
  }
  std::string line;
  appendVertexLine(line, "v ", Vec3(1, -2.5, 0.1));  // the prefix brings its own space
  EXPECT_EQ(line.back(), '\n');
  LineReader lines(line);
  std::string_view text;
  ASSERT_TRUE(lines.next(text));
  Tokens tokens(text);
  std::string_view t;
  ASSERT_TRUE(tokens.next(t));
  EXPECT_EQ(t, "v");
  for (double expected : {1.0, -2.5, 0.1}) {
    ASSERT_TRUE(tokens.next(t));
    double x = 0;
    ASSERT_TRUE(parseDouble(t, x));
    EXPECT_EQ(x, expected);
  }
  std::string n;
  appendInteger(n, -9876543210LL);
  EXPECT_EQ(n, "-9876543210");
}

TEST(FormatText, PolygonsAreFannedAndIndicesNamed) {
  std::vector<Face> faces;
  fanTriangulate({4, 5, 6, 7, 8}, faces);
  ASSERT_EQ(faces.size(), 3u);
  EXPECT_EQ(faces[0], (Face{4, 5, 6}));
  EXPECT_EQ(faces[1], (Face{4, 6, 7}));
  EXPECT_EQ(faces[2], (Face{4, 7, 8}));
  fanTriangulate({1, 2}, faces);  // not a polygon: nothing added
  EXPECT_EQ(faces.size(), 3u);
  const std::string m = outOfRange(7, 12LL, 10);
  EXPECT_NE(m.find("12"), std::string::npos) << m;
  EXPECT_NE(m.find("10"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos);
  EXPECT_FALSE(outOfRange(0, std::numeric_limits<double>::infinity(), 3).empty());
  EXPECT_EQ(quoted("abc").find("abc") != std::string::npos, true);
}
