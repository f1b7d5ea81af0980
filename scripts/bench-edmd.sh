#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The gas against Smallenburg's EDMD on this machine (docs/benchmarks.md "EDMD on this machine"):
# EDMD's cell-list variant (Cell/mdCell.c, the faster of its codes at packing 0.05) and
# gas_bench's BM_Gas, alternated, each pinned to one core, on the same initial positions
# (gas_sph), both after 2 collisions per particle to settle (gas_bench's stretches are 20, 10
# or 4 collisions per particle; EDMD's 100, 20 and 4, as its CPU time is the difference of two
# runs, which needs a second or more). Prints each run and the medians in collisions per CPU s.
#   scripts/bench-edmd.sh EDMD_DIR [--rounds R] [--sizes "10000 100000 1000000"] [--core C]
# EDMD is not part of this project: EDMD_DIR is a checkout of
# https://github.com/FSmallenburg/EDMD (MIT licence; the measurements in docs/ used commit
# 65a9972). Only its documented parameters are set, with sed, in a copy: the globals at the top
# of mdCell.c (maxtime, writeinterval, eventlisttimemultiplier) and MAXCEL, then it is built
# with its Makefile's flags (-Ofast -funroll-loops -march=native). Its CPU time over the stretch
# is the difference between a run to the end and a run to the settling time (EDMD prints its
# collision count at every write interval, set to the settling time).
# Environment: JOBS (build parallelism, default 2).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage="usage: $0 EDMD_DIR [--rounds R] [--sizes \"N ...\"] [--core C]"
(($# >= 1)) || { echo "$usage" >&2; exit 2; }
edmd=$(cd "$1" 2>/dev/null && pwd) || { echo "$0: no directory $1" >&2; exit 2; }
shift
rounds=5
sizes="10000 100000 1000000"
core=1
while (($# > 0)); do
  case "$1" in
    --rounds) rounds=$2; shift ;;
    --sizes) sizes=$2; shift ;;
    --core) core=$2; shift ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
  shift
done
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "$0: --rounds must be a positive number, not '$rounds'" >&2; exit 2; }
[[ $core =~ ^[0-9]+$ ]] || { echo "$0: --core must be a core number, not '$core'" >&2; exit 2; }
source="$edmd/Cell/mdCell.c"
[[ -f $source ]] || { echo "$0: $source not found (not an EDMD checkout?)" >&2; exit 2; }
for n in $sizes; do
  if ! [[ $n =~ ^[0-9]+$ ]] || ((n < 1000 || n >= 10000000)); then
    echo "$0: sizes must be whole numbers from 1000 to 9999999, not '$n'" >&2
    exit 2
  fi
done
command -v gcc >/dev/null || { echo "$0: gcc is needed to build EDMD" >&2; exit 1; }

"$root/scripts/deps.sh"
cmake -S "$root" --preset bench >/dev/null
build="$root/build/bench"
cmake --build "$build" --target gas_bench gas_sph -j"${JOBS:-2}" >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

packing=0.05
# gas_bench's stretches: the Enskog collision frequency per particle (kT = m = sigma = 1).
rate=$(awk -v p=$packing 'BEGIN { pi = atan2(0, -1); n = 6 * p / pi;
  g = (1 - p / 2) / (1 - p) ^ 3; printf "%.17g", 4 * n * g * sqrt(pi) }')

# EDMD built for one N: settling ends at t_eq, the stretch at t_end = (1 + k / 2) t_eq, both
# at a write (the write interval is t_eq); maxtime a little beyond so that the write happens.
build_edmd() {  # n maxtime t_eq output
  local n=$1 maxtime=$2 t_eq=$3 out=$4
  # Its cell rule: about 1 sigma, fewer while more than 8 cells per sphere, capped at MAXCEL
  # per axis (75). The cap made cells 2.9 sigma at 10^6 (40k collisions/s against 153k
  # without): raised whenever the capped cells would exceed 1.5 sigma.
  local side cells maxcel list
  side=$(awk -v n="$n" -v p=$packing 'BEGIN { printf "%.17g", (n * atan2(0, -1) / 6 / p) ^ (1 / 3) }')
  cells=$(awk -v s="$side" -v n="$n" 'BEGIN { c = int(s - 0.0001);
    while (c * c * c > 8 * n) c = int(c * 0.9); print c }')
  maxcel=$(awk -v s="$side" -v c="$cells" 'BEGIN { print (s / 75 > 1.5 && c > 75) ? c : 75 }')
  # The event list time (its multiplier: 5 the best of 1-20 below 10^6, 1 at 10^6).
  list=$((n >= 1000000 ? 1 : 5))
  sed -e "s/^double maxtime = [^;]*;/double maxtime = $maxtime;/" \
    -e "s/^double writeinterval = [^;]*;/double writeinterval = $t_eq;/" \
    -e "s/^double eventlisttimemultiplier = [^;]*;/double eventlisttimemultiplier = $list;/" \
    -e "s/^#define MAXCEL .*/#define MAXCEL $maxcel/" "$source" >"$work/mdCell.c"
  local parameter
  for parameter in "double maxtime = $maxtime;" "double writeinterval = $t_eq;" \
    "double eventlisttimemultiplier = $list;" "#define MAXCEL $maxcel"; do
    grep -qF "$parameter" "$work/mdCell.c" ||
      { echo "$0: could not set '$parameter' in $source (changed upstream?)" >&2; exit 1; }
  done
  gcc -Wall -Ofast -funroll-loops -march=native -I"$edmd/Cell" -I"$edmd/Grow" \
    "$work/mdCell.c" -o "$out" -lm
}

# One EDMD run: prints "CPU_SECONDS COLLISIONS" (the collision count at its last write).
run_edmd() {  # binary directory
  local cpu
  cpu=$( { TIMEFORMAT='%3U %3S'; time taskset -c "$core" "$1" >"$2/out.txt"; } 2>&1)
  local collisions
  collisions=$(sed -n 's/.*Collisions: \([0-9]*\),.*/\1/p' "$2/out.txt" | tail -n 1)
  [[ -n $collisions ]] || { echo "$0: EDMD printed no collision count:" >&2; cat "$2/out.txt" >&2; exit 1; }
  awk -v t="$cpu" -v c="$collisions" 'BEGIN { split(t, a, " "); print a[1] + a[2], c }'
}

run_ours() {  # n -> collisions per CPU second
  taskset -c "$core" "$build/bench/gas_bench" --benchmark_counters_tabular=true \
    --benchmark_filter="^BM_Gas/n:$1/packing%:5/allpairs0_grid1:1/" 2>/dev/null |
    awk '$1 == "Benchmark" { for (i = 1; i <= NF; ++i) if ($i == "collisions/cpu_s") c = i + 2 }
         /^BM_Gas/ && c { v = $c; m = 1; if (v ~ /k$/) m = 1e3; if (v ~ /M$/) m = 1e6;
                          sub(/[kM]$/, "", v); printf "%.0f\n", v * m }'
}

median() { sort -n | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

printf '%-8s %-6s %14s %14s\n' N round "EDMD coll/cpu_s" "ours coll/cpu_s"
for n in $sizes; do
  k=$((n >= 1000000 ? 4 : (n >= 100000 ? 20 : 100)))
  t_eq=$(awk -v r="$rate" 'BEGIN { printf "%.17g", 2 / r }')
  t_end=$(awk -v t="$t_eq" -v k=$k 'BEGIN { printf "%.17g", t * (1 + k / 2) }')
  dir="$work/$n"
  mkdir -p "$dir"
  "$build/bench/gas_sph" "$n" $packing >"$dir/init.sph"
  build_edmd "$n" "$(awk -v t="$t_eq" 'BEGIN { printf "%.17g", t * 1.001 }')" "$t_eq" "$dir/md_settle"
  build_edmd "$n" "$(awk -v t="$t_end" 'BEGIN { printf "%.17g", t * 1.001 }')" "$t_eq" "$dir/md_stretch"
  : >"$dir/edmd.txt"
  : >"$dir/ours.txt"
  for ((r = 1; r <= rounds; ++r)); do
    # Assignments, not process substitutions: a failed run then stops the script (set -e).
    settle=$(cd "$dir" && run_edmd ./md_settle "$dir")
    stretch=$(cd "$dir" && run_edmd ./md_stretch "$dir")
    read -r cpu0 coll0 <<<"$settle"
    read -r cpu1 coll1 <<<"$stretch"
    theirs=$(awk -v a="$cpu0" -v b="$cpu1" -v c="$coll0" -v d="$coll1" \
      'BEGIN { if (b <= a) print "nan"; else printf "%.0f\n", (d - c) / (b - a) }')
    ours=$(run_ours "$n")
    [[ -n $ours ]] || { echo "$0: gas_bench printed no collisions/cpu_s for N = $n" >&2; exit 1; }
    echo "$theirs" >>"$dir/edmd.txt"
    echo "$ours" >>"$dir/ours.txt"
    printf '%-8s %-6s %14s %14s\n' "$n" "$r" "$theirs" "$ours"
  done
  a=$(median <"$dir/edmd.txt")
  b=$(median <"$dir/ours.txt")
  printf '%-8s %-6s %14s %14s  ours/EDMD %.2f\n' "$n" median "$a" "$b" \
    "$(awk -v a="$a" -v b="$b" 'BEGIN { print (a > 0) ? b / a : 0 }')"
done
