"""A dense dual active-set QP solver (Goldfarb & Idnani 1983) for the small strictly convex
QPs of :mod:`snakecg.optimize` (a handful of variables and rows).

It starts every solve from the unconstrained minimiser with no constraint active, so its
answer depends on the problem alone (no hot start, no state between calls), and it costs a
few small dense solves instead of a solver call through CasADi. After each constraint is
added the point and the multipliers are recomputed from the active set's KKT system, so the
rounding of long steps (the LP's tiny curvature gives a far-away unconstrained minimiser) does
not accumulate. Returns None when the problem is infeasible or the iteration does not settle:
the caller then falls back to qpOASES.
"""

from __future__ import annotations

import numpy as np

#: Relative violation below which a row counts as satisfied.
FEAS_TOL = 1e-12


def solve(H, g, A, lba, uba, lbx, ubx):
    """``min 1/2 z^T H z + g^T z`` s.t. ``lba <= A z <= uba``, ``lbx <= z <= ubx`` (``H``
    positive definite): ``(z, lam_a)`` with ``lam_a`` the rows' multipliers (non-zero on the
    active rows only), or None."""
    n1 = g.size
    fixed = lbx == ubx
    keep = ~fixed
    zf = np.where(fixed, lbx, 0.0)
    # eliminate the fixed variables
    Hk = H[np.ix_(keep, keep)]
    gk = g[keep] + H[np.ix_(keep, fixed)] @ zf[fixed]
    Ak = A[:, keep]
    off = A[:, fixed] @ zf[fixed]
    n = int(keep.sum())
    R = A.shape[0]
    # one-sided rows c . x >= b (equalities first), then the finite variable bounds
    lo, hi = lba - off, uba - off
    nz = np.any(Ak != 0.0, axis=1)
    with np.errstate(invalid="ignore"):
        stuck = (lo > FEAS_TOL * (1 + np.abs(lo))) | (hi < -FEAS_TOL * (1 + np.abs(hi)))
    if np.any(~nz & stuck):
        return None  # a row without variables that cannot hold
    eqm = nz & (lo == hi)
    lom = nz & ~eqm & np.isfinite(lo)
    him = nz & ~eqm & np.isfinite(hi)
    lbk, ubk = lbx[keep], ubx[keep]
    eye = np.eye(n)
    fl, fu = np.isfinite(lbk), np.isfinite(ubk)
    C = np.vstack([Ak[eqm], Ak[lom], -Ak[him], eye[fl], -eye[fu]])
    b = np.concatenate([lo[eqm], lo[lom], -hi[him], lbk[fl], -ubk[fu]])
    idx = np.arange(R)
    origin = np.concatenate([idx[eqm], idx[lom], idx[him],
                             np.full(int(fl.sum() + fu.sum()), -1)]).tolist()
    m = C.shape[0]
    neq = int(eqm.sum())
    eq = np.zeros(m, dtype=bool)
    eq[:neq] = True
    cn = np.sqrt((C * C).sum(axis=1))
    try:
        Hinv = np.linalg.inv(Hk)
    except np.linalg.LinAlgError:
        return None
    x = -Hinv @ gk
    act: list[int] = []
    u = np.zeros(0)
    pending = list(range(neq))
    for _ in range(4 * (m + n) + 10):
        if pending:
            p = pending.pop(0)
            if C[p] @ x - b[p] > 0:  # enter the equality from its violated side
                C[p], b[p] = -C[p], -b[p]
        else:
            s = (C @ x - b) / cn
            if act:
                s[act] = np.inf
            s[eq] = np.inf
            p = int(np.argmin(s)) if m else -1
            if p < 0 or not s[p] < -FEAS_TOL * (1.0 + abs(b[p]) / cn[p]):
                if np.any(C @ x - b < -1e-9 * (1.0 + np.abs(b))):
                    return None  # not settled on a feasible point (rounding)
                return _result(x, act, u, origin, keep, zf, R)
        npv, bp = C[p], b[p]
        up = 0.0
        while True:
            if act:
                Nt = C[act]
                HN = Hinv @ Nt.T
                try:
                    r = np.linalg.solve(Nt @ HN, HN.T @ npv)
                except np.linalg.LinAlgError:
                    return None
                z = Hinv @ npv - HN @ r
            else:
                r = np.zeros(0)
                z = Hinv @ npv
            t1, l = np.inf, -1
            for j, a in enumerate(act):
                if not eq[a] and r[j] > 0 and u[j] / r[j] < t1:
                    t1, l = u[j] / r[j], j
            zn = z @ npv
            sp = npv @ x - bp
            # z of the size of rounding: p depends on the active rows (no primal step)
            small = np.linalg.norm(z) <= 1e-9 * np.linalg.norm(Hinv @ npv)
            t2 = -sp / zn if not small and zn > 0 else np.inf
            if sp >= 0:
                t2 = 0.0
            t = min(t1, t2)
            if not np.isfinite(t):
                return None  # infeasible
            x = x + t * z
            u = u - t * r
            up += t
            if t == t2:
                act.append(p)
                u = np.append(u, up)
                x, u = _recompute(Hk, gk, C, b, act, eq, x, u)
                break
            del act[l]
            u = np.delete(u, l)
    return None


def _recompute(H, g, C, b, act, eq, x, u):
    """The point and multipliers of the active set, from its KKT system."""
    n, k = H.shape[0], len(act)
    N = C[act]
    K = np.zeros((n + k, n + k))
    K[:n, :n] = H
    K[:n, n:] = -N.T
    K[n:, :n] = N
    try:
        sol = np.linalg.solve(K, np.concatenate([-g, b[act]]))
    except np.linalg.LinAlgError:
        return x, u
    if not np.all(np.isfinite(sol)):
        return x, u
    un = sol[n:]
    un = np.where(eq[act], un, np.maximum(un, 0.0))
    return sol[:n], un


def _result(x, act, u, origin, keep, zf, R):
    z = zf.copy()
    z[keep] = x
    lam = np.zeros(R)
    for j, a in enumerate(act):
        if origin[a] >= 0:
            lam[origin[a]] = abs(u[j])
    return z, lam
