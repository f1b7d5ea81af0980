# SPDX-License-Identifier: MIT
"""Fixtures: the `sparsedyn` command-line tool the tests compare the package with."""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _cli_path():
    given = os.environ.get("SPARSEDYN_CLI")
    path = Path(given) if given else ROOT / "build" / "release" / "apps" / "cli" / "sparsedyn"
    if not path.is_file():
        raise RuntimeError(f"the sparsedyn tool is not at {path}: build it (scripts/test.sh) or "
                           "set SPARSEDYN_CLI")
    return path


@pytest.fixture(scope="session")
def cli():
    """Runs `sparsedyn ARGS...` and returns its stdout; fails the test on a non-zero exit."""
    path = _cli_path()

    def run(*args, cwd=None):
        done = subprocess.run([str(path), *map(str, args)], capture_output=True, text=True,
                              cwd=cwd)
        assert done.returncode == 0, done.stderr
        return done.stdout

    run.path = path
    return run


@pytest.fixture(scope="session")
def cli_json(cli):
    return lambda *args: json.loads(cli(*args))


@pytest.fixture(scope="session")
def data_dir():
    return ROOT / "data"
