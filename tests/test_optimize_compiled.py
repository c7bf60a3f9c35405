"""The optimal-torque queries in C (``snakecg/engine/qp.c``, ``maps.c``, ``optimal.c``,
``wheel_states.c``, ``linalg.h``) against independent references.

References, none of them sharing code with what they check:

* cvxpy with the Clarabel interior-point solver for the QPs, LPs, QCQPs and SOCPs, each posed
  here from its data (random problems) or from the model's generated ``interaction_maps``
  (``SceneModel.maps``, a separate generated function from the ``contact_system`` the C
  builds its maps from); HiGHS (``scipy.optimize.linprog``) for LPs with ties;
* ``scipy.linalg.eigh`` for the symmetric eigensolver;
* the exact enumeration of wheel states for ``max_sr`` with sliding wheels: each state's
  Charnes-Cooper problem solved by Clarabel on that state's generated maps, confirmed by the
  exact forward solve;
* the call itself for the rule "one home": a batch of one, a batch, any shape of ``q`` and any
  split over threads give the same bits.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import eigh
from scipy.optimize import linprog

import snakecg
from snakecg.optimize import FRICTION_MARGIN, TOLERANCE

cp = pytest.importorskip("cvxpy")

SCENARIOS = ("frictionless", "wheels", "ideal_wheels")


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(joints, scenario="wheels"):
        if (joints, scenario) not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario)
            cache[joints, scenario] = snakecg.load(scene)
        return cache[joints, scenario]

    return get


@pytest.fixture(scope="module")
def kernel(models):
    return models(3).core.optimal


def clarabel(problem):
    """``problem`` solved by Clarabel with tight tolerances; its status "optimal" also when
    Clarabel calls it "optimal_inaccurate" (it stopped short of these tolerances, still far
    within the comparisons' own)."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        for tol in (1e-11, 1e-10):  # (at 1e-11 its iteration limit is sometimes reached)
            problem.solve(solver="CLARABEL", tol_gap_abs=tol, tol_gap_rel=tol, tol_feas=tol,
                          max_iter=500)
            if problem.status != "user_limit":
                break
    problem.verdict = {"optimal_inaccurate": "optimal"}.get(problem.status, problem.status)
    return problem


def random_q(rng, na, n=None):
    shape = (n,) if n else ()
    return np.concatenate([rng.normal(size=shape + (2,)), rng.uniform(-np.pi, np.pi, shape + (1,)),
                           rng.uniform(-2.3, 2.3, shape + (na,))], axis=-1)


# ------------------------------------------------------------------------------------------
# the QP block
# ------------------------------------------------------------------------------------------
def _rows(x, A, lo, hi):
    cons = []
    for r in range(len(lo)):
        if lo[r] == hi[r]:
            cons.append(A[r] @ x == lo[r])
            continue
        if np.isfinite(lo[r]):
            cons.append(A[r] @ x >= lo[r])
        if np.isfinite(hi[r]):
            cons.append(A[r] @ x <= hi[r])
    return cons


def _random_qp(rng, degenerate):
    """A strictly convex QP, feasible around a random point xf; degenerate: duplicated,
    dependent and scaled rows, a zero row that holds, and n rows tight at xf."""
    n = int(rng.integers(1, 8))
    B = rng.normal(size=(n, n))
    H = B @ B.T + 0.05 * np.eye(n)
    g = rng.normal(size=n) * 3
    m = int(rng.integers(1, 10))
    A = rng.normal(size=(m, n))
    xf = rng.normal(size=n)
    Ax = A @ xf
    kind = rng.integers(0, 4, m)  # two-sided, lower, upper, equality
    lo = np.where(kind == 2, -np.inf, Ax - rng.uniform(0, 1, m))
    hi = np.where(kind == 1, np.inf, Ax + rng.uniform(0, 1, m))
    eq = np.flatnonzero(kind == 3)[: n - 1]
    lo[eq] = hi[eq] = Ax[eq]
    if degenerate:
        r = int(rng.integers(m))
        s = 10.0 ** rng.choice([-3, 3])
        extra = [(A[r], lo[r], hi[r]), (s * A[r], s * lo[r], s * hi[r]),
                 (np.zeros(n), -1.0, 1.0)]
        if m >= 2:
            extra.append((A[0] + A[1], (A[0] + A[1]) @ xf, np.inf))
        for _ in range(n):
            c = rng.normal(size=n)
            extra.append((c, c @ xf, np.inf))
        A = np.vstack([A] + [e[0] for e in extra])
        lo = np.concatenate([lo, [e[1] for e in extra]])
        hi = np.concatenate([hi, [e[2] for e in extra]])
    return H, g, A, lo, hi


@pytest.mark.parametrize("degenerate", [False, True])
def test_dual_active_set_against_clarabel(kernel, rng, degenerate):
    for _ in range(60):
        H, g, A, lo, hi = _random_qp(rng, degenerate)
        st, x, lam, info = kernel.qp(H, g, A, lo, hi)
        assert st == 0
        ref = cp.Variable(g.size)
        pr = clarabel(cp.Problem(cp.Minimize(0.5 * cp.quad_form(ref, H) + g @ ref),
                                 _rows(ref, A, lo, hi)))
        assert pr.verdict == "optimal"
        scale = 1.0 + np.abs(ref.value).max()
        assert np.abs(x - ref.value).max() <= 1e-7 * scale
        Ax = A @ x
        rs = np.abs(A) @ np.abs(x) + 1.0
        assert np.all(Ax >= lo - 1e-12 * rs) and np.all(Ax <= hi + 1e-12 * rs)
        # KKT with the returned multipliers: H x + g = A^T lam, signs on their sides,
        # complementarity
        assert np.linalg.norm(H @ x + g - A.T @ lam) <= 1e-9 * (1 + np.abs(lam) @ np.abs(A).sum(1))
        ineq = lo != hi
        at_lo, at_hi = ineq & (lam > 0), ineq & (lam < 0)
        assert np.all(lam[at_lo] * (Ax - lo)[at_lo] <= 1e-9 * rs[at_lo])
        assert np.all(-lam[at_hi] * (hi - Ax)[at_hi] <= 1e-9 * rs[at_hi])


def test_dual_active_set_reports_infeasibility(kernel, rng):
    for _ in range(30):
        n = int(rng.integers(1, 6))
        A = rng.normal(size=(4, n))
        c = rng.normal(size=n)
        A = np.vstack([A, c, c])  # c . x >= 1 and c . x <= -1
        lo = np.concatenate([-np.ones(4), [1.0, -np.inf]])
        hi = np.concatenate([np.ones(4), [np.inf, -1.0]])
        st, *_ = kernel.qp(np.eye(n), rng.normal(size=n), A, lo, hi)
        assert st == 1


def test_lp_through_the_qp_against_highs(kernel, rng):
    """LPs as the push solves pose them: scaled variables in the unit box, rows and objective
    normalised, curvature 1e-9; ties (the objective along a row) included."""
    from snakecg.optimize.result import LP_REG

    for t in range(80):
        n = int(rng.integers(1, 6))
        m = int(rng.integers(1, 6))
        A = np.vstack([rng.normal(size=(m, n)), np.eye(n)])
        lo = np.concatenate([-rng.uniform(0.2, 1.0, m), -np.ones(n)])
        hi = np.concatenate([rng.uniform(0.2, 1.0, m), np.ones(n)])
        g = -A[0] if t % 3 == 0 else rng.normal(size=n)
        rn = np.abs(A).max(axis=1)
        A, lo, hi, g = A / rn[:, None], lo / rn, hi / rn, g / np.abs(g).max()
        st, x, _, _ = kernel.qp(LP_REG * np.eye(n), g, A, lo, hi)
        assert st == 0
        ref = linprog(g, A_ub=np.vstack([A, -A]), b_ub=np.concatenate([hi, -lo]),
                      bounds=[(None, None)] * n, method="highs")
        assert ref.status == 0
        assert g @ x <= ref.fun + 1e-9 * (1 + abs(ref.fun))
        assert np.all(A @ x >= lo - 1e-12) and np.all(A @ x <= hi + 1e-12)


@pytest.mark.parametrize("linear", [False, True])
def test_ellipsoid_multiplier_against_clarabel(kernel, rng, linear):
    """The QCQP with the ellipsoid active, and rows that miss the ellipsoid (reported as
    such); the root of the secular equation to machine precision."""
    empty = solved = 0
    for t in range(60):
        n = int(rng.integers(1, 7))
        m = int(rng.integers(0, 7)) if t % 4 else 0
        B = rng.normal(size=(n, n))
        H = np.zeros((n, n)) if linear else B @ B.T
        g = rng.normal(size=n)
        C = rng.normal(size=(n, n))
        N = C @ C.T + 0.1 * np.eye(n)
        A = rng.normal(size=(m, n))
        xf = 0.2 * rng.normal(size=n)
        lo = A @ xf - rng.uniform(0, 1, m)
        hi = np.where(rng.uniform(size=m) < 0.5, np.inf, A @ xf + rng.uniform(0, 1, m))
        rho2 = float(xf @ N @ xf) * rng.uniform(0.2, 3.0)
        if t % 4 == 0:  # a row whose points all lie outside the ellipsoid
            a = rng.normal(size=n)
            A = a[None, :]
            lo = np.array([2.0 * np.sqrt(rho2 * (a @ np.linalg.solve(N, a)))])
            hi = np.array([np.inf])
        # the problem without the ellipsoid (an LP with its tiny curvature) must end outside
        st0, x0, _, _ = kernel.qp(H + 1e-9 * np.eye(n), g, A, lo, hi)
        if st0 != 0 or x0 @ N @ x0 <= rho2:
            continue
        st, x, lam, info = kernel.qp(H, g, A, lo, hi, N=N, rho2=rho2,
                                     mu0=np.sqrt(g @ np.linalg.solve(N, g) / rho2))
        ref = cp.Variable(n)
        pr = clarabel(cp.Problem(cp.Minimize(0.5 * cp.quad_form(ref, cp.psd_wrap(H)) + g @ ref),
                                 _rows(ref, A, lo, hi) + [cp.quad_form(ref, N) <= rho2]))
        if st == 4:
            assert pr.verdict == "infeasible"
            empty += 1
            continue
        assert st == 0 and pr.verdict == "optimal"
        solved += 1
        f, f_ref = 0.5 * x @ H @ x + g @ x, pr.value
        assert f <= f_ref + 1e-8 * (1 + abs(f_ref))
        assert abs(x @ N @ x / rho2 - 1) <= 1e-14
        mu = info[3]
        assert mu > 0
        scale = 1 + np.abs(g).sum() + mu
        assert np.linalg.norm(H @ x + g + mu * N @ x - A.T @ lam) <= 1e-9 * scale
    assert solved >= 20 and empty >= 1


def test_certificate_multipliers_against_clarabel_duals(kernel, rng):
    """The certificate's multipliers, recomputed from stationarity alone, against Clarabel's
    duals at Clarabel's optimum; a point moved off the optimum fails."""
    checked = 0
    for _ in range(40):
        n = int(rng.integers(2, 6))
        B = rng.normal(size=(n, n))
        H = B @ B.T + 0.1 * np.eye(n)
        c = rng.normal(size=n) * 3
        G = rng.normal(size=(5, n))
        lo, hi = -rng.uniform(0.1, 1, 5), rng.uniform(0.1, 1, 5)
        x = cp.Variable(n)
        lower, upper = G @ x >= lo, G @ x <= hi
        ell = cp.quad_form(x, np.eye(n)) <= 1.0
        clarabel(cp.Problem(cp.Minimize(0.5 * cp.quad_form(x, H) + c @ x), [lower, upper, ell]))
        # the optimum to the certificate's precision: the KKT point polished by Clarabel's
        # active set is not exact, so the tolerances scale up with Clarabel's own (1e-11)
        values, lam, mu = kernel.kkt_certificate(x.value, H, c, G, lo, hi, Q=np.eye(n), r2=1.0,
                                                 active=1e-6)
        duals = lower.dual_value - upper.dual_value
        assert values[0] <= 1e-6 and values[1] <= 1e-9 and abs(values[3]) <= 1e-6
        big = np.abs(duals).max() + abs(ell.dual_value)
        assert np.abs(lam - duals).max() <= 1e-5 * big
        assert abs(mu - ell.dual_value) <= 1e-5 * big
        values, _, _ = kernel.kkt_certificate(x.value * 0.97, H, c, G, lo, hi, Q=np.eye(n),
                                              r2=1.0)
        assert values[0] > TOLERANCE["stationarity"] or values[3] > TOLERANCE["duality_gap"]
        checked += 1
    assert checked == 40


def test_symmetric_eigensolver_against_eigh(kernel, rng):
    for t in range(100):
        n = int(rng.integers(1, 12))
        Qm = np.linalg.qr(rng.normal(size=(n, n)))[0]
        low_rank = np.r_[np.zeros(n // 2), rng.normal(size=n - n // 2)]
        w = [rng.normal(size=n), rng.choice([-1.0, 0.5, 2.0], n),
             low_rank * 10.0 ** rng.choice([-8, 8])][t % 3]
        S = (Qm * w) @ Qm.T
        S = 0.5 * (S + S.T)
        got, V = kernel.eigen_symmetric(S)
        ref = eigh(S, eigvals_only=True)
        norm = max(np.linalg.norm(S), 1e-300)
        assert np.abs(got - ref).max() <= 1e-13 * norm * n
        assert np.linalg.norm(S @ V - V * got) <= 1e-12 * norm * n
        assert np.abs(V.T @ V - np.eye(n)).max() <= 1e-12 * n


# ------------------------------------------------------------------------------------------
# the maps
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("joints,scenario", [(1, "wheels"), (3, "wheels"), (3, "frictionless"),
                                             (4, "ideal_wheels")])
def test_state_maps_against_interaction_maps(models, rng, joints, scenario):
    """maps.c's affine maps of every wheel state (from contact_system) against the generated
    interaction_maps (SceneModel.maps with that wheel state)."""
    sm = models(joints, scenario)
    kernel = sm.core.optimal
    names = {1: "stick", 3: "slide+", 4: "slide-"}
    for q in random_q(rng, joints, 6):
        for _ in range(3):
            state = np.where(sm.present, 1, 0)
            for i in range(1, sm.n_constraints):
                if sm.present[i] and np.isfinite(sm.bounds[i]):
                    state[i] = rng.choice([1, 3, 4])
            code, got = kernel.state_maps(sm, q, state)
            ws = [names.get(int(s), "none") for s in state[1:]]
            ref = sm.maps(q, wheel_state=ws)
            assert code == 0
            assert abs(got["pivot_ratio"] - ref["pivot_ratio"]) <= 1e-10
            M = sm.mass_matrix(q)
            Qh = np.column_stack([ref["qdd_from_tau"], ref["qdd_offset"]])
            for name, r in (("L", ref["lam_from_tau"]), ("l0", ref["lam_offset"]),
                            ("W", ref["w_from_tau"]), ("w0", ref["w_offset"]),
                            ("Q", ref["qdd_from_tau"]), ("q0", ref["qdd_offset"]),
                            ("A", ref["a_obj_from_tau"]), ("a0", ref["a_obj_offset"]),
                            ("Xi_h", Qh.T @ M @ Qh), ("N", ref["input_metric"])):
                scale = max(np.abs(r).max(), 1e-12)
                assert np.abs(got[name] - r).max() <= 1e-10 * scale, name
            if all(s in (0, 1) for s in state):
                np.testing.assert_allclose(got["Omega"], ref["omega_tau"], rtol=1e-10,
                                           atol=1e-12 * np.abs(ref["omega_tau"]).max())


# ------------------------------------------------------------------------------------------
# the push tasks against Clarabel on the generated maps
# ------------------------------------------------------------------------------------------
REGIONS = [dict(tau_max=0.3), dict(radius=1.0), dict(tau_max=0.25, radius=0.8), {}]


def _push_reference(sm, q, objective, kw):
    """The task posed with cvxpy on SceneModel.maps(q): (status, objective value, tau)."""
    mp = sm.maps(q)
    na = sm.n_joints
    L, Ao, Xi, N = mp["lam_from_tau"], mp["a_obj_from_tau"], mp["xi_tau"], mp["input_metric"]
    t = cp.Variable(na)
    cons = [L[0] @ t >= 0]
    for i in range(1, sm.n_constraints):
        if sm.present[i] and np.isfinite(sm.bounds[i]):
            u = sm.bounds[i] * (1 - FRICTION_MARGIN)
            cons += [L[i] @ t <= u, L[i] @ t >= -u]
    if "tau_max" in kw:
        cons += [t <= kw["tau_max"], t >= -kw["tau_max"]]
    if "radius" in kw or "tau_max" not in kw:
        cons.append(cp.quad_form(t, N) <= kw.get("radius", 1.0) ** 2)
    if objective == "strongest_push":
        d = kw.get("direction")
        d = (Ao @ L[0]) if d is None else np.append(d, 0.0)
        d = d / np.linalg.norm(d)
        pr = clarabel(cp.Problem(cp.Maximize(d @ Ao @ t), cons))
        return pr.verdict, pr.value, t.value
    if "a_obj" in kw:
        cons.append(Ao @ t == kw["a_obj"])
    else:
        d = np.append(kw["direction"], 0.0) / np.linalg.norm(kw["direction"])
        cons.append(d @ Ao @ t >= kw["a_min"])
    pr = clarabel(cp.Problem(cp.Minimize(cp.quad_form(t, cp.psd_wrap(Xi))), cons))
    return pr.verdict, pr.value, t.value


def _feasible_on_maps(sm, q, tau, lim, kw):
    """tau keeps every limit of the task on SceneModel.maps(q), to 1e-9 relative."""
    mp = sm.maps(q)
    L, Ao = mp["lam_from_tau"], mp["a_obj_from_tau"]
    for i in range(1, sm.n_constraints):
        if sm.present[i] and np.isfinite(sm.bounds[i]):
            assert abs(L[i] @ tau) <= sm.bounds[i] * (1 - FRICTION_MARGIN) * (1 + 1e-9)
    assert L[0] @ tau >= 0
    if "tau_max" in lim:
        assert np.all(np.abs(tau) <= lim["tau_max"] * (1 + 1e-12))
    if "radius" in lim or "tau_max" not in lim:
        assert tau @ mp["input_metric"] @ tau <= lim.get("radius", 1.0) ** 2 * (1 + 1e-9)
    if "a_obj" in kw:
        np.testing.assert_allclose(Ao @ tau, kw["a_obj"], rtol=1e-9,
                                   atol=1e-9 * np.abs(kw["a_obj"]).max())
    else:
        d = np.append(kw["direction"], 0.0) / np.linalg.norm(kw["direction"])
        assert d @ Ao @ tau >= kw["a_min"] * (1 - 1e-9)


@pytest.mark.parametrize("scenario", SCENARIOS)
@pytest.mark.parametrize("region", range(len(REGIONS)))
def test_push_tasks_against_clarabel(models, rng, scenario, region):
    sm = models(3, scenario)
    lim = REGIONS[region]
    seen = {"optimal": 0, "infeasible": 0}
    for q in random_q(rng, 3, 6):
        strong = sm.optimize(q, "strongest_push", **lim)
        st, val, _ = _push_reference(sm, q, "strongest_push", lim)
        assert strong.status == "optimal" and st == "optimal", strong.reason
        assert abs(strong.objective_value - val) <= 1e-6 * abs(val)
        a = strong.analysis.a_obj
        d = a[:2] / np.linalg.norm(a[:2])
        th = rng.uniform(-1.2, 1.2)  # a direction off the normal by up to 69 deg
        d = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]]) @ d
        for kw in (dict(direction=d, a_min=float(rng.uniform(0.1, 1.5)) * (d @ a[:2])),
                   dict(a_obj=a * rng.uniform(0.2, 1.4))):
            res = sm.optimize(q, "least_slip_push", **lim, **kw)
            st, val, t = _push_reference(sm, q, "least_slip_push", dict(lim, **kw))
            if st == "optimal":
                assert res.status == "optimal", res.reason
                assert res.certificate.ok
                _feasible_on_maps(sm, q, res.tau, lim, kw)
                # as good as Clarabel's, which stops near 1e-7 of the optimum on these forms
                assert res.objective_value <= val * (1 + 1e-6) + 1e-15
                assert res.objective_value >= val * (1 - 1e-5) - 1e-15
            else:
                assert st == "infeasible" and res.status == "infeasible", res.reason
            seen[res.status] += 1
    assert seen["optimal"] and seen["infeasible"]


def test_six_joints_pushes_against_clarabel(models, rng):
    """Six joints, where the least-slip form Xi has rank 3 < 6 (a face of optima) and the
    regularised QP is ill-conditioned: every feasible task is answered (the active-set
    method once took independent rows for dependent ones there and reported infeasible
    tasks), as well as Clarabel does."""
    sm = models(6)
    found = [  # (by a seeded search) where that happened with the box
        [0.5149504261917488, -0.2084216963005503, -2.7070589484339354, -2.0345054391549913,
         -2.057898756475115, 1.3443282096240572, -0.554605995226013, -0.6160621419006942,
         0.09821953595695598],
        [-1.157795924923028, 0.19337193291244822, -2.2065219295952296, 2.1507940980909566,
         -2.1527832976725403, -0.23116844011792947, 2.198916683227298, -0.45360856861609644,
         -0.27545103899129897],
        [-1.4599174679702938, -1.608246210495793, 2.0023365221687017, -2.3262301400279504,
         2.0039251691653583, -1.2029859930137163, 1.9912997484592245, -2.129981442681457,
         0.23773920877678067]]
    for q in np.vstack([found, random_q(rng, 6, 20)]):
        for lim in (dict(tau_max=0.3), {}):
            strong = sm.optimize(q, "strongest_push", **lim)
            assert strong.status == "optimal", strong.reason
            a = strong.analysis.a_obj
            kw = dict(direction=a[:2] / np.linalg.norm(a[:2]),
                      a_min=0.5 * strong.objective_value)
            res = sm.optimize(q, "least_slip_push", **lim, **kw)
            assert res.status == "optimal", res.reason
            st, val, _ = _push_reference(sm, q, "least_slip_push", dict(lim, **kw))
            assert st == "optimal"
            _feasible_on_maps(sm, q, res.tau, lim, kw)
            assert val * (1 - 1e-5) <= res.objective_value <= val * (1 + 1e-6)


# ------------------------------------------------------------------------------------------
# max_sr with sliding wheels against the exact enumeration of wheel states
# ------------------------------------------------------------------------------------------
def _state_optimum(sm, q, state, tau_max, radius):
    """max sr on one wheel state (Charnes-Cooper in z = (tau, t)) by Clarabel on the state's
    generated maps; the torque, or None when the state is valid nowhere in the region."""
    names = {1: "stick", 3: "slide+", 4: "slide-"}
    mp = sm.maps(q, wheel_state=[names.get(int(s), "none") for s in state[1:]])
    if mp["singular"]:
        return None
    na = sm.n_joints
    M = sm.mass_matrix(q)
    Qh = np.column_stack([mp["qdd_from_tau"], mp["qdd_offset"]])
    Xih = Qh.T @ M @ Qh
    Lh = np.column_stack([mp["lam_from_tau"], mp["lam_offset"]])
    Wh = np.column_stack([mp["w_from_tau"], mp["w_offset"]])
    z = cp.Variable(na + 1)
    cons = [Lh[0] @ z == 1, z[na] >= 0]
    for i in range(1, sm.n_constraints):
        u = sm.bounds[i] * (1 - FRICTION_MARGIN)
        if state[i] == 1 and np.isfinite(sm.bounds[i]):
            cons += [Lh[i] @ z <= u * z[na], Lh[i] @ z >= -u * z[na]]
        elif state[i] == 3:
            cons.append(Wh[i] @ z <= 0)
        elif state[i] == 4:
            cons.append(Wh[i] @ z >= 0)
    if tau_max is not None:
        cons += [z[:na] <= tau_max * z[na], z[:na] >= -tau_max * z[na]]
    if radius is not None:
        R = np.linalg.cholesky(mp["input_metric"])
        cons.append(cp.norm(R.T @ z[:na]) <= radius * z[na])
    pr = clarabel(cp.Problem(cp.Minimize(cp.quad_form(z, cp.psd_wrap(Xih))), cons))
    if pr.verdict != "optimal" or not z.value[na] > 1e-9 * np.abs(z.value).max():
        return None
    return z.value[:na] / z.value[na]


@pytest.mark.parametrize("tau_max,radius,slides", [(0.15, None, True), (None, 1.0, False),
                                                   (None, 3.0, True), (0.4, 3.0, True)])
def test_max_sr_sliding_against_wheel_state_enumeration(models, rng, tau_max, radius, slides):
    """Every wheel state solved by Clarabel, each optimum confirmed by the exact forward solve
    (contact kept, only allowed wheels sliding); the query's sr equals the best of them. The
    configurations include two (found by a seeded search) where a sliding state wins, with
    the ellipsoid cutting its optimum at radius 3 (within the paper's radius 1 no sliding
    state wins at two joints: the torques are too small to overcome the wheels' friction)."""
    import itertools

    joints = 2
    sm = models(joints)
    kw = {k: v for k, v in (("tau_max", tau_max), ("radius", radius)) if v is not None}
    sliding = 0
    qs = list(random_q(rng, joints, 4)) + [
        np.array([0.0, 0.0, 0.0, -0.2992412597643468, 2.1812564889925747]),
        np.array([0.0, 0.0, 0.0, -2.0519187690443803, -0.5365031483866161])]
    for q in qs:
        res = sm.optimize(q, "max_sr", allow_slide=True, **kw)
        assert res.status == "optimal", res.reason
        wheels = [i for i in range(1, sm.n_constraints) if sm.present[i]]
        best = sm.optimize(q, "max_sr", **kw).objective_value  # every wheel sticking
        for combo in itertools.product((1, 3, 4), repeat=len(wheels)):
            state = np.where(sm.present, 1, 0)
            state[wheels] = combo
            tau = _state_optimum(sm, q, state, tau_max, radius)
            if tau is None:
                continue
            fw = sm.forward(q, tau)
            if fw.contact and not fw.singular:
                best = max(best, float(fw.sr))
        assert abs(res.objective_value - best) <= 1e-7, (q, res.objective_value, best)
        sliding += res.wheel_states_assumed is not None
    assert (sliding >= 1) == slides


def test_six_joints_sliding_state_cut_by_the_ellipsoid(models):
    """Six joints, a configuration (found by a seeded search) whose winning wheel state is cut
    by the ellipsoid and whose multiplier's root lies between two pieces of the secular
    equation (the answer once ended outside the ellipsoid by 4e-8 and failed its
    certificate): certified, and equal to that state's optimum by Clarabel."""
    sm = models(6)
    q = np.array([-0.9497741184811758, 0.4839164338469449, -0.765713683029654,
                  -0.21406720772497057, 1.37011721552684, 1.410571261862338,
                  0.11549529638356226, 1.2581310072441383, 0.12467123587509787])
    res = sm.optimize(q, "max_sr", allow_slide=True)
    assert res.status == "optimal" and res.certificate.ok, res.reason
    assert res.wheel_states_assumed is not None and "input ellipsoid (eq. 31)" in res.binding
    assert res.tau @ sm.maps(q)["input_metric"] @ res.tau <= 1 + 1e-12
    codes = {"none": 0, "stick": 1, "slide+": 3, "slide-": 4}
    state = np.array([1] + [codes[s] for s in res.wheel_states_assumed])
    tau = _state_optimum(sm, q, state, None, 1.0)
    assert abs(res.objective_value - float(sm.forward(q, tau).sr)) <= 1e-7


# ------------------------------------------------------------------------------------------
# one home: the same bits whatever the shape of q, the batch or the threads
# ------------------------------------------------------------------------------------------
QUERIES = [("max_sr", {}), ("max_sr", dict(tau_max=0.2, allow_slide=True)),
           ("least_slip_push", dict(direction=[0.0, 1.0], a_min=0.002, tau_max=0.3)),
           ("least_slip_push", dict(direction=[0.0, 1.0], a_min=0.002, radius=1.0)),
           ("strongest_push", dict(tau_max=0.3)), ("strongest_push", {}),
           ("strongest_push", dict(tau_max=0.3, radius=0.7))]


@pytest.mark.parametrize("objective,kw", QUERIES)
def test_batch_of_one_and_batches_equal_the_single_call_bit_for_bit(models, rng, objective, kw):
    sm = models(3)
    Q = random_q(rng, 3, 5)
    batch = sm.optimize(Q, objective, **kw)
    for k, q in enumerate(Q):
        for one in (sm.optimize(q, objective, **kw), sm.optimize(q[None, :], objective, **kw),
                    sm.optimize(q.tolist(), objective, **kw)):
            raw = one.analysis.raw.reshape(-1)
            assert raw.tobytes() == batch.analysis.raw[k].tobytes()
            assert np.asarray(one.tau).reshape(-1).tobytes() == batch.tau[k].tobytes()
            status = one.status if isinstance(one.status, str) else one.status[0]
            assert status == batch.status[k]


def test_threads_do_not_change_a_bit(models, rng, monkeypatch):
    from snakecg.engine import optimal

    sm = models(3)
    Q = random_q(rng, 3, 40)
    monkeypatch.setenv("SNAKECG_THREADS", "1")
    one = sm.optimize(Q, "least_slip_push", direction=[0.0, 1.0], a_min=0.002, tau_max=0.3)
    monkeypatch.setenv("SNAKECG_THREADS", "2")
    monkeypatch.setattr(optimal, "PARALLEL_MIN", 4)  # split this small batch
    two = sm.optimize(Q, "least_slip_push", direction=[0.0, 1.0], a_min=0.002, tau_max=0.3)
    assert one.analysis.raw.tobytes() == two.analysis.raw.tobytes()
    assert list(one.status) == list(two.status)


def test_forward_rows_left_to_the_reference_path_are_checked(models, rng, monkeypatch):
    """A forward row that the compiled forward solve hands to its reference path is solved
    there and then checked in C: the same answer as when the compiled row is used."""
    sm = models(3)
    kernel = sm.core.optimal
    Q = random_q(rng, 3, 4)
    plain = sm.optimize(Q, "strongest_push", tau_max=0.3)
    real = type(kernel).solve
    check = kernel.OUT["check"][0]

    def pending(self, model, query_in, qa):
        out = real(self, model, query_in, qa)
        out[1::2, check] = -1.0  # as if rows 1 and 3 needed the reference path
        return out

    monkeypatch.setattr(type(kernel), "solve", pending)
    again = sm.optimize(Q, "strongest_push", tau_max=0.3)
    assert list(again.status) == list(plain.status)
    np.testing.assert_allclose(again.objective_value, plain.objective_value, rtol=1e-12)
    np.testing.assert_allclose(again.analysis.raw, plain.analysis.raw, rtol=1e-12, atol=1e-300)


def test_without_the_compiled_core_optimize_says_why(rng):
    scene = snakecg.Scene(snakecg.Robot(joints=2), scenario="wheels")
    model = snakecg.load(scene, backend="casadi")
    with pytest.raises(snakecg.SnakecgError, match="compiled runtime core"):
        model.optimize(random_q(rng, 2), "max_sr")
