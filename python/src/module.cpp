// SPDX-License-Identifier: MIT
// The compiled part of the Python package `sparsedyn` (python/sparsedyn/__init__.py re-exports
// it). Each part of the C++ API is bound in its own file; see bindings.hpp.
#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(_sparsedyn, m) {
  m.doc() = "sparsedyn: event-driven collision detection and rigid-body simulation";
  sparsedyn::python::BindErrors(m);
  sparsedyn::python::BindTypes(m);
  sparsedyn::python::BindWorld(m);
  sparsedyn::python::BindScene(m);
  sparsedyn::python::BindDistance(m);
}
