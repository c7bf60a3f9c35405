"""The entry point :func:`optimize`: validate, build the maps, solve each configuration,
certify the answer on the original problem, check it with the exact forward solve."""

from __future__ import annotations

import math
import time

import numpy as np

from .certificate import certify
from .fast import quad
from .finish import (answerable_tau, check, objective_value, one_result, state_names,
                     unanswered)
from .max_sr import max_sr
from .problems import Answer, configs, floats
from .push import least_slip_push, strongest_push
from .query import validate
from .quick import quick
from .result import Certificate, OptimizeResult
from .solvers import cold


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
        ``solver``, ``iterations``, ``time``; ``limits``: the torque box and ellipsoid that
        bound the answer and where they came from; ``note``: what the status alone does
        not say (a push whose object moves off the requested direction).
    """
    t0 = time.perf_counter()
    query = validate(model, objective, tau_max, radius, direction, a_min, a_obj, allow_slide)
    qa, batched = _configurations(model, q)
    if not batched:  # the common case in one compiled call, when it applies
        res = quick(model, query, qa[0], t0)
        if res is not None:
            res._query = query
            return res
    cfgs = configs(model, qa)
    run = {"max_sr": max_sr, "least_slip_push": least_slip_push,
           "strongest_push": strongest_push}[query.objective]
    answers, certs = [], []
    for cfg in cfgs:
        if cfg.singular:
            answers.append(Answer(np.zeros(model.n_joints), "failed",
                                  "dependent constraint rows at this configuration (singular "
                                  "Delassus matrix); the maps are not defined", (), "none", 0,
                                  None))
            certs.append(Certificate("none", False, reason="singular configuration"))
            continue
        a, cert = _certified(model, query, cfg, run)
        answers.append(a)
        certs.append(cert)
    if not batched:  # one configuration: the one-sample forward solve, plain fields
        a, cfg = answers[0], cfgs[0]
        e = _form(query, cfg, a) if a.status == "optimal" else None
        res = one_result(model, query, cfg.q, a, certs[0], cfg.a_dir, e, t0)
        res._query = query
        return res
    checked = [answerable_tau(model, cfg.q, a.tau) for a, cfg in zip(answers, cfgs)]
    analysis = model.forward(qa, np.array([t for t, _ in checked]))
    raw = analysis.raw
    for b, (a, (_, why)) in enumerate(zip(answers, checked)):
        if why:
            unanswered(model, raw[b], a, why)
    taus = np.array([a.tau for a in answers])
    values = np.array([objective_value(model, query, cfg.a_dir, raw[b])
                       for b, cfg in enumerate(cfgs)])
    for b, (a, cfg) in enumerate(zip(answers, cfgs)):
        if a.status == "optimal" and np.isnan(values[b]) and analysis[b].reason:
            a.status, a.reason = "failed", analysis[b].reason
        if a.status == "optimal":
            problem = check(model, query, a, raw[b], values[b], _form(query, cfg, a))
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
        wheel_states_assumed=[state_names(a.states) for a in answers],
        certificate=certs,
    )
    res._query = query
    return res


def _configurations(model, q):
    """``(qa, batched)``: a plain 1-D float configuration as is, anything else validated."""
    if (type(q) is np.ndarray and q.dtype == np.float64 and q.shape == (model.n_coordinates,)
            and q.flags.c_contiguous and math.isfinite(float(q.sum()))):
        return q[None, :], False
    return model.configurations(q)


def _certified(model, query, cfg, run):
    """Solve, then certify the answer on the original problem; when the certificate fails,
    re-solve from scratch (a fresh solver, no hot start) and certify again; an answer whose
    certificate still fails is returned as ``"failed"`` with the reason."""
    a = run(model, query, cfg)
    if a.status != "optimal":
        return a, Certificate("none", False, reason=f"no optimality claim: {a.status}")
    cert = certify(model, query, cfg, a)
    if cert.ok:
        return a, cert
    with cold():
        b = run(model, query, cfg)
    cert_b = certify(model, query, cfg, b) if b.status == "optimal" else cert
    cert_b.resolved = True
    if b.status == "optimal" and cert_b.ok:
        return b, cert_b
    b = a if b.status == "optimal" else b
    b.status = "failed"
    b.reason = (f"optimality certificate ({cert_b.kind}) fails after a cold re-solve: "
                f"{cert_b.reason or b.reason}")
    return b, cert_b


def _form(query, cfg, a: Answer):
    """``tau^T N tau`` of the answer when the query has an ellipsoid (the forward check
    compares it with ``radius^2``), else None."""
    return quad(floats(cfg)["N"], a.tau.tolist()) if query.radius is not None else None
