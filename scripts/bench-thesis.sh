#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The thesis scene (§7) against Bullet (docs/lab/measurements.md "The thesis scene against Bullet"):
# builds thesis_bullet in the `bench` preset and runs it at N = 1000 (2 simulated seconds) and
# N = 10000 (1 s), and with --large also N = 100000 (0.2 s), each with Bullet at 1/60 s and
# 0.01 s steps and sparsedyn (reported unavailable until the World simulates polyhedra).
#   scripts/bench-thesis.sh [--large] [--seed S] [--density D] [--out FILE]
# Writes docs/figures/thesis_vs_bullet.csv (one row per engine and step) and prints it.
# Environment: JOBS (build parallelism, default 2: the machine is shared).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out="$root/docs/figures/thesis_vs_bullet.csv"
sizes=("1000 2" "10000 1")
seed=1
density=0.05
while (($# > 0)); do
  case "$1" in
    --large) sizes+=("100000 0.2") ;;
    --seed) seed=$2; shift ;;
    --density) density=$2; shift ;;
    --out) out=$2; shift ;;
    *) echo "usage: $0 [--large] [--seed S] [--density D] [--out FILE]" >&2; exit 2 ;;
  esac
  shift
done

"$root/scripts/deps.sh" --peers
cmake -S "$root" --preset bench >/dev/null
build="$root/build/bench"
if [[ $(cmake --build "$build" --target help) != *thesis_bullet* ]]; then
  echo "$0: Bullet not found by CMake (see its bench/peers message)" >&2
  exit 1
fi
cmake --build "$build" --target thesis_bullet -j"${JOBS:-2}" >/dev/null

# One process per N; the header once. The "sparsedyn: unavailable: ..." line goes to stderr.
mkdir -p "$(dirname "$out")"
run=$(mktemp)
trap 'rm -f "$run"' EXIT
header=--header
: >"$out"
for size in "${sizes[@]}"; do
  read -r n duration <<<"$size"
  "$build/bench/peers/thesis_bullet" --n "$n" --duration "$duration" --seed "$seed" \
    --density "$density" $header >"$run"
  grep '^sparsedyn:' "$run" >&2 || true
  grep -v '^sparsedyn:' "$run" >>"$out"
  header=
done
echo "wrote $out" >&2
column -s, -t "$out"
