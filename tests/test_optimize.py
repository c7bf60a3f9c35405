"""Optimal torque queries (issue #5): ``SceneModel.optimize`` and ``snakecg optimize``.

References, independent of the code under test:

* the maps of the all-held system built in this file from the dense numpy reference
  (``tests/reference.py``: complex-step kinematics, constraint rows from the geometry), and the
  generalized eigenproblem of eqs. (28)-(30) solved by ``scipy.linalg.eigh``;
* brute force: dense samples of the input region (random directions and magnitudes, plus
  perturbations of the answer at every scale), each evaluated by the exact forward solve and
  kept when it satisfies what the query claims (contact kept, wheels sticking unless allowed
  to slide, the task met);
* ``scipy.optimize.linprog`` (HiGHS) for the largest achievable push, and the effect of
  relaxing each limit on it (a limit named as binding must matter, the others must not).

Tolerances: the answers are exact up to the friction back-off (``FRICTION_MARGIN`` = 1e-7
relative) and solver precision, so "at least as good as every sample" is asserted to 1e-6
relative (1e-9 absolute on sr).
"""

from __future__ import annotations

import io
import json
import re
from contextlib import redirect_stdout
from pathlib import Path

import numpy as np
import pytest
from reference import Reference

import snakecg
from snakecg.optimize import CONTACT, ELLIPSOID, FRICTION_MARGIN, NORMAL, SCHEMA

SCENARIOS = ("frictionless", "wheels", "ideal_wheels")
DOCS = Path(__file__).resolve().parents[1] / "docs"


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(joints, scenario, **kw):
        key = (joints, scenario, tuple(sorted(kw.items())))
        if key not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario, **kw)
            cache[key] = (scene, snakecg.load(scene))
        return cache[key]

    return get


def random_q(rng, na):
    return np.concatenate([rng.normal(size=2), rng.uniform(-np.pi, np.pi, 1),
                           rng.uniform(-2.3, 2.3, na)])


# ------------------------------------------------------------------------------------------
# independent maps of the all-held system, from the dense reference
# ------------------------------------------------------------------------------------------
def reference_maps(scene, q):
    """``lam = L tau``, ``a_obj = Ao tau``, ``qdd = Q tau`` with every present row held, and
    ``Omega``, ``Xi`` (eqs. 28, 29), ``N = B^T M^-1 B`` (eq. 31), from tests/reference.py."""
    ref = Reference(scene)
    na, ns = ref.na, ref.ns
    sys0 = ref.system(q, np.zeros(na))
    I_inv = np.linalg.inv(sys0["I"])
    A, Gc = sys0["A"], sys0["Gc"]
    held = ref.present.copy()
    B = np.vstack([np.zeros((3, na)), np.eye(na)])
    F = np.vstack([B, np.zeros((3, na))])  # f = F tau (at rest, no wrench on the object)
    b = A @ I_inv @ F
    lam = np.zeros((ref.nc, na))
    lam[held] = -np.linalg.solve(Gc[np.ix_(held, held)], b[held])
    acc = I_inv @ (F + A.T @ lam)
    Q, Ao = acc[:ns], acc[ns:]
    M = sys0["M"]
    return dict(L=lam, Ao=Ao, Q=Q, M=M, I_obj=sys0["I_obj"], Omega=Ao.T @ sys0["I_obj"] @ Ao,
                Xi=Q.T @ M @ Q, N=B.T @ np.linalg.solve(M, B), bounds=ref.bounds,
                present=ref.present)


# ------------------------------------------------------------------------------------------
# closed form: the generalized eigenvector (only the ellipsoid, every constraint kept)
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("scenario", ("frictionless", "ideal_wheels"))
@pytest.mark.parametrize("joints", (2, 3))
def test_max_sr_is_the_generalized_eigenvector(models, rng, joints, scenario):
    from scipy.linalg import eigh

    scene, sm = models(joints, scenario)
    for _ in range(3):
        q = random_q(rng, joints)
        ref = reference_maps(scene, q)
        vals, vecs = eigh(ref["Omega"], ref["Omega"] + ref["Xi"])
        v = vecs[:, -1]
        v = v if ref["L"][0] @ v >= 0 else -v  # keep the contact
        v = v / np.sqrt(v @ ref["N"] @ v)  # on the ellipsoid's boundary
        res = sm.optimize(q, "max_sr")
        assert res.status == "optimal", res.reason
        np.testing.assert_allclose(res.objective_value, vals[-1], rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(res.tau, v, rtol=1e-6, atol=1e-9 * np.abs(v).max())
        assert res.binding == (ELLIPSOID,)
        assert res.analysis.contact and res.analysis.lam[0] > 0


@pytest.mark.parametrize("joints", (2, 3))
def test_max_sr_wheels_sticking_is_the_eigenvector_scaled_to_the_friction_bounds(
        models, rng, joints):
    """Bounded wheels that must stick: the same direction as ideal wheels (sr is homogeneous
    of degree 0), at the largest magnitude that keeps every wheel within mu m g."""
    from scipy.linalg import eigh

    scene, sm = models(joints, "wheels")
    for _ in range(3):
        q = random_q(rng, joints)
        ref = reference_maps(scene, q)
        vals, vecs = eigh(ref["Omega"], ref["Omega"] + ref["Xi"])
        v = vecs[:, -1] * np.sign(ref["L"][0] @ vecs[:, -1])
        res = sm.optimize(q, "max_sr")
        assert res.status == "optimal", res.reason
        np.testing.assert_allclose(res.objective_value, vals[-1], rtol=1e-9, atol=1e-12)
        cos = res.tau @ v / np.linalg.norm(res.tau) / np.linalg.norm(v)
        assert cos > 1 - 1e-10
        u = ref["bounds"][1:]
        load = np.abs(ref["L"][1:] @ res.tau)[ref["present"][1:]] / u[ref["present"][1:]]
        ell = res.tau @ ref["N"] @ res.tau
        # the magnitude is limited by a friction bound or by the ellipsoid, whichever first
        assert load.max() <= 1 - FRICTION_MARGIN * 0.5 and ell <= 1 + 1e-9
        assert np.isclose(load.max(), 1 - FRICTION_MARGIN, rtol=1e-9) or np.isclose(ell, 1.0)
        assert all(s in ("stick", "none") for s in res.analysis.wheel_state)


# ------------------------------------------------------------------------------------------
# brute force: the optimum is at least as good as a dense sample of feasible torques
# ------------------------------------------------------------------------------------------
def region_samples(rng, sm, q, n, tau_max=None, radius=None):
    """``n`` torques in the region: random directions, magnitudes biased towards 0 and the
    boundary (box: uniform in the box, half of them shrunk)."""
    d = rng.normal(size=(n, sm.n_joints))
    if tau_max is not None:
        T = rng.uniform(-1, 1, d.shape) * tau_max
    else:
        N = sm.maps(q)["input_metric"]
        d /= np.sqrt(np.einsum("ki,ij,kj->k", d, N, d))[:, None]
        T = d * radius * rng.uniform(0, 1, (n, 1)) ** (1 / sm.n_joints)
    T[: n // 2] *= rng.uniform(0, 1, (n // 2, 1)) ** 3
    return T


def perturbations(rng, sm, q, tau, n, tau_max=None, radius=None):
    """Perturbations of ``tau`` at scales 1e-7..1e-1 of its size, projected into the region."""
    P = tau + rng.normal(size=(n, len(tau))) * np.abs(tau).max() * np.logspace(-7, -1, n)[:, None]
    if tau_max is not None:
        return np.clip(P, -tau_max, tau_max)
    N = sm.maps(q)["input_metric"]
    e = np.sqrt(np.einsum("ki,ij,kj->k", P, N, P)) / radius
    return P / np.maximum(e, 1.0)[:, None]


def feasible(res, *, allow_slide=False):
    ok = np.asarray(res.contact, bool).copy()
    if not allow_slide:
        ok &= ~np.any(np.isin(res.wheel_state, ("slide+", "slide-")), axis=1)
    return ok


QUERIES = {
    "max_sr-ellipsoid": dict(objective="max_sr"),
    "max_sr-box": dict(objective="max_sr", tau_max=0.15),
    "least_slip_push-box": dict(objective="least_slip_push", a_min=0.004, tau_max=0.3),
    "least_slip_push-ellipsoid": dict(objective="least_slip_push", a_min=0.004, radius=1.5),
    "strongest_push-box": dict(objective="strongest_push", tau_max=[0.2, 0.3, 0.25]),
    "strongest_push-ellipsoid": dict(objective="strongest_push"),
}


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("query", list(QUERIES))
def test_optimum_beats_a_dense_sample(models, rng, scenario, query):
    joints = 3
    scene, sm = models(joints, scenario)
    kw = dict(QUERIES[query])
    objective = kw.pop("objective")
    tau_max = None if kw.get("tau_max") is None else np.broadcast_to(kw["tau_max"], (joints,))
    radius = kw.get("radius", None if tau_max is not None else 1.0)
    for _ in range(2):
        q = random_q(rng, joints)
        n_dir = sm.forward(q, np.full(joints, 0.01)).a_obj  # contact normal = a_obj direction
        d = n_dir[:2] / np.linalg.norm(n_dir[:2])
        if objective != "max_sr":
            kw["direction"] = d + 0.3 * np.array([-d[1], d[0]])  # oblique to the normal
        res = sm.optimize(q, objective, **kw)
        assert res.status == "optimal", res.reason
        T = np.vstack([region_samples(rng, sm, q, 12000, tau_max, radius),
                       perturbations(rng, sm, q, res.tau, 4000, tau_max, radius)])
        fw = sm.forward(np.repeat(q[None], len(T), axis=0), T)
        ok = feasible(fw)
        an = res.analysis
        # the answer satisfies every constraint it claims
        assert an.contact and not np.any(np.isin(an.wheel_state, ("slide+", "slide-")))
        if tau_max is not None:
            assert np.all(np.abs(res.tau) <= tau_max * (1 + 1e-12))
        if radius is not None:
            N = sm.maps(q)["input_metric"]
            assert res.tau @ N @ res.tau <= radius**2 * (1 + 1e-9)
        if objective == "max_sr":
            best = fw.sr[ok].max()
            assert res.objective_value >= best - 1e-9, (res.objective_value, best)
            np.testing.assert_allclose(res.objective_value, an.sr, rtol=1e-12)
        else:
            dd = np.append(kw["direction"], 0.0) / np.linalg.norm(kw["direction"])
            push = fw.a_obj @ dd
            if objective == "least_slip_push":
                assert an.a_obj @ dd >= kw["a_min"] * (1 - 1e-6)
                ok &= push >= kw["a_min"]
                assert ok.sum() > 100  # the sample does reach the task
                best = fw.norm_qdd[ok].min()
                assert res.objective_value <= best * (1 + 1e-6), (res.objective_value, best)
                np.testing.assert_allclose(res.objective_value, an.norm_qdd, rtol=1e-12)
            else:
                best = push[ok].max()
                assert res.objective_value >= best * (1 - 1e-6), (res.objective_value, best)
                np.testing.assert_allclose(res.objective_value, an.a_obj @ dd, rtol=1e-12)


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_random_robots_contacts_and_sides(rng, random_robot, scenario):
    """Per-link parameters over decades, any contact link, either side: the eigen-answer
    against scipy on the reference maps, and a push with the least slip against a sample."""
    from scipy.linalg import eigh

    for trial in range(2):
        joints = int(rng.integers(2, 4))  # models the suite compiles anyway
        robot = random_robot(joints)
        scene = snakecg.Scene(robot, scenario=scenario, mu=0.3, side=("left", "right")[trial],
                              contact_link=int(rng.integers(1, joints + 2)))
        sm = snakecg.load(scene)
        q = random_q(rng, joints)
        ref = reference_maps(scene, q)
        # Omega + Xi is only semidefinite when wheels brace the snake (torques that move
        # nothing): the Rayleigh quotient lives on its range
        w, V = eigh(ref["Omega"] + ref["Xi"])
        Vr = V[:, w > 1e-10 * w[-1]] / np.sqrt(w[w > 1e-10 * w[-1]])
        top = eigh(Vr.T @ ref["Omega"] @ Vr, eigvals_only=True)[-1]
        res = sm.optimize(q, "max_sr", tau_max=1.0)
        assert res.status == "optimal", res.reason
        np.testing.assert_allclose(res.objective_value, top, rtol=1e-7, atol=1e-12)
        strong = sm.optimize(q, "strongest_push", tau_max=1.0)
        assert strong.status == "optimal", strong.reason
        d = strong.analysis.a_obj[:2] / np.linalg.norm(strong.analysis.a_obj[:2])
        a_min = 0.5 * strong.objective_value
        push = sm.optimize(q, "least_slip_push", direction=d, a_min=a_min, tau_max=1.0)
        assert push.status == "optimal", push.reason
        T = np.vstack([region_samples(rng, sm, q, 8000, tau_max=np.ones(joints)),
                       perturbations(rng, sm, q, push.tau, 3000, tau_max=np.ones(joints)),
                       perturbations(rng, sm, q, strong.tau, 3000, tau_max=np.ones(joints))])
        fw = sm.forward(np.repeat(q[None], len(T), axis=0), T)
        ok = feasible(fw)
        along = fw.a_obj[:, :2] @ d
        assert strong.objective_value >= along[ok].max() * (1 - 1e-6)
        ok &= along >= a_min
        if ok.any():
            assert push.objective_value <= fw.norm_qdd[ok].min() * (1 + 1e-6)


def test_max_sr_with_sliding_wheels_beats_a_dense_sample(models, rng):
    """Wheels allowed to slide (piecewise-affine map, one convex problem per wheel state):
    never worse than keeping them stuck, never worse than any sampled torque, and sliding
    does win at some configurations (so the per-state path is exercised)."""
    joints, tau_max = 3, 0.15
    _, sm = models(joints, "wheels")
    sliding_winners = 0
    for trial in range(12):
        q = random_q(rng, joints)
        res = sm.optimize(q, "max_sr", tau_max=tau_max, allow_slide=True)
        stuck = sm.optimize(q, "max_sr", tau_max=tau_max)
        assert res.status == "optimal" and stuck.status == "optimal"
        assert res.objective_value >= stuck.objective_value - 1e-12, (res.solver, res.tau)
        assert res.analysis.contact
        if not np.any(np.isin(res.analysis.wheel_state, ("slide+", "slide-"))):
            if trial >= 3:
                continue  # the dense check below runs on sliding winners and 3 others
        else:
            sliding_winners += 1
        T = np.vstack([region_samples(rng, sm, q, 10000, tau_max=tau_max),
                       perturbations(rng, sm, q, res.tau, 4000, tau_max=tau_max)])
        fw = sm.forward(np.repeat(q[None], len(T), axis=0), T)
        best = fw.sr[feasible(fw, allow_slide=True)].max()
        assert res.objective_value >= best - 1e-9, (trial, res.objective_value, best)
    assert sliding_winners >= 1, "no configuration where a sliding wheel raises sr was found"


def test_max_sr_sliding_with_the_ellipsoid_binding(models):
    """A configuration (found by a seeded search) where the best wheel state has a wheel
    sliding and the ellipsoid cuts it, solved exactly through the ellipsoid's multiplier
    (the state's value function in t): against a dense polar grid of the 2-D ellipsoid and
    local perturbations."""
    _, sm = models(2, "wheels")
    q = np.array([0.0, 0.0, 0.0, -0.2992412597643468, 2.1812564889925747])
    radius = 3.0
    res = sm.optimize(q, "max_sr", radius=radius, allow_slide=True)
    assert res.status == "optimal", res.reason
    assert "the ellipsoid by its multiplier" in res.solver, res.solver
    assert "slide" in " ".join(res.analysis.wheel_state)
    assert ELLIPSOID in res.binding
    N = sm.maps(q)["input_metric"]
    L = np.linalg.cholesky(np.linalg.inv(N))
    th = np.linspace(0, 2 * np.pi, 720, endpoint=False)
    rad = radius * np.sqrt(np.linspace(0, 1, 200))
    U = np.stack([np.outer(rad, np.cos(th)).ravel(), np.outer(rad, np.sin(th)).ravel()], 1)
    rng = np.random.default_rng(1)
    T = np.vstack([U @ L.T, perturbations(rng, sm, q, res.tau, 20000, radius=radius)])
    fw = sm.forward(np.repeat(q[None], len(T), axis=0), T)
    best = fw.sr[fw.contact].max()
    assert res.objective_value >= best - 1e-9, (res.objective_value, best)
    assert res.tau @ N @ res.tau <= radius**2 * (1 + 1e-9)


# ------------------------------------------------------------------------------------------
# infeasible tasks: reported with the binding constraint named
# ------------------------------------------------------------------------------------------
def lp_max_contact_force(ref, tau_max, *, friction=True):
    """``max L_c tau`` s.t. the box and (``wheels``) ``|L_i tau| <= u_i``, by HiGHS."""
    from scipy.optimize import linprog

    L = ref["L"]
    rows, rhs = [], []
    if friction:
        for i in range(1, L.shape[0]):
            if ref["present"][i] and np.isfinite(ref["bounds"][i]):
                rows += [L[i], -L[i]]
                rhs += [ref["bounds"][i]] * 2
    out = linprog(-L[0], A_ub=np.array(rows) if rows else None,
                  b_ub=np.array(rhs) if rhs else None,
                  bounds=list(zip(-tau_max, tau_max)), method="highs")
    assert out.status == 0
    return -out.fun


@pytest.mark.parametrize("scenario", ("frictionless", "ideal_wheels"))
def test_infeasible_push_names_the_torque_limits_that_bind(models, rng, scenario):
    joints = 3
    scene, sm = models(joints, scenario)
    q = random_q(rng, joints)
    ref = reference_maps(scene, q)
    tau_max = np.array([0.05, 0.3, 0.2])
    a_dir = ref["Ao"] @ ref["L"][0] / (ref["L"][0] @ ref["L"][0])  # a_obj = a_dir lam_c
    d = a_dir[:2] / np.linalg.norm(a_dir[:2])
    lam_max = lp_max_contact_force(ref, tau_max)
    reachable = lam_max * np.linalg.norm(a_dir[:2])
    res = sm.optimize(q, "least_slip_push", direction=d, a_min=2 * reachable, tau_max=tau_max)
    assert res.status == "infeasible"
    assert "at most" in res.reason and "binding: torque limit on joint" in res.reason
    # the returned torque is the strongest push the limits allow
    np.testing.assert_allclose(res.analysis.a_obj[:2] @ d, reachable, rtol=1e-6)
    named = {int(m) for m in re.findall(r"torque limit on joint (\d)", " ".join(res.binding))}
    assert named and set(res.binding) == {f"torque limit on joint {j}" for j in named}
    for j in range(1, joints + 1):  # a named limit matters, the others do not
        relaxed = tau_max.copy()
        relaxed[j - 1] *= 1.5
        gain = lp_max_contact_force(ref, relaxed) / lam_max - 1
        assert (gain > 1e-6) == (j in named), (j, gain, res.binding)


def test_infeasible_push_names_the_friction_bound_that_binds(models, rng):
    joints = 3
    scene, sm = models(joints, "wheels", mu=0.02)
    q = random_q(rng, joints)
    ref = reference_maps(scene, q)
    tau_max = np.full(joints, 5.0)  # generous: the wheels' friction is what limits
    a_dir = ref["Ao"] @ ref["L"][0] / (ref["L"][0] @ ref["L"][0])
    d = a_dir[:2] / np.linalg.norm(a_dir[:2])
    lam_max = lp_max_contact_force(ref, tau_max)
    res = sm.optimize(q, "least_slip_push", direction=d,
                      a_min=1.5 * lam_max * np.linalg.norm(a_dir[:2]), tau_max=tau_max)
    assert res.status == "infeasible"
    wheels = {int(m) for m in re.findall(r"friction bound of the wheel on link (\d)", res.reason)}
    assert wheels, res.reason
    assert not any("torque limit" in b for b in res.binding)
    for i in range(2, joints + 2):  # relax one wheel's bound at a time
        bounds = ref["bounds"].copy()
        bounds[i] *= 2
        gain = lp_max_contact_force(dict(ref, bounds=bounds), tau_max) / lam_max - 1
        assert (gain > 1e-6) == (i in wheels), (i, gain, res.binding)


def test_infeasible_push_names_the_ellipsoid(models, rng):
    _, sm = models(3, "frictionless")
    q = random_q(rng, 3)
    N = sm.maps(q)["input_metric"]
    res0 = sm.optimize(q, "strongest_push", radius=0.5)
    # closed form of the strongest push on the ellipsoid alone: tau ~ N^-1 l
    assert res0.status == "optimal" and res0.binding == (ELLIPSOID,)
    np.testing.assert_allclose(res0.tau @ N @ res0.tau, 0.25, rtol=1e-9)
    res = sm.optimize(q, "least_slip_push", direction=res0.analysis.a_obj[:2],
                      a_min=1.01 * np.linalg.norm(res0.analysis.a_obj[:2]), radius=0.5)
    assert res.status == "infeasible" and ELLIPSOID in res.binding, res.reason
    np.testing.assert_allclose(res.tau, res0.tau, rtol=1e-6)


def test_structurally_impossible_accelerations(models, rng):
    """A frictionless point contact pushes along its normal only (assumption 2): an object
    acceleration off the normal, or against it, is infeasible whatever the limits."""
    _, sm = models(3, "wheels")
    q = random_q(rng, 3)
    n = sm.forward(q, np.full(3, 0.01)).a_obj
    n = n / np.linalg.norm(n)
    side = np.array([-n[1], n[0], 0.0])
    res = sm.optimize(q, "least_slip_push", a_obj=0.001 * (n + side), tau_max=10.0)
    assert res.status == "infeasible" and res.binding == (NORMAL,), res.reason
    assert "contact normal" in res.reason
    res = sm.optimize(q, "least_slip_push", a_obj=-0.001 * n, tau_max=10.0)
    assert res.status == "infeasible" and res.binding == (CONTACT,), res.reason
    res = sm.optimize(q, "strongest_push", direction=-n[:2], tau_max=10.0)
    assert res.status == "infeasible" and CONTACT in res.reason
    np.testing.assert_array_equal(res.tau, 0.0)


def test_least_slip_push_full_acceleration(models, rng):
    """``a_obj`` given in full: met exactly; among the torques that meet it (the optimum plus
    any change that keeps the contact force), none moves the snake less."""
    joints = 3
    _, sm = models(joints, "ideal_wheels")
    q = random_q(rng, joints)
    strongest = sm.optimize(q, "strongest_push", tau_max=0.3)
    target = 0.4 * strongest.analysis.a_obj
    res = sm.optimize(q, "least_slip_push", a_obj=target, tau_max=0.3)
    assert res.status == "optimal", res.reason
    np.testing.assert_allclose(res.analysis.a_obj, target, rtol=1e-7, atol=1e-12)
    ell = sm.maps(q)["lam_from_tau"][0]
    basis = np.linalg.svd(ell[None, :])[2][1:]  # directions that keep lam_c (and a_obj)
    P = res.tau + (rng.normal(size=(5000, joints - 1)) * np.logspace(-6, -1, 5000)[:, None]
                   * np.abs(res.tau).max()) @ basis
    P = P[np.all(np.abs(P) <= 0.3, axis=1)]
    fw = sm.forward(np.repeat(q[None], len(P), axis=0), P)
    assert np.all(fw.norm_qdd >= res.objective_value * (1 - 1e-6))


# ------------------------------------------------------------------------------------------
# API behaviour
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("objective, kw", [
    ("max_sr", {}),
    ("least_slip_push", dict(direction=[0, 1], a_min=0.002, tau_max=0.3)),
    ("strongest_push", dict(tau_max=0.3)),
])
def test_batched_equals_single(models, rng, objective, kw):
    _, sm = models(3, "wheels")
    Q = np.array([random_q(rng, 3) for _ in range(4)])
    batch = sm.optimize(Q, objective, **kw)
    assert batch.tau.shape == (4, 3) and batch.analysis.sr.shape == (4,)
    for k in range(4):
        one = sm.optimize(Q[k], objective, **kw)
        assert one.status == batch.status[k] and one.reason == batch.reason[k]
        np.testing.assert_allclose(one.tau, batch.tau[k], rtol=1e-7, atol=1e-12)
        np.testing.assert_allclose(one.objective_value, batch.objective_value[k], rtol=1e-7)
        assert one.binding == batch.binding[k]


def test_repeated_queries_give_the_same_answer(models, rng):
    """Warm starts change the path, not the answer."""
    _, sm = models(3, "wheels")
    qs = [random_q(rng, 3) for _ in range(3)]
    first = [sm.optimize(q, "least_slip_push", direction=[0, 1], a_min=0.001, tau_max=0.3)
             for q in qs]
    again = [sm.optimize(q, "least_slip_push", direction=[0, 1], a_min=0.001, tau_max=0.3)
             for q in reversed(qs)][::-1]
    for a, b in zip(first, again):
        assert a.status == b.status
        np.testing.assert_allclose(a.objective_value, b.objective_value, rtol=1e-8)


@pytest.mark.parametrize("kwargs, match", [
    (dict(objective="max_slippage"), "objective must be one of"),
    (dict(tau_max=-1.0), "tau_max must be positive"),
    (dict(tau_max=[0.1, 0.2]), r"tau_max has shape \(2,\)"),
    (dict(radius=0.0), "radius must be a positive number"),
    (dict(direction=[0, 1]), "direction .* not apply to objective 'max_sr'"),
    (dict(objective="least_slip_push", direction=[0, 1]), "least_slip_push needs a task"),
    (dict(objective="least_slip_push", a_obj=[0, 1]), r"a_obj has shape \(2,\)"),
    (dict(objective="least_slip_push", a_obj=[0, 1, 0], a_min=1.0), "either a_obj"),
    (dict(objective="strongest_push", direction=[0, 0]), "direction must be non-zero"),
    (dict(objective="least_slip_push", direction=[0, 1], a_min=-1), "a_min must be"),
    (dict(allow_slide=[1]), "allow_slide: link 1 has no wheel"),
    (dict(allow_slide="yes"), "allow_slide must be True, False or a list"),
    (dict(objective="strongest_push", allow_slide=True), "allow_slide applies to objective"),
    (dict(objective="strongest_push", direction=[np.nan, 1]), "direction must be finite"),
])
def test_bad_input_raises_input_error(models, kwargs, match):
    _, sm = models(3, "wheels")
    kwargs = dict(kwargs)
    objective = kwargs.pop("objective", "max_sr")
    with pytest.raises(snakecg.InputError, match=match):
        sm.optimize(np.zeros(6), objective, **kwargs)
    with pytest.raises(snakecg.InputError, match="q has shape"):
        sm.optimize(np.zeros(5), "max_sr")


def test_allow_slide_list_and_frictionless(models, rng):
    _, sm = models(3, "wheels")
    q = random_q(rng, 3)
    some = sm.optimize(q, "max_sr", allow_slide=[2, 4], tau_max=0.15)
    assert some.status == "optimal"
    assert some.analysis.wheel_state[2] in ("stick", "none")  # link 3 was not allowed
    _, fr = models(3, "frictionless")
    assert fr.optimize(q, "max_sr", allow_slide=True).status == "optimal"  # nothing can slide


# ------------------------------------------------------------------------------------------
# the command line and the JSON schema
# ------------------------------------------------------------------------------------------
def _run(argv):
    from snakecg.cli import main

    buf = io.StringIO()
    with redirect_stdout(buf):
        status = main(argv)
    return status, buf.getvalue()


def _documented_fields() -> set[str]:
    text = (DOCS / "how-to" / "optimize.md").read_text(encoding="utf-8")
    start = text.index("## JSON output")
    rows = [r for r in text[start:].splitlines() if r.startswith("| `")]
    return {re.match(r"\| `([^`]+)`", r).group(1) for r in rows}


def test_cli_json_is_the_documented_schema(capsys):
    q = "0,0,0,30deg,-45deg,60deg"
    status, out = _run(["optimize", "least-slip-push", "--joints", "3", "--q", q,
                        "--scenario", "wheels", "--direction", "0,1", "--a-min", "0.002",
                        "--tau-max", "0.3", "--json"])
    assert status == 0
    data = json.loads(out)
    assert data["schema"] == SCHEMA and data["status"] == "optimal"
    assert data["objective"] == "least_slip_push" and len(data["tau"]) == 3
    assert data["limits"] == {"tau_max": [0.3, 0.3, 0.3], "tau_max_from": "argument",
                              "radius": None}
    assert data["off_direction_deg"] == pytest.approx(0.0, abs=1e-6) and data["note"] == ""
    fields = _documented_fields()
    got = set(data) | set(data["analysis"]) | set(data["certificate"])
    assert got == fields, got ^ fields
    assert data["certificate"]["ok"] is True
    # the same numbers as the Python API
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels")
    q_rad = np.array([0, 0, 0, np.deg2rad(30), np.deg2rad(-45), np.deg2rad(60)])
    api = snakecg.load(scene).optimize(q_rad, "least_slip_push", direction=[0, 1],
                                       a_min=0.002, tau_max=0.3)
    np.testing.assert_allclose(data["tau"], api.tau, rtol=1e-7, atol=1e-12)


def test_cli_infeasible_exits_1_with_the_reason(capsys):
    status, out = _run(["optimize", "least-slip-push", "--joints", "2", "--q",
                        "0,0,0,-135deg,-135deg", "--scenario", "wheels", "--direction", "0,1",
                        "--a-min", "5", "--tau-max", "0.3", "--json"])
    assert status == 1
    data = json.loads(out)
    assert data["status"] == "infeasible" and data["binding"] and "binding:" in data["reason"]
    status, out = _run(["optimize", "max-sr", "--joints", "2", "--q", "0,0,0,-135deg,-135deg",
                        "--scenario", "wheels", "--allow-slide"])
    assert status == 0 and out.startswith("max_sr: optimal")


def test_cli_input_errors_are_one_line(capsys):
    from snakecg.cli import main

    for argv, text in [
        (["optimize", "max-sr", "--joints", "2", "--q", "0,0,0"], "q has shape"),
        (["optimize", "least-slip-push", "--joints", "2", "--q", "0,0,0,0,0"], "needs a task"),
        (["optimize", "max-sr", "--joints", "2", "--q", "0,0,0,1,1", "--allow-slide", "2"],
         "allow_slide: link 2 has no wheel"),
        (["optimize", "max-sr", "--joints", "2", "--q", "0,0,0,1,1", "--tau-max", "0.1,0.1,1"],
         "tau_max has shape"),
    ]:
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert len(err.splitlines()) == 1 and text in err, err


@pytest.mark.parametrize("objective", ["least_slip_push", "strongest_push"])
def test_a_push_off_the_contact_normal_says_where_the_object_goes(objective):
    """A frictionless point contact pushes along its normal n = (-sin phi_1, cos phi_1) only
    (assumptions 2, 6), so a push asked 30 degrees off n is optimal for ``d . a_obj`` but
    moves the object along n: the result says so, 30 degrees off."""
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="frictionless")
    model = snakecg.load(scene)
    theta = 0.4
    q = np.array([0.1, -0.2, theta, 0.5, -0.7, 0.9])
    n = np.array([-np.sin(theta), np.cos(theta)])
    off = np.radians(30)
    d = np.array([[np.cos(off), -np.sin(off)], [np.sin(off), np.cos(off)]]) @ n
    task = {"a_min": 1e-4} if objective == "least_slip_push" else {}
    res = model.optimize(q, objective, direction=d, **task)
    assert res.status == "optimal", res.reason
    a = res.analysis.a_obj[:2]
    assert abs(a[0] * n[1] - a[1] * n[0]) <= 1e-12 * np.linalg.norm(a)  # along the normal
    assert res.off_direction_deg == pytest.approx(30.0, abs=1e-9)
    assert "30 deg off the requested direction" in res.note
    data = res.to_dict()
    assert data["off_direction_deg"] == pytest.approx(30.0) and data["note"] == res.note
    along = model.optimize(q, objective, direction=n, **task)
    assert along.off_direction_deg == pytest.approx(0.0, abs=1e-6) and along.note == ""
    assert model.optimize(q, "max_sr").off_direction_deg is None


def test_tau_max_of_the_wrong_type_is_named_as_such():
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=2)))
    q = np.zeros(5)
    with pytest.raises(snakecg.InputError, match=r"tau_max must be a positive number \(N m\), "
                       r"2 of them \(one per joint\), 'robot' \(the robot's effort limits\) "
                       r"or None \(no torque box\); got '0.2' of type str"):
        model.optimize(q, "max_sr", tau_max="0.2")
    with pytest.raises(snakecg.InputError, match=r"tau_max must be .* got \['0.2', 1\] "
                       r"\(not numbers\)"):
        model.optimize(q, "max_sr", tau_max=["0.2", 1])


def test_cli_takes_either_spelling_and_prints_one(capsys):
    q = "0,0,0,30deg,-45deg"
    for spelling in ("max-sr", "max_sr"):
        status, out = _run(["optimize", spelling, "--joints", "2", "--q", q, "--json"])
        assert status == 0 and json.loads(out)["objective"] == "max_sr"
    status, out = _run(["optimize", "strongest_push", "--joints", "2", "--q", q,
                        "--scenario", "ideal-wheels"])
    assert status == 0 and out.startswith("strongest_push: optimal")
