"""Optimal torque queries: the paper's closing question as a millisecond query.

"For a given task and configuration, an analysis can be carried out to find the optimal input
(vector of joint torques) to minimize or maximize slippage of the system" (Reyes & Ma 2017,
Discussion). Three queries, all at rest (``v = 0``, no external wrench on the object):

* ``"max_sr"``: the torque that maximises the slippage ratio ``sr`` (eq. 30) over the input
  region, with the contact kept and, in the ``wheels`` scenario, every wheel within its
  friction bound unless it is explicitly allowed to slide;
* ``"least_slip_push"``: the torque that gives the object a requested acceleration (at least
  ``a_min`` along a direction, or a full planar acceleration) with the least snake motion
  ``||qdd_s||^2 = qdd^T M_s qdd`` (eq. 26), every wheel sticking;
* ``"strongest_push"``: the largest object acceleration along a direction with no wheel sliding
  and the torques within their limits (ties broken by the least ``||qdd_s||^2``).

The input region is the ellipsoid of eq. (31), ``tau^T N tau <= radius^2`` with
``N = B^T M_s^-1 B`` (``radius = 1`` is the paper's region), the box ``|tau_j| <= tau_max_j``,
or both.

Structure used (see docs/optimize.md for the derivations):

1. With every constraint row held (contact kept, wheels sticking) the system at rest is
   linear in ``tau`` (eqs. 17, 22, 24): ``lam = L tau``, ``a_obj = A tau``,
   ``qdd = Q tau``; "contact kept" is ``L_c tau >= 0`` and "no wheel slides" is
   ``|L_i tau| <= mu m_i g``: linear inequalities. ``least_slip_push`` is then a convex QP
   and ``strongest_push`` an LP (qpOASES through ``casadi.conic``). With the ellipsoid they
   are convex QCQPs: the linear relaxation (the ellipsoid's bounding box) is solved first;
   if its answer leaves the ellipsoid, the ellipsoid's multiplier ``mu`` is found by root
   finding on ``tau(mu)^T N tau(mu) = r^2``, each step a QP (exact to solver precision).
2. One frictionless point contact (assumptions 2 and 6) pushes the object only along its
   normal: ``a_obj = a_dir * lam_c`` for a fixed ``a_dir``, so every push task is a bound on
   the contact force ``lam_c = L_c tau``, and a requested acceleration off ``a_dir`` is
   infeasible whatever the torques (reported as such).
3. ``sr`` with everything held is the generalized Rayleigh quotient
   ``tau^T Omega tau / tau^T (Omega + Xi) tau`` (eqs. 28-30), homogeneous of degree 0: the
   top generalized eigenvector of ``(Omega, Omega + Xi)``, signed so that ``lam_c >= 0``,
   is the maximiser over every region that is star-shaped about 0, including the friction
   polytope; it is returned at the largest magnitude that keeps every limit (exact).
4. When wheels may slide, the map is piecewise affine: each wheel state (stick, slide+,
   slide-) has its own affine map, valid on a polyhedral cone of ``z = (tau, 1)``. With the
   rank-one numerator ``||a_obj||^2 = k lam_c^2``, ``max sr`` on one state is the convex
   problem ``min z^T Xi_h z`` subject to ``lam_c(z) = 1``, the state's validity cone and the
   region in homogeneous form (Charnes-Cooper): a QP per state; where the ellipsoid cuts
   the state's optimum, tangent-plane cuts, then a convex NLP (IPOPT) if the state can still
   win. States are pruned by an exact upper bound (the problem without the cone) before any
   solve; the candidates are ranked by the exact forward solve.

Every answer is checked with :meth:`SceneModel.forward`; a disagreement (a wheel that slides
although it was kept, a different objective value, a violated limit) turns the status into
``"failed"`` with the reason. Solvers are built once per problem size and shared by every model
with that joint count; qpOASES is hot-started from the previous query's working set (CasADi
keeps it between calls), IPOPT starts from the relaxation's solution.
"""

from __future__ import annotations

import contextlib
import io
import itertools
import time
from dataclasses import dataclass, field

import numpy as np

from .errors import InputError
from .solver import ABSENT, HELD, PIVOT_TOL, SLIDE_NEG, SLIDE_POS, _free_and_fixed

__all__ = ["optimize", "OptimizeResult", "OBJECTIVES", "STATUSES", "SCHEMA"]

#: Objective names (the CLI spells them with dashes).
OBJECTIVES = ("max_sr", "least_slip_push", "strongest_push")
STATUSES = ("optimal", "infeasible", "failed")
#: Version of :meth:`OptimizeResult.to_dict` and ``snakecg optimize --json`` (docs/optimize.md).
SCHEMA = "snakecg.optimize/1"

#: Relative back-off from the friction bounds, so the exact forward solve sees the wheels stick.
FRICTION_MARGIN = 1e-7
#: Relative tolerance of the forward check on the objective value.
CHECK_TOL = 1e-6
#: A wheel state's sr must beat the best so far by this much (absolute) to be taken: on ties
#: (a state's optimum on the boundary with another state) the exact all-stick answer is kept.
SR_TIE = 1e-9
#: Relative Tikhonov term added to the (semidefinite) QP Hessians, in scaled variables.
HESSIAN_REG = 1e-11

# names of the constraints, as reported in ``binding`` and in reasons
ELLIPSOID = "input ellipsoid (eq. 31)"
CONTACT = "contact would separate"
NORMAL = "contact normal (the frictionless contact pushes along its normal only)"


def _joint(j: int) -> str:
    return f"torque limit on joint {j}"


def _wheel(i: int) -> str:
    return f"friction bound of the wheel on link {i}"


# ------------------------------------------------------------------------------------------
@dataclass
class OptimizeResult:
    """Outcome of :func:`optimize` for one configuration, or a batch (leading axis N).

    * ``tau`` (n_a): the torque (N m). For ``"infeasible"`` push tasks: the strongest push
      that the limits allow (the closest one can get), or zeros when nothing pushes.
    * ``status``: ``"optimal"``, ``"infeasible"`` or ``"failed"``; ``reason``: ``""`` when
      optimal, else what makes it so (names the binding limit or bound).
    * ``objective_value``: ``sr`` (max_sr), ``||qdd_s||^2`` of eq. 26 (least_slip_push) or
      ``d . a_obj`` (strongest_push, m/s^2), all read from ``analysis``.
    * ``binding``: names of the constraints active at ``tau`` that limit the objective, e.g.
      ``"torque limit on joint 2"``, ``"friction bound of the wheel on link 3"``,
      ``"input ellipsoid (eq. 31)"``, ``"contact would separate"``.
    * ``analysis``: :class:`~snakecg.ForwardResult` at ``tau`` (the exact forward solve).
    * ``solver``: what produced ``tau``; ``iterations``: solver iterations (for max_sr with
      sliding wheels: QPs solved plus IPOPT iterations); ``time``: wall-clock seconds of the
      query (batched: the batch's time divided evenly).
    * ``wheel_states_assumed``: max_sr with sliding wheels, when a wheel state other than
      "every wheel sticks" won: that state per link (``"none"``, ``"stick"``, ``"slide+"``,
      ``"slide-"``); else ``None``. ``analysis.wheel_state`` is what the forward solve found
      (the same, or a neighbouring state on their common boundary).
    """

    objective: str
    tau: np.ndarray
    status: object
    reason: object
    objective_value: object
    binding: object
    analysis: object
    solver: object
    iterations: object
    time: object
    wheel_states_assumed: object = field(default=None, repr=False)

    @property
    def ok(self):
        """``status == "optimal"`` (array for a batch)."""
        return np.asarray(self.status) == "optimal"

    def to_dict(self) -> dict:
        """JSON-ready dictionary (schema ``snakecg.optimize/1``, docs/optimize.md)."""
        an = self.analysis.to_dict()
        for k in ("contact", "singular"):
            v = np.asarray(getattr(self.analysis, k))
            an[k] = v.tolist() if v.ndim else bool(v)
        out = {
            "objective": self.objective,
            "status": _plain(self.status),
            "reason": _plain(self.reason),
            "objective_value": _plain(self.objective_value),
            "tau": np.asarray(self.tau).tolist(),
            "binding": _plain(self.binding),
            "solver": _plain(self.solver),
            "iterations": _plain(self.iterations),
            "time_s": _plain(self.time),
            "analysis": an,
        }
        return out


def _plain(v):
    if isinstance(v, np.ndarray):
        return v.tolist()
    if isinstance(v, (list, tuple)):
        return [_plain(x) for x in v]
    if isinstance(v, np.generic):
        return v.item()
    return v


# ------------------------------------------------------------------------------------------
# input validation
@dataclass(frozen=True)
class _Query:
    objective: str
    tau_max: np.ndarray | None  # (n,) or None
    radius: float | None
    direction: np.ndarray | None  # unit (3,) or None
    a_min: float | None
    a_obj: np.ndarray | None  # (3,)
    slide: np.ndarray  # (n_c,) bool: rows allowed to slide


def _finite_vector(name, value, sizes, what):
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be {what}, got {value!r}") from None
    if arr.ndim != 1 or arr.shape[0] not in sizes:
        raise InputError(f"{name} has shape {arr.shape}, expected {what}")
    if not np.all(np.isfinite(arr)):
        raise InputError(f"{name} must be finite, got {arr.tolist()}")
    return arr


def _validate(model, objective, tau_max, radius, direction, a_min, a_obj, allow_slide):
    from .model import SceneModel

    if not isinstance(model, SceneModel):
        raise InputError(
            f"model must be a snakecg.SceneModel (snakecg.load(scene)), got {type(model).__name__}"
        )
    if not isinstance(objective, str) or objective.replace("-", "_") not in OBJECTIVES:
        raise InputError(
            f"objective must be one of {', '.join(OBJECTIVES)} (dashes allowed), got {objective!r}"
        )
    objective = objective.replace("-", "_")
    na = model.n_joints
    if tau_max is not None:
        if np.ndim(tau_max) == 0:
            tau_max = np.full(na, tau_max, dtype=float) if _is_number(tau_max) else tau_max
        tm = _finite_vector("tau_max", tau_max, (na,),
                            f"a positive number or {na} positive numbers (N m), one per joint")
        if np.any(tm <= 0):
            raise InputError(f"tau_max must be positive (N m), got {tm.tolist()}")
        tau_max = tm
    if radius is not None:
        if not _is_number(radius) or not np.isfinite(radius) or radius <= 0:
            raise InputError(f"radius must be a positive number (the ellipsoid "
                             f"tau^T B^T M_s^-1 B tau <= radius^2 of eq. 31), got {radius!r}")
        radius = float(radius)
    if tau_max is None and radius is None:
        radius = 1.0  # the paper's input region, eq. (31)
    # task arguments
    given = {k for k, v in (("direction", direction), ("a_min", a_min), ("a_obj", a_obj))
             if v is not None}
    allowed = {"max_sr": set(), "least_slip_push": {"direction", "a_min", "a_obj"},
               "strongest_push": {"direction"}}[objective]
    extra = given - allowed
    if extra:
        raise InputError(f"{', '.join(sorted(extra))} do(es) not apply to objective "
                         f"{objective!r} (it takes: {', '.join(sorted(allowed)) or 'no task'})")
    d = None
    if direction is not None:
        d = _finite_vector("direction", direction, (2, 3),
                           "(dx, dy) or (dx, dy, dalpha): the direction of the object's "
                           "acceleration, world frame")
        if np.linalg.norm(d) == 0:
            raise InputError("direction must be non-zero")
        d = np.r_[d, 0.0] if d.shape[0] == 2 else d
        d = d / np.linalg.norm(d)
    if a_min is not None:
        if not _is_number(a_min) or not np.isfinite(a_min) or a_min < 0:
            raise InputError(f"a_min must be a number >= 0 (m/s^2), got {a_min!r}")
        a_min = float(a_min)
    ao = None
    if a_obj is not None:
        ao = _finite_vector("a_obj", a_obj, (3,),
                            "(a_x, a_y, alpha): the object's planar acceleration (m/s^2, rad/s^2)")
    if objective == "least_slip_push":
        if ao is not None and (d is not None or a_min is not None):
            raise InputError("least_slip_push takes either a_obj (a full planar acceleration) "
                             "or direction and a_min, not both")
        if ao is None and (d is None or a_min is None):
            raise InputError("least_slip_push needs a task: direction=(dx, dy) and a_min "
                             "(m/s^2), or a_obj=(a_x, a_y, alpha)")
    # wheels allowed to slide
    bounded = model.present & np.isfinite(model.bounds)
    bounded[0] = False
    slide = np.zeros(model.n_constraints, dtype=bool)
    if allow_slide is True:
        slide = bounded.copy()
    elif allow_slide is False or allow_slide is None:
        pass
    else:
        try:
            links = [int(x) for x in allow_slide]
            if any(int(x) != x for x in allow_slide):
                raise ValueError
        except (TypeError, ValueError):
            raise InputError(f"allow_slide must be True, False or a list of link numbers, "
                             f"got {allow_slide!r}") from None
        for i in links:
            if not 1 <= i <= model.n_links or not bounded[i]:
                have = [int(r) for r in np.flatnonzero(bounded)]
                raise InputError(
                    f"allow_slide: link {i} has no wheel with a friction bound (links with one:"
                    f" {have or 'none'}; only the 'wheels' scenario bounds wheel forces)")
            slide[i] = True
    if slide.any() and objective != "max_sr":
        raise InputError("allow_slide applies to objective 'max_sr' only; push tasks keep "
                         "every wheel within its friction bound")
    return _Query(objective, tau_max, radius, d, a_min, ao, slide)


def _is_number(x) -> bool:
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool)


# ------------------------------------------------------------------------------------------
# solvers: built once per problem size, shared across models and queries
_QPOASES = {"printLevel": "none", "error_on_fail": False}
_IPOPT = {
    "print_time": False, "error_on_fail": False,
    "ipopt.print_level": 0, "ipopt.sb": "yes", "ipopt.tol": 1e-10,
    "ipopt.acceptable_tol": 1e-8, "ipopt.max_iter": 300, "ipopt.mu_strategy": "adaptive",
    "ipopt.bound_relax_factor": 0.0,
}


class _Solvers:
    """qpOASES (QP and LP) and IPOPT for ``n1`` variables ``z = (tau, t)`` and ``R`` rows."""

    def __init__(self, n1: int, R: int):
        import casadi as ca

        self.n1, self.R = n1, R
        # qpOASES prints its banner through CasADi's output stream when constructed. CasADi
        # initialises qpOASES on a solver's first call and hot-starts it from the previous
        # call's working set afterwards.
        with contextlib.redirect_stdout(io.StringIO()):
            self.qp = ca.conic("snakecg_optimize_qp", "qpoases",
                               {"h": ca.Sparsity.dense(n1, n1), "a": ca.Sparsity.dense(R, n1)},
                               _QPOASES)
            self.lp = ca.conic("snakecg_optimize_lp", "qpoases",
                               {"h": ca.Sparsity(n1, n1), "a": ca.Sparsity.dense(R, n1)},
                               _QPOASES)
        self._nlp = None
        self._packed = None

    @property
    def packed(self):
        """The QP solver behind one flat input and one flat output,
        ``[vec(H), g, vec(A), lba, uba, lbx, ubx] -> [x, lam_a]``: a call converts two arrays
        instead of seventeen (about half the cost of a small QP). A failed solve (an
        infeasible problem) raises instead of returning a status."""
        if self._packed is None:
            import casadi as ca

            n1, R = self.n1, self.R
            sizes = (n1 * n1, n1, R * n1, R, R, n1, n1)
            P = ca.MX.sym("P", sum(sizes))
            parts = ca.vertsplit(P, list(np.cumsum((0,) + sizes)))
            res = self.qp(h=ca.reshape(parts[0], n1, n1), g=parts[1],
                          a=ca.reshape(parts[2], R, n1), lba=parts[3], uba=parts[4],
                          lbx=parts[5], ubx=parts[6])
            packed = ca.Function("snakecg_optimize_qp_packed", [P],
                                 [ca.vertcat(res["x"], res["lam_a"])])
            # the first evaluation creates qpOASES's workspace, which prints a banner
            trivial = np.concatenate([np.eye(n1).ravel(), np.zeros(n1 + R * n1),
                                      np.full(R, -np.inf), np.full(R, np.inf),
                                      np.full(n1, -np.inf), np.full(n1, np.inf)])
            with contextlib.redirect_stdout(io.StringIO()):
                packed(trivial)
            self._packed = packed
        return self._packed

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


_SOLVERS: dict[tuple[int, int], _Solvers] = {}


def _solvers(n1: int, R: int) -> _Solvers:
    key = (n1, R)
    if key not in _SOLVERS:
        _SOLVERS[key] = _Solvers(n1, R)
    return _SOLVERS[key]


# ------------------------------------------------------------------------------------------
# one problem in z = (tau, t), with named rows
@dataclass
class _Problem:
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
class _Solution:
    ok: bool
    z: np.ndarray
    status: str
    iterations: int
    solver: str
    binding: tuple = ()
    unique: bool = False  # a non-degenerate vertex: the LP optimum is the only one


def _scaled(prob: _Problem):
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


def _binding(prob, zs, A, lba, uba, lam_a, extra=()):
    """Rows active at ``zs`` (scaled) with a non-zero multiplier: their names (deduplicated)
    and their indices."""
    lam_a = np.asarray(lam_a).ravel()
    big = max(np.abs(lam_a).max(initial=0.0), max((abs(v) for _, v in extra), default=0.0))
    if big <= 0:
        return (), []
    Az = A @ zs
    slack = np.minimum(np.abs(Az - lba), np.abs(Az - uba))
    rows = [r for r in range(len(lam_a))
            if abs(lam_a[r]) > 1e-7 * big and slack[r] <= 1e-6]
    out = [prob.names[r] for r in rows if prob.names[r]]
    out += [name for name, v in extra if abs(v) > 1e-7 * big]
    return tuple(dict.fromkeys(out)), rows


def _solve_conic_fast(prob: _Problem) -> _Solution:
    """A QP through the packed solver (its own hot start, no status string): for the many small
    QPs of the wheel-state search. ``ok`` is False for an infeasible (or failed) problem."""
    n1, R = prob.A.shape[1], prob.A.shape[0]
    sv = _solvers(n1, R)
    H, g, A, lba, uba, lbx, ubx = _scaled(prob)
    P = np.concatenate([H.ravel("F"), g, A.ravel("F"), lba, uba, lbx, ubx])
    try:
        out = sv.packed(P).full().ravel()
    except RuntimeError:
        return _Solution(False, np.zeros(n1), "qpOASES: infeasible or failed", 1, "qpoases")
    zs, lam_a = out[:n1], out[n1:]
    if not np.all(np.isfinite(zs)):
        return _Solution(False, np.zeros(n1), "qpOASES: not finite", 1, "qpoases")
    binding, _ = _binding(prob, zs, A, lba, uba, lam_a)
    return _Solution(True, zs * prob.scale, "Successful return.", 1, "qpoases", binding)


def _solve_conic(prob: _Problem) -> _Solution:
    """qpOASES (QP, or LP when ``prob.H`` is None), hot-started from the previous solve's
    working set (CasADi's qpOASES interface does this itself; it takes no initial guess)."""
    n1, R = prob.A.shape[1], prob.A.shape[0]
    sv = _solvers(n1, R)
    H, g, A, lba, uba, lbx, ubx = _scaled(prob)
    args = dict(g=g, a=A, lba=lba, uba=uba, lbx=lbx, ubx=ubx)
    if H is None:
        res = sv.lp(**args)
        st = sv.lp.stats()
        name = "qpoases (LP)"
    else:
        res = sv.qp(h=H, **args)
        st = sv.qp.stats()
        name = "qpoases"
    zs = res["x"].full().ravel()
    ok = bool(st.get("success", False)) and bool(np.all(np.isfinite(zs)))
    binding, rows, unique = (), [], False
    if ok:
        lam_a = res["lam_a"].full().ravel()
        binding, rows = _binding(prob, zs, A, lba, uba, lam_a)
        # an LP vertex with n independent rows active, all with non-zero multipliers
        # (t fixed): no other point reaches the optimum
        n = n1 - 1
        fixed_t = prob.lbx[n] == prob.ubx[n]
        if (H is None and fixed_t and len(rows) >= n
                and np.linalg.matrix_rank(A[rows, :n], 1e-9) == n):
            unique = True
    return _Solution(ok, zs * prob.scale, str(st.get("return_status", "")),
                     int(st.get("iter_count", 0) or 0), name, binding, unique)


def _solve_ipopt(prob: _Problem, z0: np.ndarray) -> _Solution:
    """IPOPT on the problem with the ellipsoid constraint (convex), started at ``z0``."""
    n1, R = prob.A.shape[1], prob.A.shape[0]
    n = n1 - 1
    sv = _solvers(n1, R)
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
    res = sv.nlp(x0=z0 / s, p=p, lbx=lbx, ubx=ubx, lbg=np.concatenate([lba, [-np.inf]]),
                 ubg=np.concatenate([uba, [0.0]]))
    st = sv.nlp.stats()
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
    return _Solution(ok, zs * s, status, int(st.get("iter_count", 0) or 0), "ipopt", binding)


# ------------------------------------------------------------------------------------------
# per-configuration data
@dataclass
class _Config:
    q: np.ndarray
    L: np.ndarray  # (n_c, n) lam = L tau (everything held)
    Xi: np.ndarray  # eq. 28
    Om: np.ndarray  # eq. 29
    N: np.ndarray  # input metric
    a_dir: np.ndarray  # (3,) a_obj = a_dir * lam_c
    k: float  # ||a_dir||^2 in the object's metric
    singular: bool
    widths: np.ndarray | None = None  # half-widths of the box rows (set per query)


def _configs(model, qa: np.ndarray) -> list[_Config]:
    n = qa.shape[0]
    state = np.where(model.present, HELD, ABSENT).astype(np.int8)
    mp = model._maps(qa, n, state)
    Io = np.array([model.scene.object_mass, model.scene.object_mass, model.scene.object_inertia])
    out = []
    for b in range(n):
        L = mp["lam_from_tau"][b]
        A = mp["a_obj_from_tau"][b]
        ell = L[0]
        ll = ell @ ell
        a_dir = A @ ell / ll if ll > 0 else np.zeros(3)
        out.append(_Config(
            q=qa[b], L=L, Xi=mp["xi_tau"][b], Om=mp["omega_tau"][b],
            N=mp["input_metric"][b], a_dir=a_dir, k=float(a_dir @ (Io * a_dir)),
            singular=bool(mp["singular"][b]) if "singular" in mp
            else not mp["pivot_ratio"][b] > PIVOT_TOL,
        ))
    return out


def _region_box(query: _Query, cfg: _Config) -> np.ndarray:
    """Half-widths of the box rows: the box limits, or the ellipsoid's bounding box, or both."""
    if cfg.widths is not None:
        return cfg.widths
    widths = np.full(cfg.N.shape[0], np.inf)
    if query.radius is not None:
        widths = query.radius * np.sqrt(np.diag(np.linalg.inv(cfg.N)))
    if query.tau_max is not None:
        widths = np.minimum(widths, query.tau_max)
    cfg.widths = widths
    return widths


def _rows(model, query: _Query, cfg: _Config):
    """Empty row layout: task (0), contact (1), wheels (2 per row), box (2 per joint)."""
    n, nc = cfg.N.shape[0], model.n_constraints
    R = 2 + 2 * (nc - 1) + 2 * n
    A = np.zeros((R, n + 1))
    lba = np.full(R, -np.inf)
    uba = np.full(R, np.inf)
    names = [""] * R
    # box rows: tau_j + w_j t >= 0, w_j t - tau_j >= 0
    widths = _region_box(query, cfg)
    box_name = [_joint(j + 1) if query.tau_max is not None and
                (query.radius is None or query.tau_max[j] <= widths[j] * (1 + 1e-12))
                else ELLIPSOID for j in range(n)]
    base = 2 + 2 * (nc - 1)
    for j in range(n):
        for sgn, r in ((1.0, base + 2 * j), (-1.0, base + 2 * j + 1)):
            A[r, j] = sgn
            A[r, n] = widths[j]
            lba[r] = 0.0
            names[r] = box_name[j]
    return A, lba, uba, names


def _stick_rows(model, cfg, A, lba, uba, names, L_h, slide_state=None, W_h=None):
    """Wheel rows: stick (``|lam_i| <= u_i t``) or the sliding sign condition on ``w_i``."""
    n = cfg.N.shape[0]
    for i in range(1, model.n_constraints):
        u = model.bounds[i]
        if not model.present[i] or not np.isfinite(u):
            continue
        r = 2 + 2 * (i - 1)
        s = HELD if slide_state is None else slide_state[i]
        if s == HELD:
            ub = u * (1 - FRICTION_MARGIN)
            A[r, :] = -L_h[i]
            A[r, n] += ub
            A[r + 1, :] = L_h[i]
            A[r + 1, n] += ub
            lba[r] = lba[r + 1] = 0.0
            names[r] = names[r + 1] = _wheel(i)
        elif s == SLIDE_POS:  # force at +u, the wheel slides with w_i <= 0
            A[r, :] = -W_h[i]
            lba[r] = 0.0
            names[r] = _wheel(i)
        elif s == SLIDE_NEG:
            A[r, :] = W_h[i]
            lba[r] = 0.0
            names[r] = _wheel(i)


def _scale_of(query, cfg):
    w = _region_box(query, cfg)
    return np.append(w, 1.0)


def _homog(M, c=None):
    """``[M, c]``: a map in ``tau`` extended to ``z = (tau, t)`` (offset ``c``, default 0)."""
    c = np.zeros(M.shape[0]) if c is None else c
    return np.hstack([M, c[:, None]])


# ------------------------------------------------------------------------------------------
# objectives
@dataclass
class _Answer:
    tau: np.ndarray
    status: str
    reason: str
    binding: tuple
    solver: str
    iterations: int
    expected: float | None  # the optimiser's objective value (checked against forward)
    states: np.ndarray | None = None  # assumed row states (max_sr with sliding)


def _max_scale(model, query, cfg, v):
    """Largest ``s > 0`` with ``s v`` inside every limit; and the limits that set it."""
    cands = []
    if query.radius is not None:
        cands.append((query.radius / np.sqrt(max(v @ cfg.N @ v, 1e-300)), ELLIPSOID))
    if query.tau_max is not None:
        for j in range(len(v)):
            if abs(v[j]) > 0:
                cands.append((query.tau_max[j] / abs(v[j]), _joint(j + 1)))
    for i in range(1, model.n_constraints):
        u = model.bounds[i]
        if model.present[i] and np.isfinite(u):
            li = cfg.L[i] @ v
            if abs(li) > 0:
                cands.append((u * (1 - FRICTION_MARGIN) / abs(li), _wheel(i)))
    s = min(c for c, _ in cands)
    binding = tuple(dict.fromkeys(nm for c, nm in cands if c <= s * (1 + 1e-9)))
    return s, binding


def _top_rayleigh(Om, D):
    """Top generalized eigenpair of ``(Om, D)``, ``D`` positive semidefinite: restricted to
    the range of ``D`` (directions outside it move nothing, ``sr`` is 0/0 there)."""
    w, V = np.linalg.eigh(0.5 * (D + D.T))
    keep = w > 1e-12 * max(w[-1], 1e-300)
    Vr = V[:, keep] / np.sqrt(w[keep])
    C = Vr.T @ Om @ Vr
    lw, U = np.linalg.eigh(0.5 * (C + C.T))
    return float(lw[-1]), Vr @ U[:, -1]


def _max_sr(model, query, cfg) -> _Answer:
    n = cfg.N.shape[0]
    ell = cfg.L[0]
    if cfg.k <= 0 or not np.any(ell):
        return _Answer(np.zeros(n), "infeasible",
                       "no torque accelerates the object at this configuration (sr = 0 for "
                       "every torque)", (CONTACT,), "generalized eigenproblem", 0, None)
    lam, v = _top_rayleigh(cfg.Om, cfg.Om + cfg.Xi)
    if ell @ v < 0:
        v = -v  # keep the contact: lam_c = L_c tau >= 0
    s, binding = _max_scale(model, query, cfg, v)
    best = _Answer(s * v, "optimal", "", binding, "generalized eigenproblem", 0,
                   float(np.clip(lam, 0.0, 1.0)))
    if query.slide.any():
        best = _max_sr_sliding(model, query, cfg, best)
    return best


def _slide_states(model, slide):
    choices = [(HELD,)]
    for i in range(1, model.n_constraints):
        if not model.present[i]:
            choices.append((ABSENT,))
        elif slide[i]:
            choices.append((HELD, SLIDE_POS, SLIDE_NEG))
        else:
            choices.append((HELD,))
    states = np.array(list(itertools.product(*choices)), dtype=np.int8)
    return states[1:]  # the first is "everything held", solved exactly above


def _state_maps(model, q, states):
    """Interaction maps of one configuration for many active sets, one compiled call."""
    S = states.shape[0]
    qa = q[None, :]
    q_obj, rho, _ = model._place(qa, 1)
    free, lam_fixed = _free_and_fixed(states, model.bounds)
    args = [q, model.parameters, model._contact_link, model._side, model._object_mass,
            model._object_inertia, q_obj[0], rho[0], model._wheel_offset, free, lam_fixed,
            np.zeros(1)]
    outs = model.backend("interaction_maps", S,
                         [np.ascontiguousarray(a, dtype=float) for a in args])
    names = model.backend.signatures["interaction_maps"].out_names
    res = {}
    for name_, o in zip(names, outs):
        res[name_] = o[:, :, 0] if o.shape[2] == 1 and name_.endswith("offset") else o
    res["pivot_ratio"] = outs[names.index("pivot_ratio")][:, 0, 0]
    return res


def _max_sr_sliding(model, query, cfg, stick: _Answer) -> _Answer:
    """Best wheel state (stick/slide+/slide- per allowed wheel), one convex problem each.

    States are solved best upper bound first and pruned against the best value so far; the
    candidates that beat the all-stick answer are then evaluated by one batched exact forward
    solve, which picks the winner (a state's optimum often lies on its boundary with another
    state, where the maps' rounding cannot separate them; ties keep the all-stick answer)."""
    n = cfg.N.shape[0]
    states = _slide_states(model, query.slide)
    mp = _state_maps(model, cfg.q, states)
    M = model.mass_matrix(cfg.q)
    Qh = np.concatenate([mp["qdd_from_tau"], mp["qdd_offset"][:, :, None]], axis=2)
    Xih = np.einsum("sai,ab,sbj->sij", Qh, M, Qh)
    Lh = np.concatenate([mp["lam_from_tau"], mp["lam_offset"][:, :, None]], axis=2)
    Wh = np.concatenate([mp["w_from_tau"], mp["w_offset"][:, :, None]], axis=2)
    ell = Lh[:, 0, :]
    # exact upper bound of sr on each state without its validity cone:
    # max k (l.z)^2 / (k (l.z)^2 + z^T Xi z) = k c / (k c + 1), c = l^T Xi^+ l
    pinv = np.linalg.pinv(Xih, rcond=1e-12, hermitian=True)
    c = np.einsum("si,sij,sj->s", ell, pinv, ell)
    ub = np.where(c > 0, cfg.k * c / (cfg.k * c + 1.0), 0.0)
    ub = np.where(mp["pivot_ratio"] > PIVOT_TOL, ub, -1.0)
    best_val = stick.expected
    solved = 0
    iters = 0
    cands = []  # (predicted sr, tau, binding, state) better than the all-stick answer
    outside = []  # states whose relaxed optimum leaves the ellipsoid: (value, s, prob, z)
    # phase 1: the linear relaxation (box rows; the ellipsoid's bounding box) of each state,
    # best upper bounds first; a relaxed optimum inside the region is the state's optimum
    for s in np.argsort(-ub):
        if ub[s] <= best_val + SR_TIE:
            break
        A, lba, uba, names = _rows(model, query, cfg)
        A[0] = ell[s]
        lba[0] = uba[0] = 1.0
        _stick_rows(model, cfg, A, lba, uba, names, Lh[s], states[s], Wh[s])
        lbx = np.full(n + 1, -np.inf)
        lbx[n] = 0.0
        prob = _Problem(H=2 * Xih[s], g=np.zeros(n + 1), A=A, lba=lba, uba=uba, lbx=lbx,
                        ubx=np.full(n + 1, np.inf), names=names, scale=_scale_of(query, cfg))
        sol = _solve_conic_fast(prob)
        solved += 1
        iters += sol.iterations
        if not sol.ok or sol.z[n] <= 0:
            continue  # the state is valid nowhere in the region
        z = sol.z
        val = _state_sr(cfg, Xih[s], ell[s], z)
        if not _inside(query, cfg, z[:n] / z[n]):
            outside.append((val, s, prob, z))
        elif val > stick.expected + SR_TIE:
            best_val = max(best_val, val)
            cands.append((val, z[:n] / z[n], sol.binding, states[s]))
    # phase 2: tighten the relaxation with tangent planes of the ellipsoid at the relaxed
    # optimum (Kelley's cutting planes, each a valid outer bound): most states then fall
    # below the best answer; IPOPT with the exact ellipsoid where the relaxation still beats it
    n_ipopt = 0
    for val, s, prob, z in sorted(outside, key=lambda o: -o[0]):
        if val <= best_val + SR_TIE:
            break
        cut = prob
        for _ in range(CUTS):
            cut = _with_tangent_cut(cut, cfg, query.radius, z)
            sol = _solve_conic_fast(cut)
            solved += 1
            if not sol.ok or sol.z[n] <= 0:
                break
            z = sol.z
            val = _state_sr(cfg, Xih[s], ell[s], z)
            if val <= best_val + SR_TIE or _inside(query, cfg, z[:n] / z[n]):
                break
        if not sol.ok or sol.z[n] <= 0 or val <= best_val + SR_TIE:
            continue
        if _inside(query, cfg, z[:n] / z[n]):  # the cut relaxation's optimum is feasible
            best_val = max(best_val, val)
            cands.append((val, z[:n] / z[n], sol.binding, states[s]))
            continue
        prob.N, prob.r2 = cfg.N, query.radius**2
        tau = z[:n] / z[n]
        z0 = np.append(tau * query.radius / np.sqrt(tau @ cfg.N @ tau) * (1 - 1e-6), 1.0)
        sol = _solve_ipopt(prob, z0 / (ell[s] @ z0) if ell[s] @ z0 > 0 else z0)
        n_ipopt += 1
        iters += sol.iterations
        if not sol.ok or sol.z[n] <= 0:
            continue
        z = sol.z
        val = _state_sr(cfg, Xih[s], ell[s], z)
        if val > stick.expected + SR_TIE:
            best_val = max(best_val, val)
            cands.append((val, z[:n] / z[n], sol.binding, states[s]))
    best = stick
    if cands:
        taus = np.array([t for _, t, _, _ in cands])
        fw = model.forward(np.repeat(cfg.q[None, :], len(cands), axis=0), taus)
        sliding = np.isin(fw.wheel_state, ("slide+", "slide-"))
        allowed = np.all(~sliding | query.slide[1:][None, :], axis=1)
        sr = np.where(fw.contact & allowed, fw.sr, -1.0)
        k = int(np.argmax(sr))
        if sr[k] > stick.expected + SR_TIE:
            _, tau, binding, state = cands[k]
            best = _Answer(tau, "optimal", "", binding, "", 0, float(sr[k]), states=state)
    best.solver = (f"generalized eigenproblem; {len(states)} sliding wheel states: {solved} "
                   f"QPs (qpoases), {n_ipopt} convex NLPs (ipopt)")
    best.iterations = iters
    return best


#: Tangent-plane cuts of the ellipsoid tried per wheel state before IPOPT.
CUTS = 4


def _with_tangent_cut(prob: _Problem, cfg, radius: float, z: np.ndarray) -> _Problem:
    """``prob`` plus the ellipsoid's tangent plane at the radial projection of ``tau / t``:
    ``g . tau <= g . p t`` with ``p`` on the ellipsoid and ``g = N p`` (homogeneous)."""
    n = cfg.N.shape[0]
    tau = z[:n] / z[n]
    p = tau * radius / np.sqrt(tau @ cfg.N @ tau)
    g = cfg.N @ p
    row = np.append(-g, g @ p)
    return _Problem(H=prob.H, g=prob.g, A=np.vstack([prob.A, row]),
                    lba=np.append(prob.lba, 0.0), uba=np.append(prob.uba, np.inf),
                    lbx=prob.lbx, ubx=prob.ubx, names=prob.names + [ELLIPSOID],
                    scale=prob.scale)


def _state_sr(cfg, Xih, ell, z):
    """sr at ``z = (tau, t)`` on a state's affine map: ``k / (k + z^T Xi_h z / (l . z)^2)``."""
    m = z @ Xih @ z / (ell @ z) ** 2
    return float(cfg.k / (cfg.k + m))


def _push_target(query, cfg):
    """The task as a bound on the contact force (``a_obj = a_dir lam_c``).

    Returns ``(lam_lo, equal, gain, structural)``: the task is ``lam_c >= lam_lo`` (``==``
    when ``equal``); ``gain`` converts ``lam_c`` into the task's acceleration (``d . a_obj``,
    or ``|a_obj|`` for a full acceleration); ``structural`` is ``(reason, binding)`` when no
    torque whatsoever can do the task."""
    a_dir = cfg.a_dir
    na = np.linalg.norm(a_dir)
    if na == 0 or cfg.k <= 0:
        return None, False, 0.0, ("no torque accelerates the object at this configuration",
                                  (CONTACT,))
    nrm = a_dir[:2] / max(np.linalg.norm(a_dir[:2]), 1e-300)
    if query.a_obj is not None:
        a = query.a_obj
        s0 = float(a_dir @ a) / (na * na)
        resid = np.linalg.norm(a - s0 * a_dir)
        if resid > 1e-6 * max(np.linalg.norm(a), 1e-300):
            return None, True, na, (
                f"a_obj = ({a[0]:.4g}, {a[1]:.4g}, {a[2]:.4g}) is not reachable: the object can "
                f"only accelerate along the contact normal n = ({nrm[0]:.4g}, {nrm[1]:.4g}), as "
                f"a_obj = lam_c * ({a_dir[0]:.4g}, {a_dir[1]:.4g}, {a_dir[2]:.4g}) with "
                f"lam_c >= 0", (NORMAL,))
        if s0 < 0:
            return None, True, na, (
                f"a_obj points against the contact normal n = ({nrm[0]:.4g}, {nrm[1]:.4g}): it "
                f"would need a pulling contact force; {CONTACT}", (CONTACT,))
        return s0, True, na, None
    d = query.direction
    gamma = float(d @ a_dir)
    if gamma <= 1e-9 * na:
        return None, False, gamma, (
            f"no torque accelerates the object along d = ({d[0]:.4g}, {d[1]:.4g}, {d[2]:.4g}): "
            f"the contact pushes only along its normal n = ({nrm[0]:.4g}, {nrm[1]:.4g}) and "
            f"d . n <= 0; {CONTACT}", (CONTACT,))
    lam_lo = None if query.a_min is None else query.a_min / gamma
    return lam_lo, False, gamma, None


def _push_problem(model, query, cfg, *, lam_lo=None, equal=False, lp=False):
    n = cfg.N.shape[0]
    A, lba, uba, names = _rows(model, query, cfg)
    Lh = _homog(cfg.L)
    if lam_lo is not None:
        A[0] = Lh[0]
        lba[0] = lam_lo
        uba[0] = lam_lo if equal else np.inf
        names[0] = ""
    if lam_lo is None or lam_lo < 0:  # else implied by the task row
        A[1] = Lh[0]
        lba[1] = 0.0
        names[1] = CONTACT
    _stick_rows(model, cfg, A, lba, uba, names, Lh)
    H = None
    g = np.zeros(n + 1)
    if lp:
        g[:n] = -cfg.L[0]
    else:
        H = np.zeros((n + 1, n + 1))
        H[:n, :n] = 2 * cfg.Xi
    lbx = np.full(n + 1, -np.inf)
    ubx = np.full(n + 1, np.inf)
    lbx[n] = ubx[n] = 1.0
    return _Problem(H=H, g=g, A=A, lba=lba, uba=uba, lbx=lbx, ubx=ubx, names=names,
                    scale=_scale_of(query, cfg))


def _inside(query, cfg, tau):
    return query.radius is None or tau @ cfg.N @ tau <= query.radius**2 * (1 + 1e-9)


def _solve_ellipsoid(query, cfg, prob: _Problem, phi0: float) -> _Solution:
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
        trial = _Problem(H=H0 + 2 * m * Nz, g=prob.g, A=prob.A, lba=prob.lba, uba=prob.uba,
                         lbx=prob.lbx, ubx=prob.ubx, names=prob.names, scale=prob.scale)
        sol = _solve_conic(trial)
        iters += 1
        return (sol.z[:n] @ cfg.N @ sol.z[:n] if sol.ok else np.nan), sol

    lo, f_lo = 0.0, 1.0 / np.sqrt(phi0) - 1.0 / np.sqrt(r2)  # < 0
    hi = mu
    for _ in range(60):
        p_hi, sol = phi(hi)
        if not np.isfinite(p_hi):
            return _Solution(False, sol.z, sol.status, iters, "qpoases (ellipsoid multiplier)")
        f_hi = 1.0 / np.sqrt(max(p_hi, 1e-300)) - 1.0 / np.sqrt(r2)
        if f_hi >= 0:
            break
        lo, f_lo, hi = hi, f_hi, hi * 10.0
    else:  # even the least-effort point of the linear constraints is outside: infeasible
        return _Solution(False, sol.z, "the ellipsoid and the linear limits do not intersect",
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
    return _Solution(True, best.z, best.status, iters, "qpoases (ellipsoid multiplier)",
                     tuple(dict.fromkeys(best.binding + (ELLIPSOID,))))


@dataclass
class _Strongest:
    ok: bool
    lam: float  # the largest contact force
    tau: np.ndarray
    binding: tuple
    solver: str
    iterations: int
    status: str
    unique: bool  # no other torque reaches ``lam``


def _strongest_lam(model, query, cfg) -> _Strongest:
    """Largest contact force ``lam_c`` within the limits with every wheel sticking."""
    n = cfg.N.shape[0]
    ell = cfg.L[0]
    if query.tau_max is None:
        # the ellipsoid alone: tau = r N^-1 l / sqrt(l^T N^-1 l) (closed form, unique)
        Ni = np.linalg.solve(cfg.N, ell)
        tau = query.radius * Ni / np.sqrt(ell @ Ni)
        Lw = cfg.L[1:] @ tau
        u = model.bounds[1:]
        if np.all(~np.isfinite(u) | (np.abs(Lw) <= u * (1 - FRICTION_MARGIN))):
            return _Strongest(True, float(ell @ tau), tau, (ELLIPSOID,),
                              "closed form (ellipsoid)", 0, "", True)
    prob = _push_problem(model, query, cfg, lp=True)
    sol = _solve_conic(prob)
    iters, solver, unique = sol.iterations, sol.solver, sol.unique
    if query.radius is not None and sol.ok and not _inside(query, cfg, sol.z[:n]):
        sol = _solve_ellipsoid(query, cfg, prob, sol.z[:n] @ cfg.N @ sol.z[:n])
        iters += sol.iterations
        solver = sol.solver
        # a linear objective on a strictly convex active constraint: a single maximiser
        unique = True
    if not sol.ok:
        return _Strongest(False, 0.0, np.zeros(n), (), solver, iters, sol.status, False)
    tau = sol.z[:n]
    return _Strongest(True, float(ell @ tau), tau, sol.binding, solver, iters, sol.status,
                      unique)


def _least_slip(model, query, cfg, lam_lo, equal):
    """min tau^T Xi tau s.t. lam_c >= lam_lo (== if equal), limits, wheels sticking."""
    n = cfg.N.shape[0]
    prob = _push_problem(model, query, cfg, lam_lo=lam_lo, equal=equal)
    sol = _solve_conic(prob)
    solver, iters = sol.solver, sol.iterations
    if sol.ok and not _inside(query, cfg, sol.z[:n]):
        sol = _solve_ellipsoid(query, cfg, prob, sol.z[:n] @ cfg.N @ sol.z[:n])
        solver = sol.solver
        iters += sol.iterations
    return sol, solver, iters


def _least_slip_push(model, query, cfg) -> _Answer:
    n = cfg.N.shape[0]
    lam_lo, equal, gain, structural = _push_target(query, cfg)
    if structural is not None:
        reason, binding = structural
        return _Answer(np.zeros(n), "infeasible", reason, binding, "structure", 0, None)
    sol, solver, iters = _least_slip(model, query, cfg, lam_lo, equal)
    if sol.ok:
        tau = sol.z[:n]
        return _Answer(tau, "optimal", "", sol.binding, solver, iters, float(tau @ cfg.Xi @ tau))
    # diagnose: the strongest push the limits allow, and what limits it
    st = _strongest_lam(model, query, cfg)
    iters += st.iterations
    lam_max, tau, binding, solver2 = st.lam, st.tau, st.binding, st.solver
    if not st.ok:
        return _Answer(np.zeros(n), "failed", f"solver failure: {sol.status}; {st.status}", (),
                       solver, iters, None)
    if lam_max >= lam_lo * (1 - 1e-7):
        return _Answer(np.zeros(n), "failed",
                       f"solver failure ({sol.status}) although the task is within reach",
                       (), solver, iters, None)
    want = np.linalg.norm(query.a_obj) if query.a_obj is not None else query.a_min
    what = "|a_obj|" if query.a_obj is not None else "the acceleration along d"
    names = ", ".join(binding) if binding else "the limits"
    reason = (f"{what} must reach {want:.6g} m/s^2 but is at most {gain * lam_max:.6g} m/s^2 "
              f"within the limits with every wheel sticking; binding: {names}")
    return _Answer(tau, "infeasible", reason, binding, f"{solver}; diagnosis {solver2}", iters,
                   None)


def _strongest_push(model, query, cfg) -> _Answer:
    n = cfg.N.shape[0]
    if query.direction is None:
        # default: straight along the contact normal
        query = _Query(query.objective, query.tau_max, query.radius,
                       cfg.a_dir / max(np.linalg.norm(cfg.a_dir), 1e-300), None, None,
                       query.slide)
    _, _, gamma, structural = _push_target(query, cfg)
    if structural is not None:
        reason, binding = structural
        return _Answer(np.zeros(n), "infeasible", reason, binding, "structure", 0, 0.0)
    st = _strongest_lam(model, query, cfg)
    lam_max, tau, binding, solver, iters = st.lam, st.tau, st.binding, st.solver, st.iterations
    if not st.ok:
        return _Answer(tau, "failed", f"solver failure: {st.status}", (), solver, iters, None)
    if lam_max <= 0:
        return _Answer(np.zeros(n), "infeasible",
                       "no torque within the limits pushes the object along d without a wheel "
                       f"sliding; binding: {', '.join(binding) or 'the limits'}", binding,
                       solver, iters, 0.0)
    # ties (a degenerate LP optimum): among the strongest pushes, the least snake motion
    if not st.unique:
        sol, s2, it2 = _least_slip(model, query, cfg, lam_max * (1 - 1e-9), False)
        iters += it2
        if sol.ok:
            tau = sol.z[:n]
            solver += f"; least-slip tie-break {s2}"
    return _Answer(tau, "optimal", "", binding, solver, iters, float(gamma * (cfg.L[0] @ tau)))


# ------------------------------------------------------------------------------------------
def optimize(model, q, objective: str = "max_sr", *, tau_max=None, radius=None,
             direction=None, a_min=None, a_obj=None, allow_slide=False) -> OptimizeResult:
    """The optimal joint torque for a task at configuration ``q`` (at rest).

    Parameters
    ----------
    model : SceneModel
        ``snakecg.load(scene)``.
    q : array (n_s,) or (N, n_s)
        Configuration(s) ``(x, y, theta, q_1..q_na)``.
    objective : "max_sr" | "least_slip_push" | "strongest_push"
        See the module documentation.
    tau_max : float or array (n_a,), optional
        Box limits ``|tau_j| <= tau_max_j`` (N m).
    radius : float, optional
        Ellipsoid ``tau^T B^T M_s^-1 B tau <= radius^2`` (eq. 31). With neither ``tau_max``
        nor ``radius`` the region is the paper's ellipsoid (``radius = 1``); with both, their
        intersection.
    direction : (2,) or (3,), optional
        Push direction of the object's acceleration (world frame; a 2-vector is linear only).
        ``least_slip_push``: with ``a_min``; ``strongest_push``: default the contact normal.
    a_min : float, optional
        ``least_slip_push``: required ``d . a_obj >= a_min`` (m/s^2).
    a_obj : (3,), optional
        ``least_slip_push``: the full planar acceleration ``(a_x, a_y, alpha)`` to give the
        object instead of ``direction``/``a_min``.
    allow_slide : bool or list of link numbers
        ``max_sr`` in the ``wheels`` scenario: wheels that may slide (``True``: all).
        Otherwise every wheel stays within its friction bound.

    Returns
    -------
    OptimizeResult
        ``tau``, ``status`` (``"optimal"``/``"infeasible"``/``"failed"``) with ``reason``,
        ``objective_value``, ``binding``, ``analysis`` (the forward result at ``tau``),
        ``solver``, ``iterations``, ``time``.
    """
    t0 = time.perf_counter()
    query = _validate(model, objective, tau_max, radius, direction, a_min, a_obj, allow_slide)
    qa, batched = model._q(q)
    cfgs = _configs(model, qa)
    run = {"max_sr": _max_sr, "least_slip_push": _least_slip_push,
           "strongest_push": _strongest_push}[query.objective]
    answers = []
    for cfg in cfgs:
        if cfg.singular:
            answers.append(_Answer(np.zeros(model.n_joints), "failed",
                                   "dependent constraint rows at this configuration (singular "
                                   "Delassus matrix); the maps are not defined", (), "none", 0,
                                   None))
            continue
        answers.append(run(model, query, cfg))
    taus = np.array([a.tau for a in answers])
    analysis = model.forward(qa, taus)
    values = _objective_values(query, cfgs, analysis)
    for b, (a, cfg) in enumerate(zip(answers, cfgs)):
        if a.status == "optimal":
            problem = _check(model, query, cfg, a, analysis, b, values[b])
            if problem:
                a.status, a.reason = "failed", f"forward check: {problem}"
    elapsed = (time.perf_counter() - t0) / len(answers)
    res = OptimizeResult(
        objective=query.objective, tau=taus,
        status=np.array([a.status for a in answers], dtype=object),
        reason=np.array([a.reason for a in answers], dtype=object),
        objective_value=values, binding=[a.binding for a in answers], analysis=analysis,
        solver=np.array([a.solver for a in answers], dtype=object),
        iterations=np.array([a.iterations for a in answers]),
        time=np.full(len(answers), elapsed),
        wheel_states_assumed=[_state_names(a.states) for a in answers],
    )
    if not batched:
        res.tau = res.tau[0]
        for k in ("status", "reason", "solver"):
            setattr(res, k, str(getattr(res, k)[0]))
        res.objective_value = float(values[0])
        res.binding = answers[0].binding
        res.iterations = int(res.iterations[0])
        res.time = float(res.time[0])
        res.wheel_states_assumed = res.wheel_states_assumed[0]
        for k in res.analysis.__dataclass_fields__:
            v = getattr(res.analysis, k)
            if isinstance(v, np.ndarray):
                setattr(res.analysis, k, v[0])
    return res


def _state_names(states):
    if states is None:
        return None
    table = {ABSENT: "none", HELD: "stick", SLIDE_POS: "slide+", SLIDE_NEG: "slide-"}
    return np.array([table[int(s)] for s in states[1:]])


def _objective_values(query, cfgs, an) -> np.ndarray:
    if query.objective == "max_sr":
        return np.asarray(an.sr, dtype=float)
    if query.objective == "least_slip_push":
        return np.asarray(an.norm_qdd, dtype=float)
    out = np.empty(len(cfgs))
    for b, cfg in enumerate(cfgs):
        d = query.direction
        if d is None:
            d = cfg.a_dir / max(np.linalg.norm(cfg.a_dir), 1e-300)
        out[b] = d @ an.a_obj[b]
    return out


def _check(model, query, cfg, a: _Answer, an, b, value) -> str:
    """Compare the answer with the exact forward solve; '' when everything holds."""
    tau = a.tau
    if query.tau_max is not None and np.any(np.abs(tau) > query.tau_max * (1 + 1e-9)):
        j = int(np.argmax(np.abs(tau) / query.tau_max))
        return f"|tau_{j + 1}| = {abs(tau[j]):.6g} exceeds tau_max = {query.tau_max[j]:.6g}"
    if query.radius is not None:
        e = tau @ cfg.N @ tau
        if e > query.radius**2 * (1 + 1e-7):
            return f"tau^T N tau = {e:.6g} exceeds radius^2 = {query.radius**2:.6g}"
    if not an.contact[b]:
        return "the contact separates at tau"
    ws = an.wheel_state[b]
    for i in range(1, model.n_constraints):
        if ws[i - 1] in ("slide+", "slide-") and not query.slide[i]:
            return (f"the wheel on link {i} slides ({ws[i - 1]}) although the optimiser kept it"
                    f" within its friction bound")
    if a.expected is not None:
        scale = max(abs(a.expected), 1.0 if query.objective == "max_sr" else abs(value), 1e-300)
        if abs(value - a.expected) > CHECK_TOL * scale:
            return (f"objective {value:.9g} from the forward solve differs from the optimiser's "
                    f"{a.expected:.9g}")
    if query.objective == "least_slip_push":
        if query.a_obj is not None:
            err = np.linalg.norm(an.a_obj[b] - query.a_obj)
            if err > 1e-6 * max(np.linalg.norm(query.a_obj), 1e-12):
                return f"a_obj = {an.a_obj[b].tolist()} misses the requested {query.a_obj.tolist()}"
        else:
            got = query.direction @ an.a_obj[b]
            if got < query.a_min * (1 - 1e-6):
                return f"d . a_obj = {got:.6g} < a_min = {query.a_min:.6g}"
    return ""
