"""The last steps of a query on one configuration: the exact forward solve at the answer, the
objective read from it, the forward check of the answer (:func:`check`) and the result."""

from __future__ import annotations

import math
import time
from operator import mul

import numpy as np

from ..forward import ForwardResult
from ..solver import ABSENT, HELD, SLIDE_NEG, SLIDE_POS
from .result import CHECK_TOL, OptimizeResult

__all__ = ["one_result", "check", "objective_value", "state_names"]


def one_result(model, query, q, a, cert, a_dir, e, t0, raw=None) -> OptimizeResult:
    """The result of one configuration ``q`` for the answer ``a`` and its certificate: the
    one-sample forward solve at ``a.tau`` (``raw``: its result row when the compiled query
    has run it already), the objective read from it, the forward check (``e``:
    ``tau^T N tau`` of the answer when the query has an ellipsoid)."""
    if raw is None:
        tau, why = answerable_tau(model, q, a.tau)
        analysis = model.forward(q, tau)
        if why:
            unanswered(model, analysis.raw, a, why)
    else:
        analysis = ForwardResult(raw, model.columns)
    value = objective_value(model, query, a_dir, analysis.raw)
    if a.status == "optimal" and analysis.reason and np.isnan(value):
        a.status, a.reason = "failed", analysis.reason
    if a.status == "optimal":
        problem = check(model, query, a, analysis.raw, value, e)
        if problem:
            a.status, a.reason = "failed", f"forward check: {problem}"
    return OptimizeResult(
        objective=query.objective, tau=analysis.tau.copy(), status=a.status,
        reason=a.reason, objective_value=value, binding=a.binding, analysis=analysis,
        solver=a.solver, iterations=int(a.iterations), time=time.perf_counter() - t0,
        wheel_states_assumed=state_names(a.states), certificate=cert)


def answerable_tau(model, q, tau):
    """``(tau, why)``: the answer's torque for the forward solve, or zero torque and the cause
    in one line when it is not finite or beyond the forward solve's range (an answer computed
    from a numerically singular system: the cause is then the forward solve's own)."""
    from ..solver import FORCE_LIMIT

    tau = np.ascontiguousarray(tau, dtype=float)
    with np.errstate(invalid="ignore"):
        if np.all(np.abs(tau) <= FORCE_LIMIT):
            return tau, ""
    zero = np.zeros_like(tau)
    why = model.forward(q, zero).reason
    return zero, why or (f"the optimizer's torque is not finite or beyond +-{FORCE_LIMIT:.0e}"
                         f" (max |tau| = {np.nanmax(np.abs(tau)):.3g}): the configuration is "
                         f"too ill-conditioned to answer")


def unanswered(model, row, a, why):
    """Mark the answer ``a`` failed with ``why`` and its forward result ``row`` (at zero
    torque) as no answer: NaN, flagged singular."""
    cols = model.columns
    for k in ("tau", "qdd", "a_obj", "lam", "w"):
        row[..., cols.slices[k]] = np.nan
    for k in ("norm_lambda", "norm_a_obj", "norm_qdd", "sr", "conditioning"):
        row[..., cols.index[k]] = np.nan
    row[..., cols.singular] = 1.0
    a.tau = np.full(model.n_joints, np.nan)
    a.status, a.reason = "failed", why


def state_names(states):
    if states is None:
        return None
    table = {ABSENT: "none", HELD: "stick", SLIDE_POS: "slide+", SLIDE_NEG: "slide-"}
    return np.array([table[int(s)] for s in states[1:]])


def objective_value(model, query, a_dir, row) -> float:
    """The query's objective read from the forward result's row (``a_dir``: the object's
    acceleration per unit contact force, the default push direction)."""
    cols = model.columns
    if query.objective == "max_sr":
        return float(row[cols.index["sr"]])
    if query.objective == "least_slip_push":
        return float(row[cols.index["norm_qdd"]])
    a_obj = row[cols.slices["a_obj"]].tolist()
    d = query.direction
    if d is None:  # on floats (numpy's call overhead exceeds the arithmetic of 3-vectors)
        ad = a_dir.tolist() if isinstance(a_dir, np.ndarray) else list(a_dir)
        nrm = max(math.sqrt(sum(map(mul, ad, ad))), 1e-300)
        return float(sum(map(mul, [x / nrm for x in ad], a_obj)))
    return float(sum(map(mul, d.tolist(), a_obj)))


def check(model, query, a, row, value, e) -> str:
    """Compare the answer with the exact forward solve (its result row); '' when everything
    holds. ``e``: ``tau^T N tau`` of the answer (the ellipsoid's form), None without one."""
    tau = a.tau
    tl = tau.tolist()
    if query.tau_max is not None:
        over = [abs(t) / m for t, m in zip(tl, query.tau_max.tolist())]
        if max(over) > 1 + 1e-9:
            j = over.index(max(over))
            return f"|tau_{j + 1}| = {abs(tl[j]):.6g} exceeds tau_max = {query.tau_max[j]:.6g}"
    if query.radius is not None:
        if e > query.radius**2 * (1 + 1e-7):
            return f"tau^T N tau = {e:.6g} exceeds radius^2 = {query.radius**2:.6g}"
    cols = model.columns
    if row[cols.state] != HELD:
        return "the contact separates at tau"
    states = row[cols.wheels].tolist()
    for i in (range(1, model.n_constraints)
              if SLIDE_POS in states or SLIDE_NEG in states else ()):
        s = states[i - 1]
        if (s == SLIDE_POS or s == SLIDE_NEG) and not query.slide[i]:
            name = "slide+" if s == SLIDE_POS else "slide-"
            return (f"the wheel on link {i} slides ({name}) although the optimiser kept it"
                    f" within its friction bound")
    if a.expected is not None:
        scale = max(abs(a.expected), 1.0 if query.objective == "max_sr" else abs(value), 1e-300)
        if abs(value - a.expected) > CHECK_TOL * scale:
            return (f"objective {value:.9g} from the forward solve differs from the optimiser's "
                    f"{a.expected:.9g}")
    if query.objective == "least_slip_push":
        a_obj = row[cols.slices["a_obj"]]
        if query.a_obj is not None:
            err = np.linalg.norm(a_obj - query.a_obj)
            if err > 1e-6 * max(np.linalg.norm(query.a_obj), 1e-12):
                return f"a_obj = {a_obj.tolist()} misses the requested {query.a_obj.tolist()}"
        else:
            got = sum(map(mul, query.direction.tolist(), a_obj.tolist()))
            if got < query.a_min * (1 - 1e-6):
                return f"d . a_obj = {got:.6g} < a_min = {query.a_min:.6g}"
    return ""
