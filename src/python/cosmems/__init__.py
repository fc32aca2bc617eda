"""cosmems: MEMS beams and devices simulated fast enough to be touched, from Python.

Scenes and their results are those of the ``cosmems`` command line (doc/python.md):

    import cosmems
    scene = cosmems.Scene("cantilever")
    scene.set("model.elements", 8)
    result = scene.run()              # the --json fields; number lists as numpy arrays
    summary = cosmems.sweep(scene, vary={"structure.length": "100e-6:300e-6:5"})

Underneath, ``scene.model()`` gives the linear model: K and the mass terms as scipy.sparse
matrices in SI, static and modal solves, and a Newmark stepper whose state arrays are views,
writable and current across steps, of the stepper's own vectors.
"""

import csv
import json
import math
import numbers
import os
import shutil
import tempfile

import numpy as np

from . import _cosmems
from ._cosmems import Model, NumericalError, SceneError, Stepper

__all__ = ["Model", "NumericalError", "Scene", "SceneError", "Stepper", "scenes", "sweep",
           "toml_literal"]


def scenes():
    """The names of the embedded scenes."""
    return [name for name, _ in _cosmems.scenes()]


def toml_literal(value):
    """``value`` as the TOML text ``--set`` reads: booleans, integers, floats (inf and nan too),
    strings, sequences as arrays and mappings as inline tables."""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        x = float(value)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)
    if isinstance(value, str):
        return json.dumps(value)  # JSON's escapes are all TOML basic-string escapes
    if isinstance(value, dict):
        return "{" + ", ".join(json.dumps(str(k)) + " = " + toml_literal(v)
                               for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(toml_literal(v) for v in value) + "]"
    raise TypeError(f"{value!r}: no TOML form for a {type(value).__name__}")


class Scene:
    """An embedded scene (``cosmems.scenes()``) or a .toml file, with ``--set`` overrides.

    Every change is validated at once: a misspelt key or a value the scene refuses raises
    SceneError naming it, and is not kept. A change that leaves the scene waiting for others
    (a transient's type before its duration) is kept; running an incomplete scene raises.
    """

    def __init__(self, name_or_path):
        self._scene = os.fspath(name_or_path)
        self._sets = []
        _cosmems.check_scene(self._scene, self._sets)

    @property
    def name(self):
        """The embedded name or the path the scene was made from."""
        return self._scene

    @property
    def sets(self):
        """The ``KEY=VALUE`` overrides applied so far, in order."""
        return list(self._sets)

    def set(self, key, value):
        """Overrides ``key`` (a dotted path) as ``--set KEY=VALUE`` does; returns the scene."""
        assignment = f"{key}={toml_literal(value)}"
        try:
            _cosmems.check_scene(self._scene, self._sets + [assignment])
        except SceneError as error:
            if _on_path(error.key, key):
                raise
        self._sets.append(assignment)
        return self

    def text(self):
        """The scene file's TOML text (before the overrides)."""
        return _cosmems.scene_text(self._scene)

    def model(self):
        """The linear model of the scene's structure (a Model)."""
        return Model(self._scene, self._sets)

    def run(self, out=None, tables=True):
        """Runs the scene's analysis and returns its result: the fields of ``cosmems run
        --json``, lists of numbers as numpy arrays. A numerical failure is the result's
        ``status``, as in the CLI. With ``tables`` the CSV files of ``--out`` (deflection,
        mode shapes, histories, ...) come back too, as ``result["tables"][NAME][COLUMN]``;
        with ``out`` they are also kept in that directory."""
        if out is not None:
            os.makedirs(out, exist_ok=True)  # an unusable folder fails before the run
        with tempfile.TemporaryDirectory(prefix="cosmems-") as directory:
            files = tables or out is not None
            text, ok = _cosmems.run(self._scene, self._sets, directory if files else "")
            result = _arrays(json.loads(text))
            if ok and tables:
                result["tables"] = _read_tables(directory)  # this run's files only
            if ok and out is not None:
                for name in os.listdir(directory):
                    shutil.copy(os.path.join(directory, name), out)
        return result

    def __repr__(self):
        return f"cosmems.Scene({self._scene!r}, sets={self._sets!r})"


def sweep(scene, vary=None, samples=None, method=None, seed=None, spec=None, threads=None,
          shard=None, out=None, plot=None):
    """``cosmems sweep``: runs ``scene`` (a Scene, a name or a path) over the keys in ``vary``
    ({KEY: SPEC}, SPEC as on the command line, e.g. "1e-6:3e-6:5" or "normal:2e-6:5e-8", or a
    list of values) and returns the summary of ``--json`` as a dict, plus ``rows``: every
    sample's index, parameters, status and result. The scene's ``[sweep]`` table is the
    default; ``spec`` and ``plot`` take one string or a list; ``shard`` is "K/N" or (K, N).
    Runs on ``threads`` threads (one per hardware thread by default) without the GIL."""
    if not isinstance(scene, Scene):
        scene = Scene(scene)
    request = _cosmems.SweepRequest()
    request.scene = scene._scene
    request.sets = list(scene._sets)
    request.vary = [(key, value if isinstance(value, str) else toml_literal(value))
                    for key, value in (vary or {}).items()]
    request.specs = _strings(spec)
    request.plots = _strings(plot)
    request.method = method
    request.samples = samples
    request.seed = seed
    request.threads = threads or 0
    if shard is not None:
        request.set_shard(shard if isinstance(shard, str) else f"{shard[0]}/{shard[1]}")
    request.out = os.fspath(out) if out is not None else ""
    summary_text, rows_text = _cosmems.sweep(request)
    summary = _arrays(json.loads(summary_text))
    summary["rows"] = _arrays(json.loads(rows_text))
    return summary


def _on_path(refused, key):
    """Whether the refused key is ``key``, a table holding it, or a key inside it."""
    if refused is None:
        return False
    return refused == key or key.startswith(refused + ".") or refused.startswith(key + ".")


def _strings(value):
    if value is None:
        return []
    return [value] if isinstance(value, str) else list(value)


def _is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def _arrays(value):
    """JSON values with every non-empty list of numbers (or of equal-length lists of numbers)
    as a numpy array."""
    if isinstance(value, dict):
        return {key: _arrays(item) for key, item in value.items()}
    if isinstance(value, list):
        if value and all(_is_number(x) for x in value):
            return np.array(value, dtype=float)
        if value and all(isinstance(x, list) and x and all(_is_number(y) for y in x)
                         for x in value) and len({len(x) for x in value}) == 1:
            return np.array(value, dtype=float)
        return [_arrays(item) for item in value]
    return value


def _read_tables(directory):
    """Each CSV file of ``directory`` as {column: numpy array, or a list of strings}."""
    tables = {}
    for name in sorted(os.listdir(directory)):
        if not name.endswith(".csv"):
            continue
        with open(os.path.join(directory, name), newline="") as file:
            rows = list(csv.reader(file))
        header, body = rows[0], rows[1:]
        columns = {}
        for k, column in enumerate(header):
            cells = [row[k] for row in body]
            try:
                columns[column] = np.array([float(cell) for cell in cells], dtype=float)
            except ValueError:
                columns[column] = cells
        tables[name[:-len(".csv")]] = columns
    return tables
