"""Names, constants and the result classes of :mod:`snakecg.optimize`."""

from __future__ import annotations

import functools
from dataclasses import dataclass, field

import numpy as np

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
            "certificate": (None if self.certificate is None
                            else [c.to_dict() for c in self.certificate]
                            if isinstance(self.certificate, list)
                            else self.certificate.to_dict()),
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
    (``snakecg/core/qp.c``, ``optimal.c``).
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
        """JSON-ready dictionary (the ``certificate`` object of docs/optimize.md)."""
        return {k: _plain(getattr(self, k)) for k in self.__dataclass_fields__}


#: The certificate of an answer that makes no optimality claim.
NO_CLAIM = Certificate("none", False, reason="no optimality claim (the query is not optimal)")
