"""A dense dual active-set QP solver (Goldfarb & Idnani 1983) for the small strictly convex
QPs of :mod:`snakecg.optimize` (a handful of variables and rows), on plain floats.

It starts every solve from the unconstrained minimiser with no constraint active, so its
answer depends on the problem alone (no hot start, no state between calls), and it costs a
few small dense solves instead of a solver call through CasADi. After each constraint is
added the point and the multipliers are recomputed from the active set (exactly from its rows
when they fix the point), so the rounding of long steps (the LP's tiny curvature gives a
far-away unconstrained minimiser) does not accumulate. Returns None when the problem is
infeasible or the iteration does not settle: the caller then falls back to qpOASES.
"""

from __future__ import annotations

import math
from operator import mul

import numpy as np

#: Relative violation below which a row counts as satisfied.
FEAS_TOL = 1e-12
#: Most free variables this Python solver takes; larger problems go to qpOASES, whose
#: compiled iterations win there.
DENSE_MAX = 4


def _lin_solve(M, b):
    """``M^-1 b`` by Gaussian elimination with partial pivoting (lists), None if singular."""
    n = len(b)
    if n == 1:
        return [b[0] / M[0][0]] if M[0][0] != 0.0 and math.isfinite(b[0] / M[0][0]) else None
    A = [list(row) + [bi] for row, bi in zip(M, b)]
    for c in range(n):
        p, big = c, abs(A[c][c])
        for i in range(c + 1, n):
            v = abs(A[i][c])
            if v > big:
                p, big = i, v
        if big == 0.0:
            return None
        A[c], A[p] = A[p], A[c]
        Ac = A[c]
        piv = Ac[c]
        for i in range(c + 1, n):
            Ai = A[i]
            f = Ai[c] / piv
            if f:
                for j in range(c, n + 1):
                    Ai[j] -= f * Ac[j]
    x = [0.0] * n
    for i in range(n - 1, -1, -1):
        Ai = A[i]
        x[i] = (Ai[n] - sum(map(mul, Ai[i + 1:n], x[i + 1:]))) / Ai[i]
    if not all(map(math.isfinite, x)):
        return None
    return x


def solve(H, g, A, lba, uba, lbx, ubx):
    """``min 1/2 z^T H z + g^T z`` s.t. ``lba <= A z <= uba``, ``lbx <= z <= ubx`` (``H``
    positive definite; numpy arrays or lists): ``(z, lam_a)`` with ``lam_a`` the rows' multipliers
    (non-zero on the active rows only), or None."""
    H, g, A, lba, uba, lbx, ubx = (x.tolist() if isinstance(x, np.ndarray) else x
                                   for x in (H, g, A, lba, uba, lbx, ubx))
    n1, R = len(g), len(A)
    keep = [j for j in range(n1) if lbx[j] != ubx[j]]
    fixed = [j for j in range(n1) if lbx[j] == ubx[j]]
    zf = [lbx[j] if lbx[j] == ubx[j] else 0.0 for j in range(n1)]
    n = len(keep)
    Hk = [[H[i][j] for j in keep] for i in keep]
    gk = [g[i] + sum(H[i][f] * zf[f] for f in fixed) for i in keep]
    # one-sided rows c . x >= b (equalities first), then the finite variable bounds
    eqs, ins = [], []
    for r in range(R):
        row = A[r]
        c = [row[j] for j in keep]
        off = sum(row[f] * zf[f] for f in fixed)
        lo, hi = lba[r] - off, uba[r] - off
        if not any(c):
            if lo > FEAS_TOL * (1 + abs(lo)) or hi < -FEAS_TOL * (1 + abs(hi)):
                return None  # a row without variables that cannot hold
            continue
        if lo == hi:
            eqs.append((c, lo, r))
            continue
        if lo > -math.inf:
            ins.append((c, lo, r))
        if hi < math.inf:
            ins.append(([-a for a in c], -hi, r))
    for k, j in enumerate(keep):
        if lbx[j] > -math.inf:
            e = [0.0] * n
            e[k] = 1.0
            ins.append((e, lbx[j], -1))
        if ubx[j] < math.inf:
            e = [0.0] * n
            e[k] = -1.0
            ins.append((e, -ubx[j], -1))
    cons = eqs + ins
    neq = len(eqs)
    m = len(cons)
    C = [c for c, _, _ in cons]
    b = [v for _, v, _ in cons]
    origin = [r for _, _, r in cons]
    cn = [math.sqrt(sum(map(mul, c, c))) for c in C]
    Hinv = _inverse(Hk)
    if Hinv is None:
        return None
    x0 = [-sum(map(mul, row, gk)) for row in Hinv]
    x = list(x0)
    h: dict[int, list] = {}  # Hinv c_i, per constraint

    def hv(i):
        v = h.get(i)
        if v is None:
            v = h[i] = [sum(map(mul, row, C[i])) for row in Hinv]
        return v

    act: list[int] = []
    u: list[float] = []
    if not neq and all(Hk[i][j] == 0.0 for i in range(n) for j in range(n) if i != j):
        x, act, u = _bounds_first(Hk, gk, C, b, x0, m)
    for it in range(4 * (m + n) + 10):
        if it < neq:
            p = it
            if sum(map(mul, C[p], x)) - b[p] > 0:  # enter the equality from its violated side
                C[p] = [-a for a in C[p]]
                b[p] = -b[p]
                h.pop(p, None)
        else:
            res = [sum(map(mul, c, x)) - bi for c, bi in zip(C, b)]
            p, worst = -1, 0.0
            for i in range(neq, m):
                s = res[i] / cn[i]
                if s < worst and s < -FEAS_TOL * (1.0 + abs(b[i]) / cn[i]) and i not in act:
                    p, worst = i, s
            if p < 0:
                if any(r < -1e-9 * (1.0 + abs(bi)) for r, bi in zip(res, b)):
                    return None  # not settled on a feasible point (rounding)
                return _result(x, act, u, origin, keep, zf, R)
        npv, bp = C[p], b[p]
        hp = hv(p)
        up = 0.0
        while True:
            if act:
                hs = [hv(a) for a in act]
                M = [[sum(map(mul, C[a], hj)) for hj in hs] for a in act]
                r = _lin_solve(M, [sum(map(mul, hj, npv)) for hj in hs])
                if r is None:
                    return None
                z = [hp[i] - sum(rj * hj[i] for rj, hj in zip(r, hs)) for i in range(n)]
            else:
                r, z = [], hp
            t1, l = math.inf, -1
            for j, a in enumerate(act):
                if a >= neq and r[j] > 0 and u[j] / r[j] < t1:
                    t1, l = u[j] / r[j], j
            zn = sum(map(mul, z, npv))
            sp = sum(map(mul, npv, x)) - bp
            # z of the size of rounding: p depends on the active rows (no primal step)
            small = math.sqrt(sum(map(mul, z, z))) <= 1e-9 * math.sqrt(sum(map(mul, hp, hp)))
            t2 = -sp / zn if not small and zn > 0 else math.inf
            if sp >= 0:
                t2 = 0.0
            t = min(t1, t2)
            if not math.isfinite(t):
                return None  # infeasible
            if t:
                x = [a + t * c for a, c in zip(x, z)]
                u = [a - t * c for a, c in zip(u, r)]
                up += t
            if t == t2:
                act.append(p)
                u.append(up)
                x, u = _recompute(C, b, act, neq, x0, hv, x, u, n)
                break
            del act[l]
            del u[l]
    return None


def _bounds_first(H, g, C, b, x0, m):
    """With a diagonal ``H`` (the LP's curvature): the minimiser over the rows that bound one
    variable each, i.e. ``x0`` clipped to the tightest such bounds, with those rows active
    (their multipliers are ``(H x + g)_j / c_j >= 0``). The dual active-set iteration may start
    from any such pair; this one depends on the problem alone, and saves the long path from
    the LP's far-away unconstrained minimiser."""
    n = len(x0)
    x = list(x0)
    best: dict[int, tuple] = {}  # variable -> (row, bound value) of the violated tightest bound
    for i in range(m):
        nz = [j for j in range(n) if C[i][j] != 0.0]
        if len(nz) != 1:
            continue
        j = nz[0]
        c = C[i][j]
        v = b[i] / c
        lower = c > 0
        if (lower and x0[j] < v) or (not lower and x0[j] > v):
            old = best.get(j)
            if old is None or (lower and v > old[1]) or (not lower and v < old[1]):
                best[j] = (i, v)
    act, u = [], []
    for j, (i, v) in sorted(best.items()):
        x[j] = v
        lam = (H[j][j] * v + g[j]) / C[i][j]
        if not lam >= 0:
            return list(x0), [], []
        act.append(i)
        u.append(lam)
    # the other bound rows must hold, else start from nothing
    for j, (i, v) in best.items():
        for k in range(m):
            if k != i and C[k][j] != 0.0 and all(C[k][jj] == 0.0 for jj in range(n) if jj != j):
                if C[k][j] * v - b[k] < -FEAS_TOL * (1 + abs(b[k])):
                    return list(x0), [], []
    return x, act, u


def _inverse(M):
    n = len(M)
    if all(M[i][j] == 0.0 for i in range(n) for j in range(n) if i != j):
        if not all(M[i][i] != 0.0 for i in range(n)):
            return None
        return [[1.0 / M[i][i] if i == j else 0.0 for j in range(n)] for i in range(n)]
    if n == 3:  # the adjugate (no pivoting needed for a positive definite matrix)
        (a, b, c), (d, e, f), (g, h, i) = M
        A, B, C = e * i - f * h, f * g - d * i, d * h - e * g
        det = a * A + b * B + c * C
        if det > 0 and math.isfinite(det):
            return [[A / det, (c * h - b * i) / det, (b * f - c * e) / det],
                    [B / det, (a * i - c * g) / det, (c * d - a * f) / det],
                    [C / det, (b * g - a * h) / det, (a * e - b * d) / det]]
    try:
        inv = np.linalg.inv(np.array(M))
    except np.linalg.LinAlgError:
        return None
    return inv.tolist() if np.all(np.isfinite(inv)) else None


def _recompute(C, b, act, neq, x0, hv, x, u, n):
    """The point and multipliers of the active set: ``N Hinv N^T u = b - N x0`` and
    ``x = x0 + Hinv N^T u``; the point from the rows alone when they fix it."""
    hs = [hv(a) for a in act]
    M = [[sum(map(mul, C[a], hj)) for hj in hs] for a in act]
    un = _lin_solve(M, [b[a] - sum(map(mul, C[a], x0)) for a in act])
    if un is None:
        return x, u
    if len(act) == n:
        xn = _lin_solve([C[a] for a in act], [b[a] for a in act])
    else:
        xn = [x0[i] + sum(uj * hj[i] for uj, hj in zip(un, hs)) for i in range(n)]
    if xn is None:
        return x, u
    un = [v if a < neq else max(v, 0.0) for v, a in zip(un, act)]
    return xn, un


def _result(x, act, u, origin, keep, zf, R):
    z = np.array(zf)
    z[keep] = x
    lam = np.zeros(R)
    for j, a in enumerate(act):
        if origin[a] >= 0:
            lam[origin[a]] = abs(u[j])
    return z, lam
