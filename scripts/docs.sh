#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The API reference: Doxygen (Debian's doxygen; scripts/deps.sh installs it) over the public
# headers' /// comments, with docs/Doxyfile. Any warning (an undocumented public declaration,
# a broken reference) fails. Writes build/docs/html/index.html.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
if ! command -v doxygen >/dev/null; then "$root/scripts/deps.sh"; fi
echo "scripts/docs.sh: running doxygen docs/Doxyfile" >&2
mkdir -p build/docs
doxygen docs/Doxyfile
echo "scripts/docs.sh: wrote build/docs/html/index.html" >&2
