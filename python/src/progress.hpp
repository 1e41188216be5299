// A library progress callback relayed to a Python callable.
#pragma once

#include <pybind11/pybind11.h>

#include <functional>
#include <optional>
#include <utility>

namespace acdpy {

namespace py = pybind11;

/// The library's progress callback, relayed to a Python callable with the GIL held. The library
/// cannot be stopped midway, so an exception from the callable silences it and is raised once
/// the library returns.
class ProgressRelay {
 public:
  explicit ProgressRelay(py::object callback) : callback_(std::move(callback)) {}

  template <class... Args>
  std::function<void(Args...)> function() {
    if (callback_.is_none()) return {};
    return [this](Args... args) {
      if (error_) return;
      py::gil_scoped_acquire gil;
      try {
        callback_(args...);
      } catch (py::error_already_set& e) {
        error_ = std::move(e);
      }
    };
  }

  void raiseIfFailed() {
    if (error_) throw *error_;
  }

 private:
  py::object callback_;
  std::optional<py::error_already_set> error_;
};

}  // namespace acdpy
