// SPDX-License-Identifier: MIT
#include "sparsedyn/assert.hpp"

#include <cstdio>
#include <cstdlib>

namespace sparsedyn {
namespace {

void DefaultAssertHandler(std::string_view expression, std::string_view message,
                          std::string_view file, int line) {
  std::fprintf(stderr, "%.*s:%d: SPARSEDYN_ASSERT(%.*s) failed: %.*s\n",
               static_cast<int>(file.size()), file.data(), line,
               static_cast<int>(expression.size()), expression.data(),
               static_cast<int>(message.size()), message.data());
  std::abort();
}

AssertHandler g_handler = &DefaultAssertHandler;

}  // namespace

AssertHandler SetAssertHandler(AssertHandler handler) {
  AssertHandler previous = g_handler;
  g_handler = handler != nullptr ? handler : &DefaultAssertHandler;
  return previous;
}

void AssertFailed(std::string_view expression, std::string_view message, std::string_view file,
                  int line) {
  g_handler(expression, message, file, line);
  std::abort();  // A handler that returns must not resume the failed code.
}

}  // namespace sparsedyn
