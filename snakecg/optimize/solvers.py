"""The numerical solvers of :mod:`snakecg.optimize`: qpOASES (QPs and LPs) and IPOPT
(the convex NLPs of the sliding-wheel search), through CasADi.

History independence. CasADi's qpOASES interface hot-starts every call from the previous
call's working set, and that homotopy can stop at a point that is not the optimum of the new
problem while reporting success; where the optimum is not unique (a least-slip QP with more
than three joints: its form has rank 3) it ends on a point of the optimal face that depends
on what ran before. Here no answer depends on what ran before:

* every small QP and LP (``active_set.DENSE_MAX`` free variables at most) is first solved by
  :mod:`snakecg.optimize.active_set` (a dense dual active set from the unconstrained
  minimiser, no state between calls); qpOASES, as below, when that gives up and for the
  larger problems;
* every qpOASES solve is the first solve of a freshly built solver (qpOASES's ``init``, no
  hot start): building one costs tens of microseconds, less than the reset solve that a
  shared, hot-started solver would need before each problem to forget the last one;
* the solver's active set is then solved exactly (:func:`_polish`), so the answer is a
  function of the active set alone;
* :func:`cold` opens a context in which every QP goes to qpOASES, the small ones too: used to
  re-solve a query whose answer failed its optimality certificate
  (:mod:`snakecg.optimize.certificate`);
* IPOPT starts from the given point every call (no warm start).
"""

from __future__ import annotations

import contextlib
import contextvars
import io
import threading
from dataclasses import dataclass

import numpy as np

from . import active_set
from .polish import LP_REG, binding as _binding, polish as _polish, scaled as _scaled
from .polish import scaled_lists as _scaled_lists
from .result import ELLIPSOID

_QPOASES = {"printLevel": "none", "error_on_fail": False}
_IPOPT = {
    "print_time": False, "error_on_fail": False,
    "ipopt.print_level": 0, "ipopt.sb": "yes", "ipopt.tol": 1e-10,
    "ipopt.acceptable_tol": 1e-8, "ipopt.max_iter": 300, "ipopt.mu_strategy": "adaptive",
    "ipopt.bound_relax_factor": 0.0,
}


def _conic(name: str, n1: int, R: int, lp: bool):
    import casadi as ca

    h = ca.Sparsity(n1, n1) if lp else ca.Sparsity.dense(n1, n1)
    # qpOASES prints its banner through CasADi's output stream when first used
    with contextlib.redirect_stdout(io.StringIO()):
        return ca.conic(name, "qpoases", {"h": h, "a": ca.Sparsity.dense(R, n1)}, _QPOASES)


class Solvers:
    """IPOPT for ``n1`` variables ``z = (tau, t)`` and ``R`` rows, shared by every model and
    query of that size; every use goes through :meth:`ipopt` (under ``lock``). (qpOASES is
    built afresh for every solve: :func:`_qpoases`.)"""

    def __init__(self, n1: int, R: int):
        self.n1, self.R = n1, R
        self.lock = threading.Lock()
        self._nlp = None

    def ipopt(self, **kwargs):
        with self.lock:
            res = self.nlp(**kwargs)
            return res, self.nlp.stats()

    @property
    def nlp(self):
        """IPOPT on ``min 1/2 z^T H z + g^T z`` s.t. ``lba <= A z <= uba`` and the ellipsoid in
        homogeneous form ``tau^T N tau / t - r2 t <= 0`` (``z = (tau, t)``, ``t > 0``).

        The constraint function is convex (a quadratic-over-linear minus a linear term), so
        every problem posed here is convex; with ``t`` fixed to 1 it is ``tau^T N tau <= r2``.
        Parametric in ``(H, g, A, N, r2)``; built on first use."""
        if self._nlp is None:
            import casadi as ca

            n1, R = self.n1, self.R
            n = n1 - 1
            z = ca.SX.sym("z", n1)
            H = ca.SX.sym("H", n1, n1)
            g = ca.SX.sym("g", n1)
            A = ca.SX.sym("A", R, n1)
            N = ca.SX.sym("N", n, n)
            r2 = ca.SX.sym("r2", 1)
            tau, t = z[:n], z[n]
            f = 0.5 * ca.mtimes([z.T, H, z]) + ca.dot(g, z)
            cons = ca.vertcat(ca.mtimes(A, z), ca.mtimes([tau.T, N, tau]) / t - r2 * t)
            p = ca.vertcat(ca.vec(H), g, ca.vec(A), ca.vec(N), r2)
            with contextlib.redirect_stdout(io.StringIO()):
                self._nlp = ca.nlpsol("snakecg_optimize_nlp", "ipopt",
                                      {"x": z, "p": p, "f": f, "g": cons}, _IPOPT)
        return self._nlp

_SOLVERS: dict[tuple[int, int], Solvers] = {}
_SOLVERS_LOCK = threading.Lock()
#: Inside :func:`cold`: the solvers built for it (a dict), else None.
_COLD: contextvars.ContextVar = contextvars.ContextVar("snakecg_optimize_cold", default=None)


def solvers(n1: int, R: int) -> Solvers:
    key = (n1, R)
    with _SOLVERS_LOCK:
        if key not in _SOLVERS:
            _SOLVERS[key] = Solvers(n1, R)
        return _SOLVERS[key]


@contextlib.contextmanager
def cold():
    """Every QP inside is solved by a freshly built qpOASES from scratch (no hot start)."""
    token = _COLD.set({})
    try:
        yield
    finally:
        _COLD.reset(token)


# one problem in z = (tau, t), with named rows
@dataclass
class Problem:
    """``min 1/2 z^T H z + g^T z`` (``H`` None: an LP) s.t. ``lba <= A z <= uba``,
    ``lbx <= z <= ubx`` and, for IPOPT, the ellipsoid ``tau^T N tau <= r^2 t^2`` (``N``,
    ``r2``). ``names[r]`` names row ``r`` ("" = unused or not a limit); ``scale`` are the
    variables' natural sizes (the solvers see ``z / scale``)."""

    H: np.ndarray | None
    g: np.ndarray
    A: np.ndarray
    lba: np.ndarray
    uba: np.ndarray
    lbx: np.ndarray
    ubx: np.ndarray
    names: list
    scale: np.ndarray
    N: np.ndarray | None = None
    r2: float = 0.0


@dataclass
class Solution:
    ok: bool
    z: np.ndarray
    status: str
    iterations: int
    solver: str
    binding: tuple = ()
    unique: bool = False  # a non-degenerate vertex: the LP optimum is the only one


def solve_conic(prob: Problem, polish: bool = True) -> Solution:
    """``prob`` by the dense dual active set when it is small, else (and inside :func:`cold`
    always) by a freshly built qpOASES from scratch. ``ok`` is False when the solver fails.
    ``polish``: solve the active set exactly (:func:`_polish`; every final answer is polished).

    An LP (``prob.H`` None) is solved as the QP with the curvature ``LP_REG`` (scaled
    variables, objective of size 1): at a vertex whose multipliers exceed ``LP_REG`` times the
    torque's size (every non-degenerate LP optimum here) its solution is that vertex exactly
    (the KKT conditions of the vertex hold for both); on a degenerate optimal face it is the
    face's point nearest the origin. (qpOASES's own LP mode is not used: the same solver
    and polish serve both kinds.)"""
    n1 = prob.A.shape[1]
    lp = prob.H is None
    fresh = _COLD.get()
    small = int(np.count_nonzero(prob.lbx != prob.ubx)) <= active_set.DENSE_MAX
    if fresh is None and small:  # the dense dual active set from scratch; else qpOASES
        S = _scaled_lists(prob)
        dense = active_set.solve(*S)
        if dense is not None:
            return _finish(prob, S, dense[0], dense[1], lp, polish,
                           "dual active set (LP)" if lp else "dual active set",
                           "Successful return.")
    H, g, A, lba, uba, lbx, ubx = _scaled(prob)
    name = "qpoases (LP)" if lp else "qpoases"
    if lp:
        H = LP_REG * np.eye(n1)
    if fresh is not None:
        name += ", cold re-solve"
    out, status = _qpoases(H, g, A, lba, uba, lbx, ubx)
    if out is None or not np.all(np.isfinite(out)):
        return Solution(False, np.zeros(n1), status, 1, name)
    return _finish(prob, (H, g, A, lba, uba, lbx, ubx), out[:n1], out[n1:], lp, polish, name,
                   status)


def _qpoases(H, g, A, lba, uba, lbx, ubx):
    """``([x, lam_a], status)`` of the QP solved by a freshly built qpOASES (its first solve:
    no hot start, nothing shared between calls or threads); ``None`` for ``x`` when it fails.
    qpOASES reports an infeasible QP on stdout: kept off it (``--json``)."""
    f = _conic("snakecg_optimize_qp", g.size, A.shape[0], lp=False)
    with contextlib.redirect_stdout(io.StringIO()):
        res = f(h=H, g=g, a=A, lba=lba, uba=uba, lbx=lbx, ubx=ubx)
    st = f.stats()
    status = str(st.get("return_status", ""))
    if not st.get("success", False):
        return None, status or "qpOASES: infeasible or failed"
    return np.concatenate([res["x"].full().ravel(), res["lam_a"].full().ravel()]), status


def _finish(prob, scaled, zs, lam_a, lp, polish, name, status) -> Solution:
    """Polish the solver's point on its active set, name the binding rows, and tell whether
    an LP vertex is the only optimum."""
    n1 = zs.size
    if polish:
        zs = _polish(*scaled, zs, lam_a)
    A, lba, uba = scaled[2], scaled[3], scaled[4]
    binding, rows = _binding(prob, zs, A, lba, uba, lam_a)
    unique = False
    # an LP vertex with n independent rows active, all with non-zero multipliers (t fixed):
    # no other point reaches the optimum
    n = n1 - 1
    if (lp and prob.lbx[n] == prob.ubx[n] and len(rows) >= n
            and np.linalg.matrix_rank(np.asarray(A)[rows, :n], 1e-9) == n):
        unique = True
    return Solution(True, zs * prob.scale, status, 1, name, binding, unique)


def solve_ipopt(prob: Problem, z0: np.ndarray) -> Solution:
    """IPOPT on the problem with the ellipsoid constraint (convex), started at ``z0``."""
    n1, R = prob.A.shape[1], prob.A.shape[0]
    n = n1 - 1
    sv = solvers(n1, R)
    H, g, A, lba, uba, lbx, ubx = _scaled(prob)
    if H is None:
        H = np.zeros((n1, n1))
    # rows that only relax the ellipsoid (its bounding box) would make the active set
    # degenerate at the solution: drop them
    drop = np.array([nm == ELLIPSOID for nm in prob.names])
    A = np.where(drop[:, None], 0.0, A)
    lba = np.where(drop, -np.inf, lba)
    uba = np.where(drop, np.inf, uba)
    s = prob.scale
    Ns = prob.N * np.outer(s[:n], s[:n])
    lbx = lbx.copy()
    lbx[n] = max(lbx[n], 1e-9 * max(z0[n] / s[n], 1e-300))  # t > 0
    p = np.concatenate([H.ravel("F"), g, A.ravel("F"), Ns.ravel("F"), [prob.r2]])
    res, st = sv.ipopt(x0=z0 / s, p=p, lbx=lbx, ubx=ubx,
                       lbg=np.concatenate([lba, [-np.inf]]), ubg=np.concatenate([uba, [0.0]]))
    zs = res["x"].full().ravel()
    status = str(st.get("return_status", ""))
    ok = status in ("Solve_Succeeded", "Solved_To_Acceptable_Level") and bool(
        np.all(np.isfinite(zs)))
    lam_g = res["lam_g"].full().ravel()
    t = zs[n]
    e = zs[:n] @ Ns @ zs[:n]
    q_active = abs(e - prob.r2 * t * t) <= 1e-6 * prob.r2 * t * t
    extra = ((ELLIPSOID, lam_g[-1]),) if q_active else ()
    binding = _binding(prob, zs, A, lba, uba, lam_g[:-1], extra)[0] if ok else ()
    return Solution(ok, zs * s, status, int(st.get("iter_count", 0) or 0), "ipopt", binding)


def inside(query, cfg, tau):
    """``tau`` within the ellipsoid (or no ellipsoid), to 1e-9 relative."""
    return query.radius is None or tau @ cfg.N @ tau <= query.radius**2 * (1 + 1e-9)


def solve_ellipsoid(query, cfg, prob: Problem, phi0: float) -> Solution:
    """Exact solve of a convex push problem (``t`` fixed to 1) with the ellipsoid
    ``tau^T N tau <= r^2`` when the linear relaxation's optimum (``phi0 = tau^T N tau`` there)
    lies outside it.

    The ellipsoid is then active; its multiplier ``mu > 0`` solves ``phi(mu) = r^2``, where
    ``phi(mu) = tau(mu)^T N tau(mu)`` and ``tau(mu)`` minimises the Lagrangian
    ``1/2 z^T (H + 2 mu N) z + g^T z`` over the linear constraints: a QP (qpOASES). ``phi``
    decreases with ``mu``; the root is bracketed by growing ``mu`` tenfold, then found by
    regula falsi (Illinois) on ``1/sqrt(phi)``, nearly linear in ``mu``. Converges to
    ``|phi / r^2 - 1| <= 1e-11``, i.e. the optimum to solver precision (IPOPT's interior
    point stops near 1e-6 relative on these ill-conditioned forms)."""
    n = cfg.N.shape[0]
    r2 = query.radius**2
    H0 = np.zeros((n + 1, n + 1)) if prob.H is None else prob.H
    Nz = np.zeros((n + 1, n + 1))
    Nz[:n, :n] = cfg.N
    gt = prob.g[:n]
    # natural size of mu: balance the objective's curvature (or the linear term alone,
    # tau = N^-1 g / (2 mu)) against N
    mu = max(np.trace(H0[:n, :n]) / np.trace(cfg.N),
             np.sqrt(max(gt @ np.linalg.solve(cfg.N, gt), 0.0) / (4 * r2)), 1e-300)
    iters = 0

    def phi(m):
        nonlocal iters
        trial = Problem(H=H0 + 2 * m * Nz, g=prob.g, A=prob.A, lba=prob.lba, uba=prob.uba,
                         lbx=prob.lbx, ubx=prob.ubx, names=prob.names, scale=prob.scale)
        sol = solve_conic(trial)
        iters += 1
        return (sol.z[:n] @ cfg.N @ sol.z[:n] if sol.ok else np.nan), sol

    lo, f_lo = 0.0, 1.0 / np.sqrt(phi0) - 1.0 / np.sqrt(r2)  # < 0
    hi = mu
    for _ in range(60):
        p_hi, sol = phi(hi)
        if not np.isfinite(p_hi):
            return Solution(False, sol.z, sol.status, iters, "qpoases (ellipsoid multiplier)")
        f_hi = 1.0 / np.sqrt(max(p_hi, 1e-300)) - 1.0 / np.sqrt(r2)
        if f_hi >= 0:
            break
        lo, f_lo, hi = hi, f_hi, hi * 10.0
    else:  # even the least-effort point of the linear constraints is outside: infeasible
        return Solution(False, sol.z, "the ellipsoid and the linear limits do not intersect",
                         iters, "qpoases (ellipsoid multiplier)", (ELLIPSOID,))
    best = sol
    side = 0
    for _ in range(100):
        if abs(p_hi / r2 - 1.0) <= 1e-11 or hi - lo <= 1e-15 * hi:
            break
        m = hi - f_hi * (hi - lo) / (f_hi - f_lo)
        if not lo < m < hi:
            m = 0.5 * (lo + hi)
        p_m, sol = phi(m)
        if not np.isfinite(p_m):
            break
        f_m = 1.0 / np.sqrt(max(p_m, 1e-300)) - 1.0 / np.sqrt(r2)
        if f_m >= 0:
            hi, f_hi, p_hi, best = m, f_m, p_m, sol
            if side == 1:
                f_lo *= 0.5
            side = 1
        else:
            lo, f_lo = m, f_m
            if side == -1:
                f_hi *= 0.5
            side = -1
    # ``best`` is the feasible side (phi <= r^2) of the bracket
    return Solution(True, best.z, best.status, iters, "qpoases (ellipsoid multiplier)",
                     tuple(dict.fromkeys(best.binding + (ELLIPSOID,))))

