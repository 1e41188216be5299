// OFF (libacd/src/mesh/io_off.cpp): polygons, colours, comments, counts on the header line, NOFF,
// errors that name the line, and non-finite coordinates.
#include "io_helpers.hpp"

#include <acd/io.hpp>
#include <acd/algo/shapes.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace acd;
using namespace acdtest;

TEST(Io, OffWithQuadsColoursAndComments) {
  const ReadResult r = readText(".off",
                                "COFF # coloured\n"
                                "# a unit square pyramid\n"
                                "5 2 0\n"
                                "0 0 0 255 0 0 255\n"
                                "1 0 0 255 0 0 255\n"
                                "\n"
                                "1 1 0 255 0 0 255\n"
                                "0 1 0 255 0 0 255\n"
                                "0.5 0.5 +1e0 255 0 0 255\n"
                                "4 0 3 2 1 0.5 0.5 0.5\n"
                                "3 0 1 4\n");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.mesh.vertices.size(), 5u);
  EXPECT_EQ(r.mesh.vertices[4], Vec3(0.5, 0.5, 1.0));
  ASSERT_EQ(r.mesh.faces.size(), 3u);
  EXPECT_EQ(r.mesh.faces[0], (Face{0, 3, 2}));
  EXPECT_EQ(r.mesh.faces[1], (Face{0, 2, 1}));
  EXPECT_EQ(r.mesh.faces[2], (Face{0, 1, 4}));
}

TEST(Io, OffCountsOnTheHeaderLineAndNoff) {
  const ReadResult r = readText(".off", "NOFF 3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_EQ(r.mesh.faces.size(), 1u);
}

TEST(Io, OffErrorsNameTheLine) {
  const ReadResult few = readText(".off", "OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(few.status.code, StatusCode::FileUnreadable);
  EXPECT_NE(few.status.message.find("line 4: expected 3 coordinates"), std::string::npos) << few.status.message;

  const ReadResult range = readText(".off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
  EXPECT_EQ(range.status.code, StatusCode::IndexOutOfRange);
  EXPECT_NE(range.status.message.find("face 0 refers to vertex 3 but the file has 3 vertices"), std::string::npos)
      << range.status.message;

  const ReadResult shortFile = readText(".off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  EXPECT_EQ(shortFile.status.code, StatusCode::FileUnreadable);
  EXPECT_NE(shortFile.status.message.find("read 2 of 3 vertices"), std::string::npos) << shortFile.status.message;
}

TEST(Io, NanCoordinateInOffIsReadNotRejected) {
  const ReadResult r = readText(".off", "OFF\n3 1 0\nnan 0 0\n1 inf 0\n0 1 -Infinity\n3 0 1 2\n");
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(std::isnan(r.mesh.vertices[0].x()));
  EXPECT_EQ(r.mesh.vertices[1].y(), INFINITY);
  EXPECT_EQ(r.mesh.vertices[2].z(), -INFINITY);
}
