"""A general scene's metrics (snakecg/engine/scene_metrics.c: the paper's forms taken from the
inertia's factor) against the forms written out in NumPy from the returned accelerations:
||qdd_s||^2 = qdd^T M_s qdd (eq. 26), a_o^T I_o a_o per object (eq. 27) and their sum,
||lambda||^2 = (a - a_free)^T M (a - a_free) with a_free = M^-1 f by numpy.linalg.solve, and
sr (eq. 30); on random scenes whose solves take the tiny path (either copy: mode 1 with FMA
where the processor has it, mode 2 without) and the general one (the same forms whichever path
answered: the inertia's L D L^T factor of the tiny path's copy switched on)."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene

from scenes_reference import ALL_MODELS, POLYHEDRAL, inertia_and_force, peg_obstacles, \
    random_scene


def _dense_metrics(model, res, q, tau):
    """The paper's forms in NumPy from the result's accelerations (an independent model)."""
    M, f = inertia_and_force(model, q, tau)
    ns = model.n_coordinates
    a = np.r_[res.qdd, np.ravel(res.a_obj)]
    nq = res.qdd @ M[:ns, :ns] @ res.qdd
    each = [ao @ M[ns + 3 * j:ns + 3 * j + 3, ns + 3 * j:ns + 3 * j + 3] @ ao
            for j, ao in enumerate(np.reshape(res.a_obj, (-1, 3)))]
    na = float(np.sum(each))
    d = a - np.linalg.solve(M, f)
    free = np.linalg.solve(M, f) @ M @ np.linalg.solve(M, f)
    sr = na / (na + nq) if na + nq > 1e-26 * free else 0.0
    return dict(norm_qdd=nq, norm_a_obj=na, each=np.array(each), norm_lambda=d @ M @ d, sr=sr,
                scale=nq + na + free)


def _scenes(rng, count):
    """Random solved one-sample problems: (model, q, tau), every other one of one-row blocks
    alone (wheels, contacts: the tiny path's problems where they are few)."""
    out = []
    while len(out) < count:
        models = POLYHEDRAL if len(out) % 2 else ALL_MODELS
        robot, ground, objects, pegs, q, tau = random_scene(rng, models)
        try:
            m0 = snakecg.load(GeneralScene(robot, ground=ground, objects=objects))
            model = snakecg.load(GeneralScene(robot, ground=ground, objects=objects,
                                              obstacles=peg_obstacles(m0, pegs, q)))
            if model.forward(q, tau).status == 0:
                out.append((model, q, tau))
        except InputError:
            continue
    return out


@pytest.mark.parametrize("tiny", [1, 2, 0])
def test_metrics_against_the_forms_in_numpy(rng, tiny):
    counts, tried = np.zeros(2), 0
    for model, q, tau in _scenes(rng, 40):
        model.core.scene_tiny(tiny, None)
        try:
            model.core.scene_tiny(-1, counts.ctypes.data)
            res = model.forward(q, tau)
            model.core.scene_tiny(-1, counts.ctypes.data)
        finally:
            model.core.scene_tiny(1, None)
        tried += counts[1]
        assert res.status == 0, res.reason
        want = _dense_metrics(model, res, q, tau)
        tol = 1e-11 * want["scale"]
        for k in ("norm_qdd", "norm_a_obj", "norm_lambda"):
            assert abs(getattr(res, k) - want[k]) <= tol, k
        assert np.abs(res.norm_a_obj_each - want["each"]).max(initial=0.0) <= tol
        assert abs(res.sr - want["sr"]) <= 1e-10 and 0.0 <= res.sr <= 1.0
        assert res.norm_qdd >= 0.0 and res.norm_lambda >= 0.0  # sums of squares
    if tiny:
        assert tried >= 10  # the tiny path answered some of them
    else:
        assert tried == 0


def test_batched_metrics_against_the_forms_in_numpy(rng):
    """The paper's scene through the general path, a batch (its solves started from the last
    sample's pieces, nearly all answered by the tiny path)."""
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100.0)
    model = snakecg.load(GeneralScene.from_scene(scene))
    Q = np.c_[rng.normal(0.0, 0.3, (200, 3)), rng.uniform(-1.0, 1.0, (200, 3))]
    T = rng.normal(0.0, 0.05, (200, 3))
    b = model.forward(Q, T)
    assert np.all(b.status == 0)
    for s in range(0, 200, 7):
        r = model.forward(Q[s], T[s])
        want = _dense_metrics(model, r, Q[s], T[s])
        tol = 1e-11 * want["scale"]
        for k in ("norm_qdd", "norm_a_obj", "norm_lambda"):
            assert abs(getattr(b, k)[s] - want[k]) <= tol, k
            assert abs(getattr(r, k) - want[k]) <= tol, k
        assert abs(b.sr[s] - want["sr"]) <= 1e-10


def test_a_batch_on_a_scene_without_objects_has_no_object_accelerations(rng):
    """A snake alone on Coulomb ground, a batch of 5: the objects' accelerations are an empty
    (5, 0, 3) array (their reshape of an empty span raised ValueError), sr 0 (nothing pushed)
    and ||qdd_s||^2 the form in NumPy."""
    from snakecg.scenes import Ground

    model = snakecg.load(GeneralScene(snakecg.Robot(joints=2),
                                      ground=Ground(model="coulomb", mu=0.05)))
    Q = np.c_[np.zeros((5, 3)), rng.uniform(-1.0, 1.0, (5, 2))]
    T = rng.normal(0.0, 2.0, (5, 2))
    b = model.forward(Q, T)
    assert b.a_obj.shape == (5, 0, 3) and b.norm_a_obj_each.shape == (5, 0)
    assert np.all(b.status == 0) and np.all(b.sr == 0.0)
    for s in range(5):
        want = _dense_metrics(model, model.forward(Q[s], T[s]), Q[s], T[s])
        assert abs(b.norm_qdd[s] - want["norm_qdd"]) <= 1e-11 * want["scale"]


def test_sr_is_zero_in_a_batch_where_friction_holds_the_snake_still():
    """A 1-joint snake on anisotropic and Coulomb ground beside a disc, torques of an
    ellipsoid its friction holds (Clarabel: the sets balance the boundary's torques with a
    few percent of their size, so a = 0 exactly). A batch's warm start left accelerations of
    1.3e-13 of the forces' scale (rounding through another path) and read sr 0.41 on them."""
    from snakecg.scenes import Ground, SceneObject

    from scenes_reference import Balance

    robot = snakecg.Robot(joints=1, mass=(1.8596847719220104, 1.2730504702274663),
                          length=(0.10610752464669511, 0.12719360704586752),
                          inertia=(0.0027386915630950577, 0.002502366505110026))
    ground = (Ground(model="anisotropic", mu_forward=0.495485688190076,
                     mu_backward=0.45362935374522756, mu_lateral=0.2991169298014426),
              Ground(model="coulomb", mu=0.267776956343034))
    disc = SceneObject(shape="disc", radius=0.05990113823068638, mass=9.24218859749358,
                       touching={"link": 1, "offset": 0.09542650607135723, "side": "right"})
    model = snakecg.load(GeneralScene(robot, ground=ground, objects=(disc,)))
    q = np.array([2.2233760957202238, 0.2920109919939485, 0.16929119328181486,
                  0.6557238830744752])
    ns, radius = model.n_coordinates, 0.05
    M = inertia_and_force(model, q, np.zeros(1))[0]
    tau_edge = radius / np.sqrt(np.linalg.inv(M[:ns, :ns])[3, 3])  # (the ellipsoid's ends)
    assert np.all(Balance(model, q)([[tau_edge], [-tau_edge]]) < 0.05)
    T = np.random.default_rng(0).uniform(-tau_edge, tau_edge, (3000, 1))
    b = model.forward(np.tile(q, (3000, 1)), T)
    assert np.all(b.status == 0) and np.all(b.sr == 0.0)
