"""The rows a stepper holds between steps (snakecg/engine/scene_step.c swaps its two sets of
row buffers at every accepted step; the stepper reads which is which from the step's struct):
after every step, odd and even counts alike, and after a pooled stepper's second run, the
rows at x and the inertia it reports are those of the state x, recomputed apart by the
reference rows (tests/scenes_rows_reference.py) and the generated mass matrix."""

from __future__ import annotations

import numpy as np

import snakecg
from snakecg.scenes import GeneralScene, Ground, SceneObject, load_scene


def _scene():
    box = SceneObject(shape="box", size=(0.1, 0.06), mass=0.5, mu=0.2,
                      touching={"link": 2, "offset": 0.09, "side": "left"})
    return GeneralScene(snakecg.Robot(joints=3), radius=0.01,
                        ground=Ground(model="coulomb", mu=0.3), objects=(box,))


def _check_rows_at_x(st, model, scene, tol):
    from scenes_rows_reference import rows_of

    ns = model.n_coordinates
    q, qo = st.x[:ns].copy(), st.x[ns:].reshape(-1, 3).copy()
    want, _ = rows_of(scene, model.masses, model.link_poses(q), model.link_jacobians(q),
                      obj_poses=qo, tol=tol)
    got = st.rows()
    m = len(want.A)
    assert len(got.contacts) == len(want.contacts)
    assert [(c.a, c.b) for c in got.contacts] == [(c.a, c.b) for c in want.contacts]
    assert list(got.kind) == list(want.kind) and list(got.start) == list(want.start)
    np.testing.assert_allclose(np.asarray(got.A)[:m], want.A, rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.asarray(got.par, dtype=float),
                               np.asarray(want.par, dtype=float), rtol=1e-12, atol=1e-15)
    M = np.zeros((ns + 3, ns + 3))
    M[:ns, :ns] = model.mass_matrix(q)
    o = scene.objects[0]
    M[ns:, ns:] = np.diag([o.mass, o.mass, o.plate_inertia])
    np.testing.assert_allclose(st.M, M, rtol=1e-12, atol=1e-15)
    return len(want.contacts)


def test_rows_at_x_after_every_step_and_a_second_run():
    from snakecg.scenes.stepping import STEP_DONE, _Stepper

    scene = _scene()
    model = load_scene(scene)
    tol = 1e-6
    q = np.array([0.0, 0.0, 0.0, -0.2, -0.1, 0.3])
    st = _Stepper(model, tol, np.zeros(3))
    touching = 0
    for run in range(2):  # (the second run starts from whichever buffers the first left)
        st.place(q)
        assert st.begin(q, None, None, None) == STEP_DONE
        touching += _check_rows_at_x(st, model, scene, tol)
        st.tau[:3] = [0.4, -0.3, 0.2]
        for k in range(7 + run):
            assert st.call(1e-3) == STEP_DONE
            touching += _check_rows_at_x(st, model, scene, tol)
    assert touching >= 10  # (the box against link 2: a contact row at most states)


def test_the_rows_at_x_after_a_run_through_the_engines_loop():
    """The pooled stepper after whole runs (core_scene_run, 10 and 11 steps: both buffers
    current in turn): its rows and inertia at the run's last state."""
    from snakecg.scenes import stepping

    scene = _scene()
    model = load_scene(scene)
    q = np.array([0.0, 0.0, 0.0, -0.2, -0.1, 0.3])
    for steps in (10, 11):
        run = model.simulate(q, steps * 1e-3, tau=np.array([0.4, -0.3, 0.2]), dt=1e-3)
        assert run.status == "completed" and run.steps == steps
        st = model._steppers[-1]
        ns = model.n_coordinates
        np.testing.assert_array_equal(st.x[:ns], run.q[-1])
        _check_rows_at_x(st, model, scene, stepping.contact_tolerance(scene, None))


def test_array_address_is_numpys():
    """binding.array_address (the record's buffer, the check's output) against NumPy's own
    ``ndarray.ctypes.data`` for arrays of several shapes and types."""
    from snakecg.engine.binding import array_address

    for arr in (np.zeros(2), np.empty((504, 37)), np.zeros(7, dtype=np.int64),
                np.zeros((3, 4))[1:], np.zeros(1)):
        assert array_address(arr) == arr.ctypes.data
