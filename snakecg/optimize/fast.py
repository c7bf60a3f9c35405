"""One configuration at a time without Python overhead: the all-held maps through
preallocated one-sample buffers (:class:`snakecg.native.BoundFunction`), and small dense
algebra on plain floats (a 3x3 solve through numpy costs more in call overhead than in
arithmetic).

Everything here is exact arithmetic on the same generated maps as the batched path
(:func:`snakecg.optimize.problems.configs`); a sample whose held rows are dependent takes that
path (it regularises them)."""

from __future__ import annotations

import math
import threading
from operator import mul

import numpy as np

from ..solver import ABSENT, HELD, PIVOT_TOL, _free_and_fixed
from .result import FRICTION_MARGIN, wheel_name

__all__ = ["one_sample_maps", "chol_solve", "matvec", "dot", "quad"]


class _Workspace:
    """``place_object`` and ``interaction_maps`` of one model bound to its constants."""

    def __init__(self, model):
        from ..native import BoundFunction

        be = model.backend
        sc = model.scene
        si = model.scene_inputs
        self.place = BoundFunction(be, "place_object", {
            k: si[k] for k in ("K", "contact_link", "contact_offset", "object_distance", "side")})
        state = np.where(model.present, HELD, ABSENT).astype(np.int8)
        free, lam_fixed = _free_and_fixed(state[None, :], model.bounds)
        self.maps = BoundFunction(be, "interaction_maps", {
            **{k: si[k] for k in ("K", "contact_link", "side", "object_mass", "object_inertia",
                                  "wheel_offset")},
            "free": free[0], "lam_fixed": lam_fixed[0], "regularization": [0.0]})
        self.lock = threading.Lock()
        self.Io = (sc.object_mass, sc.object_mass, sc.object_inertia)


_KEY = "_snakecg_optimize_workspace"


def one_sample_maps(model, q: np.ndarray):
    """``(L, A, Xi, Om, N, Io)`` (fresh arrays; ``Io`` the object's inertia diagonal) of the
    all-held maps at ``q``, or None when the held rows are dependent or the maps are not
    finite (the caller then takes the batched, regularised path)."""
    ws = model.__dict__.get(_KEY)
    if ws is None:
        ws = model.__dict__[_KEY] = _Workspace(model)
    own = ws.lock.acquire(False)
    if not own:  # another thread is using it: a workspace of our own
        ws = _Workspace(model)
    try:
        p = ws.place.one(q=q)
        m = ws.maps.one(q=q, q_obj=p["q_obj"], rho=p["rho"])
        if not m["pivot_ratio"][0] > PIVOT_TOL:
            return None
        n = q.shape[0] - 3  # (one joint: the buffers' views of one column are 1-D)
        out = (m["lam_from_tau"].reshape(-1, n).copy(), m["a_obj_from_tau"].reshape(3, n).copy(),
               m["xi_tau"].reshape(n, n).copy(), m["omega_tau"].reshape(n, n).copy(),
               m["input_metric"].reshape(n, n).copy(), ws.Io)
    finally:
        if own:
            ws.lock.release()
    if not math.isfinite(float(out[0].sum()) + float(out[2].sum()) + float(out[4].sum())):
        return None
    return out


# ------------------------------------------------------------------------------------------
# small dense algebra on lists of floats
def dot(x, y) -> float:
    return sum(map(mul, x, y))


def matvec(M, x) -> list:
    return [sum(map(mul, row, x)) for row in M]


def quad(M, x) -> float:
    return sum(map(mul, x, [sum(map(mul, row, x)) for row in M]))


def chol_solve(M, b, rel: float = 1e-12):
    """``M^-1 b`` for a symmetric positive definite ``M`` (lists) by Cholesky, or None when a
    pivot falls below ``rel`` times the largest diagonal (not safely definite)."""
    n = len(b)
    big = max([M[i][i] for i in range(n)])
    if not big > 0:
        return None
    Lc = []
    for i in range(n):
        Mi = M[i]
        Li = []
        for j in range(i):
            Lj = Lc[j]
            Li.append((Mi[j] - sum(map(mul, Li, Lj))) / Lj[j])
        d = Mi[i] - sum(map(mul, Li, Li))
        if not d > rel * big:
            return None
        Li.append(math.sqrt(d))
        Lc.append(Li)
    y = []
    for i in range(n):
        Li = Lc[i]
        y.append((b[i] - sum(map(mul, Li, y))) / Li[i])
    x = [0.0] * n
    for i in range(n - 1, -1, -1):
        s = y[i]
        for k in range(i + 1, n):
            s -= Lc[k][i] * x[k]
        x[i] = s / Lc[i][i]
    return x


def norm(x) -> float:
    return math.sqrt(sum(map(mul, x, x)))


def frob(M) -> float:
    return math.sqrt(sum([sum(map(mul, row, row)) for row in M]))


def wheels(model) -> list:
    """``(row, bound backed off by FRICTION_MARGIN, name)`` of every bounded wheel (cached)."""
    out = model.__dict__.get("_snakecg_optimize_wheels")
    if out is None:
        out = [(i, float(model.bounds[i]) * (1 - FRICTION_MARGIN), wheel_name(i))
               for i in range(1, model.n_constraints)
               if model.present[i] and np.isfinite(model.bounds[i])]
        model.__dict__["_snakecg_optimize_wheels"] = out
    return out


def primal_violation(model, query, L, tau) -> float:
    """Largest relative violation at ``tau`` of the all-held limits (wheels within their
    backed-off bounds, the box, the contact kept), measured as
    :func:`snakecg.optimize.certificate.kkt` does (relative to ``|G| |tau| + |bound|``)."""
    worst = 0.0
    at = None
    for i, ub, _ in wheels(model):
        row = L[i]
        g = abs(sum(map(mul, row, tau)))
        if g > ub:  # only a violated row needs its size
            at = [abs(t) for t in tau]
            rs = sum(map(mul, map(abs, row), at)) + ub
            worst = max(worst, (g - ub) / (rs if rs > 0 else 1.0))
    if query.tau_max is not None:
        for t, m in zip(tau, query.tau_max.tolist()):
            t = abs(t)
            if t > m:
                worst = max(worst, (t - m) / (t + m))
    ell = L[0]
    g = sum(map(mul, ell, tau))
    if g < 0:
        rs = sum(map(mul, map(abs, ell), map(abs, tau)))
        worst = max(worst, -g / (rs if rs > 0 else 1.0))
    return worst


def ellipsoid_violation(N, r2, tau) -> float:
    e = quad(N, tau)
    if not e > r2:
        return 0.0
    at = [abs(t) for t in tau]
    qs = quad([list(map(abs, row)) for row in N], at) + abs(r2)
    return (e - r2) / (qs if qs > 0 else 1.0)
