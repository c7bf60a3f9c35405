"""Names, constants and the result classes of :mod:`snakecg.optimize`."""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

#: Objective names (the CLI spells them with dashes).
OBJECTIVES = ("max_sr", "least_slip_push", "strongest_push")
STATUSES = ("optimal", "infeasible", "failed")
#: Version of :meth:`OptimizeResult.to_dict` and ``snakecg optimize --json``
#: (docs/how-to/optimize.md).
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
#: Curvature of the QP that stands for an LP (scaled variables, objective of size 1): at a
#: vertex whose multipliers exceed it times the torque's size (every non-degenerate LP optimum
#: here) the QP's solution is that vertex exactly; on a degenerate optimal face, the face's
#: point nearest the origin.
LP_REG = 1e-9
#: A constraint whose slack is below this (relative to the row's size) is active (certificate).
ACTIVE = 1e-7
#: Relative tolerances of the certificate.
TOLERANCE = {"stationarity": 1e-7, "primal_feasibility": 1e-9, "complementarity": 1e-8,
             "duality_gap": 1e-8}
#: A push whose object accelerates more than this many degrees off the requested direction
#: says so in its ``note``.
OFF_DIRECTION_DEG = 0.01

# names of the constraints, as reported in ``binding`` and in reasons
ELLIPSOID = "input ellipsoid (eq. 31)"
CONTACT = "contact would separate"
NORMAL = "contact normal (the frictionless contact pushes along its normal only)"


@functools.lru_cache(maxsize=None)
def joint_name(j: int) -> str:
    return f"torque limit on joint {j}"


def wheel_name(i: int) -> str:
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
    * ``solver``: the methods that produced ``tau``; ``iterations``: QPs solved plus the
      Newton steps on the ellipsoid's secular equation; ``time``: wall-clock seconds of the
      query (batched: the batch's time divided evenly).
    * ``certificate``: :class:`Certificate` (a list of them for a batch): the optimality
      conditions checked on the original problem after the solve; ``"optimal"`` is only
      returned when it holds.
    * ``wheel_states_assumed``: max_sr with sliding wheels, when a wheel state other than
      "every wheel sticks" won: that state per link (``"none"``, ``"stick"``, ``"slide+"``,
      ``"slide-"``); else ``None``. ``analysis.wheel_state`` is what the forward solve found
      (the same, or a neighbouring state on their common boundary).
    * ``limits``: the limits that bound the answer: ``tau_max`` (N m per joint, or None) and
      ``tau_max_from`` (``"robot"``: the robot's effort limits; ``"argument"``), ``radius``
      of the ellipsoid (eq. 31, or None).
    * ``off_direction_deg``: push tasks with a ``direction``: the angle between the requested
      direction and the object's linear acceleration (None otherwise); ``note``: ``""``, or
      what the status does not say, e.g. that the object moves along the contact normal,
      not along ``direction`` (the task bounds only ``d . a_obj``).
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
    certificate: object = field(default=None, repr=False)

    @property
    def ok(self):
        """``status == "optimal"`` (array for a batch)."""
        return np.asarray(self.status) == "optimal"

    @property
    def limits(self) -> dict | None:
        """The torque box and the ellipsoid that bound the answer, and their sources."""
        from ..limits import of_query

        q = getattr(self, "_query", None)
        return None if q is None else of_query(q)

    @property
    def off_direction_deg(self):
        """Degrees between the requested push direction and the object's linear
        acceleration (push tasks with a ``direction``; None otherwise; an array for a
        batch)."""
        q = getattr(self, "_query", None)
        if q is None or q.direction is None or q.objective == "max_sr":
            return None
        d = np.asarray(q.direction, float)[:2]
        a = np.atleast_2d(np.asarray(self.analysis.a_obj, float))[:, :2]
        nd, na = np.linalg.norm(d), np.linalg.norm(a, axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            cos = np.clip(a @ d / (na * nd), -1.0, 1.0)
        ang = np.where((na > 0) & (nd > 0), np.degrees(np.arccos(cos)), np.nan)
        out = [None if not np.isfinite(x) else float(x) for x in ang]
        return out[0] if np.ndim(self.analysis.a_obj) == 1 else out

    @property
    def note(self):
        """``""``, or what the status alone does not say (an array for a batch)."""
        ang = self.off_direction_deg
        single = not isinstance(ang, list)
        angs = [ang] if single else ang
        a = np.atleast_2d(np.asarray(self.analysis.a_obj, float))
        notes = []
        for i, x in enumerate(angs if ang is not None else [None] * len(a)):
            if x is None or x <= OFF_DIRECTION_DEG:
                notes.append("")
                continue
            ax, ay = a[i, :2] / np.linalg.norm(a[i, :2])
            notes.append(
                f"the object accelerates along ({ax:.4g}, {ay:.4g}), {x:.3g} deg off the "
                f"requested direction: the contact pushes along its normal only, and the "
                f"task bounds d . a_obj alone")
        return notes[0] if single else np.array(notes, dtype=object)

    def to_dict(self) -> dict:
        """JSON-ready dictionary (schema ``snakecg.optimize/1``, docs/how-to/optimize.md)."""
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
            "certificate": (None if self.certificate is None
                            else [c.to_dict() for c in self.certificate]
                            if isinstance(self.certificate, list)
                            else self.certificate.to_dict()),
            "limits": self.limits,
            "off_direction_deg": self.off_direction_deg,
            "note": _plain(self.note),
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




@dataclass
class Certificate:
    """Optimality conditions of an answer, checked on the original problem after the solve.

    The problem is rebuilt from the configuration's maps in the torque itself (no scaling, no
    regularisation, no homogeneous variable; for max_sr with sliding wheels, the winning
    state's problem in ``z = (tau, t)``), the multipliers of the constraints active at ``tau``
    are recomputed from the stationarity condition (least squares, non-negative where the
    signs bind), and:

    * ``stationarity``: ``||grad f - sum_i lam_i grad g_i||`` relative to the size of the
      gradient's terms (``||H|| ||tau|| + ||c||``, or the multipliers' terms if larger);
    * ``primal_feasibility``: the largest constraint violation, relative to the row's size;
    * ``complementarity``: ``sum_i lam_i |slack_i| / scale`` (relative);
    * ``duality_gap``: ``(f(tau) - d(lam)) / max(|f(tau)|, scale)`` with ``d`` the Lagrange
      dual function at the multipliers (convex kinds; ``None`` otherwise);
    * for ``max_sr`` with every row held, ``stationarity`` is the residual of the generalized
      eigenproblem ``Omega v = sr (Omega + Xi) v`` and the answer's ``sr`` is compared with
      the top eigenvalue (``duality_gap`` is their relative difference).

    ``kind`` names the conditions (``"kkt (convex QP)"``, ``"kkt (LP)"``, ``"kkt (convex
    QCQP)"``, ``"generalized eigenproblem"``, ``"kkt of the winning wheel state"``, or
    ``"none"`` when no optimality claim is made); ``ok`` is whether every residual is within
    ``tolerance``; ``resolved`` is True when the first solve failed the check and the answer
    comes from a second method (max_sr: the general eigenproblem after the closed form);
    ``reason`` says which condition failed ("" when ok). Computed in C with the answer
    (``snakecg/engine/qp.c``, ``optimal.c``).
    """

    kind: str
    ok: bool
    stationarity: float = 0.0
    primal_feasibility: float = 0.0
    complementarity: float = 0.0
    duality_gap: float | None = None
    tolerance: float = 0.0
    resolved: bool = False
    reason: str = ""

    def to_dict(self) -> dict:
        """JSON-ready dictionary (the ``certificate`` object of docs/how-to/optimize.md)."""
        return {k: _plain(getattr(self, k)) for k in self.__dataclass_fields__}


#: The certificate of an answer that makes no optimality claim.
NO_CLAIM = Certificate("none", False, reason="no optimality claim (the query is not optimal)")
