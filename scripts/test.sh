#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds everything (optimized, asserts on) and runs the whole test suite with CTest.
# Installs missing Debian packages first. Extra arguments go to ctest (e.g. -R Meeting).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/deps.sh"
cd "$root"
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
ctest --preset release -j"$(nproc)" "$@"
