"""The joint torques of a run: a constant, a function of time ``tau(t)`` or a feedback law
``tau(t, state)``, evaluated continuously or held over a control period (zero-order hold)."""

from __future__ import annotations

import inspect

import numpy as np

from .._inputs import all_finite, as_batch
from ..errors import InputError
from ..solver import FORCE_LIMIT
from .records import SimulationError

__all__ = ["Torques", "check_tau", "torque_law"]


def torque_law(tau, n_a: int):
    """``(kind, law)``: kind ``"constant"`` (law the ``(n_a,)`` vector), ``"time"`` or
    ``"feedback"`` (law the callable), told apart by the callable's required arguments."""
    if type(tau) is np.ndarray and tau.dtype == np.float64 and tau.shape == (n_a,) \
            and all_finite(tau):
        return "constant", tau.copy()  # already what the checks below would give
    if callable(tau):
        try:
            params = inspect.signature(tau).parameters.values()
        except (TypeError, ValueError):
            raise InputError("tau: cannot read the signature of the callable; pass a function "
                             "of t (tau(t)) or of t and the state (tau(t, state))") from None
        pos = [p for p in params if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
               and p.default is p.empty]
        var = any(p.kind == p.VAR_POSITIONAL for p in params)
        if len(pos) == 1 and not var:
            return "time", tau
        if len(pos) == 2 or (var and len(pos) <= 2):
            return "feedback", tau
        raise InputError(f"tau: a callable must take (t) or (t, state), it takes {len(pos)}"
                         " required positional arguments")
    arr, batched = as_batch("tau", tau, n_a, what=f" (one torque per joint, n_a = {n_a})")
    if batched:
        raise InputError(f"tau has shape {np.shape(tau)}; a constant torque is ({n_a},); "
                         "pass a function for a torque that changes over time")
    return "constant", arr[0]


def check_tau(value, n_a: int, t: float) -> np.ndarray:
    """What a torque law returned at ``t``, as ``n_a`` finite floats."""
    try:
        arr = np.asarray(value, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise SimulationError(f"the torque law returned {value!r} at t = {t:.6g} s; expected "
                              f"{n_a} numbers") from None
    if arr.shape != (n_a,) or not np.all(np.isfinite(arr)):
        raise SimulationError(f"the torque law returned {value!r} at t = {t:.6g} s; expected "
                              f"{n_a} finite numbers (one per joint)")
    if np.any(np.abs(arr) > FORCE_LIMIT):
        raise SimulationError(f"the torque law returned {value!r} at t = {t:.6g} s; expected "
                              f"torques within +-{FORCE_LIMIT:.0e} N m")
    return arr


class Torques:
    """The torque law of a run. :meth:`function` gives the torque function ``(t, y, mode) ->
    tau`` of the next segment; with a ``control_period``, :meth:`sample` evaluates the law at
    a control instant and the functions return that value until the next sample.

    ``state_of(t, y, mode)`` builds the :class:`~snakecg.simulate.State` a feedback law sees.
    """

    def __init__(self, kind: str, law, n_a: int, control_period, state_of):
        self.kind, self.law, self.n_a = kind, law, n_a
        self.control_period = control_period
        self.state_of = state_of
        self.held = None

    def function(self):
        """The torque function ``(t, y, mode) -> tau`` of the next segment (a new function
        object at each call: the right-hand side's cache is keyed on it)."""
        na = self.n_a
        if self.kind == "constant":
            const = self.law
            return lambda t, y, m: const
        if self.control_period is not None:
            held = self.held
            return lambda t, y, m: held
        law = self.law
        if self.kind == "time":
            return lambda t, y, m: check_tau(law(t), na, t)
        state_of = self.state_of
        return lambda t, y, m: check_tau(law(t, state_of(t, y, m)), na, t)

    def sample(self, t, y, mode) -> None:
        """Zero-order hold: evaluate the law at a control instant and hold its value."""
        if self.kind == "time":
            self.held = check_tau(self.law(t), self.n_a, t)
        else:
            self.held = check_tau(self.law(t, self.state_of(t, y, mode)), self.n_a, t)
