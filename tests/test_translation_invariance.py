"""The paper's scene has no fixed body, so its answers do not depend on where the snake lies
(a physical law: translation invariance). Far from the origin the world coordinates of the
contact and of the object once cancelled: at x = 1e16 m the forces' norm came out 2.8 times
the true one. The engine now evaluates every contact system with the base at the origin
(the object's given pose moved with it): the answers at any base position equal those at the
origin, bit for bit where the object is placed from q, on the compiled planar and spatial
paths and on CasADi's in-process one."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg


@pytest.fixture(scope="module")
def planar():
    return snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100))


def _moved(q, x, y):
    out = np.array(q, dtype=float)
    out[..., 0] += x
    out[..., 1] += y
    return out


def test_the_paper_scene_answers_the_same_anywhere(planar, rng):
    Q = np.c_[np.zeros((20, 2)), rng.uniform(-np.pi, np.pi, 20), rng.uniform(-1.5, 1.5, (20, 3))]
    T = rng.normal(0.0, 0.1, (20, 3))
    ref = planar.forward(Q, T)
    for x, y in ((1.0, -2.0), (1e8, 3e7), (1e16, -1e16), (1e300, 1e300)):
        res = planar.forward(_moved(Q, x, y), T)
        for name in ("qdd", "a_obj", "lam", "norm_lambda", "norm_a_obj", "norm_qdd", "sr"):
            assert np.array_equal(getattr(res, name), getattr(ref, name)), (x, name)
        one = planar.forward(_moved(Q[3], x, y), T[3])  # (the one-sample path)
        assert np.array_equal(one.qdd, ref.qdd[3]) and np.array_equal(one.lam, ref.lam[3])


def test_the_queries_answer_the_same_anywhere(planar):
    """maps, extremes and the optimal torque (their own evaluations of the generated at-rest
    functions) at a base 1e16 m away equal those at the origin."""
    q = np.array([0.0, 0.0, 0.3, 0.1, 0.2, 0.3])
    far = _moved(q, 1e16, -1e16)
    for key, a, b in (("maps", planar.maps(q), planar.maps(far)),):
        for name in ("qdd_from_tau", "lam_from_tau", "a_obj_from_tau"):
            assert np.array_equal(a[name], b[name]), (key, name)
    e0, e1 = planar.extremes(q), planar.extremes(far)
    assert e0.certified and e1.certified and e0.max == e1.max and e0.min == e1.min
    o0 = planar.optimize(q, "max_sr", radius=1.0)
    o1 = planar.optimize(far, "max_sr", radius=1.0)
    assert o0.status == o1.status and np.array_equal(o0.tau, o1.tau)


def test_a_given_object_pose_moves_with_the_base(planar, rng):
    """With the object's pose given, it is taken relative to the base: moved together by
    1e3 m the answers agree to the rounding of the given coordinates (1e3 eps)."""
    q = np.array([0.0, 0.0, 0.4, 0.3, -0.5, 0.2])
    tau = np.array([0.05, -0.1, 0.08])
    q_obj, rho = planar.place(q[None])[:2]
    ref = planar.forward(q, tau, q_obj=q_obj[0], rho=rho[0])
    for d in (1.0, 1e3):
        res = planar.forward(_moved(q, d, -d), tau, q_obj=_moved(q_obj[0], d, -d), rho=rho[0])
        scale = max(1.0, np.abs(ref.qdd).max())
        assert np.abs(res.qdd - ref.qdd).max() <= 1e3 * d * np.finfo(float).eps * scale


def test_casadi_s_in_process_engine_too():
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2), scenario="wheels", kappa=50),
                         backend="casadi")
    q, tau = np.array([0.0, 0.0, 0.2, 0.4, -0.3]), np.array([0.1, -0.05])
    ref = model.forward(q, tau)
    res = model.forward(_moved(q, 1e16, -1e16), tau)
    assert np.array_equal(res.qdd, ref.qdd) and np.array_equal(res.lam, ref.lam)


def test_a_spatial_snake_too():
    robot = snakecg.SpatialRobot(joints=3, joint_axis=[(0, 0, 1), (0, 1, 0), (0, 0, 1)])
    model = snakecg.load(snakecg.SpatialScene(robot, scenario="wheels", kappa=100))
    q = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -0.4, 0.0, 0.6])
    tau = np.array([0.3, 1.0, 0.3])
    ref = model.forward(q, tau)
    for x in (1e8, 1e16):
        res = model.forward(_moved(q, x, -x), tau)
        assert np.array_equal(res.qdd, ref.qdd) and np.array_equal(res.lam, ref.lam), x
    o0 = model.optimize(q, "max_sr", tau_max=1.0)  # (its at-rest maps, in Python)
    o1 = model.optimize(_moved(q, 1e16, -1e16), "max_sr", tau_max=1.0)
    assert o0.status == o1.status and np.array_equal(o0.tau, o1.tau)
