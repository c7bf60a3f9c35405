"""The engine's time step (``core_scene_step``, snakecg/engine/scene_step.c) refuses a state
that is not finite before any work: every coordinate of x and V (the snake's and a box's),
each of NaN, +inf and -inf, is refused with the stepper's error, the state and the rows at it
left as they were; the finite state steps. Reference: the IEEE definition of a finite number
(``math.isfinite``), element by element."""

from __future__ import annotations

import math

import numpy as np
import pytest

from snakecg import Robot
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene, SceneObject, load_scene
from snakecg.scenes.stepping import _Stepper


@pytest.fixture(scope="module")
def stepper():
    box = SceneObject(shape="box", size=(0.1, 0.06), mass=0.5, mu=0.2,
                      touching={"link": 2, "offset": 0.09, "side": "left"})
    model = load_scene(GeneralScene(Robot(joints=3), radius=0.01, objects=(box,)))
    st = _Stepper(model, 1e-5, np.zeros(3))
    st.place(np.array([0.0, 0.0, 0.0, -0.2, -0.1, 0.3]))
    assert st.begin(st.x[:st.ns].copy(), None, None, None) == 0
    return st


def test_a_state_not_finite_is_refused_before_any_work(stepper):
    st = stepper
    x0, v0 = st.x.copy(), np.linspace(-0.3, 0.3, st.n)
    st.V[:] = v0
    out0, m0 = st.out.copy(), st.M.copy()
    assert st.n == 9  # (the snake's 6 coordinates and the box's 3)
    for which in (st.x, st.V):
        for k in range(st.n):
            for bad in (math.nan, math.inf, -math.inf):
                keep = which[k]
                which[k] = bad
                assert not math.isfinite(which[k])
                with pytest.raises(InputError, match="not finite"):
                    st.call(1e-3)
                which[k] = keep
                np.testing.assert_array_equal(st.x, x0)
                np.testing.assert_array_equal(st.V, v0)
                np.testing.assert_array_equal(st.out, out0)
                np.testing.assert_array_equal(st.M, m0)
    assert all(math.isfinite(t) for t in (*st.x, *st.V))
    assert st.call(1e-3) == 0  # the finite state steps (STEP_DONE)
    assert not np.array_equal(st.x, x0)


def test_the_arguments_finiteness_against_numpy(rng):
    """all_finite (the run's argument checks and torque_law's on a few numbers) against
    NumPy's isfinite on random arrays of 1 to 100 numbers with a NaN, +inf, -inf or the
    largest and smallest floats put in, flat and 2-D; a constant torque with one of them
    refused by torque_law with its clear error, a finite one taken as it is."""
    from snakecg._inputs import all_finite as _finite
    from snakecg.errors import InputError
    from snakecg.simulate.torques import torque_law

    for bad in (np.nan, np.inf, -np.inf):
        with pytest.raises(InputError, match="tau"):
            torque_law(np.array([0.1, bad, 0.0]), 3)
    tau = np.array([0.1, np.finfo(float).max, -np.finfo(float).tiny])
    kind, law = torque_law(tau, 3)
    assert kind == "constant" and law is not tau and np.array_equal(law, tau)

    big, tiny = np.finfo(float).max, np.finfo(float).tiny
    for n in (1, 2, 3, 6, 9, 64, 65, 100):
        for bad in (None, np.nan, np.inf, -np.inf, big, -big, tiny, 0.0):
            a = rng.normal(size=n) * 1e3
            if bad is not None:
                a[rng.integers(n)] = bad
            for arr in (a, a.reshape(1, n), a.reshape(n, 1)):
                assert _finite(arr) is bool(np.isfinite(arr).all())
