// SHA-256 of acd batch's cache keys against coreutils' sha256sum, around the padding boundaries.
#include "sha256.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace {

std::string sha256sum(const std::string& path) {
  std::string cmd = "sha256sum '" + path + "'";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return "";
  char buf[128] = {0};
  const bool got = std::fgets(buf, sizeof buf, p) != nullptr;
  ::pclose(p);
  return got ? std::string(buf, 64) : "";
}

}  // namespace

TEST(Sha256, MatchesCoreutils) {
  if (std::system("command -v sha256sum >/dev/null 2>&1") != 0) GTEST_SKIP() << "sha256sum not installed";
  const std::string path = (std::filesystem::temp_directory_path() / ("acd_sha_" + std::to_string(::getpid()))).string();
  std::mt19937 rng(7);
  for (std::size_t size : {0, 1, 3, 55, 56, 57, 63, 64, 65, 119, 120, 128, 1000, 65536, 65537, 300001}) {
    std::string data(size, '\0');
    for (char& c : data) c = static_cast<char>(rng());
    std::ofstream(path, std::ios::binary) << data;
    std::string hex, error;
    ASSERT_TRUE(acdcli::sha256File(path, hex, error)) << error;
    EXPECT_EQ(hex, sha256sum(path)) << size << " bytes";
    acdcli::Sha256 pieces;  // fed in uneven pieces: the same digest
    for (std::size_t at = 0; at < size; at += 7 + at % 13) pieces.update(data.data() + at, std::min<std::size_t>(7 + at % 13, size - at));
    EXPECT_EQ(pieces.hex(), hex) << size << " bytes in pieces";
  }
  std::remove(path.c_str());
  std::string hex, error;
  EXPECT_FALSE(acdcli::sha256File("/nonexistent/file", hex, error));
  EXPECT_FALSE(error.empty());
}
