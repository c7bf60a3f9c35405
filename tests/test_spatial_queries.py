"""Extremes and optimal torques of a spatial snake lying on the ground (SpatialSceneModel's
extremes and optimize) against independent references: the planar engine on case study 2's
robot with its joints turned to yaw (the plane embedded in 3-D), SciPy's generalized
eigenvalues of forms built from Pinocchio's model and the rows written out here
(test_spatial_contact's dense reference), and brute-force torque searches through the
exact forward solve."""

from __future__ import annotations

import numpy as np
import pytest
from test_spatial_contact import _embed, _flat, _reference

import snakecg
from snakecg.analysis import _quadratic_extremes_numpy
from snakecg.errors import InputError

scipy_linalg = pytest.importorskip("scipy.linalg")
METRICS = ("norm_a_obj", "norm_qdd", "norm_lambda", "sr")


def _planar_pair(rng, scenario, count):
    """The planar and the embedded model, and ``count`` shapes that the spatial forward solve
    answers (drawn until then): shapes whose first three links' COMs are nearly collinear
    (joint 1 close to minus joint 2) make the ground rows nearly dependent in their order,
    which the compiled solve does not answer (test_not_answered_is_flagged)."""
    planar = snakecg.Robot(joints=3)
    pm = snakecg.load(snakecg.Scene(robot=planar, scenario=scenario))
    sm = snakecg.load(snakecg.SpatialScene(_flat(planar), scenario=scenario))
    Q = np.c_[rng.normal(size=(3 * count, 3)), np.deg2rad(rng.uniform(-100, 100, (3 * count, 3)))]
    qs = np.array([_embed(planar, q, np.zeros(6))[0] for q in Q])
    ok = ~sm.forward(qs, np.zeros((len(qs), 3))).singular
    assert ok.sum() >= count
    return pm, sm, Q[ok][:count], qs[ok][:count]


@pytest.mark.parametrize("scenario", ("frictionless", "ideal_wheels"))
def test_extremes_embed_the_planar_ones(rng, scenario):
    """Yaw joints lying flat: every extreme of the four metrics is the planar engine's
    (its eigensolver path) to 2e-10 of the metric's largest value, certified (sr's maximum,
    a ratio of forms, moves by 1.1e-10 with the rounding of the maps' inputs)."""
    pm, sm, Q, qs = _planar_pair(rng, scenario, 8)
    a, b = _quadratic_extremes_numpy(pm, Q), sm.extremes(qs)
    assert np.all(b.certified) and all(r == "" for r in b.reason)
    for m in METRICS:
        top = np.abs(a.max[m]).max()
        for attr in ("max", "min", "min_kept"):
            assert np.abs(getattr(b, attr)[m] - getattr(a, attr)[m]).max() <= 2e-10 * top, \
                (m, attr)


def test_wheel_extremes_are_bounds_of_the_planar_exact_ones(rng):
    """Bounded wheels (mu N_i = mu m_i g on the flat yaw chain: the planar bounds): the
    sampled maxima never exceed the planar engine's exact piecewise ones, come within 1e-3
    of them, and the forward solve at each returned torque gives the value."""
    pm, sm, Q, qs = _planar_pair(rng, "wheels", 3)
    a, b = pm.extremes(Q, exact=True), sm.extremes(qs)
    assert not np.any(b.certified)
    for m in METRICS:
        top = np.abs(a.max[m]).max()
        assert np.all(b.max[m] <= a.max[m] + 1e-9 * top), m
        assert np.all(b.max[m] >= a.max[m] - 1e-3 * top), m
        assert np.all(b.min_kept[m] >= a.min_kept[m] - 1e-9 * top), m
        r = sm.forward(qs, b.tau_max[m])
        assert np.abs(getattr(r, m) - b.max[m]).max() <= 1e-9 * top


def _dense_forms(robot, scene, model, q, held):
    """The metrics' forms from test_spatial_contact's dense reference (Pinocchio + rows
    written there), least-norm held forces by NumPy's pseudo-inverse."""
    nl, na = robot.n_links, robot.joints
    sc = {"K": model.robot_model.parameters, "contact_link": np.eye(nl)[scene.contact_link - 1],
          "side": scene.side_sign, "object_mass": scene.object_mass,
          "object_inertia": scene.object_inertia, "wheel_offset": np.zeros(nl)}
    pose = model.robot_model.link_poses(q)[scene.contact_link - 1]
    e = pose[:2, 0] / np.linalg.norm(pose[:2, 0])
    P = pose[:2, 3] + scene.contact_offset * e
    n = np.array([-e[1], e[0]])
    q_obj = np.r_[P + scene.object_distance * n, np.arctan2(e[1], e[0])]
    rho = np.array([0.0, -scene.object_distance])
    refs = [_reference(robot, q, np.zeros(robot.nv), t, q_obj, np.zeros(3), np.zeros(3), rho,
                       sc)[0] for t in np.vstack([np.zeros(na), np.eye(na)])]
    G, M = refs[0]["delassus"], refs[0]["M"]
    b = np.array([r["b"] for r in refs])
    qf = np.array([r["qdd_free"] for r in refs])
    H = np.flatnonzero(held)
    lam = np.zeros((na, G.shape[0]))
    lam[:, H] = -(np.linalg.pinv(G[np.ix_(H, H)]) @ (b[1:] - b[0])[:, H].T).T
    Q = (qf[1:] - qf[0]) + lam @ refs[0]["qdd_from_lam"].T
    Pr = slice(0, nl + 1)
    N = np.linalg.inv(M)[6:, 6:]
    return {"norm_qdd": Q @ M @ Q.T, "norm_lambda": lam[:, Pr] @ G[Pr, Pr] @ lam[:, Pr].T,
            "c": lam[:, 0]}, N


@pytest.mark.parametrize("scenario", ("frictionless", "ideal_wheels"))
def test_extremes_against_scipy_and_a_brute_force_search(rng, scenario):
    """A yaw-pitch snake lying flat: the extremes of ||qdd||^2 and ||lambda||^2 are SciPy's
    extreme generalized eigenvalues of the dense reference's forms (to 1e-9); no torque of a
    dense random search on the ellipsoid's boundary beats a maximum or undercuts a minimum
    (1e-9), and the returned torques reach them (1e-8)."""
    robot = snakecg.SpatialRobot(joints=3)
    scene = snakecg.SpatialScene(robot, scenario=scenario, contact_link=4, kappa=5)
    model = snakecg.load(scene)
    nl = robot.n_links
    for _ in range(3):
        q = robot.neutral()
        q[:2] = rng.normal(size=2)
        th = rng.uniform(-3, 3)
        q[3:7] = (0, 0, np.sin(th / 2), np.cos(th / 2))
        q[7:] = (rng.uniform(-1.2, 1.2), 0.0, rng.uniform(-1.2, 1.2))
        ex = model.extremes(q)
        assert ex.certified and ex.reason == ""
        for kept in (True, False):
            held = np.zeros(3 * nl + 1, bool)
            held[0] = kept
            held[nl + 1:] = True
            if scenario == "ideal_wheels":
                held[1:nl] = True  # every link but the contacting one (4) has a wheel
            forms, N = _dense_forms(robot, scene, model, q, held)
            for m in ("norm_qdd", "norm_lambda"):
                w = scipy_linalg.eigh(forms[m], N, eigvals_only=True)
                top = max(ex.max[m], 1e-300)
                if kept:
                    kmax, kmin = w[-1], w[0]
                else:
                    assert ex.max[m] >= w[-1] - 1e-9 * top
                    assert ex.min[m] <= w[0] + 1e-9 * top
                    continue
                assert ex.max[m] >= kmax - 1e-9 * top and ex.min_kept[m] <= kmin + 1e-9 * top
                assert abs(ex.min_kept[m] - kmin) <= 1e-9 * top
        # brute force on the boundary
        L = np.linalg.cholesky(np.linalg.inv(model.robot_model.mass_matrix(q))[6:, 6:])
        u = rng.normal(size=(3000, 3))
        u /= np.linalg.norm(u, axis=1, keepdims=True)
        taus = np.linalg.solve(L.T, u.T).T  # tau^T N tau = 1
        res = model.forward(np.tile(q, (len(taus), 1)), taus)
        for m in METRICS:
            v = getattr(res, m)
            top = max(ex.max[m], 1e-300)
            assert v.max() <= ex.max[m] + 1e-9 * top, m
            assert v.min() >= ex.min[m] - 1e-9 * top, m
            assert v[res.contact].min() >= ex.min_kept[m] - 1e-9 * top, m
            assert v.max() >= 0.5 * ex.max[m] or m == "sr"  # the search is dense enough
            at = model.forward(q, ex.tau_max[m])
            assert abs(getattr(at, m) - ex.max[m]) <= 1e-8 * top, m


_TASKS = (("max_sr", {}), ("max_sr", {"tau_max": 0.5}), ("strongest_push", {}),
          ("strongest_push", {"tau_max": 0.5, "radius": 2.0}),
          ("least_slip_push", {"direction": (1.0, 0.3), "a_min": 0.002}),
          ("least_slip_push", {"direction": (1.0, 0.3), "a_min": 0.5}))


@pytest.mark.parametrize("scenario", ("frictionless", "wheels", "ideal_wheels"))
def test_optimize_embeds_the_planar_answers(rng, scenario):
    """Yaw joints lying flat: every task's status and optimal value are the planar engine's
    (its certified compiled solve), to 1e-10 relative."""
    pm, sm, Q, qs = _planar_pair(rng, scenario, 3)
    for objective, kw in _TASKS:
        a, b = pm.optimize(Q, objective, **kw), sm.optimize(qs, objective, **kw)
        assert list(a.status) == list(b.status), (objective, kw, b.reason)
        va, vb = np.asarray(a.objective_value), np.asarray(b.objective_value)
        solved = np.asarray(a.status) == "optimal"  # infeasible: the closest push, not unique
        scale = np.maximum(np.abs(va), np.abs(va[solved]).max(initial=1e-300))
        assert np.all(np.abs(va - vb)[solved] <= 1e-10 * scale[solved]), (objective, kw, va, vb)


def _flat_yaw_pitch(rng, robot):
    q = robot.neutral()
    q[:2] = rng.normal(size=2)
    th = rng.uniform(-3, 3)
    q[3:7] = (0, 0, np.sin(th / 2), np.cos(th / 2))
    q[7:] = (rng.uniform(-1.2, 1.2), 0.0, rng.uniform(-1.2, 1.2))
    return q


def test_optimize_is_never_beaten_by_a_torque_search(rng):
    """A yaw-pitch snake lying flat, bounded wheels (the pitch torque moves the normal forces
    and with them the bounds), a torque box: no torque of a dense random search in the box
    that keeps the contact and every wheel sticking pushes harder than strongest_push or has
    a larger sr than max_sr (exact forward solve, 1e-9), and the answers are inside the box."""
    robot = snakecg.SpatialRobot(joints=3)
    model = snakecg.load(snakecg.SpatialScene(robot, scenario="wheels", mu=0.3,
                                              contact_link=4, kappa=3))
    for _ in range(2):
        q = _flat_yaw_pitch(rng, robot)
        push = model.optimize(q, "strongest_push", tau_max=0.4)
        best = model.optimize(q, "max_sr", tau_max=0.4)
        assert push.status == "optimal" and best.status == "optimal", (push.reason, best.reason)
        assert np.all(np.abs(push.tau) <= 0.4 * (1 + 1e-9))
        taus = rng.uniform(-0.4, 0.4, (4000, 3))
        taus[:1000, 1] = rng.choice([-0.4, 0.4], 1000)  # the pitch joint at its limit
        res = model.forward(np.tile(q, (len(taus), 1)), taus)
        ok = res.contact & np.all(res.wheel_state[:, :3] == "stick", axis=1)
        assert ok.sum() > 100
        d = push.analysis.a_obj[:2] / np.linalg.norm(push.analysis.a_obj[:2])
        pushes = res.a_obj[ok, :2] @ d
        assert pushes.max() <= push.objective_value * (1 + 1e-9)
        assert res.sr[ok].max() <= best.objective_value + 1e-9
        # the pitch torque is used: without it the push is weaker
        assert abs(push.tau[1]) > 1e-3


def test_optimize_and_extremes_refuse_and_flag():
    robot = snakecg.SpatialRobot(joints=2)
    model = snakecg.load(snakecg.SpatialScene(robot, scenario="wheels"))
    q = robot.neutral()
    q[7:] = (0.4, 0.0)
    with pytest.raises(InputError, match="a_obj"):
        model.optimize(q, "least_slip_push", a_obj=(1, 0, 0))
    with pytest.raises(InputError, match="allow_slide"):
        model.optimize(q, "max_sr", allow_slide=True)
    with pytest.raises(InputError, match="objective"):
        model.optimize(q, "fastest")
    with pytest.raises(InputError, match="a_min"):
        model.optimize(q, "least_slip_push", direction=(1, 0))
    with pytest.raises(InputError, match="samples"):
        model.extremes(q, samples=1)
    lifted = q.copy()
    lifted[7:] = (0.4, 0.5)  # the pitch joint lifts the second link off the ground
    ex = model.extremes(np.array([q, lifted]))
    assert ex.reason[0] == "" and "not lying on the ground" in ex.reason[1]
    assert np.isnan(ex.max["sr"][1]) and not ex.certified[1]
    r = model.optimize(lifted, "max_sr")
    assert r.status == "failed" and "not lying on the ground" in r.reason
    import json

    json.dumps(model.optimize(q, "strongest_push").to_dict(), allow_nan=False)


def test_not_answered_is_flagged():
    """Links 1 and 3 nearly parallel (joint 1 = -joint 2 + 1e-4 rad: the first three COMs
    nearly collinear): the compiled forward solve does not answer (nearly dependent ground
    rows in its row order); extremes and optimize then return NaN and "failed" with the
    forward solve's reason, not a value."""
    planar = snakecg.Robot(joints=3)
    sm = snakecg.load(snakecg.SpatialScene(_flat(planar), scenario="frictionless"))
    q = _embed(planar, np.r_[0.3, -0.2, 0.4, 0.92, -0.92 + 1e-4, 0.39], np.zeros(6))[0]
    assert sm.forward(q, np.zeros(3)).singular
    ex = sm.extremes(q)
    assert np.isnan(ex.max["sr"]) and not ex.certified and "did not answer" in ex.reason
    r = sm.optimize(q, "max_sr")
    assert r.status == "failed" and "did not answer" in r.reason
