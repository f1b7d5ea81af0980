# SPDX-License-Identifier: MIT
"""Plots the collisions of a recording exported as JSON lines: one dot per collision at its
time, on the row of each body it involved (walls in grey).

    sparsedyn run data/scenes/billiards.json --record break.sdrec
    sparsedyn export-jsonl break.sdrec -o break.jsonl
    python examples/python/plot_collisions.py break.jsonl --out break.png

Needs only matplotlib (Debian's python3-matplotlib); docs/recording-format.md describes the lines.
"""

import argparse
import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("jsonl")
    parser.add_argument("--out", default="collisions.png")
    args = parser.parse_args()

    with open(args.jsonl) as f:
        lines = [json.loads(line) for line in f]
    header = next(line for line in lines if line.get("record") == "header")
    hits = [line for line in lines if line.get("record") == "collision"]
    pairs = [(c["time"], c["a"], c["b"]) for c in hits if c["flags"] == 0]
    walls = [(c["time"], c["a"]) for c in hits if c["flags"] == 1]

    fig, ax = plt.subplots(figsize=(7.5, 3.8), dpi=110)
    ax.scatter([t for t, a, b in pairs for _ in (a, b)], [i for _, a, b in pairs for i in (a, b)],
               s=14, color="#2e86c1", label="body-body")
    ax.scatter([t for t, _ in walls], [a for _, a in walls], s=14, color="#95a5a6",
               marker="s", label="cushion (wall)")
    ax.set_xlabel("time, s")
    ax.set_ylabel("body")
    ax.set_title(f"{header.get('scene', '')}: {len(pairs)} collisions between bodies, "
                 f"{len(walls)} with walls", fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(args.out)
    print(f"plot_collisions: {len(hits)} collisions, wrote {args.out}")


if __name__ == "__main__":
    main()
