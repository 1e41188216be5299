// Status (libacd/src/mesh/status.cpp): every code has its own non-empty name, success is ok and an
// error is not, with its message kept.
#include <acd/status.hpp>

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace acd;

TEST(Status, EveryCodeHasItsOwnName) {
  std::set<std::string> names;
  int count = 0;
  for (int c = static_cast<int>(StatusCode::Ok); c <= static_cast<int>(StatusCode::InternalError); ++c, ++count) {
    const std::string name = toString(static_cast<StatusCode>(c));
    EXPECT_FALSE(name.empty()) << c;
    EXPECT_NE(name, "unknown") << c;
    names.insert(name);
  }
  EXPECT_EQ(static_cast<int>(names.size()), count);
  EXPECT_STREQ(toString(StatusCode::Ok), "ok");
  EXPECT_STREQ(toString(StatusCode::OpenMesh), "open mesh");
  EXPECT_STREQ(toString(static_cast<StatusCode>(999)), "unknown");
}

TEST(Status, SuccessAndError) {
  EXPECT_TRUE(Status::success().ok());
  EXPECT_TRUE(Status::success().message.empty());
  const Status e = Status::error(StatusCode::InvalidParameter, "tau must be positive");
  EXPECT_FALSE(e.ok());
  EXPECT_EQ(e.code, StatusCode::InvalidParameter);
  EXPECT_EQ(e.message, "tau must be positive");
}
