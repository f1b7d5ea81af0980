// SPDX-License-Identifier: MIT
#include "support/fp_traps.hpp"

#include <fenv.h>  // feenableexcept, fedisableexcept, fegetexcept: glibc extensions

namespace sparsedyn::testing {
namespace {
constexpr int kTrapped = FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW;
}  // namespace

bool EnableFloatingPointTraps() {
  feclearexcept(FE_ALL_EXCEPT);
  return feenableexcept(kTrapped) != -1;
}

FloatingPointTrapsPaused::FloatingPointTrapsPaused() : enabled_(fegetexcept()) {
  fedisableexcept(kTrapped);
}

FloatingPointTrapsPaused::~FloatingPointTrapsPaused() {
  feclearexcept(FE_ALL_EXCEPT);
  if (enabled_ > 0) feenableexcept(enabled_);
}

}  // namespace sparsedyn::testing
