"""The scaled copy of a problem that the solvers see, and what is done with a solver's answer:
its active set solved exactly (:func:`polish`) and the binding rows named (:func:`binding`).

:func:`scaled` (numpy, for qpOASES and IPOPT) and :func:`scaled_lists` (plain floats, for
:mod:`snakecg.optimize.active_set`) perform the same operations in the same order, so they
give the same numbers.
"""

from __future__ import annotations

import math
from operator import mul

import numpy as np

from .active_set import _lin_solve
from .result import HESSIAN_REG

#: Curvature of the QP that stands for an LP (scaled variables, objective of size 1).
LP_REG = 1e-9


def scaled(prob):
    """The problem as the solvers see it: variables ``z / scale``, rows normalised to a largest
    coefficient of 1, the objective to a largest coefficient of 1, and a relative Tikhonov
    term ``HESSIAN_REG`` on the Hessian; ``H`` None for an LP."""
    s = prob.scale
    A = prob.A * s[None, :]
    rn = np.abs(A).max(axis=1)
    used = rn > 0
    rn = np.where(used, rn, 1.0)
    A = A / rn[:, None]
    lba = np.where(used, prob.lba / rn, -np.inf)
    uba = np.where(used, prob.uba / rn, np.inf)
    H = None if prob.H is None else prob.H * np.outer(s, s)
    g = prob.g * s
    fs = max(np.abs(g).max(), 0.0 if H is None else np.abs(H).max())
    fs = fs if fs > 0 else 1.0
    g = g / fs
    if H is not None:
        H = H / fs
        H = H + HESSIAN_REG * max(np.abs(np.diag(H)).max(), 1e-300) * np.eye(len(s))
    return H, g, A, lba, uba, prob.lbx / s, prob.ubx / s


def scaled_lists(prob):
    """:func:`scaled` on plain floats (the same operations in the same order, so the same
    numbers), with the LP's curvature ``LP_REG`` in place of ``H``: lists for
    :func:`snakecg.optimize.active_set.solve`."""
    s = prob.scale.tolist()
    n1 = len(s)
    A, lo, hi = [], [], []
    for row, a, b in zip(prob.A.tolist(), prob.lba.tolist(), prob.uba.tolist()):
        row = [x * y for x, y in zip(row, s)]
        rn = max(map(abs, row))
        if rn > 0:
            A.append([x / rn for x in row])
            lo.append(a / rn)
            hi.append(b / rn)
        else:
            A.append(row)
            lo.append(-math.inf)
            hi.append(math.inf)
    g = [x * y for x, y in zip(prob.g.tolist(), s)]
    if prob.H is None:
        H = None
        fs = max(map(abs, g))
    else:
        H = [[h * (si * sj) for h, sj in zip(row, s)] for row, si in zip(prob.H.tolist(), s)]
        fs = max(max(map(abs, g)), max(abs(h) for row in H for h in row))
    fs = fs if fs > 0 else 1.0
    g = [x / fs for x in g]
    if H is None:
        H = [[LP_REG if i == j else 0.0 for j in range(n1)] for i in range(n1)]
    else:
        H = [[h / fs for h in row] for row in H]
        reg = HESSIAN_REG * max(max(abs(H[i][i]) for i in range(n1)), 1e-300)
        for i in range(n1):
            H[i][i] += reg
    lbx = [a / b for a, b in zip(prob.lbx.tolist(), s)]
    ubx = [a / b for a, b in zip(prob.ubx.tolist(), s)]
    return H, g, A, lo, hi, lbx, ubx


def binding(prob, zs, A, lba, uba, lam_a, extra=()):
    """Rows active at ``zs`` (scaled) with a non-zero multiplier: their names (deduplicated)
    and their indices."""
    lam_a = np.asarray(lam_a).ravel().tolist()
    big = max(max(map(abs, lam_a), default=0.0), max((abs(v) for _, v in extra), default=0.0))
    if big <= 0:
        return (), []
    zl = np.asarray(zs).tolist()
    Al, lo, hi = _plain(A), _plain(lba), _plain(uba)
    rows = []
    for r, lam in enumerate(lam_a):
        if abs(lam) > 1e-7 * big:
            az = sum(map(mul, Al[r], zl))
            if min(abs(az - lo[r]), abs(az - hi[r])) <= 1e-6:
                rows.append(r)
    out = [prob.names[r] for r in rows if prob.names[r]]
    out += [name for name, v in extra if abs(v) > 1e-7 * big]
    return tuple(dict.fromkeys(out)), rows


def _plain(x):
    return x.tolist() if isinstance(x, np.ndarray) else x


def polish(H, g, A, lba, uba, lbx, ubx, zs, lam_a):
    """The exact optimum on the solver's active set: the equality-constrained QP with the rows
    that carry a multiplier held at their active bound (and the fixed variables), solved
    directly (one dense KKT system, on plain floats; :func:`_polish_dense` when it is
    singular). Taken when it keeps every row and bound (to 1e-12) and its objective is no
    worse; the solver's point otherwise. A homotopy (qpOASES) stops within about 1e-7 of the
    optimum on ill-conditioned Hessians; this makes the answer a function of the active set
    alone, exact to rounding."""
    Hl, gl, Al = _plain(H), _plain(g), _plain(A)
    lo, hi, xl, xu = _plain(lba), _plain(uba), _plain(lbx), _plain(ubx)
    z0, la = zs.tolist(), lam_a.tolist()
    n1 = len(gl)
    E, e = [], []
    for r, row in enumerate(Al):
        if la[r] != 0.0:
            az = sum(map(mul, row, z0))
            target = lo[r] if abs(az - lo[r]) <= abs(az - hi[r]) else hi[r]
            if math.isfinite(target):
                E.append(row)
                e.append(target)
    for j in range(n1):
        at_lo = xl[j] == xu[j] or abs(z0[j] - xl[j]) <= 1e-12 * (1 + abs(xl[j]))
        if math.isfinite(xl[j]) and at_lo:
            E.append([1.0 if i == j else 0.0 for i in range(n1)])
            e.append(xl[j])
    K = [Hl[i] + [row[i] for row in E] for i in range(n1)]
    K += [row + [0.0] * len(E) for row in E]
    rhs = [-v for v in gl] + e
    if len(rhs) <= 4:
        sol = _lin_solve(K, rhs)
    else:  # one LAPACK call beats Python elimination from here on
        try:
            sol = np.linalg.solve(np.array(K), np.array(rhs)).tolist()
        except np.linalg.LinAlgError:
            sol = None
        if sol is not None and not all(map(math.isfinite, sol)):
            sol = None
    if sol is None:
        return polish_dense(*(np.asarray(x, dtype=float) for x in (H, g, A, lba, uba, lbx, ubx)),
                             zs, lam_a)
    z = sol[:n1]
    for row, a, b in zip(Al, lo, hi):
        az = sum(map(mul, row, z))
        tol = 1e-12 * (1.0 + abs(az))
        if az < a - tol or az > b + tol:
            return zs
    for v, a, b in zip(z, xl, xu):
        if v < a - 1e-12 * (1 + abs(v)) or v > b + 1e-12 * (1 + abs(v)):
            return zs

    def obj(x):
        return 0.5 * sum(map(mul, x, [sum(map(mul, row, x)) for row in Hl])) + sum(map(mul, gl, x))

    f_old, f_new = obj(z0), obj(z)
    if f_new > f_old + 1e-12 * max(abs(f_old), 1e-300):
        return zs
    return np.array(z)


def polish_dense(H, g, A, lba, uba, lbx, ubx, zs, lam_a):
    """:func:`polish` with dense numpy (least squares when the active rows are dependent).

    The exact optimum on the solver's active set: the equality-constrained QP with the rows
    that carry a multiplier held at their active bound (and the fixed variables), solved
    directly (one dense KKT system). Taken when it keeps every row and bound (to 1e-12) and
    its objective is no worse; the solver's point otherwise. A homotopy (qpOASES) stops within
    about 1e-7 of the optimum on ill-conditioned Hessians; this makes the answer a function of
    the active set alone, exact to rounding."""
    n1 = zs.size
    Az = A @ zs
    act = np.abs(lam_a) > 0
    at_lo = np.abs(Az - lba) <= np.abs(Az - uba)
    target = np.where(at_lo, lba, uba)
    act &= np.isfinite(target)
    fixed = np.isfinite(lbx) & ((lbx == ubx) | (np.abs(zs - lbx) <= 1e-12 * (1 + abs(lbx))))
    E = np.vstack([A[act], np.eye(n1)[fixed]])
    e = np.concatenate([target[act], lbx[fixed]])
    k = E.shape[0]
    K = np.zeros((n1 + k, n1 + k))
    K[:n1, :n1] = H
    K[:n1, n1:] = E.T
    K[n1:, :n1] = E
    rhs = np.concatenate([-g, e])
    try:
        sol = np.linalg.solve(K, rhs)
    except np.linalg.LinAlgError:  # dependent active rows: the least-squares solution
        sol = np.linalg.lstsq(K, rhs, rcond=1e-14)[0]
    z = sol[:n1]
    if not np.all(np.isfinite(z)):
        return zs
    Az2 = A @ z
    tol = 1e-12 * (1.0 + np.abs(Az2))
    if np.any(Az2 < lba - tol) or np.any(Az2 > uba + tol):
        return zs
    if np.any(z < lbx - 1e-12 * (1 + np.abs(z))) or np.any(z > ubx + 1e-12 * (1 + np.abs(z))):
        return zs
    f_old = 0.5 * zs @ H @ zs + g @ zs
    f_new = 0.5 * z @ H @ z + g @ z
    if f_new > f_old + 1e-12 * max(abs(f_old), 1e-300):
        return zs
    return z
