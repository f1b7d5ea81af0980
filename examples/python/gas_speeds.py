# SPDX-License-Identifier: MIT
"""Runs the hard-sphere gas and plots its speed distribution against Maxwell-Boltzmann.

    python examples/python/gas_speeds.py [--n 5000] [--until 5] [--out gas_speeds.png]

The gas preset starts from Maxwell-Boltzmann velocities at kT = 1 (mass 1); elastic collisions
keep the distribution. The speeds are sampled at several times (all bodies in one call each,
from their analytic paths) and histogrammed against f(v) = 4 pi v^2 (2 pi kT / m)^(-3/2)
exp(-m v^2 / (2 kT)).
"""

import argparse

import matplotlib

matplotlib.use("Agg")  # writes a file; no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import sparsedyn  # noqa: E402


def maxwell_boltzmann(v, kT=1.0, m=1.0):
    return 4 * np.pi * v**2 * (m / (2 * np.pi * kT)) ** 1.5 * np.exp(-m * v**2 / (2 * kT))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=5000)
    parser.add_argument("--density", type=float, default=0.05)
    parser.add_argument("--until", type=float, default=5.0)
    parser.add_argument("--samples", type=int, default=10)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", default="gas_speeds.png")
    args = parser.parse_args()

    world = sparsedyn.preset("gas", n=args.n, density=args.density, seed=args.seed).build()
    speeds = []
    for t in np.linspace(args.until / args.samples, args.until, args.samples):
        world.advance_to(t)
        speeds.append(np.linalg.norm(world.velocities(), axis=1))
    speeds = np.concatenate(speeds)
    stats = world.stats()

    v = np.linspace(0, speeds.max() * 1.05, 300)
    fig, ax = plt.subplots(figsize=(7, 4.2), dpi=110)
    ax.hist(speeds, bins=60, density=True, color="#8fb3d9", edgecolor="#4a78a8",
            label=f"sparsedyn, {args.n} spheres, {args.samples} times up to t = {args.until:g}")
    ax.plot(v, maxwell_boltzmann(v), color="#c0392b", lw=2, label="Maxwell-Boltzmann, kT = 1")
    ax.set_xlabel("speed |v|")
    ax.set_ylabel("probability density")
    ax.set_title(f"Hard-sphere gas, packing {args.density:g}: "
                 f"{stats['collisions']} collisions, energy "
                 f"{stats['kinetic_energy_initial']:.6g} -> {stats['kinetic_energy_final']:.6g}")
    ax.title.set_fontsize(9)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out)
    print(f"gas_speeds: {stats['collisions']} collisions in {stats['wall_seconds']:.2f} s, "
          f"mean speed {speeds.mean():.4f} (Maxwell-Boltzmann: {np.sqrt(8 / np.pi):.4f}); "
          f"wrote {args.out}")


if __name__ == "__main__":
    main()
