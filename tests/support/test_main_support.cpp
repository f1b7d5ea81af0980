// SPDX-License-Identifier: MIT
// Makes SPARSEDYN_ASSERT failures inside tests fail loudly with their message, and turns on the
// floating-point traps (support/fp_traps.hpp); linked into every test executable through
// sparsedyn_test_support.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "sparsedyn/assert.hpp"
#include "support/fp_traps.hpp"

namespace {

[[noreturn]] void TestAssertHandler(std::string_view expression, std::string_view message,
                                    std::string_view file, int line) {
  std::fprintf(stderr, "%.*s:%d: SPARSEDYN_ASSERT(%.*s) failed in a test: %.*s\n",
               static_cast<int>(file.size()), file.data(), line,
               static_cast<int>(expression.size()), expression.data(),
               static_cast<int>(message.size()), message.data());
  std::abort();
}

// Installed before main() runs so that even static initialisers are covered. The traps can be
// left off (SPARSEDYN_FP_TRAPS=0) to see how far a trapping test gets.
const bool kInstalled = [] {
  sparsedyn::SetAssertHandler(&TestAssertHandler);
  const char* traps = std::getenv("SPARSEDYN_FP_TRAPS");
  if (traps == nullptr || traps[0] != '0') sparsedyn::testing::EnableFloatingPointTraps();
  return true;
}();

}  // namespace
