// SPDX-License-Identifier: MIT
// Makes SPARSEDYN_ASSERT failures inside tests fail loudly with their message; linked into
// every test executable through sparsedyn_test_support.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "sparsedyn/assert.hpp"

namespace {

[[noreturn]] void TestAssertHandler(std::string_view expression, std::string_view message,
                                    std::string_view file, int line) {
  std::fprintf(stderr, "%.*s:%d: SPARSEDYN_ASSERT(%.*s) failed in a test: %.*s\n",
               static_cast<int>(file.size()), file.data(), line,
               static_cast<int>(expression.size()), expression.data(),
               static_cast<int>(message.size()), message.data());
  std::abort();
}

// Installed before main() runs so that even static initialisers are covered.
const bool kInstalled = [] {
  sparsedyn::SetAssertHandler(&TestAssertHandler);
  return true;
}();

}  // namespace
