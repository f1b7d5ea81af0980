#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The §7.3 feature-tracking benchmark (issue #3 part 7, docs/lab/measurements.md): builds the `bench`
# preset, runs closest_features_peers_bench (ours, FCL+libccd, FCL GJK and Bullet GJK in one
# process; closest_features_bench, ours alone, when the peers are not installed) and writes
#   docs/figures/closest_features.csv        one row per engine, angle and face count (medians)
#   docs/figures/closest_features.png        ns/update against faces, one panel per angle
#   docs/figures/closest_features_sqrt.png   ours: ns and steps per update against sqrt(faces)
#   docs/figures/closest_features_agreement.txt   the program's stderr: distance agreement checks
# and prints, as Markdown, the table of ns/update and peer/ours ratios and the fit of our time
# per update against sqrt(faces) (thesis App. J.2).
#   scripts/bench-closest-features.sh [--quick] [--out DIR] [--report-only]
#     --quick        one repetition of 0.05 s per case instead of 3 of 0.2 s (a smoke test)
#     --out          where the CSV and PNG go (default docs/figures)
#     --report-only  no build or run: tables and plot from the CSV already in --out
# Environment: JOBS (build parallelism, default 2: the machine is shared).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out="$root/docs/figures"
min_time=0.2
repetitions=3
run=1
while (($# > 0)); do
  case "$1" in
    --quick) min_time=0.05; repetitions=1 ;;
    --out) out=$2; shift ;;
    --report-only) run=0 ;;
    *) echo "usage: $0 [--quick] [--out DIR] [--report-only]" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$out"
csv="$out/closest_features.csv"
if ((run)); then
  "$root/scripts/deps.sh" --peers

  # Build: the peers program when CMake found the peers, else ours alone.
  cmake -S "$root" --preset bench >/dev/null
  build="$root/build/bench"
  program="$build/bench/peers/closest_features_peers_bench"
  targets=$(cmake --build "$build" --target help)
  if [[ $targets == *closest_features_peers_bench* ]]; then
    cmake --build "$build" --target closest_features_peers_bench -j"${JOBS:-2}" >/dev/null
  else
    echo "$0: peers not found by CMake (see its bench/peers message); running ours alone" >&2
    program="$build/bench/closest_features_bench"
    cmake --build "$build" --target closest_features_bench -j"${JOBS:-2}" >/dev/null
  fi

  # Run. Per case, the engines run one after the other (see the program), so the ratios of
  # neighbouring rows are what to trust on a noisy machine.
  json=$(mktemp)
  "$program" --benchmark_min_time="$min_time" --benchmark_repetitions="$repetitions" \
    --benchmark_report_aggregates_only=true --benchmark_out="$json" \
    --benchmark_out_format=json >/dev/null 2>"$out/closest_features_agreement.txt"
  trap 'rm -f "$json"' EXIT
  grep -E '^(agreement|closest)' "$out/closest_features_agreement.txt" >&2 || true

  # CSV: medians over the repetitions (the only aggregate with one repetition is the run itself).
  jq -r '
    ["engine", "deg", "faces", "ns_per_update", "steps_per_update", "max_dev", "max_dev_brute"],
    (.benchmarks[]
     | select((.aggregate_name // "median") == "median")
     | [(.run_name | split("/")[0]), .deg, .faces, .cpu_time,
        (.["steps/update"] // ""), (.max_dev // ""), (.max_dev_brute // "")])
    | @csv' "$json" | tr -d '"' >"$csv"
  echo "wrote $csv" >&2
fi

# Table: ns/update of every engine and the peer/ours ratios, per angle and face count.
awk -F, '
  NR > 1 { key = $2 "," $3; ns[$1, key] = $4; steps[$1, key] = $5
           if (!($3 in seen)) { seen[$3] = 1; faces[++n] = $3 } }
  function cell(e, k) { return ((e, k) in ns) ? sprintf("%.0f", ns[e, k]) : "–" }
  function ratio(e, k) {
    if (!((e, k) in ns) || !(("ours_warm", k) in ns)) return "–"
    return sprintf("%.1f", ns[e, k] / ns["ours_warm", k]) }
  END {
    print "| deg/step | faces | ours ns | steps/update | FCL+libccd ns | FCL GJK ns | Bullet GJK ns | libccd/ours | FCL GJK/ours | Bullet/ours |"
    print "|---|---|---|---|---|---|---|---|---|---|"
    split("1 5 25", angle, " ")
    for (a = 1; a <= 3; ++a) for (i = 1; i <= n; ++i) {
      k = angle[a] "," faces[i]; split(k, p, ",")
      if (!(("fcl_libccd", k) in ns) && !(("ours_warm", k) in ns)) continue
      s = (("ours_warm", k) in steps) ? sprintf("%.2f", steps["ours_warm", k]) : "–"
      printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", p[1], p[2],
             cell("ours_warm", k), s, cell("fcl_libccd", k), cell("fcl_indep", k),
             cell("bullet_gjk", k), ratio("fcl_libccd", k), ratio("fcl_indep", k),
             ratio("bullet_gjk", k)
    }
  }' "$csv"

# Cold starts (ours, 5°/step poses): with and without the J.1.2 direction table.
awk -F, '
  $1 == "ours_cold_table" { table[$3] = $4; tsteps[$3] = $5 }
  $1 == "ours_cold_plain" { plain[$3] = $4; psteps[$3] = $5; faces[++n] = $3 }
  END {
    if (n == 0) { print "\n(no cold-start rows in the CSV)"; exit }
    print "\n| faces | cold, J.1.2 table: ns | steps | cold, from vertex 0: ns | steps | plain/table |"
    print "|---|---|---|---|---|---|"
    for (i = 1; i <= n; ++i) {
      f = faces[i]
      printf "| %s | %.0f | %.1f | %.0f | %.1f | %.1f |\n", f, table[f], tsteps[f], plain[f],
             psteps[f], plain[f] / table[f]
    }
  }' "$csv"

# Least-squares fits of our warm ns/update and steps/update against sqrt(faces), per angle:
# y = a + b sqrt(F) with R^2, and the one-parameter y = c sqrt(F) of the thesis's figure.
awk -F, '
  $1 == "ours_warm" {
    d = $2; x = sqrt($3); if (!(d in n)) angles++; n[d]++; sx[d] += x; sxx[d] += x * x
    for (j = 0; j < 2; ++j) { y = (j == 0) ? $4 : $5
      sy[d, j] += y; syy[d, j] += y * y; sxy[d, j] += x * y }
  }
  END {
    if (angles == 0) { print "\n(no rows of ours in the CSV: no sqrt(faces) fit)"; exit }
    print "\n| deg/step | quantity | a | b | R^2 of a + b sqrt(F) | c of c sqrt(F) | R^2 of c sqrt(F) |"
    print "|---|---|---|---|---|---|---|"
    split("1 5 25", angle, " ")
    for (i = 1; i <= 3; ++i) for (j = 0; j < 2; ++j) {
      d = angle[i]; if (!(d in n)) continue
      m = n[d]; b = (m * sxy[d, j] - sx[d] * sy[d, j]) / (m * sxx[d] - sx[d] * sx[d])
      a = (sy[d, j] - b * sx[d]) / m
      tot = syy[d, j] - sy[d, j] * sy[d, j] / m
      res = syy[d, j] - 2 * a * sy[d, j] - 2 * b * sxy[d, j] + m * a * a \
            + 2 * a * b * sx[d] + b * b * sxx[d]
      c = sxy[d, j] / sxx[d]; res0 = syy[d, j] - 2 * c * sxy[d, j] + c * c * sxx[d]
      r2 = (tot > 0) ? 1 - res / tot : 1; r20 = (tot > 0) ? 1 - res0 / tot : 1
      printf "| %s | %s | %.3g | %.3g | %.3f | %.3g | %.3f |\n", d,
             (j == 0) ? "ns/update" : "steps/update", a, b, r2, c, r20
    }
  }' "$csv"

# Growth of every engine's time with the face count: the exponent beta of ns = alpha F^beta
# (least squares on log ns against log F; sqrt(F) growth is beta = 0.5, a linear scan 1).
awk -F, '
  NR > 1 && $1 !~ /cold/ {
    k = $1 "," $2; if (!(k in n)) { keys[++m] = k }; x = log($3); y = log($4)
    n[k]++; sx[k] += x; sy[k] += y; sxx[k] += x * x; sxy[k] += x * y; syy[k] += y * y
  }
  END {
    print "\n| engine | deg/step | beta of ns ~ F^beta | R^2 (log-log) |"
    print "|---|---|---|---|"
    for (i = 1; i <= m; ++i) {
      k = keys[i]; split(k, p, ","); c = n[k]
      b = (c * sxy[k] - sx[k] * sy[k]) / (c * sxx[k] - sx[k] * sx[k]); a = (sy[k] - b * sx[k]) / c
      tot = syy[k] - sy[k] * sy[k] / c
      res = syy[k] - 2 * a * sy[k] - 2 * b * sxy[k] + c * a * a + 2 * a * b * sx[k] + b * b * sxx[k]
      printf "| %s | %s | %.2f | %.3f |\n", p[1], p[2], b, (tot > 0) ? 1 - res / tot : 1
    }
  }' "$csv" | { read -r blank; echo "$blank"; read -r head; echo "$head"; read -r rule; echo "$rule"; sort -t'|' -k2,2 -k3,3n; }

# Plot: one log-log panel per angle, every engine's ns/update against faces (one data file per
# engine and angle, so that gnuplot draws connected lines; an engine with no rows is skipped).
png="$out/closest_features.png"
series=$(mktemp -d)
trap 'rm -rf "$series" "${json:-}"' EXIT
awk -F, -v dir="$series" 'NR > 1 { print $3, $4, $5 > (dir "/" $1 "_" $2 ".dat") }' "$csv"
gnuplot 2>/dev/null <<EOF
set terminal pngcairo size 1500,520 font "Sans,11"
set output "$png"
set logscale xy
set xrange [6:1300]
set yrange [20:200000]
set xtics (8, 16, 32, 64, 128, 256, 512, 1000)
set format y "10^{%L}"
set grid xtics ytics mytics lc rgb "#dddddd"
set key top left box opaque font "Sans,10"
set xlabel "faces per polyhedron"
set multiplot layout 1,3 title "Closest-feature tracking, one polyhedron spinning next to another (thesis §7.3): CPU time per distance update (median)"
do for [deg in "1 5 25"] {
  set title sprintf("%s° per step", deg)
  set ylabel (deg eq "1") ? "ns per update" : ""
  plot \\
    "$series/ours_warm_".deg.".dat" with linespoints lw 2.5 pt 7 lc rgb "#d62728" title "sparsedyn (warm start)", \\
    "$series/fcl_libccd_".deg.".dat" with linespoints lw 2 pt 5 lc rgb "#1f77b4" title "FCL + libccd", \\
    "$series/fcl_indep_".deg.".dat" with linespoints lw 2 pt 9 lc rgb "#9467bd" title "FCL own GJK", \\
    "$series/bullet_gjk_".deg.".dat" with linespoints lw 2 pt 13 lc rgb "#2ca02c" title "Bullet btGjkPairDetector", \\
    (deg eq "1" ? 100 : 1/0) with lines dt 2 lw 1.5 lc rgb "#d62728" title (deg eq "1" ? "target at 1°: 100 ns" : "")
}
unset multiplot
EOF
echo "wrote $png" >&2

# Plot: our ns/update and steps/update against sqrt(faces) with the least-squares lines
# a + b sqrt(F) per angle (thesis App. J.2 predicts a straight line).
png_sqrt="$out/closest_features_sqrt.png"
if [[ -s "$series/ours_warm_1.dat" ]]; then
  gnuplot 2>/dev/null <<EOF
set terminal pngcairo size 1200,520 font "Sans,11"
set output "$png_sqrt"
set fit quiet nolog
set xrange [0:33]
set xtics ("8" sqrt(8), "32" sqrt(32), "128" sqrt(128), "256" sqrt(256), "512" sqrt(512), "1000" sqrt(1000))
set grid xtics ytics lc rgb "#dddddd"
set key top left box opaque font "Sans,10"
set xlabel "faces per polyhedron (axis linear in sqrt(faces))"
set multiplot layout 1,2 title "sparsedyn warm-started closest-feature tracking against sqrt(faces) (thesis App. J.2), lines: least-squares a + b sqrt(F)"
colors = "#1f77b4 #ff7f0e #d62728"
array A[3]; array B[3]
do for [col in "2 3"] {
  set ylabel (col eq "2") ? "ns per update (median CPU time)" : "walk steps per update"
  do for [i=1:3] {
    deg = word("1 5 25", i); a = 1; b = 1
    fit a + b * x "$series/ours_warm_".deg.".dat" using (sqrt(\$1)):(column(col + 0)) via a, b
    A[i] = a; B[i] = b
  }
  plot [][0:*] for [i=1:3] "$series/ours_warm_".word("1 5 25", i).".dat" using (sqrt(\$1)):(column(col + 0)) \\
         with points pt 7 ps 1.3 lc rgb word(colors, i) title sprintf("%s° per step", word("1 5 25", i)), \\
       for [i=1:3] A[i] + B[i] * x with lines lw 2 lc rgb word(colors, i) \\
         title sprintf("%.3g + %.3g sqrt(F)", A[i], B[i])
}
unset multiplot
EOF
  echo "wrote $png_sqrt" >&2
fi
