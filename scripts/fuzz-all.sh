#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs every fuzz target (tests/fuzz/corpus/*) for SECONDS each, two at a time (scripts/fuzz.sh),
# and fails if any target found something. SPARSEDYN_FUZZ_SKIP="a b" leaves targets out (CI,
# while a finding of theirs is being fixed).
#   scripts/fuzz-all.sh SECONDS
set -euo pipefail
seconds=${1:?usage: scripts/fuzz-all.sh SECONDS}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
if [[ -z "${SPARSEDYN_FUZZ_NO_BUILD:-}" ]]; then
  "$root/scripts/deps.sh"
  cmake --preset asan >/dev/null
  targets=()
  for dir in tests/fuzz/corpus/*/; do targets+=("fuzz_$(basename "$dir")"); done
  cmake --build --preset asan --target "${targets[@]}" -j"$(nproc)" >/dev/null
fi
mkdir -p build/fuzz-logs
# Each target's output goes to its own log; the failures are listed, their logs printed.
targets_run=$(ls tests/fuzz/corpus | grep -vxF -f <(tr ' ' '\n' <<< "${SPARSEDYN_FUZZ_SKIP:-}" | grep .) || true)
echo "$targets_run" | SPARSEDYN_FUZZ_NO_BUILD=1 xargs -P 2 -I{} sh -c \
  'scripts/fuzz.sh {} '"$seconds"' > build/fuzz-logs/{}.log 2>&1 || echo {} >> build/fuzz-logs/failed'
for target in $targets_run; do
  echo "fuzz $target: $(grep -Eo 'stat::number_of_executed_units: *[0-9]+' "build/fuzz-logs/$target.log" | grep -Eo '[0-9]+$' || echo '?') runs"
done
if [[ -s build/fuzz-logs/failed ]]; then
  for target in $(cat build/fuzz-logs/failed); do
    echo "=== fuzz $target failed:"
    cat "build/fuzz-logs/$target.log"
  done
  rm -f build/fuzz-logs/failed
  exit 1
fi
