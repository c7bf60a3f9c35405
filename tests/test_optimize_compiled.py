"""The compiled optimal-torque query (``snakecg/core/optimal.c``, ``dense.h``).

References, independent of the code under test:

* qpOASES (``casadi.conic``) for the dense dual active set on random strictly convex QPs,
  degenerate ones included (duplicated and dependent rows, rows scaled by 1e-3 and 1e3, zero
  rows, equalities, many rows tight at one point);
* HiGHS (``scipy.optimize.linprog``) for the LPs it solves with a tiny curvature, ties
  included (the objective parallel to a row);
* ``scipy.linalg.eigh`` for the largest eigenvalue of symmetric matrices (repeated
  eigenvalues, rank-deficient, negative semidefinite with a zero top as in the certificate);
* on the model's maps (``SceneModel.maps``): ``scipy.linalg.eigh`` of ``(Omega, Omega + Xi)``
  for ``max_sr``, HiGHS for the strongest push, qpOASES for the least-slip push;
* the Python path of :mod:`snakecg.optimize` (the compiled call switched off), which must
  give the same answers, statuses, binding limits and certificates.
"""

from __future__ import annotations

import contextlib
import io

import numpy as np
import pytest
from scipy.linalg import eigh
from scipy.optimize import linprog

import snakecg
from snakecg.optimize import api
from snakecg.optimize import FRICTION_MARGIN


@pytest.fixture(scope="module")
def model3():
    return snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels"))


@pytest.fixture(scope="module")
def kernel(model3):
    return model3.core.optimal


def _qpoases(n, R):
    import casadi as ca

    with contextlib.redirect_stdout(io.StringIO()):
        return ca.conic("ref", "qpoases", {"h": ca.Sparsity.dense(n, n),
                                           "a": ca.Sparsity.dense(R, n)},
                        {"printLevel": "none", "error_on_fail": False})


def _qpoases_solve(H, g, A, lo, hi):
    n, R = g.size, A.shape[0]
    solver = _qpoases(n, R)
    with contextlib.redirect_stdout(io.StringIO()):
        r = solver(h=H, g=g, a=A, lba=lo, uba=hi, lbx=-np.inf * np.ones(n),
                   ubx=np.inf * np.ones(n))
    ok = solver.stats()["success"]
    return np.array(r["x"]).ravel(), ok


def _random_qp(rng, degenerate):
    """A feasible strictly convex QP around a random point ``xf``."""
    n = int(rng.integers(1, 5))
    B = rng.normal(size=(n, n))
    H = B @ B.T + 0.1 * np.eye(n)
    g = rng.normal(size=n) * 3
    R = int(rng.integers(1, 8))
    A = rng.normal(size=(R, n))
    xf = rng.normal(size=n)
    Ax = A @ xf
    kind = rng.integers(0, 4, R)  # two-sided, lower, upper, equality
    lo = np.where(kind == 2, -np.inf, Ax - rng.uniform(0, 1, R))
    hi = np.where(kind == 1, np.inf, Ax + rng.uniform(0, 1, R))
    n_eq = 0
    for r in range(R):
        if kind[r] == 3 and n_eq < n - 1:
            lo[r] = hi[r] = Ax[r]
            n_eq += 1
        elif kind[r] == 3:
            kind[r] = 0
    if degenerate:
        extra_A, extra_lo, extra_hi = [], [], []
        r = int(rng.integers(R))
        extra_A.append(A[r].copy())  # a duplicated row
        extra_lo.append(lo[r])
        extra_hi.append(hi[r])
        if R >= 2:  # a dependent row, tight at xf
            c = A[0] + A[1]
            extra_A.append(c)
            extra_lo.append(c @ xf)
            extra_hi.append(np.inf)
        s = 10.0 ** rng.choice([-3, 3])  # a scaled row
        extra_A.append(s * A[r])
        extra_lo.append(s * lo[r] if np.isfinite(lo[r]) else -np.inf)
        extra_hi.append(s * hi[r] if np.isfinite(hi[r]) else np.inf)
        extra_A.append(np.zeros(n))  # a zero row that holds
        extra_lo.append(-1.0)
        extra_hi.append(1.0)
        for _ in range(n):  # rows tight at xf: a degenerate vertex
            c = rng.normal(size=n)
            extra_A.append(c)
            extra_lo.append(c @ xf)
            extra_hi.append(np.inf)
        A = np.vstack([A, extra_A])
        lo = np.concatenate([lo, extra_lo])
        hi = np.concatenate([hi, extra_hi])
    return H, g, A, lo, hi, xf


@pytest.mark.parametrize("degenerate", [False, True])
def test_dense_qp_matches_qpoases(kernel, rng, degenerate):
    from snakecg.optimize import active_set

    answered = 0
    trials = 150
    for _ in range(trials):
        H, g, A, lo, hi, _ = _random_qp(rng, degenerate)
        got = kernel.dense_qp(H, g, A, lo, hi)
        # the Python method it transcribes gives up exactly when it does
        py = active_set.solve(H, g, A, lo, hi, -np.inf * np.ones(g.size),
                              np.inf * np.ones(g.size))
        assert (got is None) == (py is None)
        if got is None:
            continue
        answered += 1
        x, lam = got
        np.testing.assert_allclose(x, py[0], rtol=1e-12, atol=1e-12)
        ref, ok = _qpoases_solve(H, g, A, lo, hi)
        assert ok
        scale = 1.0 + np.abs(ref).max()
        assert np.abs(x - ref).max() <= 1e-6 * scale
        Ax = A @ x
        rs = np.abs(A) @ np.abs(x) + 1.0
        assert np.all(Ax >= lo - 1e-9 * rs) and np.all(Ax <= hi + 1e-9 * rs)
        # KKT: H x + g = A^T lam_signed, the multipliers on the active sides (an equality's
        # sign is not returned: fitted by least squares)
        side = np.where(np.abs(Ax - lo) <= np.abs(Ax - hi), 1.0, -1.0)
        eq = lo == hi
        resid = H @ x + g - A[~eq].T @ (side[~eq] * lam[~eq])
        if eq.any():
            mu = np.linalg.lstsq(A[eq].T, resid, rcond=None)[0]
            assert np.all(np.abs(np.abs(mu) - lam[eq]) <= 1e-7 * (1 + np.abs(mu)))
            resid = resid - A[eq].T @ mu
        assert np.linalg.norm(resid) <= 1e-7 * (1 + np.linalg.norm(g) + np.abs(lam).sum())
    # it gives up (the caller then takes qpOASES) on some degenerate problems, as the Python
    # method does, never on most
    assert answered >= (0.75 if degenerate else 0.9) * trials


def test_dense_lp_matches_highs(kernel, rng):
    """The LPs as the push solves pose them: scaled variables in the unit box, rows and
    objective normalised, curvature 1e-9; ties (the objective along a row) included."""
    from snakecg.optimize import active_set

    answered = 0
    trials = 150
    for t in range(trials):
        n = int(rng.integers(1, 5))
        R = int(rng.integers(1, 6))
        A = rng.normal(size=(R, n))
        lo = -rng.uniform(0.2, 1.0, R)
        hi = rng.uniform(0.2, 1.0, R)
        g = rng.normal(size=n)
        if t % 3 == 0:  # a tie: the objective parallel to a row
            g = -A[0].copy()
        A = np.vstack([A, np.eye(n)])
        lo = np.concatenate([lo, -np.ones(n)])
        hi = np.concatenate([hi, np.ones(n)])
        rn = np.abs(A).max(axis=1)
        A, lo, hi = A / rn[:, None], lo / rn, hi / rn
        g = g / np.abs(g).max()
        got = kernel.dense_qp(1e-9 * np.eye(n), g, A, lo, hi)
        py = active_set.solve(1e-9 * np.eye(n), g, A, lo, hi, -np.inf * np.ones(n),
                              np.inf * np.ones(n))
        assert (got is None) == (py is None)
        ref = linprog(g, A_ub=np.vstack([A, -A]), b_ub=np.concatenate([hi, -lo]),
                      bounds=[(None, None)] * n, method="highs")
        assert ref.status == 0
        if got is None:
            continue
        answered += 1
        x = got[0]
        # at a vertex the point is solved from its n rows (exact); on a tie fewer rows fix
        # it, and x = x0 + ... cancels the unconstrained minimiser's size |g| / 1e-9: a
        # rounding of about 1e9 eps = 2e-7
        tol = 1e-6 if t % 3 == 0 else 1e-9
        assert g @ x <= ref.fun + tol * (1 + abs(ref.fun))
        assert np.all(A @ x >= lo - 1e-9) and np.all(A @ x <= hi + 1e-9)
        np.testing.assert_allclose(x, py[0], rtol=1e-12, atol=1e-12)
    assert answered >= 0.85 * trials


def test_top_eigenvalue_matches_eigh(kernel, rng):
    for t in range(200):
        n = int(rng.integers(1, 17))
        Q = np.linalg.qr(rng.normal(size=(n, n)))[0]
        kind = t % 4
        if kind == 0:
            w = rng.normal(size=n)
        elif kind == 1:  # repeated eigenvalues
            w = rng.choice([-1.0, 0.5, 2.0], n)
        elif kind == 2:  # negative semidefinite with a zero top (the certificate's S)
            w = -np.abs(rng.normal(size=n))
            w[rng.integers(n)] = 0.0
        else:  # rank-deficient, scaled far from 1
            w = np.zeros(n)
            w[: max(1, n // 3)] = rng.normal(size=max(1, n // 3))
            w *= 10.0 ** rng.choice([-8, 8])
        S = (Q * w) @ Q.T
        S = 0.5 * (S + S.T)
        ref = eigh(S, eigvals_only=True)[-1]
        got = kernel.top_eigenvalue(S)
        assert abs(got - ref) <= 1e-13 * max(np.linalg.norm(S), 1e-300) * n


def _python_path(monkeypatch):
    monkeypatch.setattr(api, "quick", lambda *a: None)


def _compiled(model):
    """The compiled call's return code of the last query (0: it answered)."""
    return int(model.__dict__["_snakecg_optimize_quick"].out[0])


def _same(r0, r1):
    assert r1.status == r0.status
    assert r1.binding == r0.binding
    assert r1.solver == r0.solver
    assert r1.iterations == r0.iterations
    assert (r1.certificate.kind, r1.certificate.ok) == (r0.certificate.kind,
                                                        r0.certificate.ok)
    np.testing.assert_allclose(r1.tau, r0.tau, rtol=1e-10, atol=1e-14)
    np.testing.assert_allclose(r1.objective_value, r0.objective_value, rtol=1e-9, atol=1e-14)


def _random_configurations(rng, na, n):
    Q = np.column_stack([rng.normal(size=(n, 2)), rng.uniform(-np.pi, np.pi, n),
                         rng.uniform(-2.35, 2.35, (n, na))])
    Q[0, 3:] = 0.0  # the straight snake
    Q[1, 3:] = [0.5 * (-1) ** j for j in range(na)]  # a symmetric zig-zag
    return Q


@pytest.mark.parametrize("joints", [2, 3])
def test_compiled_query_matches_references(joints, rng):
    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=joints), scenario="wheels"))
    wheels = [i for i in range(1, sm.n_constraints)
              if sm.present[i] and np.isfinite(sm.bounds[i])]
    u = np.array([sm.bounds[i] for i in wheels]) * (1 - FRICTION_MARGIN)
    tm = 0.3
    counts = {"max_sr": 0, "least_slip_push": 0, "strongest_push": 0}
    for q in _random_configurations(rng, joints, 25):
        mp = sm.maps(q)
        L, Xi, Om, Ao = (mp[k] for k in ("lam_from_tau", "xi_tau", "omega_tau",
                                         "a_obj_from_tau"))
        # max_sr: the top generalized eigenvalue of (Omega, Omega + Xi)
        r = sm.optimize(q, "max_sr")
        if _compiled(sm) == 0:
            counts["max_sr"] += 1
            top = eigh(Om, Om + Xi, eigvals_only=True)[-1]
            assert r.status == "optimal" and r.certificate.ok
            assert abs(r.objective_value - top) <= 1e-8
        # strongest push along the contact normal, box: HiGHS on the maps
        r = sm.optimize(q, "strongest_push", tau_max=tm)
        if _compiled(sm) == 0:
            counts["strongest_push"] += 1
            W = L[wheels]
            lp = linprog(-L[0], A_ub=np.vstack([W, -W]), b_ub=np.concatenate([u, u]),
                         bounds=[(-tm, tm)] * joints, method="highs")
            a_dir = Ao @ L[0] / (L[0] @ L[0])
            gamma = np.linalg.norm(a_dir)
            assert r.status == "optimal" and r.certificate.ok
            assert abs(r.objective_value - gamma * -lp.fun) <= 1e-7 * gamma * abs(lp.fun)
            d = r.analysis.a_obj[:2] / np.linalg.norm(r.analysis.a_obj[:2])
            a_min = 0.5 * r.objective_value
            # least-slip push for half of it: qpOASES on the maps
            r = sm.optimize(q, "least_slip_push", direction=d, a_min=a_min, tau_max=tm)
            if _compiled(sm) == 0:
                counts["least_slip_push"] += 1
                A = np.vstack([np.append(d, 0.0) @ Ao, W])
                solver = _qpoases(joints, A.shape[0])
                with contextlib.redirect_stdout(io.StringIO()):
                    ref = solver(h=2 * Xi, g=np.zeros(joints), a=A,
                                 lba=np.concatenate([[a_min], -u]),
                                 uba=np.concatenate([[np.inf], u]),
                                 lbx=-tm * np.ones(joints), ubx=tm * np.ones(joints))
                x = np.array(ref["x"]).ravel()
                assert r.status == "optimal" and r.certificate.ok
                f_ref = x @ Xi @ x
                f = r.tau @ Xi @ r.tau
                assert f <= f_ref * (1 + 1e-6) + 1e-15
                assert abs(r.objective_value - f) <= 1e-6 * f  # forward: ||qdd_s||^2 = tau Xi tau
    # the compiled call answers the common queries
    assert counts["max_sr"] >= 20 and counts["strongest_push"] >= 20
    assert counts["least_slip_push"] >= 18


@pytest.mark.parametrize("joints", [1, 2, 3])
def test_compiled_query_equals_python_path(joints, rng, monkeypatch):
    """Every kind the compiled call takes, answered or not, feasible or not: the same result
    as the Python path."""
    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=joints), scenario="wheels"))
    codes = {}
    for q in _random_configurations(rng, joints, 15):
        cases = [("max_sr", {}), ("max_sr", dict(tau_max=0.2)),  # (one joint: the Python
                 # path's one-sample maps were 1-D there and failed)
                 ("max_sr", dict(tau_max=0.2, radius=0.8)),
                 ("strongest_push", dict(tau_max=0.3)),
                 ("strongest_push", dict(tau_max=0.3, direction=np.array([1.0, 0.0]))),
                 ("least_slip_push", dict(tau_max=0.3, direction=np.array([0.0, 1.0]),
                                          a_min=1e-3)),
                 ("least_slip_push", dict(tau_max=0.3, direction=np.array([0.0, 1.0]),
                                          a_min=1e3))]  # out of reach: infeasible
        for objective, kw in cases:
            r1 = sm.optimize(q, objective, **kw)
            code = _compiled(sm)
            codes[code] = codes.get(code, 0) + 1
            with monkeypatch.context() as m:
                _python_path(m)
                r0 = sm.optimize(q, objective, **kw)
            _same(r0, r1)
            # the forward solve the compiled call ran is SceneModel.forward's, bit for bit
            np.testing.assert_array_equal(r1.analysis.raw, sm.forward(q, r1.tau).raw)
            if code == 0:  # answered and certified (the forward check may still refuse a
                # degenerate answer, e.g. a push of 1e-16: then both paths say "failed")
                assert r1.certificate.ok and r1.status in ("optimal", "failed")
    assert codes.get(0, 0) >= 0.5 * sum(codes.values())
    assert sum(v for k, v in codes.items() if k != 0) > 0  # the Python path was exercised


def test_compiled_query_leaves_sliding_and_ellipsoid_pushes_to_python(model3):
    q = np.array([0.1, -0.2, 0.3, 0.4, -0.5, 0.6])
    sm = model3
    sm.optimize(q, "max_sr")  # builds the workspace
    ws_out = sm.__dict__["_snakecg_optimize_quick"].out
    for objective, kw in (("max_sr", dict(allow_slide=True)),
                          ("strongest_push", {}),  # the ellipsoid
                          ("least_slip_push", dict(direction=[0.0, 1.0], a_min=1e-3))):
        ws_out[0] = -1.0
        r = sm.optimize(q, objective, **kw)
        assert ws_out[0] == -1.0  # not called
        assert r.status in ("optimal", "infeasible")


@pytest.mark.parametrize("joints,scenario", [(1, "wheels"), (3, "wheels"), (3, "frictionless"),
                                             (6, "ideal_wheels")])
def test_held_maps_match_interaction_maps(joints, scenario, rng):
    """maps.c's all-held maps (from contact_system) against the generated interaction_maps
    (``SceneModel.maps``), including the straight snake; dependent rows refused."""
    from snakecg.solver import PIVOT_TOL

    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario))
    kernel = sm.core.optimal
    for q in _random_configurations(rng, joints, 12):
        code, got = kernel.held_maps(sm, q, PIVOT_TOL)
        ref = sm.maps(q)
        if not ref["pivot_ratio"] > PIVOT_TOL:
            assert code == 2
            continue
        assert code == 0
        assert abs(got["pivot_ratio"] - ref["pivot_ratio"]) <= 1e-12
        for name, key in (("L", "lam_from_tau"), ("A", "a_obj_from_tau"), ("Xi", "xi_tau"),
                          ("Omega", "omega_tau"), ("N", "input_metric")):
            scale = max(np.abs(ref[key]).max(), 1e-300)
            assert np.abs(got[name] - ref[key]).max() <= 1e-11 * scale, name
