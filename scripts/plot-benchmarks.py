#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Draws the summary plots of docs/benchmarks.md from the CSVs in docs/figures/:

  gas_vs_edmd.csv       -> gas_vs_edmd.png       (scripts/bench-edmd.sh's rounds, as logged)
  thesis_vs_bullet.csv  -> thesis_vs_bullet.png  (written by scripts/bench-thesis.sh)

Debian's matplotlib (python3-matplotlib, scripts/deps.sh). Usage: scripts/plot-benchmarks.py
[--figures DIR]. The other figures of the page are drawn by the scripts that measure them.
"""

import argparse
import csv
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def gas_plot(figures):
    data = rows(figures / "gas_vs_edmd.csv")
    labels = [f"N = 10^{len(r['n']) - 1}" for r in data]
    x = range(len(data))
    fig, ax = plt.subplots(figsize=(7.5, 4), dpi=110)

    def bar(offset, low, high, color, label):
        lows = [float(r[low]) / 1e3 for r in data]
        highs = [float(r[high]) / 1e3 for r in data]
        mids = [(lo + hi) / 2 for lo, hi in zip(lows, highs)]
        spans = [(hi - lo) / 2 for lo, hi in zip(lows, highs)]
        ax.bar([i + offset for i in x], mids, 0.26, yerr=spans, capsize=3, color=color,
               label=label)

    bar(-0.27, "ours_low", "ours_high", "#2e86c1", "sparsedyn (this machine)")
    bar(0.0, "edmd_low", "edmd_high", "#e67e22", "EDMD Cell (this machine, same rounds)")
    published = [float(r["dynamo_published"]) / 1e3 for r in data]
    ax.bar([i + 0.27 for i in x], published, 0.26, color="#95a5a6",
           label="DynamO (published figures)")
    for i, r in enumerate(data):
        ax.annotate(f"{float(r['ratio_median']):.2f}x EDMD", (i - 0.27, float(r["ours_high"]) / 1e3),
                    textcoords="offset points", xytext=(0, 6), ha="center", fontsize=8)
    ax.set_xticks(list(x), labels)
    ax.set_ylabel("collisions per CPU second (thousands)")
    ax.set_title("Hard-sphere gas, packing 0.05, one core (bars: range over the rounds)",
                 fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(figures / "gas_vs_edmd.png")


def bullet_plot(figures):
    data = rows(figures / "thesis_vs_bullet.csv")
    fig, ax = plt.subplots(figsize=(7.5, 4), dpi=110)
    series = {"sparsedyn": ("sparsedyn (event-driven, exact)", "#2e86c1", "o")}
    for r in data:
        if r["engine"] == "bullet":
            key = f"bullet {float(r['dt']):.4g}"
            sixtieth = abs(float(r["dt"]) - 1 / 60) < 1e-6
            name = "Bullet, 1/60 s steps" if sixtieth else f"Bullet, {float(r['dt']):g} s steps"
            series.setdefault(key, (name, "#e67e22" if sixtieth else "#c0392b", "s"))
    for key, (name, color, marker) in series.items():
        points = [(int(r["n"]), float(r["steady_sim_per_cpu"])) for r in data
                  if (r["engine"] == "sparsedyn" and key == "sparsedyn")
                  or (r["engine"] == "bullet" and key == f"bullet {float(r['dt'] or 0):.4g}")]
        ax.loglog(*zip(*points), marker=marker, color=color, label=name)
    ax.axhline(1.0, color="#7f8c8d", lw=0.8, ls="--")
    ax.text(1100, 1.1, "real time", fontsize=8, color="#7f8c8d")
    ax.set_xlabel("bodies N (rotating convex polyhedra, 24-600 faces, 5% density)")
    ax.set_ylabel("simulated s per CPU s (steady)")
    ax.set_title("The thesis scene: sparsedyn against Bullet 3.24", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(figures / "thesis_vs_bullet.png")


def main():
    parser = argparse.ArgumentParser(description="Draws docs/benchmarks.md's summary plots.")
    parser.add_argument("--figures", type=Path, default=ROOT / "docs" / "figures")
    args = parser.parse_args()
    gas_plot(args.figures)
    bullet_plot(args.figures)
    print(f"plot-benchmarks: wrote gas_vs_edmd.png and thesis_vs_bullet.png in {args.figures}")


if __name__ == "__main__":
    main()
