// SPDX-License-Identifier: MIT
// The library's errors as Python exceptions (sparsedyn.InputError, sparsedyn.SimulationError),
// each carrying the library's message unchanged.
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <utility>

#include "sparsedyn/result.hpp"

namespace sparsedyn::python {

/// Bad input refused by the library (a body, a scene file, a preset's option): InputError.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A run that failed (the event loop stalled or crawled): SimulationError.
struct SimulationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The value of `result`, or InputError with its message.
template <typename T>
T ValueOrRaise(Result<T> result) {
  if (!result) throw InputError(result.error().message);
  return std::move(*result);
}

/// Nothing when `status` is ok, else an exception of type E with its message.
template <typename E = InputError>
void Check(const Status& status) {
  if (!status) throw E(status.error().message);
}

/// Creates the exception classes in `m` and translates the C++ ones into them.
void BindErrors(pybind11::module_& m);

}  // namespace sparsedyn::python
