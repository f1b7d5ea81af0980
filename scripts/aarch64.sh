#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Cross-builds the library and the fast test subset for 64-bit ARM (Debian's g++-aarch64-linux-gnu,
# -O2 with asserts, as the release preset) and runs it under qemu-user (docs/reliability.md):
#   scripts/aarch64.sh            the subset CI runs: every fast test of the suites built below
#   scripts/aarch64.sh -R Regex   extra arguments go to ctest
# The subset: the golden state hashes and reference runs (world_tests), math, sparse, events,
# geometry and io. narrow_tests needs CGAL and FCL for arm64 and is not cross-built; the suites
# not built show up in CTest as *_NOT_BUILT and are left out.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
"$root/scripts/deps.sh" --aarch64
build=build/aarch64
cmake -S . -B "$build" -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPARSEDYN_ASSERTS=ON -DSPARSEDYN_BUILD_TOOLS=OFF \
  -DSPARSEDYN_BUILD_BENCHMARKS=OFF -DSPARSEDYN_BUILD_PEERS=OFF -DSPARSEDYN_BUILD_EXAMPLES=OFF \
  >/dev/null
targets=(world_tests math_tests sparse_tests events_tests geometry_tests io_tests)
cmake --build "$build" --target "${targets[@]}" -j"$(nproc)"
# Under qemu the slow label is left out, as in the sanitizer run.
ctest --test-dir "$build" -LE slow -E '_NOT_BUILT$' -j"$(nproc)" --output-on-failure "$@"
