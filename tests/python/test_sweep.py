"""cosmems.sweep: the options and outputs of `cosmems sweep`."""
import json
import subprocess

import numpy as np
import pytest

import cosmems

EI = 169e9 * 20e-6 * 2e-6**3 / 12.0


def plain(value):
    """JSON-like data with numpy arrays as lists and every number as a float, to compare."""
    if isinstance(value, dict):
        return {key: plain(item) for key, item in value.items()}
    if isinstance(value, (list, np.ndarray)):
        return [plain(item) for item in value]
    if isinstance(value, (int, float, np.floating)) and not isinstance(value, bool):
        return float(value)
    return value


def test_a_grid_sweep_of_the_tip_deflection():
    # P L^3 / 3 E I at each of five lengths (1e-9: exact elements, round-off only).
    summary = cosmems.sweep("cantilever", vary={"structure.length": "100e-6:300e-6:5"},
                            spec="max_deflection<=1.5e-7")
    assert summary["samples"] == 5 and summary["failed"] == 0
    rows = summary["rows"]
    assert [row["index"] for row in rows] == list(range(5))
    for row in rows:
        length = row["parameters"]["structure.length"]
        assert row["status"] == "ok"
        assert row["result"]["max_deflection"] == pytest.approx(1e-7 * length**3 / (3 * EI),
                                                                rel=1e-9)
    deflections = np.array([row["result"]["max_deflection"] for row in rows])
    assert summary["yield"] == pytest.approx(np.mean(deflections <= 1.5e-7), abs=1e-15)
    assert isinstance(rows[0]["result"]["tip_displacement"], np.ndarray)


def test_the_same_summary_as_the_cli(cli, tmp_path):
    # Same scene, sets, draws and specs: every figure but the timings is the CLI's.
    scene = cosmems.Scene("cantilever-modal").set("model.elements", 8)
    summary = cosmems.sweep(scene, vary={"structure.thickness": "normal:2e-6:0.05e-6",
                                         "structure.length": [180e-6, 200e-6]},
                            samples=20, method="lhs", seed=7, spec=["frequencies_hz[0]<70000"],
                            threads=2, out=tmp_path / "py")
    command = [cli, "sweep", "cantilever-modal", "--set", "model.elements=8", "--vary",
               "structure.thickness=normal:2e-6:0.05e-6", "--vary",
               "structure.length=[0.00018, 0.0002]", "--samples", "20", "--method", "lhs",
               "--seed", "7", "--spec", "frequencies_hz[0]<70000", "--threads", "2", "--json"]
    expected = json.loads(subprocess.run(command, check=True, capture_output=True,
                                         text=True).stdout)
    # Timings differ run to run: the sweep's own and each sample's (an output like any other).
    for figures in (summary, expected):
        for key in ("wall_time_s", "workers"):
            figures.pop(key)
        figures["outputs"].pop("wall_time_s")
        figures["sensitivities"].pop("wall_time_s")
    rows = summary.pop("rows")
    assert len(rows) == 40
    assert plain(summary) == plain(expected)
    for name in ("samples.jsonl", "samples.csv", "summary.json", "sweep.json"):
        assert (tmp_path / "py" / name).is_file()


def test_shards_and_resume(tmp_path):
    vary = {"structure.length": "100e-6:300e-6:6"}
    first = cosmems.sweep("cantilever", vary=vary, shard=(1, 2), out=tmp_path)
    assert [row["index"] for row in first["rows"]] == [0, 2, 4]
    both = cosmems.sweep("cantilever", vary=vary, shard="2/2", out=tmp_path)
    assert [row["index"] for row in both["rows"]] == list(range(6))
    assert both["samples"] == 6


def test_bad_sweeps_raise_scene_error_naming_the_key():
    with pytest.raises(cosmems.SceneError, match="structure.lenght") as error:
        cosmems.sweep("cantilever", vary={"structure.lenght": "1e-4:2e-4:3"})
    assert error.value.key == "structure.lenght"
    with pytest.raises(cosmems.SceneError, match="--method"):
        cosmems.sweep("cantilever", vary={"structure.length": "1e-4:2e-4:3"}, method="grid")
    with pytest.raises(cosmems.SceneError, match="--shard"):
        cosmems.sweep("cantilever", vary={"structure.length": "1e-4:2e-4:3"}, shard="3/2")
