// The bytes a capped child sends back to its parent through the pipe (ChildOptions::pipe): values
// copied as they lie in memory, texts as a u64 length and their bytes. Parent and child are the
// same program, so neither byte order nor padding needs converting; the parent still checks every
// length against what is left, since a child that crashed half-way may leave any prefix behind.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>

namespace acdsandbox {

class PipeWriter {
 public:
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "only plain values go through the pipe");
    bytes(&value, sizeof value);
  }
  void bytes(const void* data, std::size_t n) { bytes_.append(static_cast<const char*>(data), n); }
  void text(const std::string& s) { put(static_cast<std::uint64_t>(s.size())), bytes(s.data(), s.size()); }
  const std::string& data() const { return bytes_; }

 private:
  std::string bytes_;
};

class PipeReader {
 public:
  explicit PipeReader(std::string_view bytes) : bytes_(bytes) {}
  /// false (and nothing read) when fewer than sizeof(T) bytes are left
  template <class T>
  bool get(T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "only plain values go through the pipe");
    return bytes(&value, sizeof value);
  }
  bool bytes(void* data, std::size_t n) {
    if (n > left()) return false;
    std::memcpy(data, bytes_.data() + at_, n);
    at_ += n;
    return true;
  }
  bool text(std::string& s) {
    std::uint64_t n = 0;
    if (!get(n) || n > left()) return false;
    s.assign(bytes_.data() + at_, static_cast<std::size_t>(n));
    at_ += static_cast<std::size_t>(n);
    return true;
  }
  /// Whether `count` items of `itemBytes` each can still be there: a guard before resizing to a
  /// count read from the pipe.
  bool fits(std::uint64_t count, std::size_t itemBytes) const { return count <= left() / itemBytes; }
  std::size_t left() const { return bytes_.size() - at_; }

 private:
  std::string_view bytes_;
  std::size_t at_ = 0;
};

/// Writes all of `bytes` to `fd` (retrying interrupted writes); false when the reader is gone.
/// Async-signal-safe apart from what built `bytes`: usable in a forked child.
bool writeAll(int fd, std::string_view bytes);

}  // namespace acdsandbox
