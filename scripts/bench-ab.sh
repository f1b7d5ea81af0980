#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Two gas_bench binaries against each other (docs/lab/measurements.md "Measuring a change"): BM_Gas at
# packing 0.05, both on one core at once, taking turns (SPARSEDYN_GAS_TURNS, see
# bench/support/turns.hpp): each builds and settles its gas, then they time their stretches
# in alternating slices of about a tenth of a second, so that the machine's swings, which
# last seconds here, fall on both alike. Who goes first alternates between rounds. Prints each
# round's collisions per CPU s and B / A, then the median and range of the paired ratios.
#   scripts/bench-ab.sh A_BINARY B_BINARY [--n N] [--rounds R] [--stretch S] [--slices K] [--core C]
# Defaults: N = 10000, 9 rounds, a stretch of 2 x 10^6 collisions (200 per particle at 10^4,
# about 3 s a binary here), 20 slices, core 1. Both binaries need the turns (gas_bench since
# it has bench/support/turns.hpp). A and B are built from two checkouts, e.g.
#   git worktree add /tmp/base main && cmake -S /tmp/base --preset bench && \
#   cmake --build /tmp/base/build/bench --target gas_bench
set -euo pipefail
usage="usage: $0 A_BINARY B_BINARY [--n N] [--rounds R] [--stretch S] [--slices K] [--core C]"
(($# >= 2)) || { echo "$usage" >&2; exit 2; }
a=$1 b=$2
shift 2
n=10000 rounds=9 stretch="" slices=20 core=1
while (($# > 0)); do
  (($# >= 2)) || { echo "$usage" >&2; exit 2; }
  case "$1" in
    --n) n=$2 ;;
    --rounds) rounds=$2 ;;
    --stretch) stretch=$2 ;;
    --slices) slices=$2 ;;
    --core) core=$2 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
  shift 2
done
for binary in "$a" "$b"; do
  [[ -x $binary ]] || { echo "$0: $binary is not an executable" >&2; exit 2; }
done
[[ $n =~ ^[1-9][0-9]*$ ]] || { echo "$0: --n must be a positive number, not '$n'" >&2; exit 2; }
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "$0: --rounds must be a positive number, not '$rounds'" >&2; exit 2; }
[[ $slices =~ ^[1-9][0-9]*$ ]] || { echo "$0: --slices must be a positive number, not '$slices'" >&2; exit 2; }
[[ $core =~ ^[0-9]+$ ]] || { echo "$0: --core must be a core number, not '$core'" >&2; exit 2; }
if [[ -z $stretch ]]; then
  stretch=$(awk -v n="$n" 'BEGIN { s = 2e6 / n; print (s < 2 ? 2 : s) }')
fi
[[ $stretch =~ ^[0-9]*\.?[0-9]+$ ]] || { echo "$0: --stretch must be a positive number, not '$stretch'" >&2; exit 2; }

filter="^BM_Gas/n:$n/packing%:5/allpairs0_grid1:1/"
work=$(mktemp -d)
pids=()
trap 'kill "${pids[@]}" 2>/dev/null; rm -rf "$work"' EXIT
# Collisions per CPU s from a run's JSON, or a failure naming the binary.
rate_of() {
  awk -F': ' '/"collisions\/cpu_s"/ { gsub(/[ ,]/, "", $2); print $2; found = 1 }
              END { if (!found) exit 1 }' "$2" ||
    { echo "$0: $1 reported no BM_Gas run for n = $n:" >&2; grep -i error "$2" >&2; return 1; }
}
# One round: `first` takes the first turn. Each binary waits on its own pipe and passes the
# token on through the other's.
round() {
  local first=$1 second=$2
  rm -f "$work"/*
  mkfifo "$work/first" "$work/second"
  SPARSEDYN_GAS_STRETCH=$stretch SPARSEDYN_GAS_TURNS="$work/first,$work/second,$work/ready1,$slices" \
    taskset -c "$core" "$first" --benchmark_filter="$filter" --benchmark_format=json \
    >"$work/out1" 2>/dev/null &
  pids=($!)
  SPARSEDYN_GAS_STRETCH=$stretch SPARSEDYN_GAS_TURNS="$work/second,$work/first,$work/ready2,$slices" \
    taskset -c "$core" "$second" --benchmark_filter="$filter" --benchmark_format=json \
    >"$work/out2" 2>/dev/null &
  pids+=($!)
  # Both set up (or one failed, which ends it): the first turn starts.
  while [[ ! -e $work/ready1 || ! -e $work/ready2 ]]; do
    for pid in "${pids[@]}"; do
      kill -0 "$pid" 2>/dev/null || [[ -e $work/ready1 && -e $work/ready2 ]] ||
        { wait "$pid" || true; echo "$0: a binary ended before its turns" >&2; return 1; }
    done
    sleep 0.2
  done
  printf t >"$work/first"
  wait "${pids[@]}"
  pids=()
  r1=$(rate_of "$first" "$work/out1") && r2=$(rate_of "$second" "$work/out2")
}

echo "N = $n, $stretch collisions per particle in $slices turns each, core $core"
echo "A = $a"
echo "B = $b"
printf '%-6s %12s %12s %8s\n' round A B B/A
ratios=()
for ((r = 1; r <= rounds; ++r)); do
  if ((r % 2)); then
    round "$a" "$b"; ra=$r1 rb=$r2
  else
    round "$b" "$a"; rb=$r1 ra=$r2
  fi
  ratio=$(awk -v x="$ra" -v y="$rb" 'BEGIN { printf "%.4f", y / x }')
  ratios+=("$ratio")
  printf '%-6s %12.0f %12.0f %8s\n' "$r" "$ra" "$rb" "$ratio"
done
printf '%s\n' "${ratios[@]}" | sort -g | awk '{ v[NR] = $1 } END {
  m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
  printf "B/A: median %.4f, range %.4f-%.4f over %d rounds\n", m, v[1], v[NR], NR }'
