// One-line status and error messages on stderr, each starting with the program's name
// ("tetmesh: --tau must be positive, got -1"), so that a script reading several programs' output
// knows who spoke.
#pragma once

#include <acd/status.hpp>

#include <string>
#include <utility>

namespace appcli {

class Console {
 public:
  explicit Console(std::string program) : program_(std::move(program)) {}

  /// "PROGRAM: message"; returns `code`, so that `return console.fail(kBadParameter, ...)` ends a run.
  int fail(int code, const std::string& message) const;
  /// printf-style fail, for messages that format numbers.
  int failf(int code, const char* format, ...) const __attribute__((format(printf, 3, 4)));
  /// A failed Status as "PROGRAM: WHERE: message", WHERE said once (readers' messages already
  /// start with the path); returns exitFor(status).
  int fail(const std::string& where, const acd::Status& status) const;
  /// "PROGRAM: line": a status line (progress, a note).
  void say(const std::string& line) const;
  /// printf-style say.
  void sayf(const char* format, ...) const __attribute__((format(printf, 2, 3)));

  const std::string& program() const { return program_; }

 private:
  std::string program_;
};

}  // namespace appcli
