// SPDX-License-Identifier: MIT
// One libFuzzer executable per target: SPARSEDYN_FUZZ_TARGET names it (tests/fuzz/CMakeLists.txt).
// A broken invariant aborts, which libFuzzer reports and saves as a crash input.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem = sparsedyn::fuzz::RunInput(
      SPARSEDYN_FUZZ_TARGET, std::string_view(reinterpret_cast<const char*>(data), size));
  if (!problem.empty()) {
    std::fprintf(stderr, "fuzz target %s: %s\n", SPARSEDYN_FUZZ_TARGET, problem.c_str());
    std::abort();
  }
  return 0;
}
