# SPDX-License-Identifier: MIT
"""examples/python/gas_speeds.py runs and writes its plot."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_gas_speeds_writes_a_png(tmp_path):
    out = tmp_path / "speeds.png"
    done = subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "gas_speeds.py"),
                           "--n", "500", "--until", "2", "--samples", "4", "--out", str(out)],
                          capture_output=True, text=True, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert "collisions" in done.stdout
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # The gas keeps Maxwell-Boltzmann: the printed mean speed is near sqrt(8 / pi) = 1.5958.
    mean = float(done.stdout.split("mean speed ")[1].split()[0])
    assert abs(mean - 1.5958) < 0.08


def test_plot_collisions_draws_a_recording(cli, data_dir, tmp_path):
    cli("run", data_dir / "scenes" / "billiards.json", "--record", tmp_path / "break.sdrec")
    cli("export-jsonl", tmp_path / "break.sdrec", "-o", tmp_path / "break.jsonl")
    out = tmp_path / "break.png"
    done = subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "plot_collisions.py"),
                           str(tmp_path / "break.jsonl"), "--out", str(out)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "65 collisions" in done.stdout  # the billiards break over its 6 s, as the CLI counts
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
