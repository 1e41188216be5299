// SHA-256 (FIPS 180-4), for the content hashes that key acd batch's cache.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace acdcli {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  void update(const std::string& s) { update(s.data(), s.size()); }
  /// The digest as 64 lower-case hex digits; the object is spent afterwards.
  std::string hex();

 private:
  void block(const unsigned char* p);
  std::array<std::uint32_t, 8> h_;
  unsigned char buffer_[64];
  std::size_t buffered_ = 0;
  std::uint64_t bytes_ = 0;
};

/// SHA-256 of a file's bytes; false when it cannot be read (then `error` says why).
bool sha256File(const std::string& path, std::string& hex, std::string& error);

}  // namespace acdcli
