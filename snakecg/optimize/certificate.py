"""Optimality certificates, checked on the original problem after the solve.

The solvers work on a scaled, regularised, homogenised copy of each problem (``z = (tau, t)``,
rows normalised, a Tikhonov term on semidefinite Hessians). The certificate forgets all of
that: it rebuilds the problem in the torque itself from the configuration's maps and the query
(every limit as the optimiser poses it: the box, the ellipsoid of eq. 31, the contact kept,
every wheel within its friction bound backed off by ``FRICTION_MARGIN``), then

1. measures the largest constraint violation at ``tau`` (primal feasibility);
2. takes the constraints active at ``tau`` (relative slack below :data:`ACTIVE`) and
   recomputes their multipliers from the stationarity condition
   ``grad f(tau) = sum_i lam_i grad g_i(tau)`` by non-negative least squares (so the
   multipliers are dual feasible by construction), and reports the relative residual;
3. complementarity ``sum_i lam_i |slack_i|`` relative to the objective's size;
4. for the convex kinds (the least-slip QP, the strongest-push LP, either with the
   ellipsoid), the duality gap ``f(tau) - d(lam)`` with ``d`` the Lagrange dual function at
   those multipliers, ``sum_i lam_i slack_i + 1/2 r^T K^+ r`` (``r`` the Lagrangian's
   gradient at ``tau``, ``K`` its Hessian): by weak duality ``f(tau) - f* <= gap``, a proof
   of global optimality, not only of a KKT point.

``max_sr`` with every row held is not convex, but homogeneous of degree 0: ``tau`` is a
global maximiser iff ``Omega - sr(tau) (Omega + Xi)`` is negative semidefinite; the certificate
is its largest eigenvalue (relative, the "gap"), the residual of ``Omega v = sr (Omega + Xi) v``
at ``tau``, and primal feasibility. With sliding wheels the winning wheel state's problem
(the Charnes-Cooper form in ``z``) is certified by its KKT conditions (no gap: the homogeneous
ellipsoid is not a convex quadratic form); the choice between states rests on the exact
enumeration.
"""

from __future__ import annotations

import math

import numpy as np

from .active_set import _lin_solve
from .fast import (chol_solve, dot, ellipsoid_violation, frob, matvec, norm, primal_violation,
                   wheels)
from .problems import floats
from .result import ELLIPSOID, FRICTION_MARGIN, Certificate

#: A constraint whose slack is below this (relative to the row's size) is active.
ACTIVE = 1e-7
#: Relative tolerances of the certificate.
TOLERANCE = {"stationarity": 1e-7, "primal_feasibility": 1e-9, "complementarity": 1e-8,
             "duality_gap": 1e-8}


def _rows_of(G, lo, hi):
    return np.atleast_2d(np.asarray(G, float)), np.asarray(lo, float), np.asarray(hi, float)


def kkt(x, H, c, G, lo, hi, quad=None, *, convex: bool, kind: str) -> Certificate:
    """Certificate of ``x`` for ``min 1/2 x^T H x + c^T x`` (``H`` None: linear) subject to
    ``lo <= G x <= hi`` and, when ``quad = (Q, r2)``, ``x^T Q x <= r2``."""
    x = np.asarray(x, float)
    n = x.size
    Hx = np.zeros(n) if H is None else H @ x
    f = 0.5 * x @ Hx + c @ x
    grad = Hx + c
    G, lo, hi = _rows_of(G, lo, hi)
    Gx = G @ x
    bnd = np.where(np.isfinite(lo), np.abs(lo), 0.0)
    bnd = np.maximum(bnd, np.where(np.isfinite(hi), np.abs(hi), 0.0))
    rs = np.abs(G) @ np.abs(x) + bnd
    rs = np.where(rs > 0, rs, 1.0)
    low = np.isfinite(lo)
    upp = np.isfinite(hi)
    s_lo = np.where(low, Gx - lo, np.inf)
    s_hi = np.where(upp, hi - Gx, np.inf)
    primal = float(np.max(np.maximum(np.maximum(-s_lo, -s_hi), 0.0) / rs, initial=0.0))
    a_lo = s_lo <= ACTIVE * rs
    a_hi = s_hi <= ACTIVE * rs
    eq = a_lo & a_hi & (lo == hi)  # an equality: one column, a multiplier of either sign
    a_hi &= ~eq
    cols = [G[a_lo], -G[a_hi]]
    slacks = [np.where(eq[a_lo], 0.0, s_lo[a_lo]), s_hi[a_hi]]
    free = [eq[a_lo], np.zeros(int(a_hi.sum()), bool)]
    q_col = None
    if quad is not None:
        Q, r2 = quad
        qx = Q @ x
        qs = np.abs(x) @ np.abs(Q) @ np.abs(x) + abs(r2)
        qs = qs if qs > 0 else 1.0
        qv = x @ qx - r2
        primal = max(primal, max(qv, 0.0) / qs)
        if -qv <= ACTIVE * qs:
            q_col = int(a_lo.sum() + a_hi.sum())
            cols.append(-2.0 * qx[None, :])
            slacks.append(np.array([-qv]))
            free.append(np.zeros(1, bool))
    C = np.concatenate(cols, axis=0).T  # (n, k): one column per active constraint
    slacks = np.concatenate(slacks)
    free = np.concatenate(free)
    fscale = max(abs(f), abs(grad @ x), 1e-300)
    k = C.shape[1]
    # the size of the gradient's terms (its value can be much smaller, by cancellation)
    ref = (0.0 if H is None else np.linalg.norm(H) * np.linalg.norm(x)) + np.linalg.norm(c)
    if k:
        norms = np.linalg.norm(C, axis=0)
        norms = np.where(norms > 0, norms, 1.0)
        Cn = C / norms
        try:  # the normal equations (a handful of unit columns)
            lam_s = np.linalg.solve(Cn.T @ Cn, Cn.T @ grad)
        except np.linalg.LinAlgError:
            lam_s = np.full(k, np.nan)
        ok = bool(np.all(np.isfinite(lam_s)) and np.all(lam_s[~free] >= 0))
        if ok:
            r = np.linalg.norm(Cn @ lam_s - grad)
            ok = r <= 0.1 * TOLERANCE["stationarity"] * max(np.linalg.norm(grad), ref, 1e-300)
        if not ok:  # signs bind or the columns are dependent: non-negative least squares
            from scipy.optimize import nnls

            split = np.hstack([Cn, -Cn[:, free]])  # a free multiplier as a difference
            both = nnls(split, grad, maxiter=50 * split.shape[1])[0]
            lam_s = both[:k]
            lam_s[free] -= both[k:]
        lam = lam_s / norms
        resid = np.linalg.norm(C @ lam - grad)
        size = max(np.linalg.norm(grad), float(np.abs(lam) @ np.linalg.norm(C, axis=0)))
    else:
        lam = np.zeros(0)
        resid = np.linalg.norm(grad)
        size = 0.0
    stationarity = float(resid / max(size, ref, 1e-300)) if resid > 0 else 0.0
    complementarity = float(np.abs(lam) @ np.abs(slacks) / fscale) if k else 0.0
    gap = None
    if convex:
        # d(lam) = min_y L(y) with L(y) = f(y) - sum_i lam_i slack_i(y) (the ellipsoid's slack
        # r2 - y^T Q y among them): L is quadratic with Hessian K = H + 2 mu Q, so
        # d = L(x) - 1/2 r^T K^+ r with r = grad L(x) = grad - C lam, and the gap f(x) - d is
        # sum_i lam_i slack_i(x) + 1/2 r^T K^+ r, every term small at a KKT point (evaluating
        # L at a computed minimiser instead loses the gap to K's conditioning)
        K = np.zeros((n, n)) if H is None else H.copy()
        if q_col is not None:
            K = K + 2.0 * lam[q_col] * quad[0]
        r = grad - C @ lam if k else grad
        corr = 0.0
        if np.any(K) and np.any(r):
            y = np.linalg.lstsq(K, r, rcond=1e-12)[0]
            corr = 0.5 * float(r @ y)
        gap = float((float(np.abs(lam) @ np.abs(slacks)) + corr) / fscale) if k else corr / fscale
    values = {"stationarity": stationarity, "primal_feasibility": primal,
              "complementarity": complementarity, "duality_gap": gap}
    return _verdict(kind, values)


def _verdict(kind, values) -> Certificate:
    bad = [f"{k} {v:.3g} > {TOLERANCE[k]:.0e}" for k, v in values.items()
           if v is not None and not (abs(v) <= TOLERANCE[k])]
    return Certificate(kind, not bad, values["stationarity"], values["primal_feasibility"],
                       values["complementarity"], values["duality_gap"],
                       TOLERANCE["stationarity"], False, "; ".join(bad))


# ------------------------------------------------------------------------------------------
# the original problems, in tau
def _limits(model, query, cfg):
    """Rows ``lo <= G tau <= hi`` of the wheels (sticking, backed off) and the box, and the
    ellipsoid ``(N, r^2)`` or None."""
    n = cfg.N.shape[0]
    G, lo, hi = [], [], []
    for i in range(1, model.n_constraints):
        u = model.bounds[i]
        if model.present[i] and np.isfinite(u):
            G.append(cfg.L[i])
            lo.append(-u * (1 - FRICTION_MARGIN))
            hi.append(u * (1 - FRICTION_MARGIN))
    if query.tau_max is not None:
        G.extend(np.eye(n))
        lo.extend(-query.tau_max)
        hi.extend(query.tau_max)
    quad = None if query.radius is None else (cfg.N, query.radius**2)
    return G, lo, hi, quad


def _push(model, query, cfg, lam_lo, equal, lp):
    n = cfg.N.shape[0]
    G, lo, hi, quad = _limits(model, query, cfg)
    ell = cfg.L[0]
    G.append(ell)  # the contact is kept
    lo.append(0.0)
    hi.append(np.inf)
    if lam_lo is not None:  # the task, as a bound on the contact force
        G.append(ell)
        lo.append(lam_lo)
        hi.append(lam_lo if equal else np.inf)
    if lp:
        H, c = None, -ell
    else:
        H, c = 2.0 * cfg.Xi, np.zeros(n)
    kind = ("kkt (LP)" if lp else "kkt (convex QP)") if quad is None else "kkt (convex QCQP)"
    return dict(H=H, c=c, G=np.array(G), lo=np.array(lo), hi=np.array(hi), quad=quad,
                convex=True, kind=kind)


def _eigen(model, query, cfg, tau) -> Certificate:
    """``tau`` maximises the Rayleigh quotient of eqs. (28)-(30) iff ``Omega - sr(tau) D`` is
    negative semidefinite (``D = Omega + Xi``; on the null space of ``D`` both vanish): its
    largest eigenvalue, relative to ``||D||``, is the gap; the residual of ``Omega tau =
    sr (D tau)`` the stationarity. Plus primal feasibility of ``tau``. (Small dense
    arithmetic on floats, one eigenvalue solve.)"""
    fl = floats(cfg)
    Om = fl["Om"]
    D = [[a + b for a, b in zip(r1, r2)] for r1, r2 in zip(Om, fl["Xi"])]
    tau = tau.tolist()
    Dt = matvec(D, tau)
    Ot = matvec(Om, tau)
    den = dot(tau, Dt)
    sr = dot(tau, Ot) / den if den > 0 else 0.0
    nD = frob(D)
    n = len(tau)
    S = [[a - sr * b for a, b in zip(r1, r2)] for r1, r2 in zip(Om, D)]
    S = np.array([[0.5 * (S[i][j] + S[j][i]) for j in range(n)] for i in range(n)])
    top = float(np.linalg.eigvalsh(S)[-1])
    scale = (frob(Om) + nD) * norm(tau)
    resid = norm([a - sr * b for a, b in zip(Ot, Dt)])
    prim = primal_violation(model, query, fl["L"], tau)
    if query.radius is not None:
        prim = max(prim, ellipsoid_violation(fl["N"], query.radius**2, tau))
    values = {"stationarity": float(resid / scale) if scale > 0 else 0.0,
              "primal_feasibility": prim, "complementarity": 0.0,
              "duality_gap": max(top, 0.0) / max(nD, 1e-300)}
    return _verdict("generalized eigenproblem", values)


def _push_floats(model, query, cfg, tau, lam_lo, equal, lp):
    """:func:`kkt` of a push answer without the ellipsoid, on plain floats; None when the
    multipliers need more than the normal equations (the general :func:`kkt` then)."""
    L = floats(cfg)["L"]
    n = len(L[0])
    G, lo, hi = [], [], []
    for i, ub, _ in wheels(model):
        G.append(L[i])
        lo.append(-ub)
        hi.append(ub)
    if query.tau_max is not None:
        for j, m in enumerate(query.tau_max.tolist()):
            G.append([1.0 if k == j else 0.0 for k in range(n)])
            lo.append(-m)
            hi.append(m)
    ell = L[0]
    G.append(ell)
    lo.append(0.0)
    hi.append(math.inf)
    if lam_lo is not None:
        G.append(ell)
        lo.append(lam_lo)
        hi.append(lam_lo if equal else math.inf)
    x = tau.tolist()
    if lp:
        H, c, Hx = None, [-a for a in ell], [0.0] * n
    else:
        H = [[2.0 * a for a in row] for row in floats(cfg)["Xi"]]
        c, Hx = [0.0] * n, None
        Hx = matvec(H, x)
    f = 0.5 * dot(x, Hx) + dot(c, x)
    grad = [a + b for a, b in zip(Hx, c)]
    ax = [abs(a) for a in x]
    primal = 0.0
    cols, slacks, free = [], [], []
    his = []
    for row, lo_i, hi_i in zip(G, lo, hi):
        gx = dot(row, x)
        bnd = max(abs(lo_i) if lo_i > -math.inf else 0.0, abs(hi_i) if hi_i < math.inf else 0.0)
        rs = dot([abs(a) for a in row], ax) + bnd
        rs = rs if rs > 0 else 1.0
        s_lo = gx - lo_i if lo_i > -math.inf else math.inf
        s_hi = hi_i - gx if hi_i < math.inf else math.inf
        primal = max(primal, max(-s_lo, -s_hi, 0.0) / rs)
        a_lo, a_hi = s_lo <= ACTIVE * rs, s_hi <= ACTIVE * rs
        eq = a_lo and a_hi and lo_i == hi_i
        if a_lo:
            cols.append(row)
            slacks.append(0.0 if eq else s_lo)
            free.append(eq)
        if a_hi and not eq:
            his.append(([-a for a in row], s_hi))
    for row, sl in his:  # the upper sides after the lower ones, as kkt orders them
        cols.append(row)
        slacks.append(sl)
        free.append(False)
    fscale = max(abs(f), abs(dot(grad, x)), 1e-300)
    ref = (0.0 if H is None else frob(H) * norm(x)) + norm(c)
    k = len(cols)
    ng = norm(grad)
    lam = []
    if k:
        norms = [norm(col) or 1.0 for col in cols]
        Cn = [[a / nv for a in col] for col, nv in zip(cols, norms)]
        lam_s = _lin_solve([[dot(ci, cj) for cj in Cn] for ci in Cn], [dot(ci, grad) for ci in Cn])
        if lam_s is None or any(v < 0 for v, fr in zip(lam_s, free) if not fr):
            return None
        fit = [sum(lv * ci[j] for lv, ci in zip(lam_s, Cn)) - grad[j] for j in range(n)]
        if not norm(fit) <= 0.1 * TOLERANCE["stationarity"] * max(ng, ref, 1e-300):
            return None
        lam = [lv / nv for lv, nv in zip(lam_s, norms)]
        res = [sum(lv * ci[j] for lv, ci in zip(lam, cols)) - grad[j] for j in range(n)]
        resid = norm(res)
        size = max(ng, sum(abs(lv) * nv for lv, nv in zip(lam, norms)))
    else:
        res = [-a for a in grad]
        resid, size = ng, 0.0
    stationarity = resid / max(size, ref, 1e-300) if resid > 0 else 0.0
    comp = sum(abs(lv) * abs(sl) for lv, sl in zip(lam, slacks))
    corr = 0.0
    r = [-a for a in res]  # grad - C lam
    if H is not None and any(r):
        y = chol_solve(H, r, rel=1e-9)
        if y is None:
            return None  # nearly singular: the general kkt (least squares)
        corr = 0.5 * dot(r, y)
    gap = (comp + corr) / fscale if k else corr / fscale
    values = {"stationarity": stationarity, "primal_feasibility": primal,
              "complementarity": comp / fscale if k else 0.0, "duality_gap": gap}
    return _verdict("kkt (LP)" if lp else "kkt (convex QP)", values)


def certify(model, query, cfg, answer) -> Certificate:
    """The certificate of an answer that claims optimality (``answer.claim``)."""
    claim = answer.claim
    if claim is None:
        return Certificate("none", False, reason="the answer carries no optimality claim")
    if claim[0] == "eigen":
        return _eigen(model, query, cfg, answer.tau)
    if claim[0] == "push":
        _, lam_lo, equal, lp = claim
        if query.radius is None:
            cert = _push_floats(model, query, cfg, answer.tau, lam_lo, equal, lp)
            if cert is not None:
                return cert
        return kkt(answer.tau, **_push(model, query, cfg, lam_lo, equal, lp))
    if claim[0] == "state":
        _, prob, z = claim
        n1 = z.size
        G = np.vstack([prob.A, np.eye(n1)])
        lo = np.concatenate([prob.lba, prob.lbx])
        hi = np.concatenate([prob.uba, prob.ubx])
        quad = None
        if prob.N is not None:
            n = n1 - 1
            Q = np.zeros((n1, n1))
            Q[:n, :n] = prob.N
            Q[n, n] = -prob.r2
            quad = (Q, 0.0)
        # rows named after the ellipsoid (its bounding box) only relax it: left out
        keep = np.array([nm != ELLIPSOID or prob.N is None for nm in prob.names] + [True] * n1)
        return kkt(z, prob.H, prob.g, G[keep], lo[keep], hi[keep], quad, convex=False,
                   kind="kkt of the winning wheel state")
    raise ValueError(f"unknown claim {claim[0]!r}")


__all__ = ["certify", "kkt", "ACTIVE", "TOLERANCE"]
