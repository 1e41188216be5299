// acd.Error: every failed library Status, raised as a ValueError subclass carrying the library's
// one-line message and its StatusCode in `code`.
#include "binding.hpp"

namespace acdpy {

void bindErrors(py::module_& m) {
  using C = acd::StatusCode;
  py::enum_<C>(m, "StatusCode", "Why the library refused an input (acd.Error.code)")
      .value("Ok", C::Ok)
      .value("FileUnreadable", C::FileUnreadable)
      .value("UnsupportedFormat", C::UnsupportedFormat)
      .value("EmptyMesh", C::EmptyMesh)
      .value("NonFiniteVertex", C::NonFiniteVertex)
      .value("IndexOutOfRange", C::IndexOutOfRange)
      .value("DegenerateFace", C::DegenerateFace)
      .value("DuplicateFace", C::DuplicateFace)
      .value("NonManifoldEdge", C::NonManifoldEdge)
      .value("NonManifoldVertex", C::NonManifoldVertex)
      .value("InconsistentOrientation", C::InconsistentOrientation)
      .value("OpenMesh", C::OpenMesh)
      .value("InvalidParameter", C::InvalidParameter)
      .value("InternalError", C::InternalError);
  // Kept for the life of the process (a static py::object would be released after the interpreter).
  static py::handle error = py::exception<StatusError>(m, "Error", PyExc_ValueError).release();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const StatusError& e) {
      py::object instance = py::reinterpret_borrow<py::object>(error)(e.status.message);
      instance.attr("code") = py::cast(e.status.code);
      PyErr_SetObject(error.ptr(), instance.ptr());
    }
  });
}

}  // namespace acdpy
