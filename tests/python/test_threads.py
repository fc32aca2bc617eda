"""Python threads calling the module at once. A scene's run, a sweep and a model's static and
modal solves release the GIL, so on threads they run together for real: each thread on objects
of its own, and several on one shared Model. Every result must equal the same call's made alone.

CTest runs this file twice: in the Python suite, and as ThreadSanitizer.PythonThreads against
a copy of the module and of the libraries under it built with -fsanitize=thread, in Debian's
python3 with the sanitizer's runtime preloaded (tests/python/CMakeLists.txt), where any data
race between the threads fails it.
"""
import threading

import numpy as np

import cosmems

THREADS = 4
# What a run measures on the wall clock; the rest of a result is the physics.
TIMED = {"wall_time_s", "tick_time_us", "rate_hz", "step_time_us", "realtime_factor",
         "stepping_realtime_factor", "deadline_misses", "overruns"}


def together(work, count=THREADS):
    """work(i) for i < count, each on a thread of its own, all let go at once; the results in
    order. An exception on any thread is raised here."""
    start = threading.Barrier(count)
    results, errors = [None] * count, []

    def body(i):
        try:
            start.wait()
            results[i] = work(i)
        except BaseException as error:  # raised again below, on the test's thread
            errors.append(error)

    threads = [threading.Thread(target=body, args=(i,)) for i in range(count)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    if errors:
        raise errors[0]
    return results


def physics(value):
    """A result without what it timed, with numpy arrays as lists, to compare with ==."""
    if isinstance(value, dict):
        return {key: physics(item) for key, item in value.items() if key not in TIMED}
    if isinstance(value, list):
        return [physics(item) for item in value]
    if isinstance(value, np.ndarray):
        return value.tolist()
    return value


# One scene a kind of run: beam and device statics, modal, pull-in, a transient with contact,
# a release with stiction, and a haptic session (the scripted device's servo thread, on the
# fast clock so that its ticks do not depend on the wall clock).
SCENES = [
    ("cantilever", []),
    ("folded-flexure", []),
    ("micromirror", []),
    ("cantilever-pullin", []),
    ("cantilever-touchdown", []),
    ("cantilever-stiction", []),
    ("cantilever-haptic", [("device.realtime", False), ("analysis.duration", 0.2)]),
]


def scene(i):
    name, sets = SCENES[i % len(SCENES)]
    made = cosmems.Scene(name)
    for key, value in sets:
        made.set(key, value)
    return made


def test_scene_runs_on_threads():
    # Each thread runs every scene, starting at a different one, with the tables written to a
    # folder of its run's own and read back: different analyses and the same one overlap.
    alone = [physics(scene(i).run()) for i in range(len(SCENES))]

    def work(i):
        return [(k, physics(scene(k).run())) for k in np.roll(np.arange(len(SCENES)), -i)]

    for runs in together(work):
        for k, result in runs:
            assert result["status"] == "ok"
            assert result == alone[k], SCENES[k][0]


def test_sweeps_on_threads():
    # Sweeps on Python threads, each with worker threads of its own.
    vary = [{"structure.length": "100e-6:300e-6:4"}, {"structure.gap": "1.5e-6:2.5e-6:4"}]
    alone = [physics(cosmems.sweep("cantilever-pullin", vary=v, threads=1)["rows"]) for v in vary]
    rows = together(lambda i: physics(
        cosmems.sweep("cantilever-pullin", vary=vary[i % 2], threads=2)["rows"]))
    for i, got in enumerate(rows):
        assert got == alone[i % 2]


def test_one_model_shared_by_threads():
    # Static and modal solves on one Model at once (both release the GIL), and a stepper of each
    # thread's own on it, stepped between them.
    model = cosmems.Scene("cantilever").set("model.elements", 8).model()
    tip = model.dof_labels.index("node8.uy")

    def load(i):
        f = np.zeros(model.size)
        f[tip] = -1e-7 * (i + 1)
        return f

    def work(i):
        stepper = model.newmark(1e-7)
        zero = np.zeros(model.size)
        stepper.initialize(zero, zero, zero)
        out = []
        for _ in range(3):
            out.append(model.static(load(i)))
            out.append(model.modal(3)[0])
            for _ in range(10):
                stepper.step(load(i))
            out.append(stepper.d.copy())
        return out

    alone = [work(i) for i in range(THREADS)]
    for got, expected in zip(together(work), alone):
        for x, y in zip(got, expected):
            assert np.array_equal(x, y)
