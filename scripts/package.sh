#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The .deb and .tar.gz (CPack, cmake/SparsedynPackage.cmake): the library, headers, CMake
# package files, the `sparsedyn` tool with the viewer, the viewer's files.
#   scripts/package.sh             configures and builds build/package (Release, asserts off,
#                                  no tests or benchmarks; minutes the first time), then packs
#   scripts/package.sh BUILD_DIR   packs a tree that is already built (CI: build/release)
# The files land in BUILD_DIR/package/. Install with: sudo apt install ./sparsedyn_*.deb
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
say() { echo "scripts/package.sh: $*" >&2; }
if (($# == 0)); then
  "$root/scripts/deps.sh"
  tree="$root/build/package"
  say "configuring and building $tree (several minutes the first time)"
  cmake -S "$root" -B "$tree" -DCMAKE_BUILD_TYPE=Release -DSPARSEDYN_ASSERTS=OFF \
        -DSPARSEDYN_BUILD_TESTS=OFF -DSPARSEDYN_BUILD_BENCHMARKS=OFF \
        -DSPARSEDYN_BUILD_EXAMPLES=OFF -DSPARSEDYN_BUILD_PEERS=OFF >/dev/null
  cmake --build "$tree" -j"$(nproc)" >/dev/null
else
  tree=$(cd "$1" && pwd)
fi
say "packing $tree (cpack -G DEB;TGZ)"
(cd "$tree" && cpack -G "DEB;TGZ" -B "$tree/package" >/dev/null)
for file in "$tree"/package/sparsedyn*.deb "$tree"/package/sparsedyn*.tar.gz; do
  say "wrote $file ($(du -h "$file" | cut -f1))"
done
