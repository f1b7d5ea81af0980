// SPDX-License-Identifier: MIT
#include <cstdio>

#include "sparsedyn/result.hpp"

int main() {
  sparsedyn::Result<int> r = 1;
  std::printf("consumer: linked sparsedyn, ok=%d\n", r.ok() ? 1 : 0);
  return r.ok() ? 0 : 1;
}
