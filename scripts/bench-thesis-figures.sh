#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The thesis's figures (§7.0-§7.2, App. I.1; docs/lab/measurements.md "The thesis's figures"): builds
# thesis_figures (bench/scenes/thesis_figures.cpp) with the `bench` preset, runs it on the
# thesis scene against N (D = 0.05) and against D (N = 1000), and writes
#   docs/figures/thesis_figures_n.csv        one row per N: sparsedyn and the conventional method
#   docs/figures/thesis_figures_density.csv  one row per D: sparsedyn
#   docs/figures/thesis_figures_fits.txt     the §7.2 line and App. I.1 law fits, the progress
#   docs/figures/thesis_7_0_time_vs_n.png, thesis_7_1_breakdown.png,
#   docs/figures/thesis_7_2_collisions_vs_n.png, thesis_i1_collisions_vs_density.png,
#   docs/figures/thesis_stale_fraction.png
# and prints the tables as Markdown.
#   scripts/bench-thesis-figures.sh [--quick] [--large] [--seed S] [--out DIR] [--report-only]
#     --quick        N <= 2000 over 2 simulated s, N = 250 for the densities (under a minute)
#     --large        also N = 32000 and 64000
#     --report-only  no build or run: tables and plots from the CSVs already in --out
# Environment: JOBS (build parallelism, default 2: the machine is shared).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
out="$root/docs/figures"
args=()
density_args=(--duration 10)
run=1
while (($# > 0)); do
  case "$1" in
    --quick) args+=(--quick); density_args=() ;;
    --large) args+=(--large) ;;
    --seed) args+=(--seed "$2"); shift ;;
    --out) out=$2; shift ;;
    --report-only) run=0 ;;
    *) echo "usage: $0 [--quick] [--large] [--seed S] [--out DIR] [--report-only]" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$out"
csv_n="$out/thesis_figures_n.csv"
csv_d="$out/thesis_figures_density.csv"
fits="$out/thesis_figures_fits.txt"

if ((run)); then
  # gnuplot comes with the peers' packages.
  if ! command -v gnuplot >/dev/null; then "$root/scripts/deps.sh" --peers; fi
  cmake -S "$root" --preset bench >/dev/null
  cmake --build "$root/build/bench" --target thesis_figures -j"${JOBS:-2}" >/dev/null
  program="$root/build/bench/bench/thesis_figures"
  {
    echo "# $(date -u '+%Y-%m-%d %H:%M UTC'), $(nproc) cores, load:$(uptime | sed 's/.*load//')"
    "$program" --figure n "${args[@]}" >"$csv_n"
    "$program" --figure density "${args[@]}" "${density_args[@]}" >"$csv_d"
    echo "# done $(date -u '+%H:%M UTC'), load:$(uptime | sed 's/.*load//')"
  } 2>&1 | tee "$fits" | grep -E '^(#|fit|law)' >&2
fi

# Tables. Columns are found by name, so that added columns do not shift them.
table() {
  awk -F, -v want="$2" '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; n = split(want, names, " ")
              line = "|"; rule = "|"
              for (k = 1; k <= n; ++k) { line = line " " names[k] " |"; rule = rule "---|" }
              print line; print rule; next }
    { line = "|"; for (k = 1; k <= n; ++k) line = line " " $(col[names[k]]) " |"; print line }
  ' "$1"
}
echo
echo "§7.0/§7.1/§7.2, seed and duration in $csv_n:"
table "$csv_n" "n sparsedyn_cpu_per_sim_s conv_cpu_per_sim_s conv_over_sparsedyn conv_dt conv_digits conv_equal conv_halvings conv_missing conv_spurious conv_steps conv_narrow_queries conv_bisection_evaluations"
echo
table "$csv_n" "n sparse_s_per_sim_s detailed_s_per_sim_s response_s_per_sim_s queue_s_per_sim_s profiled_cpu_per_sim_s"
echo
table "$csv_n" "n collisions collisions_per_s collisions_per_body_s encounters wall_collisions events stale_target_absent stale_actor_absent stale_fraction stale_fraction_no_cells stale_of_sphere_meets"
echo
echo "App. I.1, $csv_d:"
table "$csv_d" "n density law_x density_accessible law_x_accessible collisions_per_body_s encounters_per_body_s wall_collisions sparsedyn_cpu_per_sim_s stale_fraction stale_fraction_no_cells stale_of_sphere_meets"
echo
grep -E '^(fit|law)' "$fits" || true

# Plots: gnuplot reads the CSVs by column name.
plot() { gnuplot -e "set datafile separator ','" - 2>&1 >/dev/null; }
# The log-log axes against N that the §7.0 and §7.1 plots share.
n_axes='set logscale xy
set autoscale xfix
set offsets graph 0.04, graph 0.04, 0, 0
set xtics (125, 250, 500, 1000, 2000, 4000, 8000, 16000, 32000, 64000) rotate by -30
set grid xtics ytics mytics lc rgb "#dddddd"
set key top left box opaque
set xlabel "N (bodies)"'
plot <<EOF
set terminal pngcairo size 1300,520 font "Sans,11"
set output "$out/thesis_7_0_time_vs_n.png"
set multiplot layout 1,2 title "Thesis §7.0 on the thesis scene (D = 0.05, seed 1): CPU time per simulated second, conventional method at equal accuracy"
$n_axes
set ylabel "CPU s per simulated s"
set format y "10^{%L}"
set key top left box opaque
# A search that stopped on its budget (conv_equal = 0) is drawn apart: not equal accuracy.
equal(c) = column("conv_equal") == 1 ? column(c) : 1/0
unequal(c) = column("conv_equal") == 0 ? column(c) : 1/0
set offsets graph 0.04, graph 0.04, graph 0.3, 0
plot "$csv_n" using "n":(equal("conv_cpu_per_sim_s")) with linespoints lw 2 pt 5 lc rgb "#1f77b4" title "conventional at equal accuracy", \
     "" using "n":(unequal("conv_cpu_per_sim_s")) with points pt 4 ps 1.5 lc rgb "#1f77b4" title "conventional, equal accuracy not reached (last dt)", \
     "" using "n":"sparsedyn_cpu_per_sim_s" with linespoints lw 2 pt 7 lc rgb "#d62728" title "sparsedyn"
set ylabel "conventional / sparsedyn"
unset logscale y
set format y "%g"
set yrange [0:*]
set key top left
set offsets graph 0.04, graph 0.04, graph 0.25, 0
plot "$csv_n" using "n":(equal("conv_over_sparsedyn")) with linespoints lw 2 pt 7 lc rgb "#2ca02c" title "CPU time ratio (labels: the conventional step dt)", \
     "" using "n":(unequal("conv_over_sparsedyn")) with points pt 6 ps 1.5 lc rgb "#2ca02c" title "not at equal accuracy", \
     "" using "n":"conv_over_sparsedyn":(sprintf("%g", column("conv_dt"))) with labels offset 0,-1.1 font "Sans,9" notitle
unset multiplot
EOF

plot <<EOF
set terminal pngcairo size 1400,560 font "Sans,11"
set output "$out/thesis_7_1_breakdown.png"
set multiplot layout 1,2 title "Thesis §7.1: sparsedyn's cost by phase (D = 0.05; WorldSettings::profile_phases; least of three runs)" noenhanced
$n_axes
set title "cumulative"
set ylabel "CPU s per simulated s"
set format y "10^{%L}"
plot "$csv_n" using "n":"sparse_s_per_sim_s" with linespoints lw 2 dt 3 pt 7 lc rgb "#1f77b4" title "sparse (predictions)", \
     "" using "n":(column("sparse_s_per_sim_s") + column("detailed_s_per_sim_s")) with linespoints lw 2 dt 2 pt 5 lc rgb "#ff7f0e" title "+ detailed (polyhedra)", \
     "" using "n":(column("sparse_s_per_sim_s") + column("detailed_s_per_sim_s") + column("response_s_per_sim_s")) with linespoints lw 2 dt 4 pt 9 lc rgb "#2ca02c" title "+ response", \
     "" using "n":(column("sparse_s_per_sim_s") + column("detailed_s_per_sim_s") + column("response_s_per_sim_s") + column("queue_s_per_sim_s")) with linespoints lw 2 pt 13 lc rgb "#9467bd" title "+ queue", \
     "" using "n":"profiled_cpu_per_sim_s" with linespoints lw 2.5 pt 7 lc rgb "#d62728" title "whole run (CPU time of AdvanceTo)"
set title "share of the whole run"
unset logscale y
set format y "%.0f %%"
set yrange [0:100]
set ylabel "per cent of the whole run's CPU time"
set key top right box opaque
share(c) = 100 * column(c) / column("profiled_cpu_per_sim_s")
plot "$csv_n" using "n":(share("detailed_s_per_sim_s")) with linespoints lw 2 pt 5 lc rgb "#ff7f0e" title "detailed", \
     "" using "n":(share("sparse_s_per_sim_s")) with linespoints lw 2 pt 7 lc rgb "#1f77b4" title "sparse", \
     "" using "n":(share("response_s_per_sim_s")) with linespoints lw 2 pt 9 lc rgb "#2ca02c" title "response", \
     "" using "n":(share("queue_s_per_sim_s")) with linespoints lw 2 pt 13 lc rgb "#9467bd" title "queue"
unset multiplot
EOF

plot <<EOF
set terminal pngcairo size 900,560 font "Sans,11"
set output "$out/thesis_7_2_collisions_vs_n.png"
set fit quiet nolog
a = 1; b = 0.1
fit a + b * x "$csv_n" using "n":"collisions_per_s" via a, b
mean = 0; sst = 0; ssr = 0
stats "$csv_n" using "collisions_per_s" name "Y" nooutput
stats "$csv_n" using (column("collisions_per_s") - a - b * column("n")) name "R" nooutput
r2 = 1 - (R_ssd**2 * R_records) / (Y_ssd**2 * Y_records)
set title sprintf("Thesis §7.2: body-body collisions per simulated second, D = 0.05\nleast squares %.3g + %.4g N, R^2 = %.5f", a, b, r2)
set grid xtics ytics lc rgb "#dddddd"
set key top left box opaque
set xlabel "N (bodies)"
set ylabel "collisions per simulated s"
plot "$csv_n" using "n":"collisions_per_s" with points pt 7 ps 1.5 lc rgb "#d62728" title "sparsedyn", \
     a + b * x with lines lw 2 lc rgb "#1f77b4" title "least-squares line"
EOF

plot <<EOF
set terminal pngcairo size 900,560 font "Sans,11"
set output "$out/thesis_i1_collisions_vs_density.png"
set fit quiet nolog
f(d) = d / (1 - d)
kc = 2; km = 2
fit kc * f(x) "$csv_d" using "density":"collisions_per_body_s" via kc
fit km * f(x) "$csv_d" using "density":"encounters_per_body_s" via km
law = 3 * sqrt(2) / 2
stats "$csv_d" using "n" name "N" nooutput
set title sprintf("Thesis App. I.1: collisions per body per simulated second against density D, N = %d", N_max)
set grid xtics ytics lc rgb "#dddddd"
set key top left box opaque
set xlabel "D (fraction of the box filled by bounding spheres)"
set ylabel "per body per simulated s"
set xrange [0:*]
set yrange [0:*]
set samples 200
plot "$csv_d" using "density":"collisions_per_body_s" with points pt 7 ps 1.5 lc rgb "#d62728" title "polyhedra collisions", \
     kc * f(x) with lines lw 2 lc rgb "#d62728" title sprintf("fit %.3g D/(1-D)", kc), \
     "" using "density":"encounters_per_body_s" with points pt 5 ps 1.3 lc rgb "#1f77b4" title "encounters (a pair's strikes within 1 s count once)", \
     km * f(x) with lines lw 2 lc rgb "#1f77b4" title sprintf("fit %.3g D/(1-D)", km), \
     law * f(x) with lines lw 2 dt 2 lc rgb "black" title "law (3√2/2) D/(1-D), spheres of radius 1, mean speed 1"
EOF

plot <<EOF
set terminal pngcairo size 1300,520 font "Sans,11"
set output "$out/thesis_stale_fraction.png"
set multiplot layout 1,2 title "Stale events (§4.2; the thesis saw 20-50 %)"
set key below
set grid xtics ytics lc rgb "#dddddd"
set ylabel "stale events"
set yrange [0:*]
set format y "%.0f %%"
set logscale x
set autoscale xfix
set offsets graph 0.04, graph 0.04, 0, 0
set xtics (125, 250, 500, 1000, 2000, 4000, 8000, 16000, 32000, 64000) rotate by -30
set xlabel "N (bodies), D = 0.05"
plot "$csv_n" using "n":(100 * column("stale_fraction")) with linespoints lw 2 pt 7 lc rgb "#d62728" title "stale / all events", \
     "" using "n":(100 * column("stale_fraction_no_cells")) with linespoints lw 2 pt 5 lc rgb "#ff7f0e" title "stale / events other than cell crossings", \
     "" using "n":(100 * column("stale_of_sphere_meets")) with linespoints lw 2 pt 9 lc rgb "#1f77b4" title "stale / sphere-meet events"
unset logscale x
set offsets 0, 0, 0, 0
set xrange [0:*]
stats "$csv_d" using "n" name "N" nooutput
set xlabel sprintf("D, N = %d", N_max)
plot "$csv_d" using "density":(100 * column("stale_fraction")) with linespoints lw 2 pt 7 lc rgb "#d62728" title "stale / all events", \
     "" using "density":(100 * column("stale_fraction_no_cells")) with linespoints lw 2 pt 5 lc rgb "#ff7f0e" title "stale / events other than cell crossings", \
     "" using "density":(100 * column("stale_of_sphere_meets")) with linespoints lw 2 pt 9 lc rgb "#1f77b4" title "stale / sphere-meet events"
unset multiplot
EOF
echo "wrote $out/thesis_*.png" >&2
