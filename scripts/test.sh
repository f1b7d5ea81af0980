#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds everything (optimized, asserts on, with the Python module) and runs the whole test
# suite: CTest, then the Python package's pytest tests (python/tests) against a virtual
# environment it installs the package into (build/python-venv). Installs missing Debian
# packages first. Extra arguments go to ctest (e.g. -R Meeting), and then pytest is skipped.
# Says on stderr what it is doing: the first build takes minutes.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
say() { echo "scripts/test.sh: $*" >&2; }
"$root/scripts/deps.sh"
cd "$root"
# Debian's interpreter: its pybind11 and numpy build the module (a pyenv or conda `python3`
# first on PATH has neither).
python=/usr/bin/python3
say "configuring build/release"
cmake --preset release -DSPARSEDYN_BUILD_PYTHON=ON -DPython_EXECUTABLE="$python" >/dev/null
say "building everything in build/release (several minutes the first time, seconds after)"
cmake --build --preset release -j"$(nproc)"
say "running the C++, CLI and viewer tests (ctest)"
ctest --preset release -j"$(nproc)" "$@"
if (($# > 0)); then
  exit 0
fi

venv="$root/build/python-venv"
if [[ ! -x "$venv/bin/python" ]]; then
  say "making the virtual environment $venv (python3 -m venv --system-site-packages)"
  "$python" -m venv --system-site-packages "$venv"
fi
say "installing the Python package into it (pip install --no-build-isolation .)"
SPARSEDYN_CMAKE_BUILD_DIR="$root/build/release" \
  "$venv/bin/pip" install --quiet --no-build-isolation --no-index --no-deps --force-reinstall . >&2
say "running the Python tests (pytest python/tests)"
SPARSEDYN_CLI="$root/build/release/apps/cli/sparsedyn" \
  "$venv/bin/python" -m pytest -q -p no:cacheprovider python/tests
