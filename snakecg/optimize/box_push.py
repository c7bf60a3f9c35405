"""The push problems with box limits only, posed directly in the torque on plain floats.

The same problem as :func:`snakecg.optimize.problems.push_problem` with ``t = 1``
eliminated, in the scaled variables ``y = tau / tau_max`` and rows normalised as
:func:`snakecg.optimize.solvers._scaled` does (a Tikhonov term ``HESSIAN_REG`` on the QP,
the curvature ``LP_REG`` on the LP), solved by the dense dual active set
(:mod:`snakecg.optimize.active_set`), which ends with the point and multipliers of its active
set solved exactly. None when that method gives up (an infeasible task among them): the
caller then takes the general path (qpOASES), which also words the diagnosis.
"""

from __future__ import annotations

from operator import mul

import numpy as np

from . import active_set
from .fast import wheels
from .problems import floats
from .result import CONTACT, HESSIAN_REG, joint_name
from .solvers import LP_REG, Solution


def solve_box_push(model, query, cfg, *, lam_lo=None, equal=False, lp=False):
    """:class:`~snakecg.optimize.solvers.Solution` (``z`` = ``(tau, 1)``) of the least-slip
    QP (``lp`` False) or the strongest-push LP with box limits only, or None."""
    s = query.tau_max.tolist()
    n = len(s)
    if n > active_set.DENSE_MAX:
        return None
    fl = floats(cfg)
    L = fl["L"]
    ell = L[0]
    rows, lo, hi, names = [], [], [], []

    def add(c, a, b, name):
        c = list(map(mul, c, s))
        rn = max(map(abs, c))
        if rn > 0:
            rows.append([x / rn for x in c])
            lo.append(a / rn)
            hi.append(b / rn)
            names.append(name)

    if lam_lo is not None:
        add(ell, lam_lo, lam_lo if equal else np.inf, "")
    if lam_lo is None or lam_lo < 0:  # else implied by the task row
        add(ell, 0.0, np.inf, CONTACT)
    for i, ub, name in wheels(model):
        add(L[i], -ub, ub, name)
    for j in range(n):
        e = [0.0] * n
        e[j] = 1.0
        rows.append(e)
        lo.append(-1.0)
        hi.append(1.0)
        names.append(joint_name(j + 1))
    if lp:
        g = [-a * b for a, b in zip(ell, s)]
        fs = max(map(abs, g))
        fs = fs if fs > 0 else 1.0
        g = [x / fs for x in g]
        H = [[LP_REG if i == j else 0.0 for j in range(n)] for i in range(n)]
    else:
        Xi = fl["Xi"]
        H = [[2.0 * Xi[i][j] * (s[i] * s[j]) for j in range(n)] for i in range(n)]
        fs = max(abs(h) for row in H for h in row)
        fs = fs if fs > 0 else 1.0
        H = [[h / fs for h in row] for row in H]
        reg = HESSIAN_REG * max(max(abs(H[i][i]) for i in range(n)), 1e-300)
        for i in range(n):
            H[i][i] += reg
        g = [0.0] * n
    inf = [np.inf] * n
    out = active_set.solve(H, g, rows, lo, hi, [-np.inf] * n, inf)
    if out is None:
        return None
    y, lam = out[0].tolist(), out[1].tolist()
    big = max(map(abs, lam), default=0.0)
    act = []
    if big > 0:
        for r, v in enumerate(lam):
            if abs(v) > 1e-7 * big:
                ry = sum(map(mul, rows[r], y))
                if min(abs(ry - lo[r]), abs(ry - hi[r])) <= 1e-6:
                    act.append(r)
    binding = tuple(dict.fromkeys(names[r] for r in act if names[r]))
    unique = bool(lp and len(act) >= n
                  and np.linalg.matrix_rank(np.array([rows[r] for r in act]), 1e-9) == n)
    tau = [a * b for a, b in zip(y, s)]
    return Solution(True, np.array(tau + [1.0]), "Successful return.", 1,
                    "dual active set (LP)" if lp else "dual active set", binding, unique)
