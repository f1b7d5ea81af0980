// SPDX-License-Identifier: MIT
#include "base/format.hpp"

#include <sstream>

namespace sparsedyn {

std::string FormatExact(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

}  // namespace sparsedyn
