# SPDX-License-Identifier: MIT
"""The package against the command-line tool: the same seed gives the same run."""

import json

import numpy as np
import pytest

import sparsedyn

# Wall-clock figures are the only ones allowed to differ between two runs.
WALL_KEYS = {"wall_seconds", "collisions_per_second", "events_per_second"}


def without_wall(summary):
    return {k: v for k, v in summary.items() if k not in WALL_KEYS}


@pytest.mark.parametrize("broadphase", ["grid", "allpairs"])
def test_gas_stats_equal_the_cli_summary(cli_json, broadphase):
    expected = cli_json("run", "--preset", "gas", "--n", 300, "--seed", 7, "--until", 3,
                        "--broadphase", broadphase, "--json")
    world = sparsedyn.preset("gas", n=300, seed=7,
                             broadphase=sparsedyn.Broadphase.__members__[broadphase]).build()
    world.advance_to(3.0)
    stats = world.stats()
    assert set(stats) == set(expected)
    assert without_wall(stats) == without_wall(expected)
    assert stats["collisions"] > 100


def test_collisions_equal_the_cli_recording(cli, tmp_path):
    recording = tmp_path / "gas.sdrec"
    cli("run", "--preset", "gas", "--n", 200, "--seed", 3, "--until", 4, "--record", recording)
    cli("export-jsonl", recording, "-o", tmp_path / "gas.jsonl")
    lines = [json.loads(line) for line in (tmp_path / "gas.jsonl").read_text().splitlines()]
    recorded = [line for line in lines if line.get("record") == "collision"]

    world = sparsedyn.preset("gas", n=200, seed=3).build()
    world.advance_to(4.0)
    got = world.collisions()
    assert len(got) == len(recorded) > 50
    np.testing.assert_array_equal(got["time"], [c["time"] for c in recorded])
    np.testing.assert_array_equal(got["a"], [c["a"] for c in recorded])
    np.testing.assert_array_equal(got["b"], [c["b"] for c in recorded])
    np.testing.assert_array_equal(got["normal"], [c["normal"] for c in recorded])
    np.testing.assert_array_equal(got["impulse"], [c["impulse"] for c in recorded])


def test_scene_file_runs_as_the_cli_runs_it(cli_json, data_dir):
    path = data_dir / "scenes" / "billiards.json"
    expected = cli_json("run", path, "--until", 2, "--json")
    scene = sparsedyn.load_scene(str(path))
    world = scene.build()
    world.advance_to(2.0)
    assert without_wall(world.stats()) == without_wall(expected)


def test_written_scene_loads_back_to_the_same_run(tmp_path):
    scene = sparsedyn.preset("gas", n=100, seed=2)
    scene.write(str(tmp_path / "gas.json"))
    again = sparsedyn.load_scene(str(tmp_path / "gas.json"))
    a, b = scene.build(), again.build()
    a.advance_to(2.0)
    b.advance_to(2.0)
    assert a.state_hash() == b.state_hash()
    np.testing.assert_array_equal(a.positions(), b.positions())


def test_distance_equals_the_cli(cli_json, data_dir):
    meshes = sorted(p for p in data_dir.glob("*.off"))[:2]
    assert len(meshes) == 2, "data/ has OFF meshes"
    pose_b = [3, 0.5, 0, 0.8, 0.6, 0, 0]
    expected = cli_json("distance", meshes[0], meshes[1], "--pose-b", *pose_b, "--json")
    got = sparsedyn.distance(sparsedyn.Polyhedron.read(str(meshes[0])),
                             sparsedyn.Polyhedron.read(str(meshes[1])), pose_b=pose_b)
    assert set(got) == set(expected)
    for key in ("distance", "status", "feature_a", "feature_b", "steps"):
        assert got[key] == expected[key], key
    for key in ("point_a", "point_b", "normal"):
        np.testing.assert_array_equal(got[key], expected[key])
