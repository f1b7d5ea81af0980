// SPDX-License-Identifier: MIT
#include "errors.hpp"

namespace py = pybind11;

namespace sparsedyn::python {
namespace {

// The classes live as long as the interpreter: handles kept here are never released, so
// nothing is decremented after the interpreter has shut down.
py::handle input_error;
py::handle simulation_error;

// class `name`(*bases) in `m`, made by type() as a class statement would.
py::handle MakeClass(py::module_& m, const char* name, const py::tuple& bases, const char* doc) {
  py::dict body;
  body["__module__"] = "sparsedyn";
  body["__doc__"] = doc;
  py::object type = py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(&PyType_Type));
  py::object cls = type(name, bases, body);
  m.attr(name) = cls;
  return cls.release();
}

}  // namespace

void BindErrors(py::module_& m) {
  // Error is the base of both; InputError is also a ValueError and SimulationError a
  // RuntimeError, so that code catching the built-in kinds catches ours.
  const py::handle error = MakeClass(m, "Error", py::make_tuple(py::handle(PyExc_Exception)),
                                     "Base of the exceptions that carry the library's messages.");
  input_error = MakeClass(m, "InputError", py::make_tuple(error, py::handle(PyExc_ValueError)),
                          "Input the library refused; the message names the body, file, line, "
                          "JSON path or option and what is wrong.");
  simulation_error =
      MakeClass(m, "SimulationError", py::make_tuple(error, py::handle(PyExc_RuntimeError)),
                "A run that failed, e.g. an event loop that stalled; the World's clock stays "
                "at the last processed event.");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(input_error.ptr(), e.what());
    } catch (const SimulationError& e) {
      PyErr_SetString(simulation_error.ptr(), e.what());
    }
  });
}

}  // namespace sparsedyn::python
