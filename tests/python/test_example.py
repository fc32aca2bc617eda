"""examples/pullin_sweep.py, the notebook-style example, runs headless and finds the L^-2 law."""
import os
import pathlib
import re
import subprocess
import sys

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "pullin_sweep.py"


def test_the_pullin_sweep_example_runs_headless(tmp_path):
    png = tmp_path / "pullin.png"
    environment = dict(os.environ, MPLBACKEND="Agg")
    run = subprocess.run([sys.executable, str(EXAMPLE), str(png)], capture_output=True,
                         text=True, env=environment, check=True)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    # V_PI = c L^-2 holds exactly in the linear theory without fringing (the problem scales
    # with L): the fit's exponent is -2 up to the pull-in search's tolerance.
    exponent = float(re.search(r"V_PI ~ L\^(-?[0-9.]+)", run.stdout).group(1))
    assert abs(exponent + 2.0) < 1e-3
    assert "21 pull-in analyses" in run.stdout
