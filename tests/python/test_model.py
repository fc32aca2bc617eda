"""The library underneath: matrices, static and modal solves, and stepping from Python."""
import math
import threading
import time

import numpy as np
import pytest
import scipy.linalg
import scipy.sparse
import scipy.sparse.linalg

import cosmems

EI = 169e9 * 20e-6 * 2e-6**3 / 12.0  # the embedded cantilever's (test_scenes reads the same)
RHO_A = 2330.0 * 20e-6 * 2e-6
LENGTH = 200e-6


def cantilever(elements=8, order=1):
    scene = cosmems.Scene("cantilever").set("model.elements", elements)
    return scene.set("model.series_order", order).model()


def tip_uy(model):
    return model.dof_labels.index(f"node{model.size // 6}.uy")


def test_matrices_are_symmetric_scipy_sparse_in_si():
    model = cantilever()
    k, m0 = model.stiffness(), model.mass(0)
    assert scipy.sparse.issparse(k) and k.shape == (model.size, model.size)
    assert abs(k - k.T).max() <= 1e-15 * abs(k).max()
    assert abs(m0 - m0.T).max() <= 1e-15 * abs(m0).max()
    # K in SI: the tip load P gives P L^3 / 3 E I, exact for Hermite elements (1e-9 covers
    # the round-off of the solve); the library's own solve gives the same.
    f = np.zeros(model.size)
    f[tip_uy(model)] = -1e-7
    d = scipy.sparse.linalg.spsolve(k.tocsc(), f)
    assert d[tip_uy(model)] == pytest.approx(-1e-7 * LENGTH**3 / (3 * EI), rel=1e-9)
    assert model.static(f) == pytest.approx(d, rel=1e-9, abs=1e-9 * abs(d).max())
    assert np.all(scipy.linalg.eigvalsh(m0.toarray()) > 0)
    assert model.series_order == 1
    assert model.mass(1).shape == k.shape
    with pytest.raises(cosmems.SceneError, match="j = 2"):
        model.mass(2)


def test_labels_positions_and_units():
    model = cantilever()
    assert model.size == 8 * 6
    assert model.dof_labels[tip_uy(model)] == "node8.uy"
    assert model.dof_positions[tip_uy(model)] == pytest.approx([LENGTH, 0, 0], rel=1e-12)
    units = model.units
    assert set(units) == {"length_m", "force_n", "time_s"}
    scale = model.dof_scale
    assert scale[tip_uy(model)] == units["length_m"]
    assert scale[model.dof_labels.index("node8.rz")] == 1.0


def test_modes_against_scipy_on_the_same_matrices():
    # At series order 0 the modal problem is K x = w^2 M_0 x exactly: scipy's dense
    # generalised eigensolver on the SI matrices is a second method (1e-9: both converge to
    # round-off; the library's tolerance is 1e-12 on eigenvalues).
    model = cantilever(elements=10, order=0)
    frequencies, shapes, kinds = model.modal(4)
    w2 = scipy.linalg.eigh(model.stiffness().toarray(), model.mass(0).toarray(),
                           eigvals_only=True)[:4]
    assert frequencies == pytest.approx(np.sqrt(w2) / (2 * math.pi), rel=1e-9)
    m0 = model.mass(0).toarray()
    assert shapes.T @ m0 @ shapes == pytest.approx(np.eye(4), abs=1e-9)
    assert kinds[0] in ("bending_y", "bending_z")
    # With the power series the first bending frequency meets the closed form far closer than
    # the consistent mass alone at this mesh.
    f1 = 1.8751040687119611**2 / (2 * math.pi) * math.sqrt(EI / RHO_A) / LENGTH**2
    series, _, _ = cantilever(elements=10, order=1).modal(1)
    assert abs(series[0] / f1 - 1) < abs(frequencies[0] / f1 - 1)
    assert series[0] == pytest.approx(f1, rel=1e-7)


@pytest.mark.parametrize("name", ["cantilever", "microbridge", "folded-flexure"])
def test_the_scenes_loads_give_the_cli_static(name):
    # K d = the scene's loads, solved in SI, against the static analysis `cosmems run` reports
    # (1e-10: the same linear solve, reached through the SI conversions both ways).
    scene = cosmems.Scene(name)
    model = scene.model()
    d = model.static(model.loads())
    result = scene.run(tables=False)
    if name == "folded-flexure":
        k = model.dof_labels.index("shuttle.ux")
        assert d[k] == pytest.approx(result["bodies"]["shuttle"]["displacement"][0], rel=1e-10)
    else:
        uy = d[[label.endswith(".uy") for label in model.dof_labels]]
        assert np.max(np.abs(uy)) == pytest.approx(result["max_deflection"], rel=1e-10)


def test_a_device_model():
    # The folded-flexure's shuttle moves F / k along x, k = 24 E I / L^3 of its eight guided
    # beams (exact for Hermite elements: 1e-9).
    model = cosmems.Scene("folded-flexure").model()
    f = np.zeros(model.size)
    f[model.dof_labels.index("shuttle.ux")] = 1e-6
    d = model.static(f)
    ei = 160e9 * 2e-6 * 2e-6**3 / 12.0
    assert d[model.dof_labels.index("shuttle.ux")] == pytest.approx(1e-6 * 100e-6**3 / (24 * ei),
                                                                    rel=1e-9)
    assert np.all(scipy.linalg.eigvalsh(model.stiffness().toarray()) > 0)


def test_the_state_arrays_are_the_integrators_own():
    model = cantilever()
    stepper = model.newmark(1e-7)
    zero = np.zeros(model.size)
    stepper.initialize(zero, zero, zero)
    d = stepper.d
    assert d.flags.writeable and d.shape == (model.size,)
    assert stepper.d.__array_interface__["data"][0] == d.__array_interface__["data"][0]
    # Writing through the array moves the beam: the next step starts from the written state.
    k = tip_uy(model)
    d[k] = 1e-3  # internal units
    assert stepper.d[k] == 1e-3
    stepper.step(zero)
    moved = stepper.d.copy()
    assert np.abs(moved).max() > 0
    # A second stepper started from that state the ordinary way (d0 = S d, v0 = 0 and the load
    # K d0 that holds it, so a0 = 0 as in the written state) takes the same step bit for bit.
    other = model.newmark(1e-7)
    d0 = np.zeros(model.size)
    d0[k] = 1e-3 * model.dof_scale[k]
    other.initialize(d0, zero, model.stiffness() @ d0)
    other.step(zero)
    assert other.d == pytest.approx(moved, rel=1e-12, abs=1e-12 * np.abs(moved).max())


def test_state_arrays_kept_across_steps_stay_current():
    # d, v and a taken once, before any step, against the same steppers' state read afresh and
    # against a second stepper that takes the same steps (it moves, so a stale array would
    # differ): an odd and an even number of steps, as a buffer swapped each step would alternate.
    model = cantilever()
    f = np.zeros(model.size)
    f[tip_uy(model)] = -1e-7
    zero = np.zeros(model.size)
    stepper, reference = model.newmark(1e-7), model.newmark(1e-7)
    stepper.initialize(zero, zero, zero)
    reference.initialize(zero, zero, zero)
    d, v, a = stepper.d, stepper.v, stepper.a
    for _ in range(3):
        before = d.copy()
        stepper.step(f)
        reference.step(f)
        assert not np.array_equal(d, before)
        for kept, now, other in ((d, stepper.d, reference.d), (v, stepper.v, reference.v),
                                 (a, stepper.a, reference.a)):
            assert np.array_equal(kept, now) and np.array_equal(kept, other)
    # A write through the kept array after a step is the state the next step starts from.
    k = tip_uy(model)
    d[k] += 1e-3
    reference.d[k] += 1e-3
    assert stepper.d[k] == reference.d[k]
    stepper.step(f)
    reference.step(f)
    assert np.array_equal(d, reference.d)


def test_average_acceleration_conserves_the_energy():
    # The trapezoidal rule conserves E = v^T M v / 2 + d^T K d / 2 of a free, undamped linear
    # system exactly; 1e-10 bounds the round-off of 2000 steps.
    model = cantilever()
    k, m0 = model.stiffness(), model.mass(0)
    stepper = model.newmark(2e-8)
    zero = np.zeros(model.size)
    f = np.zeros(model.size)
    f[tip_uy(model)] = -1e-7
    d0 = model.static(f)
    stepper.initialize(d0, zero, zero)
    scale, t = model.dof_scale, model.units["time_s"]

    def energy():
        d, v = stepper.d * scale, stepper.v * scale / t
        return 0.5 * v @ (m0 @ v) + 0.5 * d @ (k @ d)

    start = energy()
    for _ in range(2000):
        stepper.step(zero)
    assert stepper.time == pytest.approx(2000 * 2e-8, rel=1e-12)
    assert energy() == pytest.approx(start, rel=1e-10)
    assert start == pytest.approx(0.5 * d0 @ f, rel=1e-9)


def test_a_damped_stepper_settles_on_the_static_solution():
    model = cantilever()
    f = np.zeros(model.size)
    f[tip_uy(model)] = -1e-7
    # Mass damping 2 w1 damps every mode at the rate w1 (critically the first); rho_inf = 0.5
    # takes out the modes the step does not resolve, which the physical damping alone leaves
    # ringing. After 400 steps the transient is down by e^-170.
    w1 = 2 * math.pi * model.modal(1)[0][0]
    stepper = model.newmark(1e-6, rho_inf=0.5, mass_damping=2 * w1)
    zero = np.zeros(model.size)
    stepper.initialize(zero, zero, f)
    for _ in range(400):
        stepper.step(f)
    settled = stepper.d * model.dof_scale
    assert settled == pytest.approx(model.static(f), rel=1e-6, abs=1e-6 * abs(settled).max())


def test_steppers_refuse_bad_input():
    model = cantilever()
    with pytest.raises(cosmems.SceneError, match="time_step"):
        model.newmark(-1.0)
    stepper = model.newmark(1e-7)
    with pytest.raises(cosmems.SceneError, match="f has 3 entries"):
        stepper.step(np.zeros(3))
    with pytest.raises(cosmems.SceneError, match="f has 3 entries"):
        model.static(np.zeros(3))


def test_sweeps_release_the_gil():
    # While a sweep runs on another Python thread, this thread keeps running through it. With
    # the GIL held, it could run only before the sweep's C++ starts and after it ends.
    started, done = threading.Event(), threading.Event()
    span = {}

    def work():
        started.set()
        begin = time.perf_counter()
        cosmems.sweep("cantilever-pullin", vary={"structure.length": "100e-6:300e-6:400"},
                      threads=1)
        span["sweep"] = time.perf_counter() - begin
        done.set()

    thread = threading.Thread(target=work)
    thread.start()
    first = last = None
    while not done.is_set():
        if started.is_set():
            last = time.perf_counter()
            first = first or last
    thread.join()
    assert span["sweep"] > 0.02
    assert last - first > 0.5 * span["sweep"]
