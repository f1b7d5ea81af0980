#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The main job: installs what is missing, builds the optimized `sparsedyn` tool and runs it.
# With no arguments it runs the embedded default scene, prints a summary, writes the recording
# sparsedyn-default.sdrec in the current folder and prints the command that views it; any
# arguments are passed to `sparsedyn` (e.g. scripts/run.sh run --preset gas --n 10000 --json,
# scripts/run.sh view sparsedyn-default.sdrec). Says on stderr what it does before the tool
# runs (installing, building: minutes the first time); stdout is the tool's alone.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
say() { echo "scripts/run.sh: $*" >&2; }
"$root/scripts/deps.sh"
tool="$root/build/bench/apps/cli/sparsedyn"
if [[ -x "$tool" ]]; then
  say "checking that build/bench/apps/cli/sparsedyn is up to date"
else
  say "building build/bench/apps/cli/sparsedyn (optimized; several minutes the first time)"
fi
# The benchmarks stay configured (the bench preset's own build folder): only the tool is built.
cmake -S "$root" --preset bench -DSPARSEDYN_BUILD_TESTS=OFF -DSPARSEDYN_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$root/build/bench" --target sparsedyn_cli -j"$(nproc)" >/dev/null
if (($# == 0)); then
  set -- run
  say "running the default scene (1000 rotating polyhedra, 10 simulated s)"
fi
# The tool's hints ("view it with: ...") then name this script, which is how the user runs it.
export SPARSEDYN_PROGRAM="$0"
exec "$tool" "$@"
