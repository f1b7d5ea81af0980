#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Fuzzes one target (tests/fuzz/, docs/reliability.md) under ASan + UBSan with libFuzzer:
#   scripts/fuzz.sh TARGET SECONDS     TARGET: off obj stl ply ohio scene recording polyhedron
# Builds the clang asan preset's fuzz_TARGET, starts from the seed corpus tests/fuzz/corpus/TARGET
# (new inputs go to build/fuzz-corpus/TARGET, so the checked-in corpus stays small) and stops
# after SECONDS. A finding is written to build/fuzz-findings/TARGET/ and the script fails: fix
# it and keep the input in tests/fuzz/regressions/TARGET/, which fuzz_tests replays.
set -euo pipefail
if (($# != 2)); then
  echo "usage: scripts/fuzz.sh TARGET SECONDS" >&2
  exit 2
fi
target=$1
seconds=$2
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
if [[ ! -d tests/fuzz/corpus/$target ]]; then
  echo "scripts/fuzz.sh: unknown target '$target' (see tests/fuzz/corpus/)" >&2
  exit 2
fi
if [[ -z "${SPARSEDYN_FUZZ_NO_BUILD:-}" ]]; then
  "$root/scripts/deps.sh"
  cmake --preset asan >/dev/null
  cmake --build --preset asan --target "fuzz_$target" -j"$(nproc)" >/dev/null
fi
work=build/fuzz-corpus/$target
findings=build/fuzz-findings/$target
mkdir -p "$work" "$findings"
log=$findings/last-run.log
stamp=$findings/.started
touch "$stamp"
# detect_leaks: a leak is a finding too. -timeout: an input that takes 10 s is a hang.
status=0
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  "build/asan/tests/fuzz/fuzz_$target" "$work" "tests/fuzz/corpus/$target" \
  -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
  -artifact_prefix="$findings/" -print_final_stats=1 > "$log" 2>&1 || status=$?
tail -n 12 "$log"
if ((status != 0)); then
  # A finding must be reproducible from a CI log alone: the report's start (where it hung or
  # crashed) and the input itself, base64, to decode into tests/fuzz/regressions/TARGET/.
  echo "=== the report's start:"
  grep -n -m1 -E '^==[0-9]+==|ALARM|deadly signal|ERROR: libFuzzer' "$log" | cut -d: -f1 |
    xargs -r -I{} sed -n '{},+40p' "$log"
  for input in $(find "$findings" -type f -newer "$stamp" -regex '.*/\(crash\|timeout\|leak\|oom\)-.*'); do
    echo "=== the input $input ($(wc -c < "$input") bytes), base64:"
    head -c 65536 "$input" | base64
  done
  exit "$status"
fi
