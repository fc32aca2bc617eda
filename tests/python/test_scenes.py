"""Scenes and their results: the contract of SCENES.md's "Python" section."""
import math
import tomllib

import numpy as np
import pytest

import cosmems


def beam_constants(scene):
    """E I, rho A and L of a scene's beam, read from its TOML text independently of the core."""
    text = tomllib.loads(scene.text())
    s, m = text["structure"], text["material"]
    inertia = s["width"] * s["thickness"] ** 3 / 12.0
    return m["young_modulus"] * inertia, m["density"] * s["width"] * s["thickness"], s["length"]


def test_the_embedded_scenes_are_listed():
    names = cosmems.scenes()
    assert {"cantilever", "microbridge", "folded-flexure", "cantilever-pullin"} <= set(names)
    assert len(names) == len(set(names))


def test_a_static_result_has_the_json_fields_and_numpy_arrays():
    # The tip of a cantilever under a tip force P moves P L^3 / 3 E I: Hermite elements are
    # exact for end loads, so only round-off separates them (1e-9).
    scene = cosmems.Scene("cantilever")
    ei, _, length = beam_constants(scene)
    result = scene.run()
    assert result["status"] == "ok"
    assert result["analysis"] == "static"
    tip = result["tip_displacement"]
    assert isinstance(tip, np.ndarray) and tip.shape == (3,)
    assert tip[1] == pytest.approx(-1e-7 * length**3 / (3 * ei), rel=1e-9)
    # The deflection table is `run --out`'s deflection.csv: the last node is the tip.
    deflection = result["tables"]["deflection"]
    assert deflection["x_m"][-1] == pytest.approx(length, rel=1e-12)
    # The JSON's tip is the field interpolated at x = L, the table's the node's value: equal
    # up to the interpolation's round-off.
    assert deflection["uy_m"][-1] == pytest.approx(tip[1], rel=1e-14)
    assert len(deflection["x_m"]) == result["model"]["elements"] + 1


def test_set_has_the_cli_semantics():
    scene = cosmems.Scene("cantilever").set("model.elements", 8).set("structure.length", 150e-6)
    assert scene.sets == ["model.elements=8", "structure.length=0.00015"]
    result = scene.run(tables=False)
    assert result["model"]["elements"] == 8
    assert "tables" not in result
    ei, _, _ = beam_constants(cosmems.Scene("cantilever"))
    assert result["tip_displacement"][1] == pytest.approx(-1e-7 * 150e-6**3 / (3 * ei), rel=1e-9)
    # Strings, booleans and arrays go as TOML.
    scene.set("analysis.type", "modal").set("material.plate_modulus", True)
    scene.set("loads.tip_force", np.array([0.0, -2e-7, 0.0]))
    assert scene.sets[-3:] == ['analysis.type="modal"', "material.plate_modulus=true",
                               "loads.tip_force=[0.0, -2e-07, 0.0]"]


def test_modal_frequencies_and_mode_shapes():
    # f1 = 1.8751^2 / (2 pi) sqrt(E I / rho A) / L^2; 20 power-series elements resolve it to
    # far better than 1e-6.
    scene = cosmems.Scene("cantilever-modal")
    ei, rho_a, length = beam_constants(scene)
    result = scene.run()
    f1 = 1.8751040687119611**2 / (2 * math.pi) * math.sqrt(ei / rho_a) / length**2
    frequencies = result["frequencies_hz"]
    assert isinstance(frequencies, np.ndarray)
    assert np.all(np.diff(frequencies) >= 0)
    assert frequencies[0] == pytest.approx(f1, rel=1e-6)
    shapes = result["tables"]["mode_shapes"]
    assert set(shapes) >= {"mode", "x_m", "uy"}
    assert result["tables"]["modes"]["kind"][0] == result["modes"][0]["kind"]


def test_a_transient_history_comes_back_as_arrays():
    # A transient needs a duration and a step: the scene is incomplete between the sets.
    scene = cosmems.Scene("cantilever").set("analysis.type", "transient")
    with pytest.raises(cosmems.SceneError, match="analysis.duration") as error:
        scene.run()
    assert error.value.key == "analysis.duration"
    scene.set("analysis.duration", 2e-5).set("analysis.time_step", 1e-7)
    result = scene.run()
    history = result["tables"]["history"]
    assert len(history["time_s"]) == result["steps"] + 1
    assert np.max(np.abs(history["tip_uy_m"])) == pytest.approx(result["tip_displacement_max"],
                                                                rel=1e-12)


def test_out_keeps_the_files(tmp_path):
    # The tables are this run's: a file already in the folder is left there and not read.
    (tmp_path / "run").mkdir()
    (tmp_path / "run" / "old.csv").write_text("x\n1\n")
    result = cosmems.Scene("cantilever").run(out=tmp_path / "run")
    assert (tmp_path / "run" / "deflection.csv").is_file()
    assert (tmp_path / "run" / "old.csv").is_file()
    assert sorted(result["tables"]) == ["deflection", "reactions"]


def test_a_numerical_failure_is_the_status_as_in_the_cli():
    # Above analysis.voltage_max the comb drive has no pull-in: the CLI's exit 3.
    scene = cosmems.Scene("comb-drive").set("analysis.type", "pullin")
    result = scene.set("analysis.voltage_max", 1000.0).run()
    assert result["status"] == "not converged"
    assert "tables" not in result


@pytest.mark.parametrize("key, value, refused", [
    ("structure.lenght", 1e-4, "structure.lenght"), ("structure.length", -1e-4, "structure.length"),
    ("model.elements", "eight", "model.elements"), ("structur.length", 1e-4, "structur"),
    ("structure", {"length": 1e-4}, "structure.kind")])
def test_bad_input_raises_scene_error_naming_the_key(key, value, refused):
    # A table set whole replaces the table, as --set does: its kind is then missing.
    scene = cosmems.Scene("cantilever")
    with pytest.raises(cosmems.SceneError, match=refused.replace(".", r"\.")) as error:
        scene.set(key, value)
    assert error.value.key == refused
    assert isinstance(error.value, ValueError)
    assert scene.sets == []  # the refused override is not kept


def test_unknown_scenes_and_unreadable_files_are_scene_errors(tmp_path):
    with pytest.raises(cosmems.SceneError, match="no-such-scene"):
        cosmems.Scene("no-such-scene")
    broken = tmp_path / "broken.toml"
    broken.write_text("[structure\n")
    with pytest.raises(cosmems.SceneError, match="broken.toml"):
        cosmems.Scene(broken)


def test_a_scene_file_is_a_scene(tmp_path):
    path = tmp_path / "mine.toml"
    path.write_text(cosmems.Scene("cantilever").text().replace("elements = 20", "elements = 6"))
    assert cosmems.Scene(path).run(tables=False)["model"]["elements"] == 6
