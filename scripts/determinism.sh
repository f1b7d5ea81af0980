#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The golden state hashes (tests/world/state_hash_test.cpp, reference_run_test.cpp) from the
# builds CI does not make: gcc -O0 (the debug preset) and clang -O2 without sanitizers (the
# clang preset). CI checks gcc -O2 (scripts/test.sh), clang -O2 under ASan + UBSan (the asan
# preset) and aarch64 (scripts/aarch64.sh). docs/reliability.md has the results.
#   scripts/determinism.sh [debug|clang ...]   (default: both)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
"$root/scripts/deps.sh"
presets=("$@")
if ((${#presets[@]} == 0)); then
  presets=(debug clang)
fi
for preset in "${presets[@]}"; do
  echo "=== $preset"
  cmake --preset "$preset" -DSPARSEDYN_BUILD_BENCHMARKS=OFF >/dev/null
  cmake --build --preset "$preset" --target world_tests -j"$(nproc)" >/dev/null
  "build/$preset/tests/world_tests" --gtest_filter='StateHash.*:*ReferenceRuns*:ReferenceSmallPeriodicBox.*:ReferenceSettling.*' | grep -E 'hash 0x|PASSED|FAILED'
done
