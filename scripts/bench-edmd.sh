#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The gas against Smallenburg's EDMD on this machine (docs/lab/measurements.md "EDMD on this machine"):
# EDMD's cell-list variant (Cell/mdCell.c, the faster of its codes at packing 0.05) and
# gas_bench's BM_Gas on the same initial positions (gas_sph), both settled for 2 collisions per
# particle, then timed taking turns on one core: gas_bench runs its stretch in slices
# (SPARSEDYN_GAS_TURNS, as in scripts/bench-ab.sh) and between two of its slices this script
# lets EDMD run for a like time (SIGCONT, then SIGSTOP), so that the machine's swings, which
# last seconds here, fall on both alike. EDMD prints its collision count at every write
# interval (a small fraction of the stretch); each printed line is stamped with EDMD's CPU time
# (/proc/PID/schedstat), and its rate is that of the lines printed while the turns ran.
# Prints each round's collisions per CPU s, the ratio, and the medians.
# Each switch costs the process that resumes its caches, EDMD more than gas_bench: with 30
# slices EDMD ran ~10% below its rate alone at 10^4, ours ~3% (measured 2026-11-28,
# docs/lab/measurements.md#twenty-seventh-measurement); hence 6 slices by default, and --alone, where each runs its whole stretch alone
# on the core, one after the other (order alternating by round): no switch, but each in its own
# seconds of the machine.
#   scripts/bench-edmd.sh EDMD_DIR [--rounds R] [--sizes "10000 100000 1000000"] [--core C]
#                                  [--slices K] [--alone]
# EDMD is not part of this project: EDMD_DIR is a checkout of
# https://github.com/FSmallenburg/EDMD (MIT licence; the measurements in docs/ used commit
# 65a9972). Only its documented parameters are set, with sed, in a copy: the globals at the top
# of mdCell.c (maxtime, writeinterval, eventlisttimemultiplier) and MAXCEL, then it is built
# with its Makefile's flags (-Ofast -funroll-loops -march=native). Its writes sum the kinetic
# energy over all particles: about 30 of them in a stretch, under 0.2% of its time at 10^6.
# Environment: JOBS (build parallelism, default 2).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
usage="usage: $0 EDMD_DIR [--rounds R] [--sizes \"N ...\"] [--core C] [--slices K] [--alone]"
(($# >= 1)) || { echo "$usage" >&2; exit 2; }
edmd=$(cd "$1" 2>/dev/null && pwd) || { echo "$0: no directory $1" >&2; exit 2; }
shift
rounds=5
sizes="10000 100000 1000000"
core=1
slices=6
alone=0
while (($# > 0)); do
  if [[ $1 == --alone ]]; then
    alone=1
    shift
    continue
  fi
  (($# >= 2)) || { echo "$usage" >&2; exit 2; }
  case "$1" in
    --rounds) rounds=$2 ;;
    --sizes) sizes=$2 ;;
    --core) core=$2 ;;
    --slices) slices=$2 ;;
    *) echo "$usage" >&2; exit 2 ;;
  esac
  shift 2
done
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "$0: --rounds must be a positive number, not '$rounds'" >&2; exit 2; }
[[ $core =~ ^[0-9]+$ ]] || { echo "$0: --core must be a core number, not '$core'" >&2; exit 2; }
[[ $slices =~ ^[1-9][0-9]*$ ]] || { echo "$0: --slices must be a positive number, not '$slices'" >&2; exit 2; }
source="$edmd/Cell/mdCell.c"
[[ -f $source ]] || { echo "$0: $source not found (not an EDMD checkout?)" >&2; exit 2; }
for n in $sizes; do
  if ! [[ $n =~ ^[0-9]+$ ]] || ((n < 1000 || n >= 10000000)); then
    echo "$0: sizes must be whole numbers from 1000 to 9999999, not '$n'" >&2
    exit 2
  fi
done
command -v gcc >/dev/null || { echo "$0: gcc is needed to build EDMD" >&2; exit 1; }
command -v stdbuf >/dev/null || { echo "$0: stdbuf (coreutils) is needed" >&2; exit 1; }
[[ -r /proc/self/schedstat ]] || { echo "$0: /proc/PID/schedstat is needed (Linux)" >&2; exit 1; }
# The script's own work (stamping EDMD's lines, passing the turns) runs on another core.
other=$((core == 0 ? 1 : 0))

"$root/scripts/deps.sh"
cmake -S "$root" --preset bench >/dev/null
build="$root/build/bench"
cmake --build "$build" --target gas_bench gas_sph -j"${JOBS:-2}" >/dev/null
work=$(mktemp -d)
pids=()
cleanup() {
  local pid
  for pid in "${pids[@]}"; do kill -CONT "$pid" 2>/dev/null; kill "$pid" 2>/dev/null; done
  rm -rf "$work"
}
trap cleanup EXIT

packing=0.05
# gas_bench's stretches: the Enskog collision frequency per particle (kT = m = sigma = 1).
rate=$(awk -v p=$packing 'BEGIN { pi = atan2(0, -1); n = 6 * p / pi;
  g = (1 - p / 2) / (1 - p) ^ 3; printf "%.17g", 4 * n * g * sqrt(pi) }')

# EDMD built for one N, to run until maxtime, writing every write_interval.
build_edmd() {  # n maxtime write_interval output
  local n=$1 maxtime=$2 write=$3 out=$4
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
    -e "s/^double writeinterval = [^;]*;/double writeinterval = $write;/" \
    -e "s/^double eventlisttimemultiplier = [^;]*;/double eventlisttimemultiplier = $list;/" \
    -e "s/^#define MAXCEL .*/#define MAXCEL $maxcel/" "$source" >"$work/mdCell.c"
  local parameter
  for parameter in "double maxtime = $maxtime;" "double writeinterval = $write;" \
    "double eventlisttimemultiplier = $list;" "#define MAXCEL $maxcel"; do
    grep -qF "$parameter" "$work/mdCell.c" ||
      { echo "$0: could not set '$parameter' in $source (changed upstream?)" >&2; exit 1; }
  done
  gcc -Wall -Ofast -funroll-loops -march=native -I"$edmd/Cell" -I"$edmd/Grow" \
    "$work/mdCell.c" -o "$out" -lm
}

# Copies EDMD's output lines, each prefixed with the wall clock and EDMD's CPU time in ns.
stamp_lines() {  # pid
  local line cpu
  while IFS= read -r line; do
    read -r cpu _ <"/proc/$1/schedstat" 2>/dev/null || cpu=0
    printf '%s %s %s\n' "$EPOCHREALTIME" "$cpu" "$line"
  done
}

# EDMD's simulated time on its last stamped line (-1 before its first write).
edmd_time() {  # log
  [[ -e $1 ]] || { echo -1; return; }
  sed -n 's/.*Simtime: \([0-9.]*\),.*/\1/p' "$1" | tail -n 1 | awk '{ v = $1 } END { print (NR ? v : -1) }'
}

# --alone: lets the stopped EDMD run alone for `seconds`; sets edmd_begin and edmd_end.
run_edmd_for() {  # pid seconds
  edmd_begin=$EPOCHREALTIME
  kill -CONT "$1"
  sleep "$2"
  kill -STOP "$1"
  edmd_end=$EPOCHREALTIME
}

# One round: EDMD and gas_bench set up and settle side by side; then gas_bench's slices and
# EDMD's alternate (gas_bench first in odd rounds). Sets r_edmd and r_ours, collisions per CPU s.
round() {  # n dir edmd_binary stretch slice_seconds ours_first t_eq
  local n=$1 dir=$2 binary=$3 stretch=$4 slice=$5 ours_first=$6 t_eq=$7
  rm -f "$work"/pipe_* "$work"/ready "$work"/edmd.log "$work"/ours.json
  mkfifo "$work/pipe_ours" "$work/pipe_edmd" "$work/pipe_out"
  (cd "$dir" && exec taskset -c "$core" stdbuf -oL "$binary" >"$work/pipe_out") &
  local edmd_pid=$!
  pids=("$edmd_pid")
  taskset -c "$other" bash -c "$(declare -f stamp_lines); stamp_lines $edmd_pid" \
    <"$work/pipe_out" >"$work/edmd.log" &
  pids+=($!)
  # EDMD settled: stopped until the turns start.
  while (($(awk -v t="$(edmd_time "$work/edmd.log")" -v e="$t_eq" 'BEGIN { print (t < e) }'))); do
    kill -0 "$edmd_pid" 2>/dev/null ||
      { echo "$0: EDMD ended before settling:" >&2; cut -d' ' -f3- "$work/edmd.log" >&2; return 1; }
    sleep 0.05
  done
  kill -STOP "$edmd_pid"
  local begin end
  if ((alone)); then
    # gas_bench's whole stretch, then EDMD for as long (or the other way round: EDMD's run
    # first lasts the script's estimate of gas_bench's stretch).
    local seconds
    seconds=$(awk -v s="$slice" -v k="$slices" 'BEGIN { printf "%.3f", s * k }')
    if ((!ours_first)); then run_edmd_for "$edmd_pid" "$seconds"; fi
    local ours_begin=$EPOCHREALTIME
    SPARSEDYN_GAS_STRETCH=$stretch taskset -c "$core" "$build/bench/gas_bench" \
      --benchmark_filter="^BM_Gas/n:$n/packing%:5/allpairs0_grid1:1/" --benchmark_format=json \
      >"$work/ours.json" 2>/dev/null || { echo "$0: gas_bench failed" >&2; return 1; }
    seconds=$(awk -v a="$ours_begin" -v b="$EPOCHREALTIME" -v s="$seconds" \
      'BEGIN { t = (b - a) * 0.8; printf "%.3f", (t > s ? t : s) }')
    if ((ours_first)); then run_edmd_for "$edmd_pid" "$seconds"; fi
  else
    SPARSEDYN_GAS_STRETCH=$stretch SPARSEDYN_GAS_TURNS="$work/pipe_ours,$work/pipe_edmd,$work/ready,$slices" \
      taskset -c "$core" "$build/bench/gas_bench" \
      --benchmark_filter="^BM_Gas/n:$n/packing%:5/allpairs0_grid1:1/" --benchmark_format=json \
      >"$work/ours.json" 2>/dev/null &
    local ours_pid=$!
    pids+=("$ours_pid")
    while [[ ! -e $work/ready ]]; do
      kill -0 "$ours_pid" 2>/dev/null || { echo "$0: gas_bench ended before its turns" >&2; return 1; }
      sleep 0.05
    done
    exec 3<>"$work/pipe_edmd" 4<>"$work/pipe_ours"
    local token
    begin=$EPOCHREALTIME
    if ((ours_first)); then printf t >&4; else printf t >&3; fi
    # EDMD's turns, until gas_bench's last slice has passed the turn and it has ended.
    while kill -0 "$ours_pid" 2>/dev/null; do
      if read -r -n 1 -t 0.5 token <&3; then
        kill -CONT "$edmd_pid" 2>/dev/null || true
        sleep "$slice"
        kill -STOP "$edmd_pid" 2>/dev/null || true
        printf t >&4
      fi
    done
    end=$EPOCHREALTIME
    exec 3>&- 4>&-
    wait "$ours_pid" || true
  fi
  # EDMD must have outlasted the turns (ended, it is a zombie until waited for).
  local state
  state=$(awk '{ print $3 }' "/proc/$edmd_pid/stat" 2>/dev/null || echo gone)
  [[ $state != Z && $state != gone ]] ||
    { echo "$0: EDMD ended during the turns (its maxtime is too short)" >&2; return 1; }
  kill -CONT "$edmd_pid" 2>/dev/null || true
  kill "$edmd_pid" 2>/dev/null || true
  wait "${pids[@]}" 2>/dev/null || true
  pids=()
  r_ours=$(awk -F': ' '/"collisions\/cpu_s"/ { gsub(/[ ,]/, "", $2); print $2 }' "$work/ours.json")
  [[ -n $r_ours ]] || { echo "$0: gas_bench reported no rate for N = $n" >&2; return 1; }
  # EDMD's rate between its first and last lines stamped while the turns ran.
  if ((alone)); then begin=$edmd_begin end=$edmd_end; fi
  r_edmd=$(awk -v b="$begin" -v e="$end" '
    $1 >= b && $1 <= e && match($0, /Collisions: [0-9]+/) {
      c = substr($0, RSTART + 12, RLENGTH - 12) + 0
      if (!seen) { c0 = c; t0 = $2; seen = 1 }
      c1 = c; t1 = $2; lines++
    }
    END { if (lines < 3 || t1 <= t0) print ""; else printf "%.0f %d\n", (c1 - c0) / ((t1 - t0) * 1e-9), lines }' \
    "$work/edmd.log")
  read -r r_edmd edmd_lines <<<"$r_edmd"
  [[ -n $r_edmd ]] || { echo "$0: EDMD wrote fewer than 3 lines during the turns (N = $n)" >&2; return 1; }
}

median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

if ((alone)); then
  echo "core $core, each alone in turn; collisions per CPU s"
else
  echo "core $core, $slices turns each; collisions per CPU s"
fi
printf '%-8s %-6s %12s %12s %10s %6s\n' N round EDMD ours ours/EDMD lines
for n in $sizes; do
  # gas_bench's stretch: 2 x 10^6 collisions (at least 2 per particle), as in bench-ab.sh.
  stretch=$(awk -v n="$n" 'BEGIN { s = 2e6 / n; print (s < 2 ? 2 : s) }')
  # EDMD's turns last about as long as gas_bench's (measured roughly, ~2 us per collision
  # pair here at 10^6, less below); it writes ~30 lines in the stretch and runs long enough
  # never to end during the turns.
  slice=$(awk -v n="$n" -v s="$stretch" -v k="$slices" 'BEGIN { c = n * s / 2 / k;
    us = n >= 1000000 ? 2.5 : (n >= 100000 ? 1.8 : 1.0); printf "%.3f", c * us * 1e-6 }')
  t_eq=$(awk -v r="$rate" 'BEGIN { printf "%.17g", 2 / r }')
  write=$(awk -v r="$rate" -v s="$stretch" 'BEGIN { printf "%.17g", s / r / 30 / 1.5 }')
  maxtime=$(awk -v r="$rate" -v s="$stretch" -v t="$t_eq" 'BEGIN { printf "%.17g", t + 4 * s / r }')
  dir="$work/$n"
  mkdir -p "$dir"
  "$build/bench/gas_sph" "$n" $packing >"$dir/init.sph"
  build_edmd "$n" "$maxtime" "$write" "$dir/md"
  ratios=()
  : >"$dir/edmd.txt"
  : >"$dir/ours.txt"
  for ((r = 1; r <= rounds; ++r)); do
    round "$n" "$dir" "$dir/md" "$stretch" "$slice" $((r % 2)) "$t_eq"
    ratio=$(awk -v a="$r_edmd" -v b="$r_ours" 'BEGIN { printf "%.3f", b / a }')
    ratios+=("$ratio")
    echo "$r_edmd" >>"$dir/edmd.txt"
    echo "$r_ours" >>"$dir/ours.txt"
    printf '%-8s %-6s %12.0f %12.0f %10s %6s\n' "$n" "$r" "$r_edmd" "$r_ours" "$ratio" "$edmd_lines"
  done
  printf '%-8s %-6s %12.0f %12.0f %10s  (median of the rounds'"'"' ratios; range %s-%s)\n' "$n" median \
    "$(median <"$dir/edmd.txt")" "$(median <"$dir/ours.txt")" \
    "$(printf '%s\n' "${ratios[@]}" | median)" \
    "$(printf '%s\n' "${ratios[@]}" | sort -g | head -n 1)" "$(printf '%s\n' "${ratios[@]}" | sort -g | tail -n 1)"
done
