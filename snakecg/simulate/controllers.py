"""Feedback laws for :func:`~snakecg.simulate.simulate`: the "push with least slippage"
torque query of :mod:`snakecg.optimize` answered at every call (:class:`LeastSlipPush`).
Any other law ``tau(t, state)`` plugs in the same way."""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError, SnakecgError

__all__ = ["LeastSlipPush", "least_slip_push_controller"]


class LeastSlipPush:
    """Feedback law ``tau(t, state)``: the "push with least slippage" torque query
    (``objective="least_slip_push"`` of :mod:`snakecg.optimize`) answered at every call.

    The query is the instant analysis at rest: it sees the current configuration
    ``state.q`` only (velocity terms, the object's actual pose and the contact point's drift
    along the link are left out), which is exactly what a simulation of it can reveal. The
    task: the object's acceleration along ``direction`` at least ``a_min`` (``direction``
    default: the current contact normal), or the full planar acceleration ``a_obj``; torque
    limits ``tau_max`` and/or the ellipsoid ``radius`` as in :func:`snakecg.optimize.optimize`
    (default: the robot's effort limits where it has them, as the query's).
    An infeasible task gives the query's closest torque (its strongest push within the
    limits). ``history`` lists ``(t, status, objective_value)`` of every call.
    """

    def __init__(self, model, *, a_min=None, direction="normal", a_obj=None, tau_max=None,
                 radius=None):
        query = getattr(model, "optimize", None)
        if query is None:
            try:
                from ..optimize import optimize as _optimize
            except ImportError:
                raise SnakecgError("the least-slippage push query needs snakecg.optimize, "
                                   "which this installation does not have; pass your own "
                                   "feedback law tau(t, state) instead") from None

            def query(q, **kw):
                return _optimize(model, q, **kw)
        if a_obj is None and a_min is None:
            raise InputError("least_slip_push_controller needs a task: a_min (m/s^2 along "
                             "direction, default the contact normal) or a_obj")
        self.model = model
        self._query = query
        self.a_min, self.direction, self.a_obj = a_min, direction, a_obj
        self.limits = {k: v for k, v in (("tau_max", tau_max), ("radius", radius))
                       if v is not None}
        self.history: list[tuple[float, str, float]] = []

    def normal(self, q) -> np.ndarray:
        """The contact normal ``n = side (-sin phi_k, cos phi_k)`` at configuration ``q``."""
        scene = self.model.scene
        k = scene.contact_link - 1
        phi = q[2] + float(np.sum(q[3:3 + k]))
        return scene.side_sign * np.array([-math.sin(phi), math.cos(phi)])

    def __call__(self, t, state):
        if self.a_obj is not None:
            task = {"a_obj": self.a_obj}
        else:
            d = self.normal(state.q) if isinstance(self.direction, str) else self.direction
            task = {"direction": d, "a_min": self.a_min}
        res = self._query(state.q, objective="least_slip_push", **task, **self.limits)
        value = getattr(res, "objective_value", None)
        self.history.append((float(t), str(getattr(res, "status", "")),
                             float(value) if value is not None else math.nan))
        return getattr(res, "tau", res)


def least_slip_push_controller(model, **options) -> LeastSlipPush:
    """The "push with least slippage" query as a feedback law for :func:`simulate`; see
    :class:`LeastSlipPush` (options: ``a_min``, ``direction``, ``a_obj``, ``tau_max``,
    ``radius``). Use it with ``control_period`` (one query per period, zero-order hold). Any
    other law ``tau(t, state)`` plugs into :func:`simulate` the same way."""
    return LeastSlipPush(model, **options)

