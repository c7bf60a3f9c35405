"""The entry point :func:`optimize`: validate the query, build the compiled call's inputs, one
call of the runtime core for every configuration (:mod:`snakecg.engine.optimal`: the maps, the
solve, the certificate, the forward solve at the answer and its check), the answers as an
:class:`~snakecg.optimize.OptimizeResult`."""

from __future__ import annotations

import math
import time

import numpy as np

from ..engine.optimal import CHECK, KINDS, REASON
from ..errors import SnakecgError
from .answers import result
from .arguments import screen
from .query import Query, validate
from .result import (ACTIVE, CHECK_TOL, FRICTION_MARGIN, HESSIAN_REG, LP_REG, SR_TIE,
                     TOLERANCE, OptimizeResult)

#: The settings of the compiled query (Layout.optimal_in_fields, in order).
_SETTINGS = [FRICTION_MARGIN, CHECK_TOL, SR_TIE, HESSIAN_REG, LP_REG, ACTIVE,
             TOLERANCE["stationarity"], TOLERANCE["primal_feasibility"],
             TOLERANCE["complementarity"], TOLERANCE["duality_gap"]]
_NAN = math.nan


def optimize(model, q, objective: str = "max_sr", *, tau_max="robot", radius=None,
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
    tau_max : float or array (n_a,) or "robot" or None
        Box limits ``|tau_j| <= tau_max_j`` (N m). Default ``"robot"``: the robot's
        ``effort_limits`` (no box when it has none); None: no box.
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
        ``solver``, ``iterations``, ``time``, ``certificate``; ``limits``: the torque box and
        ellipsoid that bound the answer and where they came from; ``note``: what the status
        alone does not say (a push whose object moves off the requested direction).
    """
    t0 = time.perf_counter()
    query = validate(model, objective, tau_max, radius, direction, a_min, a_obj, allow_slide)
    qa, batched = _configurations(model, q)
    core = model.core
    if core is None:
        raise SnakecgError(
            "optimal torques are computed by the compiled runtime core, which this model does "
            f"not have (backend {model.backend_kind!r}: no C compiler, or the build failed); "
            "install a C compiler (gcc or clang, or set CC) and load the scene again")
    kernel = core.optimal
    query_in = query_vector(query)
    out = kernel.solve(model, query_in, qa)
    check = kernel.OUT["check"][0]
    pending = np.flatnonzero(out[:, check] == CHECK["pending"])
    f0, t0_ = kernel.OUT["forward"][0], kernel.OUT["tau"][0]
    if pending.size:  # forward rows that the compiled forward solve left to its reference path
        taus = out[pending, t0_:t0_ + model.n_joints]
        rows = model.forward(qa[pending], np.ascontiguousarray(taus)).raw
        out[pending, f0:f0 + rows.shape[1]] = rows
        kernel.check(query_in, out)
    reason = out[:, kernel.OUT["reason"][0]]
    unanswered = np.flatnonzero((reason == REASON["not_finite"])
                                | (reason == REASON["unanswerable"]))
    for i in unanswered.tolist():  # no torque to check: the forward solve at zero says why
        fw = model.forward(qa[i], np.zeros(model.n_joints))
        out[i, f0:f0 + fw.raw.size] = no_answer(model, fw.raw)
        out[i, t0_:t0_ + model.n_joints] = np.nan
        out[i, kernel.OUT["detail"][0] + 1] = fw.raw[model.columns.status]
    res = result(model, query, kernel, out, batched, time.perf_counter() - t0,
                 tuple(_SETTINGS[6:10]))
    res._query = query  # for its limits and note
    return res


def no_answer(model, row):
    """A forward result row marked as no answer: NaN, flagged singular (its status kept)."""
    row = row.copy()
    cols = model.columns
    for k in ("tau", "qdd", "a_obj", "lam", "w"):
        row[cols.slices[k]] = np.nan
    for k in ("norm_lambda", "norm_a_obj", "norm_qdd", "sr", "conditioning"):
        row[cols.index[k]] = np.nan
    row[cols.singular] = 1.0
    return row


def query_vector(query: Query) -> np.ndarray:
    """The compiled query's input vector (:meth:`snakecg.engine.Layout.optimal_in_fields`):
    the settings, then the query with NaN where it has no such value."""
    tm = query.tau_max
    d = query.direction
    ao = query.a_obj
    na = len(query.slide) - 2
    vals = _SETTINGS + [KINDS[query.objective],
                        _NAN if query.radius is None else query.radius]
    vals += [_NAN] * na if tm is None else tm.tolist()
    vals += [_NAN] * 3 if d is None else d.tolist()
    vals.append(_NAN if query.a_min is None else query.a_min)
    vals += [_NAN] * 3 if ao is None else ao.tolist()
    vals += query.slide.tolist()
    return np.array(vals, dtype=float)


def _configurations(model, q):
    """``(qa, batched)``: a plain 1-D float configuration as is, anything else validated."""
    if (type(q) is np.ndarray and q.dtype == np.float64 and q.shape == (model.n_coordinates,)
            and q.flags.c_contiguous and math.isfinite(float(q.sum()))):
        return q[None, :], False
    return model.configurations(q)


def optimize_model(model, q, objective, kwargs: dict) -> OptimizeResult:
    """:meth:`SceneModel.optimize`: a batch's memory checked first, the keywords screened
    (:func:`~snakecg.optimize.arguments.screen`), then :func:`optimize`."""
    if not (type(q) is np.ndarray and q.ndim == 1):  # a batch: its memory first
        qa, _ = model._q(q)
        model._check_memory("optimize", qa.shape[0], ["place_object", "interaction_maps"],
                            extra=model.columns.width + 4 * model.n_joints)
    return optimize(model, q, objective=objective, **screen(kwargs))
