// SPDX-License-Identifier: MIT
#pragma once

#include <string_view>

namespace sparsedyn {

/// Called when a SPARSEDYN_ASSERT fails. The default prints the location and message to stderr
/// and aborts. Replace it (e.g. to throw in a test harness) with SetAssertHandler.
using AssertHandler = void (*)(std::string_view expression, std::string_view message,
                               std::string_view file, int line);

/// Installs `handler` (nullptr restores the default) and returns the previous handler.
AssertHandler SetAssertHandler(AssertHandler handler);

/// Invokes the current handler; used by SPARSEDYN_ASSERT.
[[noreturn]] void AssertFailed(std::string_view expression, std::string_view message,
                               std::string_view file, int line);

}  // namespace sparsedyn

/// Checks a precondition or internal invariant (a bug if false, never bad user input).
/// On when the library is built with SPARSEDYN_ASSERTS=ON (the default, and in all tests).
#if defined(SPARSEDYN_ENABLE_ASSERTS)
#define SPARSEDYN_ASSERT(cond, message)                                          \
  do {                                                                           \
    if (!(cond)) ::sparsedyn::AssertFailed(#cond, (message), __FILE__, __LINE__); \
  } while (false)
#else
// Off: the condition and message are still compiled (never evaluated), so that variables used
// only in asserts do not become "unused" in release builds.
#define SPARSEDYN_ASSERT(cond, message) \
  do {                                  \
    if (false) {                        \
      (void)(cond);                     \
      (void)(message);                  \
    }                                   \
  } while (false)
#endif
