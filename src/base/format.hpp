// SPDX-License-Identifier: MIT
#pragma once

#include <string>

namespace sparsedyn {

/// `x` with 17 significant digits (it reads back to the same double): what error messages and
/// failure reports print, so that a reported configuration can be pasted into a test.
std::string FormatExact(double x);

}  // namespace sparsedyn
