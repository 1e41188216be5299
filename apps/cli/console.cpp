#include <appcli/console.hpp>

#include <appcli/exit_codes.hpp>

#include <cstdarg>
#include <cstdio>
#include <vector>

namespace appcli {

namespace {

std::string vformat(const char* format, va_list args) {
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  if (n <= 0) return {};
  std::vector<char> text(static_cast<std::size_t>(n) + 1);
  std::vsnprintf(text.data(), text.size(), format, args);
  return std::string(text.data(), static_cast<std::size_t>(n));
}

}  // namespace

int Console::fail(int code, const std::string& message) const {
  say(message);
  return code;
}

int Console::failf(int code, const char* format, ...) const {
  va_list args;
  va_start(args, format);
  const std::string message = vformat(format, args);
  va_end(args);
  return fail(code, message);
}

int Console::fail(const std::string& where, const acd::Status& status) const {
  if (status.message.rfind(where, 0) == 0)
    say(status.message);
  else
    say(where + ": " + status.message);
  return exitFor(status);
}

void Console::say(const std::string& line) const { std::fprintf(stderr, "%s: %s\n", program_.c_str(), line.c_str()); }

void Console::sayf(const char* format, ...) const {
  va_list args;
  va_start(args, format);
  const std::string line = vformat(format, args);
  va_end(args);
  say(line);
}

}  // namespace appcli
