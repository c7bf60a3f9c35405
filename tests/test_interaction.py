"""The interaction analysis (issue #3): ``SceneModel.forward``, ``SceneModel.maps`` and the
active-set solver, against an independent dense numpy reference (``tests/reference.py``: link
kinematics by complex step, constraint rows from the gap and wheel-point geometry, brute-force
enumeration of the active sets) and against physical laws (Newton-Euler balances of the whole
system, complementarity, friction opposing sliding, mass scaling of eqs. 22-25, the sr bound
of a frictionless push). Every random draw is seeded (``rng`` fixture, tests/conftest.py).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from reference import Reference

import snakecg
from snakecg import cli

SCENARIOS = ("frictionless", "wheels", "ideal_wheels")
JOINTS = (2, 3, 5)
HELD_NAMES = ("stick",)


# ------------------------------------------------------------------------------------------
# helpers
# ------------------------------------------------------------------------------------------
def close(actual, expected, rtol=1e-7, what=""):
    """``|actual - expected| <= rtol * max(1, |expected|)`` (max norms), with a useful message."""
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    scale = max(1.0, float(np.abs(expected).max(initial=0.0)))
    err = float(np.abs(actual - expected).max(initial=0.0))
    assert err <= rtol * scale, f"{what}: max error {err:.3e} > {rtol:g} * {scale:.3e}"


def random_q(rng, na, n):
    """Configurations: base pose anywhere, joints within +-135 deg (the paper's range)."""
    base = np.column_stack([rng.normal(size=(n, 2)), rng.uniform(-np.pi, np.pi, n)])
    return np.column_stack([base, rng.uniform(-2.35, 2.35, (n, na))])


def random_tau(rng, na, n, lo=0.01, hi=2.0):
    """Torques with random directions and magnitudes over two decades."""
    d = rng.normal(size=(n, na))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    return d * np.exp(rng.uniform(np.log(lo), np.log(hi), (n, 1)))


def random_motion(rng, na, n):
    return (rng.normal(scale=0.7, size=(n, na + 3)), rng.normal(scale=0.3, size=(n, 3)),
            rng.normal(scale=2.0, size=(n, 3)))


def wheel_state_names(ref_states):
    return ["none" if s == "absent" else ("stick" if s == "held" else s)
            for s in ref_states[1:]]


@pytest.fixture(scope="module")
def models():
    """``models(joints, scenario, **scene)`` -> (scene, SceneModel, Reference), memoised."""
    cache = {}

    def get(joints, scenario, robot=None, **kw):
        key = (joints, scenario, robot, tuple(sorted(kw.items())))
        if key not in cache:
            r = robot if robot is not None else snakecg.Robot(joints=joints)
            scene = snakecg.Scene(r, scenario=scenario, **kw)
            cache[key] = (scene, snakecg.load(scene), Reference(scene))
        return cache[key]

    return get


def reference_all(ref, q, tau, v=None, v_obj=None, f_obj=None, q_obj=None, rho=None,
                  method="enumerate"):
    out = []
    for i in range(len(q)):
        kw = {}
        for name, arr in (("v", v), ("v_obj", v_obj), ("f_obj", f_obj), ("q_obj", q_obj),
                          ("rho", rho)):
            if arr is not None:
                kw[name] = arr[i]
        out.append(ref.solve(q[i], tau[i], method=method, **kw))
    return out


def assert_matches_reference(res, refs, ref, what):
    """Runtime batch ``res`` against a list of reference solutions (continuous outputs always,
    discrete states wherever the reference's margin makes them unambiguous)."""
    for i, r in enumerate(refs):
        tag = f"{what} sample {i}"
        assert abs(r["kkt_violation"]) < 1e-9, f"{tag}: reference found no KKT point"
        close(res.qdd[i], r["qdd"], what=f"{tag} qdd")
        close(res.a_obj[i], r["a_obj"], what=f"{tag} a_obj")
        close(res.lam[i], r["lam"], what=f"{tag} lam")
        close(res.w[i], r["w"], what=f"{tag} w")
        close(res.norm_qdd[i], r["norm_qdd"], what=f"{tag} norm_qdd")
        close(res.norm_a_obj[i], r["norm_a_obj"], what=f"{tag} norm_a_obj")
        close(res.norm_lambda[i], r["norm_lambda"], what=f"{tag} norm_lambda")
        close(res.sr[i], r["sr"], rtol=1e-6, what=f"{tag} sr")
        scale = 1e-6 * max(1.0, np.abs(r["lam"]).max(), np.abs(r["w"]).max())
        sure = r["margins"] > scale
        if sure[0]:
            assert bool(res.contact[i]) == r["contact"], f"{tag}: contact flag"
        names = wheel_state_names(r["states"])
        for j in range(ref.nl):
            if sure[j + 1]:
                assert res.wheel_state[i][j] == names[j], f"{tag}: wheel {j + 1} state"
        assert not res.singular[i], f"{tag}: flagged singular"


# ------------------------------------------------------------------------------------------
# 1. forward against the reference
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("joints", JOINTS)
def test_forward_matches_reference(models, rng, joints, scenario):
    """qdd, a_obj, lam, w, contact, wheel states, norms and sr agree with the dense reference,
    at rest and with velocities, object twist and external wrench, for the paper's robot."""
    scene, sm, ref = models(joints, scenario)
    n = 12 if joints == 5 and scenario == "wheels" else 20
    q, tau = random_q(rng, joints, n), random_tau(rng, joints, n)
    res = sm.forward(q, tau)
    assert_matches_reference(res, reference_all(ref, q, tau), ref, "at rest")
    v, v_obj, f_obj = random_motion(rng, joints, n)
    res = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    refs = reference_all(ref, q, tau, v, v_obj, f_obj)
    assert_matches_reference(res, refs, ref, "moving")
    # the draws exercise both contact outcomes
    assert 0 < sum(r["contact"] for r in refs) < n


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_forward_matches_reference_random_robot(models, rng, random_robot, scenario):
    """Random per-link parameters (four decades of mass), a random contact link, side, offset,
    wheel offsets and kappa."""
    robot = random_robot(3)
    k = int(rng.integers(1, 5))
    scene_kw = dict(kappa=float(np.exp(rng.uniform(0, np.log(1000)))), mu=0.3,
                    contact_link=k, side=str(rng.choice(["left", "right"])),
                    contact_offset=float(rng.uniform(0, 1) * robot.length[k - 1]),
                    wheel_offset=tuple(rng.uniform(-0.5, 0.5, 4) * np.array(robot.length)))
    scene, sm, ref = models(3, scenario, robot=robot, **scene_kw)
    n = 15
    m = np.mean(robot.mass)
    q, tau = random_q(rng, 3, n), random_tau(rng, 3, n, 0.01 * m, 3.0 * m)
    v, v_obj, f_obj = random_motion(rng, 3, n)
    res = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj * m)
    assert_matches_reference(res, reference_all(ref, q, tau, v, v_obj, f_obj * m), ref,
                             f"random robot {scene_kw}")


@pytest.mark.parametrize("scenario", ("frictionless", "wheels"))
def test_forward_custom_object_placement(models, rng, scenario):
    """A given object pose and contact point (``q_obj``, ``rho``): object COM off the contact
    normal, any orientation, the contact anywhere on the link."""
    scene, sm, ref = models(3, scenario)
    n = 10
    q, tau = random_q(rng, 3, n), random_tau(rng, 3, n)
    v, v_obj, f_obj = random_motion(rng, 3, n)
    q_obj = np.empty((n, 3))
    rho = rng.uniform(-0.08, 0.08, (n, 2))
    for i in range(n):
        r, e = ref.rear_ends(q[i])
        P = r[ref.k] + rng.uniform(0, 0.15) * e[ref.k]
        psi = rng.uniform(-np.pi, np.pi)
        R = np.array([[np.cos(psi), -np.sin(psi)], [np.sin(psi), np.cos(psi)]])
        q_obj[i] = [*(P - R @ rho[i]), psi]
    res = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj, q_obj=q_obj, rho=rho)
    close(res.gap, 0.0, what="gap of a touching placement")
    refs = reference_all(ref, q, tau, v, v_obj, f_obj, q_obj, rho)
    assert_matches_reference(res, refs, ref, "custom placement")


def test_place_object_matches_reference(models, rng):
    for side in ("left", "right"):
        scene, sm, ref = models(5, "wheels", contact_link=3, side=side, contact_offset=0.03)
        q = random_q(rng, 5, 6)
        q_obj, rho, P = sm.place_object(q)
        for i in range(6):
            eq, erho, eP = ref.place_object(q[i])
            close(q_obj[i], eq, 1e-12, "q_obj")
            close(rho[i], erho, 1e-12, "rho")
            close(P[i], eP, 1e-12, "contact point")
            close(ref.gap(np.concatenate([q[i], q_obj[i]]), rho[i]), 0.0, 1e-12, "gap")


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_batched_equals_single_calls(models, rng, scenario):
    """One configuration broadcast against a batch of torques (small batch: one shared output
    buffer; large: one array per output), and sample by sample."""
    scene, sm, ref = models(3, scenario)
    q = random_q(rng, 3, 1)[0]
    tau = random_tau(rng, 3, 100)
    v, v_obj, f_obj = random_motion(rng, 3, 1)
    for kw in ({}, dict(v=v[0], v_obj=v_obj[0], f_obj=f_obj[0])):
        big = sm.forward(q, tau, **kw)
        small = sm.forward(q, tau[:10], **kw)
        for i in range(10):
            one = sm.forward(q, tau[i], **kw)
            for k in ("qdd", "a_obj", "lam", "w", "norm_qdd", "norm_a_obj", "norm_lambda", "sr"):
                close(getattr(one, k), getattr(big, k)[i], 1e-12, k)
                close(getattr(small, k)[i], getattr(big, k)[i], 1e-12, k)
            assert one.contact == big.contact[i] == small.contact[i]
            assert list(one.wheel_state) == list(big.wheel_state[i]) == list(small.wheel_state[i])
        assert 0 < big.contact.sum() < 100
    assert big.qdd.shape == (100, 6) and np.shape(big.contact) == (100,)
    assert big.wheel_state.shape == (100, 4)
    assert one.qdd.shape == (6,) and np.ndim(one.sr) == 0 and np.ndim(one.contact) == 0


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_single_call_path_equals_general_path(models, rng, scenario):
    """A single sample takes forward's one-sample path (preallocated buffers, scalar active-set
    passes); the CasADi backend and batches take the general one. Both agree to rounding, with
    a given object placement, motion and wrench, and with ``max_iter=1`` (enumeration)."""
    scene, sm, ref = models(2, scenario)
    casadi = snakecg.load(scene, backend="casadi")
    n = 12
    q, tau = random_q(rng, 2, n), random_tau(rng, 2, n)
    v, v_obj, f_obj = random_motion(rng, 2, n)
    q_obj, rho = sm.place_object(q)[:2]
    rho = rho + rng.uniform(-0.03, 0.03, rho.shape)  # off the normal: the object turns
    for kw in ({}, {"max_iter": 1}, {"v": v, "v_obj": v_obj, "f_obj": f_obj},
               {"q_obj": q_obj, "rho": rho, "f_obj": f_obj}):
        batch = sm.forward(q, tau, **kw)
        for i in range(n):
            one_kw = {k: (x[i] if isinstance(x, np.ndarray) else x) for k, x in kw.items()}
            for model in (sm, casadi):
                one = model.forward(q[i], tau[i], **one_kw)
                for k in ("qdd", "a_obj", "lam", "w", "norm_qdd", "norm_a_obj", "norm_lambda",
                          "sr", "gap"):
                    close(getattr(one, k), getattr(batch, k)[i], 1e-11, f"{k} {kw.keys()}")
                    assert np.shape(getattr(one, k)) == np.shape(getattr(batch, k))[1:]
                assert one.contact == batch.contact[i] and not one.singular
                assert type(one.contact) is np.bool_ and type(one.sr) is np.float64
                assert list(one.wheel_state) == list(batch.wheel_state[i])
                close(one.tau, tau[i], 0.0, "tau")


def test_compiled_state_update_equals_the_reference_rules(rng):
    """The row-state update of the compiled core (snakecg/engine/forward.c) and the vectorized
    one of the reference path (solver._violations with _tolerances) give the same next states,
    on random states, forces and accelerations placed at and around the bounds and the
    tolerances."""
    from snakecg import solver

    core = snakecg.load(snakecg.Robot(joints=4)).backend.core
    if core is None:
        pytest.fail("the compiled backend is needed: the C compiler failed")

    nc = 6
    bounds = np.array([np.inf, np.inf, 0.5, 0.5, 2.0, 1.0])
    n = 4000
    state = np.empty((n, nc), np.int8)
    state[:, 0] = rng.choice([solver.HELD, solver.LOST], n)
    state[:, 1] = solver.ABSENT
    state[:, 2:5] = rng.choice([solver.HELD, solver.SLIDE_POS, solver.SLIDE_NEG], (n, 3))
    state[:, 5] = solver.HELD
    scale = np.exp(rng.uniform(-3, 3, (n, 1)))
    lam = rng.normal(size=(n, nc)) * scale
    w = rng.normal(size=(n, nc)) * scale
    # values right at the bounds and within a few tolerances of them or of zero
    near = rng.random((n, nc)) < 0.4
    G = rng.normal(size=(n, nc, nc)) * np.exp(rng.uniform(-3, 3, (n, 1, 1)))
    G = G @ np.swapaxes(G, 1, 2)
    g = np.abs(np.diagonal(G, axis1=1, axis2=2)).max(axis=1)
    tol = 1e-9 * np.abs(lam).max(axis=1, keepdims=True)
    edge = np.where(np.isfinite(bounds), bounds, 0.0) * rng.choice([-1, 1], (n, nc))
    lam = np.where(near, edge + rng.integers(-2, 3, (n, nc)) * tol, lam)
    w = np.where(rng.random((n, nc)) < 0.3, rng.integers(-2, 3, (n, nc)) * 1e-9, w)
    tl, tw = solver._tolerances({"lam": lam, "w": w, "delassus": G})
    vec = solver._violations(state, lam, w, bounds, tl, tw)
    assert g.shape == (n,)
    for i in range(n):
        one, moved = core.next_states(state[i], lam[i], w[i], G[i], bounds)
        assert one.tolist() == vec[i].tolist(), f"sample {i}"
        assert moved == bool(np.any(vec[i] != state[i]))
    assert np.any(vec != state)


# ------------------------------------------------------------------------------------------
# 2. the KKT system and the complementarity conditions
# ------------------------------------------------------------------------------------------
def _held_and_fixed(res_i, nc, present):
    held = np.zeros(nc, bool)
    held[0] = bool(res_i["contact"])
    held[1:] = [s == "stick" for s in res_i["wheel_state"]]
    held &= present
    return held


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("joints", (2, 5))
def test_dense_kkt_system(models, rng, joints, scenario):
    """``[[I, A_H^T], [A_H, 0]] [a; -lam_H] = [f - p + A_F^T lam_F; -Adot v_H]`` solved densely
    (I, A, f, p, Adot v of the reference; H the rows the runtime holds, F the others with the
    runtime's fixed forces) reproduces the runtime's accelerations and held forces."""
    scene, sm, ref = models(joints, scenario)
    n = 10
    q, tau = random_q(rng, joints, n), random_tau(rng, joints, n)
    v, v_obj, f_obj = random_motion(rng, joints, n)
    res = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    for i in range(n):
        s = ref.system(q[i], tau[i], v[i], v_obj[i], f_obj[i])
        ri = {"contact": res.contact[i], "wheel_state": res.wheel_state[i]}
        H = _held_and_fixed(ri, ref.nc, ref.present)
        F = ~H
        lam_F = res.lam[i][F]
        A, I = s["A"], s["I"]
        nH, nd = int(H.sum()), I.shape[0]
        K = np.zeros((nd + nH, nd + nH))
        K[:nd, :nd] = I
        K[:nd, nd:] = A[H].T
        K[nd:, :nd] = A[H]
        rhs = np.concatenate([s["f"] - s["p"] + A[F].T @ lam_F, -s["Adv"][H]])
        sol = np.linalg.solve(K, rhs)
        a, lam_H = sol[:nd], -sol[nd:]
        close(res.qdd[i], a[: ref.ns], what="KKT qdd")
        close(res.a_obj[i], a[ref.ns:], what="KKT a_obj")
        close(res.lam[i][H], lam_H, what="KKT lam_H")
        # the fixed forces are 0 (absent row, lost contact) or the friction bound
        for r in np.flatnonzero(F):
            assert res.lam[i][r] == 0.0 or np.isclose(abs(res.lam[i][r]), ref.bounds[r],
                                                      rtol=1e-12)


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("joints", JOINTS)
def test_complementarity_and_friction(models, rng, joints, scenario):
    """Row accelerations ``w = A a + Adot v`` (reference rows, runtime accelerations) vanish on
    held rows; ``lam_c >= 0``, ``w_c >= 0``, ``lam_c w_c = 0``; ``|lam_i| <= mu m_i g``; at the
    bound friction opposes sliding (``lam_i w_i <= 0``); sr in [0, 1], 0 when the contact is
    lost. 200 samples, with motion and an external wrench on half of them."""
    scene, sm, ref = models(joints, scenario)
    n = 200
    q, tau = random_q(rng, joints, n), random_tau(rng, joints, n)
    v, v_obj, f_obj = random_motion(rng, joints, n)
    v[::2], v_obj[::2] = 0.0, 0.0
    f_obj[::2] = 0.0
    res = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    lam, w = res.lam, res.w
    tol_lam = 1e-9 * np.maximum(1, np.abs(lam).max(axis=1))
    tol_w = 1e-9 * np.maximum(1, np.abs(w).max(axis=1))
    assert np.all(lam[:, 0] >= -tol_lam)
    assert np.all(w[:, 0] >= -tol_w)
    assert np.all(np.minimum(np.abs(lam[:, 0]) / (1 + np.abs(lam).max(axis=1)),
                             np.abs(w[:, 0]) / (1 + np.abs(w).max(axis=1))) < 1e-9)
    assert np.all(lam[~res.contact, 0] == 0.0), "a lost contact carries force"
    assert np.all(np.abs(w[res.contact, 0]) <= tol_w[res.contact]), "a kept contact separates"
    bounds = ref.bounds[1:]
    for j in range(ref.nl):
        st = res.wheel_state[:, j]
        lj, wj = lam[:, 1 + j], w[:, 1 + j]
        if not ref.present[1 + j]:
            assert np.all(st == "none") and np.all(lj == 0.0)
            continue
        stick = st == "stick"
        assert np.all(np.abs(wj[stick]) <= tol_w[stick]), "held wheel has lateral acceleration"
        if np.isfinite(bounds[j]):
            assert np.all(np.abs(lj) <= bounds[j] * (1 + 1e-9) + tol_lam)
            slide = ~stick
            assert np.all(np.isclose(np.abs(lj[slide]), bounds[j], rtol=1e-12))
            assert np.all(lj[slide] * wj[slide] <= 0), "friction does not oppose sliding"
            assert np.all((st[slide] == "slide+") == (lj[slide] > 0))
        else:
            assert np.all(stick)
    # rows' accelerations are A a + Adot v (reference rows)
    for i in range(0, n, 25):
        s = ref.system(q[i], tau[i], v[i], v_obj[i], f_obj[i])
        a = np.concatenate([res.qdd[i], res.a_obj[i]])
        close(res.w[i], s["A"] @ a + s["Adv"], what="w = A a + Adot v")
    assert np.all((res.sr >= 0) & (res.sr <= 1))
    lost = ~res.contact
    assert lost.any() and res.contact.any()
    assert np.all(res.sr[lost] == 0.0), "sr must be 0 when the contact is lost (eq. 30)"
    if scenario == "wheels":
        assert np.any(res.wheel_state == "stick") and np.any(res.sliding)


def test_sr_zero_when_contact_lost_with_external_wrench(models, rng):
    """ForwardResult documents sr = 0 when the contact is lost; an external wrench on the object
    must not turn the ratio of an interaction that does not exist into a positive number."""
    scene, sm, ref = models(3, "wheels")
    n = 60
    q, tau = random_q(rng, 3, n), random_tau(rng, 3, n)
    f_obj = rng.normal(size=(n, 3))
    res = sm.forward(q, tau, f_obj=f_obj)
    lost = ~res.contact
    assert lost.any()
    assert np.all(res.sr[lost] == 0.0)
    # the object still accelerates under the wrench alone
    close(res.a_obj[lost], f_obj[lost] / [ref.m_obj, ref.m_obj, ref.I_obj_rot], 1e-10, "a_obj")


@pytest.mark.parametrize("scenario", ("wheels", "ideal_wheels"))
def test_power_of_constraint_forces_at_rest(models, rng, scenario):
    """At rest the held rows do no work (``lam_H^T A_H a = 0``) and sliding wheels dissipate
    (``lam^T A a <= 0``)."""
    scene, sm, ref = models(3, scenario)
    n = 40
    q, tau = random_q(rng, 3, n), random_tau(rng, 3, n)
    res = sm.forward(q, tau)
    for i in range(n):
        s = ref.system(q[i], tau[i])
        a = np.concatenate([res.qdd[i], res.a_obj[i]])
        Aa = s["A"] @ a
        H = _held_and_fixed({"contact": res.contact[i], "wheel_state": res.wheel_state[i]},
                            ref.nc, ref.present)
        scale = np.abs(res.lam[i]).max() * max(1.0, np.abs(Aa).max())
        assert abs(res.lam[i][H] @ Aa[H]) <= 1e-9 * scale
        assert res.lam[i] @ Aa <= 1e-9 * scale


# ------------------------------------------------------------------------------------------
# 3. physical laws
# ------------------------------------------------------------------------------------------
def _jdot_v(sm, q, v, h=1e-4):
    """``Jdot_i v`` from the runtime's Jacobians by a fourth-order central difference."""
    Js = sm.link_jacobians(np.stack([q + 2 * h * v, q + h * v, q - h * v, q - 2 * h * v]))
    Jd = (-Js[0] + 8 * Js[1] - 8 * Js[2] + Js[3]) / (12 * h)
    return Jd @ v


def _cross(p, f):
    return p[..., 0] * f[..., 1] - p[..., 1] * f[..., 0]


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("joints", JOINTS)
def test_newton_euler_balance_of_the_whole_system(models, rng, joints, scenario):
    """The contact forces are internal: the rate of linear momentum of snake + object equals the
    external forces (wheel forces ``lam_i n_i`` and ``f_obj``); so does the rate of angular
    momentum about the origin (wheel forces act at the wheel points). Frictionless and
    ``f_obj = 0``: ``sum m_i a_com,i + kappa m a_obj,lin = 0``. Link COM accelerations are
    ``J_i qdd + Jdot_i qdot`` from the runtime's own Jacobians."""
    scene, sm, ref = models(joints, scenario, wheel_offset=0.03)
    n = 20
    q, tau = random_q(rng, joints, n), random_tau(rng, joints, n)
    v, v_obj, f_obj = random_motion(rng, joints, n)
    v[:5], v_obj[:5], f_obj[:5] = 0.0, 0.0, 0.0
    res = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    m = np.array(scene.robot.mass)
    inertia = np.array(scene.robot.inertia)
    m_o, I_o = ref.m_obj, ref.I_obj_rot
    for i in range(n):
        J = sm.link_jacobians(q[i])
        acc = J @ res.qdd[i] + _jdot_v(sm, q[i], v[i])  # (n_l, 3)
        poses = sm.link_poses(q[i])
        q_obj = sm.place_object(q[i])[0]
        phi = poses[:, 2]
        n_lat = np.stack([-np.sin(phi), np.cos(phi)], axis=1)
        f_wheel = res.lam[i][1:, None] * n_lat
        wheel_pts = poses[:, :2] + 0.03 * np.stack([np.cos(phi), np.sin(phi)], axis=1)
        # linear momentum
        lhs = (m[:, None] * acc[:, :2]).sum(0) + m_o * res.a_obj[i][:2]
        rhs = f_wheel.sum(0) + f_obj[i][:2]
        scale = max(1.0, np.abs(m[:, None] * acc[:, :2]).max(), m_o * np.abs(res.a_obj[i]).max())
        close(lhs, rhs, 1e-7 * scale, "linear momentum rate")
        # angular momentum about the origin: sum m p x a + I alpha (+ object)
        L_dot = (m * _cross(poses[:, :2], acc[:, :2])).sum() + (inertia * acc[:, 2]).sum()
        L_dot += m_o * _cross(q_obj[:2], res.a_obj[i][:2]) + I_o * res.a_obj[i][2]
        moment = _cross(wheel_pts, f_wheel).sum() + _cross(q_obj[:2], f_obj[i][:2]) + f_obj[i][2]
        close(L_dot, moment, 1e-7 * scale * (1 + np.abs(poses[:, :2]).max()),
              "angular momentum rate")
        if scenario == "frictionless" and i < 5:
            close(lhs, 0.0, 1e-9 * scale, "momentum rate of the isolated system")


@pytest.mark.parametrize("joints", JOINTS)
@pytest.mark.parametrize("kappa", (1.0, 10.0, 100.0))
def test_frictionless_slippage_ratio_bound(models, rng, joints, kappa):
    """Frictionless, object COM on the contact normal (the default placement), at rest: the
    object's acceleration is ``lam n / m_o`` and the snake's momentum rate is ``-lam n``, so by
    Cauchy-Schwarz ``|qdd|_M^2 >= lam^2 / (n_l m)`` and ``sr <= n_l / (n_l + kappa)``. Checked
    over 2000 random torques and configurations; the object does not rotate."""
    scene, sm, ref = models(joints, "frictionless", kappa=kappa)
    n = 2000
    q, tau = random_q(rng, joints, n), random_tau(rng, joints, n)
    res = sm.forward(q, tau)
    nl = joints + 1
    bound = nl / (nl + kappa)
    assert np.all(res.sr <= bound * (1 + 1e-12))
    assert res.sr.max() > 0.05 * bound  # the bound is not vacuous for these draws
    close(res.a_obj[:, 2], 0.0, 1e-10, "object angular acceleration")
    # norm_a_obj = lam^2 / m_o
    close(res.norm_a_obj, res.lam[:, 0] ** 2 / ref.m_obj, 1e-9, "norm_a_obj")


# ------------------------------------------------------------------------------------------
# 4. limits of the friction coefficient
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("joints", JOINTS)
def test_wheels_tend_to_frictionless_and_ideal(models, rng, joints):
    """mu = 1e-9: the wheels' forces vanish and the result is the frictionless one; mu = 1e6:
    the bound is never reached and the result is that of ideal wheels."""
    _, tiny, _ = models(joints, "wheels", mu=1e-9)
    _, huge, _ = models(joints, "wheels", mu=1e6)
    _, fric, _ = models(joints, "frictionless")
    _, ideal, _ = models(joints, "ideal_wheels")
    n = 100
    q, tau = random_q(rng, joints, n), random_tau(rng, joints, n)
    v, v_obj, f_obj = random_motion(rng, joints, n)
    a, b = tiny.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj), fric.forward(
        q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    for k in ("qdd", "a_obj", "norm_qdd", "norm_a_obj", "sr"):
        close(getattr(a, k), getattr(b, k), 1e-6, f"mu -> 0: {k}")
    close(a.lam[:, 0], b.lam[:, 0], 1e-6, "mu -> 0: contact force")
    assert np.all(np.abs(a.lam[:, 1:]) <= 1e-9 * 9.81 * (1 + 1e-9))
    assert np.array_equal(a.contact, b.contact)
    a, b = huge.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj), ideal.forward(
        q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    for k in ("qdd", "a_obj", "lam", "w", "norm_qdd", "norm_a_obj", "norm_lambda", "sr"):
        close(getattr(a, k), getattr(b, k), 1e-10, f"mu -> inf: {k}")
    assert np.array_equal(a.wheel_state, b.wheel_state)
    assert np.array_equal(a.contact, b.contact)


# ------------------------------------------------------------------------------------------
# 5. the linear maps (eqs. 14-29)
# ------------------------------------------------------------------------------------------
MAP_KEYS = ("qdd_from_tau", "qdd_from_f_obj", "a_obj_from_tau", "a_obj_from_f_obj")


def _scaled_scene(joints, scenario, s, kappa):
    robot = snakecg.Robot(joints=joints, mass=1.0 * s, inertia=0.002 * s)
    return snakecg.Scene(robot, scenario=scenario, kappa=kappa)


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("joints", JOINTS)
def test_maps_scale_with_mass(rng, joints, scenario):
    """Scaling every link's mass and inertia by s (kappa fixed, so the object scales too):
    the maps of eqs. 22-25 scale with 1/s, the forces (eq. 17) do not change, the forms of
    eqs. 28-29 scale with 1/s."""
    q = random_q(rng, joints, 4)
    base = snakecg.load(_scaled_scene(joints, scenario, 1.0, 100.0)).maps(q)
    for s in (0.25, 7.0):
        m = snakecg.load(_scaled_scene(joints, scenario, s, 100.0)).maps(q)
        for k in MAP_KEYS + ("xi_tau", "omega_tau", "lambda_form_tau"):
            close(m[k] * s, base[k], 1e-9, f"{k} x s")
        close(m["lam_from_tau"], base["lam_from_tau"], 1e-9, "lam_from_tau invariant")
        close(m["lam_from_f_obj"], base["lam_from_f_obj"], 1e-9, "lam_from_f_obj invariant")
        close(m["delassus"] * s, base["delassus"], 1e-9, "G_c x s")


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("joints", (2, 3))
def test_maps_equal_paper_equations_22_to_25_with_mass_factors(rng, joints, scenario):
    """The paper's printed forms, with ``M_s = m Mbar``, ``I_obj = kappa m Ibar`` and the
    unit-mass Delassus matrix ``Gbar_c = A diag(Mbar, kappa Ibar)^-1 A^T`` (the form in which
    eqs. 22-25 carry their 1/m, 1/(kappa m) and 1/kappa factors), for several m and kappa."""
    q = random_q(rng, joints, 3)
    for m_link, kappa in ((1.0, 100.0), (2.5, 1.0), (0.3, 1000.0), (1.0, 7.0)):
        scene = _scaled_scene(joints, scenario, m_link, kappa)
        sm, ref = snakecg.load(scene), Reference(scene)
        maps = sm.maps(q)
        P = ref.present
        for i in range(len(q)):
            s = ref.system(q[i], np.zeros(joints))
            ns = ref.ns
            Mbar = s["M"] / m_link
            Ibar = s["I_obj"] / (kappa * m_link)
            Js = -s["A"][P, :ns]
            GT = s["A"][P, ns:]
            G = GT.T
            B = s["B"]
            Mi, Ii = np.linalg.inv(Mbar), np.linalg.inv(Ibar)
            Gbar = Js @ Mi @ Js.T + GT @ Ii @ G / kappa
            Gbi = np.linalg.inv(Gbar)
            eq22 = Mi @ (np.eye(ns) - Js.T @ Gbi @ Js @ Mi) @ B / m_link
            eq23 = Mi @ Js.T @ Gbi @ GT @ Ii / (kappa * m_link)
            eq24 = Ii @ G @ Gbi @ Js @ Mi @ B / (kappa * m_link)
            eq25 = Ii @ (np.eye(3) - G @ Gbi @ GT @ Ii / kappa) / (kappa * m_link)
            eq29 = (B.T @ Mi @ Js.T @ Gbi @ GT @ Ii @ G @ Gbi @ Js @ Mi @ B) / (kappa * m_link)
            for key, exp in zip(MAP_KEYS + ("omega_tau",), (eq22, eq23, eq24, eq25, eq29)):
                close(maps[key][i], exp, 1e-8, f"{key} m={m_link} kappa={kappa}")


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("joints", JOINTS)
def test_all_held_forward_equals_closed_forms(models, rng, joints, scenario):
    """With every constraint kept (the torque's sign chosen so that the contact pushes; ideal
    or unreached wheel bounds), forward equals eqs. 17, 22-25 computed here from the reference's
    ``M``, ``J_s = -A_s``, ``G^T = A_o``: ``lam = G_c^-1 (J_s M^-1 B tau - G^T I_obj^-1 f_obj)``,
    and so does ``maps``; Xi (eq. 28) and Omega (eq. 29) are ``qdd^T M qdd`` and
    ``a^T I a`` as forms; the projector of eq. 14 is a left pseudo-inverse of ``A^T`` on the
    held rows (eq. 15), that of eq. 19 is idempotent and gives ``a = I^-1 P19 f`` (eq. 18)."""
    kw = {"mu": 1e6} if scenario == "wheels" else {}
    scene, sm, ref = models(joints, scenario, **kw)
    P = ref.present
    n = 6
    q = random_q(rng, joints, n)
    maps = sm.maps(q)
    for i in range(n):
        tau = random_tau(rng, joints, 1)[0]
        f_obj = rng.normal(size=3) * 0.1
        s = ref.system(q[i], tau)
        ns = ref.ns
        M, Iob, B = s["M"], s["I_obj"], s["B"]
        Js, GT = -s["A"][P, :ns], s["A"][P, ns:]
        Mi, Ii = np.linalg.inv(M), np.linalg.inv(Iob)
        Gc = Js @ Mi @ Js.T + GT @ Ii @ GT.T
        Gci = np.linalg.inv(Gc)
        lam_tau = Gci @ Js @ Mi @ B  # eq. 17 with A = [-J_s, G^T]
        lam_f = -Gci @ GT @ Ii
        if (lam_tau @ tau + lam_f @ f_obj)[0] < 0:
            tau = -tau
            f_obj = -f_obj
        lam = lam_tau @ tau + lam_f @ f_obj
        qdd_tau = Mi @ (np.eye(ns) - Js.T @ Gci @ Js @ Mi) @ B  # eq. 22
        qdd_f = Mi @ Js.T @ Gci @ GT @ Ii  # eq. 23
        a_tau = Ii @ GT.T @ Gci @ Js @ Mi @ B  # eq. 24
        a_f = Ii @ (np.eye(3) - GT.T @ Gci @ GT @ Ii)  # eq. 25
        res = sm.forward(q[i], tau, f_obj=f_obj)
        assert res.contact and all(st in ("stick", "none") for st in res.wheel_state)
        lam_full = np.zeros(ref.nc)
        lam_full[P] = lam
        close(res.lam, lam_full, what="eq. 17")
        close(res.qdd, qdd_tau @ tau + qdd_f @ f_obj, what="eqs. 20, 22, 23")
        close(res.a_obj, a_tau @ tau + a_f @ f_obj, what="eqs. 21, 24, 25")
        for key, exp in (("qdd_from_tau", qdd_tau), ("qdd_from_f_obj", qdd_f),
                         ("a_obj_from_tau", a_tau), ("a_obj_from_f_obj", a_f)):
            close(maps[key][i], exp, 1e-8, key)
        lt = np.zeros((ref.nc, joints))
        lt[P] = lam_tau
        close(maps["lam_from_tau"][i], lt, 1e-8, "lam_from_tau")
        # eq. 28: Xi = B^T (1 - Jhat^T)^T M^-1 (1 - Jhat^T) B, Jhat^T = J_s^T G_c^-1 J_s M^-1
        Jhat_T = Js.T @ Gci @ Js @ Mi
        xi = B.T @ (np.eye(ns) - Jhat_T).T @ Mi @ (np.eye(ns) - Jhat_T) @ B
        close(maps["xi_tau"][i], xi, 1e-8, "eq. 28")
        close(maps["omega_tau"][i], a_tau.T @ Iob @ a_tau, 1e-8, "eq. 29")
        close(maps["lambda_form_tau"][i], lam_tau.T @ Gc @ lam_tau, 1e-8, "lam^T G_c lam")
        close(maps["input_metric"][i], B.T @ Mi @ B, 1e-8, "eq. 31 metric")
        res0 = sm.forward(q[i], tau)
        close(res0.norm_qdd, tau @ maps["xi_tau"][i] @ tau, 1e-8, "norm_qdd = tau^T Xi tau")
        close(res0.norm_a_obj, tau @ maps["omega_tau"][i] @ tau, 1e-8, "norm_a_obj = Omega form")
        close(res0.norm_lambda, tau @ maps["lambda_form_tau"][i] @ tau, 1e-8, "lambda form")
        # projectors
        A = s["A"]
        P14, P19 = maps["projector_constrained"][i], maps["projector_orthogonal"][i]
        I_full = s["I"]
        close((P14 @ A.T)[np.ix_(P, P)], np.eye(P.sum()), 1e-9, "eq. 15: P14 A^T = 1")
        close(P14[P], Gci @ A[P] @ np.linalg.inv(I_full), 1e-8, "eq. 14")
        close(P14[~P], 0.0, 1e-12, "absent rows of eq. 14")
        close(P19 @ P19, P19, 1e-9, "eq. 19 idempotent")
        close(P19 @ A[P].T, 0.0, 1e-9, "eq. 19 annihilates the constraint forces")
        f = np.concatenate([B @ tau, f_obj])
        a18 = np.linalg.solve(I_full, P19 @ f)
        close(a18, np.concatenate([res.qdd, res.a_obj]), what="eq. 18")


@pytest.mark.parametrize("joints", (2, 5))
def test_maps_at_forward_active_set(models, rng, joints):
    """At rest, with the active set forward found (contact lost, wheels sliding), the affine maps
    reproduce forward: ``x = x_from_tau tau + x_offset`` for qdd, a_obj, lam and w (the offsets
    come from the sliding wheels' fixed forces, eq. 17)."""
    scene, sm, ref = models(joints, "wheels")
    n = 40
    q, tau = random_q(rng, joints, n), random_tau(rng, joints, n)
    res = sm.forward(q, tau)
    assert res.sliding.any() and (~res.contact).any()
    for i in range(n):
        maps = sm.maps(q[i], contact=bool(res.contact[i]), wheel_state=res.wheel_state[i])
        for key, got in (("qdd", res.qdd[i]), ("a_obj", res.a_obj[i]), ("lam", res.lam[i]),
                         ("w", res.w[i])):
            close(maps[f"{key}_from_tau"] @ tau[i] + maps[f"{key}_offset"], got, 1e-9,
                  f"{key} from maps, sample {i}")


# ------------------------------------------------------------------------------------------
# 6. dependent constraint rows
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("scenario", ("ideal_wheels", "wheels"))
@pytest.mark.parametrize("joints", (2, 3, 5))
def test_dependent_rows_are_flagged_and_least_norm(models, rng, joints, scenario):
    """Two wheels on the same point: the front wheel of link j (offset +c_j) and the rear wheel
    of link j + 1 (offset -c_{j+1}), with joint j straight, have identical rows. The runtime
    must flag ``singular``, stay finite, give the accelerations of the scene with one of the two
    wheels, and split the force evenly (the least-norm solution)."""
    j = 2  # joint between links 2 and 3 (the contact is on link 1)
    off = [0.0] * (joints + 1)
    off[j - 1], off[j] = 0.075, -0.075
    mu = 1e3 if scenario == "wheels" else 0.1
    scene, sm, ref = models(joints, scenario, wheel_offset=tuple(off), mu=mu)
    single = snakecg.load(scene.replace(wheel_links=tuple(i for i in scene.wheel_links
                                                          if i != j + 1)))
    n = 12
    q, tau = random_q(rng, joints, n), random_tau(rng, joints, n)
    q[:, 3 + j - 1] = 0.0  # joint j straight
    v, v_obj, f_obj = random_motion(rng, joints, n)
    v[:, 3 + j - 1] = 0.0  # ... and staying straight (rows stay identical along the motion)
    # the rows are identical (reference geometry)
    A = ref.rows(np.concatenate([q[0], ref.place_object(q[0])[0]]), ref.place_object(q[0])[1])
    close(A[j], A[j + 1], 1e-12, "identical wheel rows")
    res = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    one = single.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    for k in ("qdd", "lam", "a_obj", "w", "norm_qdd", "norm_a_obj", "norm_lambda", "sr"):
        assert np.all(np.isfinite(getattr(res, k))), k
    stuck = (res.wheel_state[:, j - 1] == "stick") & (res.wheel_state[:, j] == "stick")
    assert np.all(res.singular == stuck)
    assert stuck.sum() >= n // 2
    close(res.qdd, one.qdd, 1e-6, "qdd with one of the twin wheels")
    close(res.a_obj, one.a_obj, 1e-6, "a_obj")
    pair = res.lam[:, j] + res.lam[:, j + 1]
    close(pair[stuck], one.lam[stuck, j], 1e-6, "sum of the twin forces")
    close(res.lam[stuck, j], res.lam[stuck, j + 1], 1e-4, "least-norm split")
    # one sample at a time (the one-sample path leaves dependent rows to the general path)
    for i in range(3):
        one = sm.forward(q[i], tau[i], v=v[i], v_obj=v_obj[i], f_obj=f_obj[i])
        assert one.singular == res.singular[i]
        close(one.lam, res.lam[i], 1e-12, "single-sample singular lam")
    # maps at such a configuration: finite and flagged
    maps = sm.maps(q[:3])
    for k, val in maps.items():
        assert np.all(np.isfinite(val)), k
    assert np.all(maps["pivot_ratio"] <= 1e-10)
    assert "singular" in maps and np.all(maps["singular"])
    lt = maps["lam_from_tau"]
    close(lt[:, j], lt[:, j + 1], 1e-4, "maps: least-norm split")
    close(maps["qdd_from_tau"], single.maps(q[:3])["qdd_from_tau"], 1e-6, "maps: qdd")


def test_regular_scene_is_not_singular(models, rng):
    scene, sm, ref = models(5, "ideal_wheels")
    maps = sm.maps(random_q(rng, 5, 20))
    assert np.all(maps["pivot_ratio"] > 1e-10)
    assert not np.any(maps["singular"])


# ------------------------------------------------------------------------------------------
# 7. bad input
# ------------------------------------------------------------------------------------------
def test_forward_bad_input(models):
    scene, sm, ref = models(3, "wheels")
    q = np.zeros(6)
    cases = [
        (dict(tau=[1.0, 2.0]), r"tau has shape \(2,\), expected \(3,\) or \(N, 3\)"),
        (dict(tau=[[1.0, 2.0, 3.0, 4.0]]), r"tau has shape \(1, 4\)"),
        (dict(tau=[np.nan, 0, 0]), r"tau must be finite"),
        (dict(tau="abc"), r"tau must be numeric"),
        (dict(tau=[0, 0, 0], v=np.zeros(5)), r"v has shape \(5,\), expected \(6,\)"),
        (dict(tau=[0, 0, 0], f_obj=[0, np.inf, 0]), r"f_obj must be finite"),
        (dict(tau=[0, 0, 0], v_obj=[0, 0]), r"v_obj has shape"),
        (dict(tau=[0, 0, 0], q_obj=[0, 0, 0]), r"q_obj and rho"),
        (dict(tau=np.zeros((3, 3)), q=np.zeros((2, 6))), r"batch sizes differ"),
        (dict(tau=[0, 0, 0], q=np.zeros(5)), r"q has shape \(5,\), expected \(6,\)"),
        (dict(tau=[0, 0, 0], max_iter=0), r"max_iter"),
        (dict(tau=[0, 0, 0], max_iter=2.5), r"max_iter"),
    ]
    for kw, pattern in cases:
        kw = dict(kw)
        qq = kw.pop("q", q)
        tau = kw.pop("tau")
        with pytest.raises(snakecg.InputError, match=pattern):
            sm.forward(qq, tau, **kw)


def test_scene_bad_input():
    robot = snakecg.Robot(joints=3)
    for kw, pattern in ((dict(mu=-0.1), "mu must be >= 0"), (dict(kappa=-2.0), "kappa must be > 0"),
                        (dict(kappa=0.0), "kappa must be > 0"),
                        (dict(mu=float("nan")), "mu must be finite"),
                        (dict(contact_link=5), r"contact_link must be a link number 1\.\.4"),
                        (dict(contact_link=0), "contact_link must be a link number"),
                        (dict(wheel_links=(1,)), "cannot carry a wheel"),
                        (dict(scenario="ice"), "scenario must be one of")):
        with pytest.raises(snakecg.InputError, match=pattern):
            snakecg.Scene(robot, scenario=kw.pop("scenario", "wheels"), **kw)
    sm = snakecg.load(snakecg.Scene(robot, scenario="wheels"))
    for ws, pattern in ((["stick"] * 3, "wheel_state must list 4"),
                        ("abcd", "wheel_state must list 4"),
                        (["none", "slide", "stick", "stick"], r"wheel_state\[1\] must be 'stick'"),
                        (["none", "none", "stick", "stick"], r"wheel_state\[1\].*has a wheel"),
                        (["held", "stick", "stick", "stick"], r"wheel_state\[0\].*no wheel")):
        with pytest.raises(snakecg.InputError, match=pattern):
            sm.maps(np.zeros(6), wheel_state=ws)


# ------------------------------------------------------------------------------------------
# 8. the active-set solver against brute force
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("joints", (2, 3, 5))
def test_active_set_against_enumeration(models, rng, joints, monkeypatch):
    """Wheels scenario, random samples with sticking and sliding wheels and lost contacts, with
    and without motion: the active-set iteration and the forced enumeration fallback
    (``max_iter=1``) both equal the reference's brute-force enumeration; the reference's
    enumeration and BVLS agree with each other."""
    scene, sm, ref = models(joints, "wheels", mu=0.2)
    n = 30 if joints == 5 else 80
    q, tau = random_q(rng, joints, n), random_tau(rng, joints, n, 0.02, 3.0)
    v, v_obj, f_obj = random_motion(rng, joints, n)
    v[: n // 2], v_obj[: n // 2], f_obj[: n // 2] = 0.0, 0.0, 0.0
    refs = reference_all(ref, q, tau, v, v_obj, f_obj)
    states = np.array([r["states"] for r in refs])
    assert (states[:, 0] == "lost").sum() >= 3
    assert (states[:, 0] == "held").sum() >= 3
    assert np.isin(states[:, 1:], ("slide+", "slide-")).sum() >= 5
    assert (states[:, 2:] == "held").sum() >= 5
    # the reference's two solvers agree
    for i in range(0, n, 7):
        r = refs[i]
        lam_b = ref.solve_bvls(r["system"])
        close(lam_b, r["lam"], 1e-8, f"reference BVLS vs enumeration sample {i}")

    import snakecg.forward as forward_mod

    seen = []
    original = forward_mod.solve_active_set

    def spy(*args, **kwargs):
        out = original(*args, **kwargs)
        seen.append(out)
        return out

    monkeypatch.setattr(forward_mod, "solve_active_set", spy)
    res = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj)
    assert_matches_reference(res, refs, ref, "active set")
    if sm.core is not None:  # every sample answered by the compiled core's iteration
        assert not seen and np.all(res.raw[:, sm.columns.status] == 0)
    # the reference path's iteration on its own (the one used for the samples the core marks)
    seen.clear()
    res_ref = forward_mod.forward(snakecg.load(sm.scene, backend="casadi"), q, tau, v=v,
                                  v_obj=v_obj, f_obj=f_obj)
    assert_matches_reference(res_ref, refs, ref, "reference active set")
    assert seen[-1].enumerated == 0 and seen[-1].iterations >= 2
    res1 = forward_mod.forward(snakecg.load(sm.scene, backend="casadi"), q, tau, v=v,
                               v_obj=v_obj, f_obj=f_obj, max_iter=1)
    assert seen[-1].enumerated > n // 4, "max_iter=1 should leave samples to the enumeration"
    assert_matches_reference(res1, refs, ref, "enumeration (Python engine)")
    if sm.core is not None:  # the compiled engine enumerates them itself (engine/rows.c)
        seen.clear()
        res1 = sm.forward(q, tau, v=v, v_obj=v_obj, f_obj=f_obj, max_iter=1)
        assert not seen and np.count_nonzero(res1.raw[:, sm.columns.status]) > n // 4
        assert_matches_reference(res1, refs, ref, "enumeration (compiled engine)")


# ------------------------------------------------------------------------------------------
# 9. the CLI
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("scenario", SCENARIOS)
def test_cli_forward_json_matches_api(capsys, scenario):
    argv = ["forward", "--joints", "3", "--q", "0.1,0.2,0.3,-135deg,40deg,20deg",
            "--tau", "0.3,-0.1,0.2", "--scenario", scenario, "--kappa", "50", "--mu", "0.05",
            "--json"]
    assert cli.main(argv) == 0
    out = json.loads(capsys.readouterr().out)
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario, kappa=50.0, mu=0.05)
    q = [0.1, 0.2, 0.3, np.deg2rad(-135), np.deg2rad(40), np.deg2rad(20)]
    res = snakecg.load(scene).forward(q, [0.3, -0.1, 0.2])
    assert out["schema"] == "snakecg.forward/1" and out["scenario"] == scenario
    for k in ("qdd", "a_obj", "lam", "w", "norm_lambda", "norm_a_obj", "norm_qdd", "sr"):
        close(out[k], getattr(res, k), 1e-14, f"cli {k}")
    assert out["contact"] is bool(res.contact)
    assert out["wheel_state"] == list(res.wheel_state)
    assert out["singular"] is False
    close(out["q"], q, 1e-15, "q")


def test_cli_forward_bad_input(capsys):
    assert cli.main(["forward", "--joints", "3", "--q", "0,0,0,0,0,0", "--tau", "1,2"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "tau has shape (2,)" in err


# ------------------------------------------------------------------------------------------
# 6. decisions independent of the torque's scale; the finite range
# ------------------------------------------------------------------------------------------
SCALES = np.logspace(-12, 6, 10)


@pytest.mark.parametrize("scenario", ["frictionless", "ideal_wheels"])
@pytest.mark.parametrize("joints", [2, 3])
def test_homogeneous_scenarios_are_scale_free(models, rng, joints, scenario):
    """Frictionless and ideal wheels at rest are homogeneous in tau: forward(q, s tau) has
    the same contact state, the norms s^2 times those at s = 1 and the same sr (1e-9), for
    s from 1e-12 to 1e6, on both code paths; the state is the independent reference's."""
    from reference import rest_maps, solve_rest_batch

    _, model, ref = models(joints, scenario)
    q = random_q(rng, joints, 6)
    tau = rng.normal(0, 0.3, (6, joints))
    base = model.forward(q, tau)
    for i in range(len(q)):
        r = solve_rest_batch(ref, rest_maps(ref, q[i]), tau[i])
        assert bool(base.contact[i]) == bool(r["contact"][0])
    for s in SCALES:
        res = model.forward(q, s * tau)
        assert np.array_equal(res.contact, base.contact), s
        assert np.array_equal(res.wheel_state, base.wheel_state), s
        for m in ("norm_qdd", "norm_a_obj", "norm_lambda"):
            np.testing.assert_allclose(getattr(res, m) / s**2, getattr(base, m), rtol=1e-9,
                                       atol=1e-12 * np.abs(getattr(base, m)).max(), err_msg=m)
        np.testing.assert_allclose(res.sr, base.sr, rtol=1e-9, atol=1e-15)
        for i in (0, 3):
            one = model.forward(q[i], s * tau[i])
            assert bool(one.contact) == bool(base.contact[i])
            assert one.sr == pytest.approx(base.sr[i], rel=1e-9, abs=1e-15)


@pytest.mark.parametrize("joints", [2, 3])
def test_bounded_wheels_agree_with_an_exact_solve_at_every_scale(models, rng, joints):
    """Bounded wheels are not homogeneous (the bounds mu m g fix a force scale): at every
    scale of the torque the forces, hence the contact and wheel states, are those of the
    reference's brute-force solve with relative KKT tolerances."""
    from reference import rest_maps, solve_rest_batch

    _, model, ref = models(joints, "wheels")
    q = random_q(rng, joints, 4)
    tau = rng.normal(0, 1.0, (4, joints))
    for i in range(len(q)):
        maps = rest_maps(ref, q[i])
        taus = SCALES[:, None] * tau[i]
        r = solve_rest_batch(ref, maps, taus)
        res = model.forward(q[i], taus)
        assert np.array_equal(res.contact, r["contact"])
        scale = np.abs(r["lam"]).max(axis=1, keepdims=True)
        assert np.all(np.abs(res.lam - r["lam"]) <= 1e-7 * scale)
        u = model.bounds[1:]
        at_bound = np.isclose(np.abs(r["lam"][:, 1:]), u, rtol=1e-9, atol=0)
        sliding = np.isin(res.wheel_state, ("slide+", "slide-"))
        present = model.present[1:]
        # a sliding wheel is at its bound (sticking at exactly the bound is allowed)
        assert np.all(~sliding[:, present] | at_bound[:, present])


def test_tiny_pulling_torque_loses_the_contact(capsys):
    """A pulling torque of 5e-11 N m loses the contact exactly as one of 0.05 N m does (the
    contact tolerance used to be 1e-9 N absolute, which kept it with lam_c = -2e-10 N)."""
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2)))
    q = np.array([0.0, 0.0, 0.0, 0.4, -0.7])
    for tau in ([-5e-11, 0.0], [-0.05, 0.0]):
        for res in (model.forward(q, tau), model.forward(q[None], np.array([tau]))):
            assert not np.any(res.contact) and np.all(res.sr == 0.0)
            assert np.all(res.lam == 0.0)
    assert cli.main(["forward", "--joints", "2", "--q", "0,0,0,0.4,-0.7", "--tau=-5e-11,0",
                     "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["contact"] is False and out["sr"] == 0.0


def test_finite_range_of_the_inputs(capsys):
    """Finite inputs give finite outputs or an InputError: tau = 1e150 is answered (norms
    near 1e300), tau = 1e200 is refused, naming tau and the range, also by the CLI (one
    line, exit 2)."""
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2)))
    q = np.array([0.0, 0.0, 0.0, 0.4, -0.7])
    big = model.forward(q, [1e150, 0.0])
    small = model.forward(q, [1.0, 0.0])
    assert not big.singular and np.isfinite(big.norm_qdd)
    assert big.norm_qdd == pytest.approx(1e300 * small.norm_qdd, rel=1e-9)
    assert big.sr == pytest.approx(small.sr, rel=1e-9)
    with pytest.raises(snakecg.InputError, match=r"tau .*1e\+150"):
        model.forward(q, [1e200, 0.0])
    with pytest.raises(snakecg.InputError, match="f_obj"):
        model.forward(q, [1.0, 0.0], f_obj=[1e160, 0.0, 0.0])
    with pytest.raises(snakecg.InputError, match="v must"):
        model.forward(q, [1.0, 0.0], v=[0.0, 0.0, 0.0, 1e80, 0.0])
    assert cli.main(["forward", "--joints", "2", "--q", "0,0,0,0.4,-0.7", "--tau=1e200,0",
                     "--json"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "tau" in err
