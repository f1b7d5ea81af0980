# SPDX-License-Identifier: MIT
"""`sparsedyn run` shows progress with an estimate of the time left on a terminal (stderr),
and never on stdout: `--json` stays one JSON object."""

import json
import os
import pty
import select
import subprocess


def run_with_terminal_stderr(cli, args):
    leader, follower = pty.openpty()
    process = subprocess.Popen([str(cli.path), *args], stdout=subprocess.PIPE, stderr=follower)
    os.close(follower)
    seen = b""
    while True:
        ready, _, _ = select.select([leader], [], [], 60)
        if not ready:
            break
        try:
            chunk = os.read(leader, 4096)
        except OSError:  # the terminal closed with the process
            break
        if not chunk:
            break
        seen += chunk
    out, _ = process.communicate(timeout=120)
    os.close(leader)
    return process.returncode, out.decode(), seen.decode(errors="replace")


# About 800k collisions: a second or two, longer than the half second before progress shows.
LONG_RUN = ["run", "--preset", "gas", "--n", "20000", "--until", "100", "--json"]


def test_long_json_run_shows_progress_on_the_terminal_only(cli):
    status, out, terminal = run_with_terminal_stderr(cli, LONG_RUN)
    assert status == 0
    summary = json.loads(out)  # stdout holds the JSON object and nothing else
    assert summary["simulated_time"] == 100
    assert summary["wall_seconds"] > 0.5, "too short a run to show progress"
    assert "left" in terminal and "%" in terminal and "events" in terminal


def test_piped_stderr_stays_silent(cli):
    done = subprocess.run([str(cli.path), *LONG_RUN], capture_output=True, text=True)
    assert done.returncode == 0
    assert json.loads(done.stdout)["wall_seconds"] > 0.5
    assert done.stderr == ""
