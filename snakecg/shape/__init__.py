"""Optimal shapes: the joint angles (and torque) that do a pushing task best.

The paper evaluates grids of shapes (784 and 21,952, 10 degrees apart); here the shape is a
continuous decision variable. ``optimize_shape(model, objective, ...)`` maximises (or, for
``least_slip_push``, minimises) the objective of :func:`snakecg.optimize.optimize` jointly over
the joint angles and the torque, at rest, with the pose fixed (planar invariance):

* ``"max_sr"``: the slippage ratio ``sr`` (eq. 30) at its best torque;
* ``"max_a_obj"``: the object's acceleration ``||a_obj||^2`` (eq. 27) over the input region;
* ``"strongest_push"``: ``d . a_obj`` along ``direction`` (default: the contact normal);
* ``"least_slip_push"``: the least ``||qdd_s||^2`` (eq. 26) for ``d . a_obj >= a_min`` (or a
  full ``a_obj``).

Every row is held by the NLP: the contact is kept (``lam_c >= 0``) and, in the ``wheels``
scenario, every wheel sticks within its friction bound (the wheel forces are bounded on the
smooth stick-state map; sliding states are discontinuous). For ``max_sr`` and ``max_a_obj``
with bounded wheels the answer is then refined over every wheel state, sliding ones included
(the exact piecewise extremes, up to 4 joints; ``status`` ``"stick_only"`` where that search
does not apply). Geometric constraints (``feasible=True``): non-adjacent links at least
``clearance`` apart and no link inside the object's plate (:mod:`snakecg.geometry`). Joint
limits always apply.

Method: IPOPT (through CasADi) on the generated CasADi functions composed symbolically, with
their exact first and second derivatives; multi-started from the best distinct points of a
coarse grid scored by the exact inner optimum over the torque; the best run wins, with ties
broken by the joint angles, so the answer does not depend on the order of the starts. At the
answer the torque is recomputed by the exact per-configuration optimizer
(:func:`snakecg.optimize.optimize`; for ``max_a_obj`` the closed form or IPOPT's torque) and
checked by the forward analysis. See docs/how-to/shapes.md.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from ..limits import ROBOT, of_query, resolve_joint_limits
from . import _nlp, _sliding, _starts

__all__ = ["optimize_shape", "OptimizeShapeResult", "OBJECTIVES", "SCHEMA"]

OBJECTIVES = ("max_sr", "strongest_push", "least_slip_push", "max_a_obj")
SCHEMA = "snakecg.optimize_shape/1"
#: Joint limits (rad) of a robot that states none: the range of the paper's grids.
JOINT_LIMITS = (-0.75 * math.pi, 0.75 * math.pi)
_SUCCESS = ("Solve_Succeeded", "Solved_To_Acceptable_Level")
_AT_ANSWER = "the exact torque optimizer at the answer: "
_NO_TORQUE = _AT_ANSWER + "infeasible"
_TASK_KEYS = ("tau_max", "radius", "direction", "a_min", "a_obj")
#: IPOPT's value and the exact forward value at the answer must agree to this (relative; sr:
#: absolute).
CHECK_TOL = 1e-6
#: The same for least_slip_push, whose NLP carries the Tikhonov term of ``Xi + eps N``
#: (its relative bias, reported as ``regularization_gap``, far below this with eps 1e-12).
REGULARIZED_TOL = 1e-4
#: Geometric constraints are checked at the answer to this tolerance (m).
GEOMETRY_TOL = 1e-9

@dataclass
class OptimizeShapeResult:
    """Outcome of :func:`optimize_shape`.

    * ``q`` (n_s): the best shape (pose as given); ``tau`` (n_a): its torque;
    * ``value``: the objective at ``(q, tau)`` read from ``analysis`` (sr, ``||a_obj||^2``,
      ``d . a_obj`` in m/s^2, or ``||qdd_s||^2``); ``analysis``: the forward result there;
    * ``status``: ``"optimal"`` (best local optimum of the starts, every check passed,
      sliding wheel states included), ``"stick_only"`` (the same with every wheel sticking:
      sliding states could not be searched), ``"infeasible"`` (no start reached a point
      meeting the constraints, or no torque does the task at the answer) or ``"failed"``;
      ``reason``: ``""`` or why;
    * ``certificate``: KKT residuals of the solved NLP (``stationarity``,
      ``primal_infeasibility``, ``complementarity``), ``active`` constraint names, IPOPT's
      ``ipopt_status`` and ``iterations``, and ``regularization_gap`` (IPOPT's objective minus
      the exact value at the answer);
    * ``starts`` (k, n_s): the starting shapes, ``start_values`` their grid values,
      ``start_index``: the start the answer came from (``starts[start_index]`` is the grid
      point it started from); ``grid_best`` / ``grid_best_value``: the coarse grid's best
      point (``None`` when ``q0`` was given); ``runs``: per start, IPOPT's status, iterations
      and value; ``time``: seconds;
    * ``limits``: the joint range, torque box and ellipsoid that bound the answer, and their
      sources (:func:`snakecg.limits.describe`).
    """

    objective: str
    q: np.ndarray
    tau: np.ndarray
    value: float
    status: str
    reason: str
    analysis: object
    certificate: dict
    starts: np.ndarray
    start_values: np.ndarray
    start_index: int
    grid_best: np.ndarray | None
    grid_best_value: float | None
    runs: list = field(default_factory=list, repr=False)
    form: str = ""
    time: float = 0.0
    limits: dict = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return self.status == "optimal"

    def to_dict(self) -> dict:
        """JSON-ready dictionary (schema ``snakecg.optimize_shape/1``, docs/how-to/shapes.md)."""
        an = self.analysis.to_dict() if self.analysis is not None else None
        if an is not None:
            for k in ("contact", "singular"):
                an[k] = bool(np.asarray(getattr(self.analysis, k)))
        cert = dict(self.certificate)
        cert["active"] = list(cert.get("active", ()))
        return {
            "objective": self.objective, "status": self.status, "reason": self.reason,
            "value": _f(self.value), "q": _l(self.q), "tau": _l(self.tau),
            "certificate": {k: (_f(v) if isinstance(v, (float, np.floating)) else v)
                            for k, v in cert.items()},
            "starts": _l(self.starts), "start_values": _l(self.start_values),
            "start_index": int(self.start_index),
            "grid_best": None if self.grid_best is None else _l(self.grid_best),
            "grid_best_value": _f(self.grid_best_value), "runs": self.runs,
            "form": self.form, "time_s": self.time, "limits": self.limits, "analysis": an,
        }


def _f(v):
    if v is None:
        return None
    v = float(v)
    return v if math.isfinite(v) else None


def _l(a):
    return [[_f(x) for x in row] for row in np.asarray(a)] if np.ndim(a) == 2 else \
        [_f(x) for x in np.asarray(a).ravel()]


# ------------------------------------------------------------------------------------------
def _validate(model, objective, q0, starts, seed, joint_limits, feasible, clearance, task):
    from ..kinds import is_scene_model
    from ..optimize.query import validate as validate_task

    if not is_scene_model(model):
        raise InputError(f"model must be a snakecg.SceneModel (snakecg.load(scene)), got "
                         f"{type(model).__name__}")
    if not isinstance(objective, str) or objective.replace("-", "_") not in OBJECTIVES:
        raise InputError(f"objective must be one of {', '.join(OBJECTIVES)} (dashes allowed), "
                         f"got {objective!r}")
    objective = objective.replace("-", "_")
    unknown = set(task) - set(_TASK_KEYS)
    if "allow_slide" in unknown:
        raise InputError("allow_slide does not apply to optimize_shape: every wheel is kept "
                         "within its friction bound (the stick-state map is the smooth one)")
    if unknown:
        raise InputError(f"unknown keyword(s) {', '.join(sorted(unknown))}; optimize_shape "
                         f"takes q0, starts, seed, joint_limits, feasible, clearance and the "
                         f"task keywords {', '.join(_TASK_KEYS)}")
    if objective == "max_a_obj":
        extra = {k for k in ("direction", "a_min", "a_obj") if task.get(k) is not None}
        if extra:
            raise InputError(f"{', '.join(sorted(extra))} do(es) not apply to objective "
                             f"'max_a_obj' (it takes: radius, tau_max)")
    query = validate_task(model, "max_sr" if objective == "max_a_obj" else objective,
                          task.get("tau_max", ROBOT), task.get("radius"), task.get("direction"),
                          task.get("a_min"), task.get("a_obj"), False)
    na = model.n_joints
    if isinstance(starts, bool) or not isinstance(starts, (int, np.integer)) or starts < 1:
        raise InputError(f"starts must be an integer >= 1 (IPOPT runs from the best grid "
                         f"points), got {starts!r}")
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise InputError(f"seed must be an integer >= 0, got {seed!r}")
    if not isinstance(feasible, bool):
        raise InputError(f"feasible must be True or False, got {feasible!r}")
    if (isinstance(clearance, bool) or not isinstance(clearance, (int, float, np.floating))
            or not math.isfinite(clearance) or clearance < 0):
        raise InputError(f"clearance must be a number >= 0 (m, least distance between "
                         f"non-adjacent links), got {clearance!r}")
    joint_limits, jl_from = resolve_joint_limits(model.robot, joint_limits)
    try:
        jl = np.asarray(joint_limits, dtype=float)
        if jl.shape == (2,):
            jl = np.tile(jl, (na, 1))
        if jl.shape != (na, 2):
            raise ValueError
    except (TypeError, ValueError):
        raise InputError(f"joint_limits must be (lo, hi) in radians or {na} such pairs, got "
                         f"{joint_limits!r}") from None
    lo, hi = jl[:, 0].copy(), jl[:, 1].copy()
    if not (np.all(np.isfinite(jl)) and np.all(lo < hi) and np.all(lo >= -math.pi)
            and np.all(hi <= math.pi)):
        raise InputError(f"joint_limits must satisfy -pi <= lo < hi <= pi (radians), got "
                         f"{jl.tolist()}")
    Q0 = None
    if q0 is not None:
        try:
            Q0 = np.array(q0, dtype=float)
        except (TypeError, ValueError):
            raise InputError(f"q0 must be a configuration (n_s = {na + 3},) or a list of them, "
                             f"got {q0!r}") from None
        Q0 = Q0[None] if Q0.ndim == 1 else Q0
        if Q0.ndim != 2 or Q0.shape[1] != na + 3 or Q0.shape[0] == 0:
            raise InputError(f"q0 has shape {Q0.shape}, expected ({na + 3},) or (k, {na + 3}) "
                             f"(x, y, theta, q_1..q_{na})")
        if not np.all(np.isfinite(Q0)):
            raise InputError("q0 must be finite")
        if np.any(Q0[:, 3:] < lo - 1e-12) or np.any(Q0[:, 3:] > hi + 1e-12):
            raise InputError("q0's joint angles must lie within joint_limits")
    return objective, query, Q0, lo, hi, float(clearance), jl_from


def _problem(model, objective, form, feasible, box, ellipsoid, task):
    cache = model.data().derived.setdefault("shape.problems", {})
    key = (objective, form, feasible, box, ellipsoid, task)
    if key not in cache:
        cache[key] = _nlp.Problem(model, objective, form, feasible=feasible, box=box,
                                  ellipsoid=ellipsoid, task=task)
    return cache[key]


def _to_objective(objective, form, v, a_min=None):
    """The NLP's ``value`` expressed as the objective (sr, ||a_obj||^2, ...)."""
    if objective == "least_slip_push" and form == "reduced":
        return a_min * a_min / (v * v) if v > 0 else math.inf
    if objective == "max_sr":
        return v / (1.0 + v)
    if objective == "max_a_obj":  # the NLP maximises sqrt(norm_a_obj)
        return v * v
    return v


def _params(query, pose, scale, clearance):
    p = np.zeros(_nlp.N_P)
    L = _nlp.P_LAYOUT
    p[L["pose"]] = pose
    p[L["scale"]] = scale
    if query.direction is not None:
        p[L["direction"]] = query.direction
    p[L["a_min"]] = query.a_min or 0.0
    if query.a_obj is not None:
        p[L["a_obj"]] = query.a_obj
    p[L["radius"]] = 1.0 if query.radius is None else query.radius
    p[L["clearance"]] = clearance
    return p


def optimize_shape(model, objective: str = "max_sr", *, q0=None, starts: int = 8,
                   seed: int = 0, joint_limits=ROBOT, feasible: bool = True,
                   clearance: float | None = None, **task) -> OptimizeShapeResult:
    """The best shape (joint angles) and torque for a task; see the module documentation.

    Parameters
    ----------
    model : SceneModel
    objective : "max_sr" | "strongest_push" | "least_slip_push" | "max_a_obj"
    q0 : (n_s,) or (k, n_s), optional
        Starting shapes (used as given, instead of the coarse grid); their pose is kept.
    starts : int
        Number of IPOPT runs, from the best distinct points of the coarse grid.
    seed : int
        Seed of the Sobol sample that replaces the grid beyond 8 joints (the grid itself is
        deterministic).
    joint_limits : (lo, hi) or (n_a, 2) or "robot"
        Radians. Default ``"robot"``: the robot's ``joint_limits`` (within +-pi), or +-135
        degrees (the paper's grid range, :data:`JOINT_LIMITS`) for a robot without them.
    feasible : bool
        Impose the geometric constraints (default); ``False`` keeps every shape, as the
        paper's grid does.
    clearance : float
        Least distance between non-adjacent links (m), default
        :data:`snakecg.geometry.SELF_CLEARANCE`.
    **task
        ``tau_max`` (default: the robot's ``effort_limits``), ``radius``, ``direction``,
        ``a_min``, ``a_obj`` as in :func:`snakecg.optimize.optimize`.
    """
    from ..geometry import SELF_CLEARANCE

    t0 = time.perf_counter()
    clearance = SELF_CLEARANCE if clearance is None else clearance
    objective, query, Q0, lo, hi, clearance, jl_from = _validate(
        model, objective, q0, starts, seed, joint_limits, feasible, clearance, task)
    na = model.n_joints
    bounded = _sliding.bounded(model)
    if objective == "max_sr" or (objective in ("max_a_obj", "strongest_push")
                                 and not bounded and query.tau_max is None):
        form = "reduced"
    else:
        form = "joint"
    task_kind = "a_obj" if query.a_obj is not None else ("a_min" if query.a_min is not None
                                                         else None)
    prob = _problem(model, objective, form, feasible, query.tau_max is not None,
                    query.radius is not None, task_kind)

    # starting points ------------------------------------------------------------------
    grid_best = grid_best_value = None
    symmetric = False
    if Q0 is None:
        pts, step = _starts.coarse_points(lo, hi, seed)
        Q = np.hstack([np.zeros((len(pts), 3)), pts])
        score, taus = _starts.inner_optimum(model, objective, model.maps(Q), query)
        if feasible:
            from ..geometry import feasibility

            fz = feasibility(model, Q, clearance=clearance)
            score = np.where(fz.feasible, score, np.minimum(score, -1e300))
        symmetric = _starts.mirrored(objective, query, lo, hi)

        def rescore(p_):  # the grid's score at other joint angles
            Qm = np.hstack([np.zeros((len(p_), 3)), p_])
            sc = _starts.inner_optimum(model, objective, model.maps(Qm), query)[0]
            if feasible:
                from ..geometry import feasibility

                fm = feasibility(model, Qm, clearance=clearance)
                sc = np.where(fm.feasible, sc, np.minimum(sc, -1e300))
            return sc

        mirror = _starts.mirror_scores(pts, score, rescore) if symmetric else None

        def basin(idx):
            return _starts.ascend(pts[idx], score[idx], step, lo, hi, rescore)

        idx = _starts.pick_starts(pts, score, step, starts, mirror, basin)
        S, svals, staus = Q[idx], score[idx], taus[idx]
        best = int(idx[0])
        grid_best = Q[best]
        if score[best] > -1e299:  # its exact value (the scores carry the Tikhonov term)
            hint = np.concatenate([grid_best[3:], taus[best]])
            grid_best_value = _answer(model, objective, "joint" if objective == "max_a_obj"
                                      else form, query, grid_best, hint, None)[2]
    else:
        S = Q0
        svals, staus = _starts.inner_optimum(model, objective, model.maps(S), query)
    finite = np.abs(svals[np.isfinite(svals) & (np.abs(svals) < 1e300)])
    scale = float(np.max(finite)) if finite.size and np.max(finite) > 0 else 1.0

    # IPOPT runs -----------------------------------------------------------------------
    # Each start is solved first without the geometric constraints (fewer variables, and the
    # flat optima of max_sr are easier for the barrier method without them); when that answer
    # meets them (checked with snakecg.geometry), it is a KKT point of the constrained
    # problem too (their multipliers are zero); otherwise the constrained NLP is solved from
    # the same start.
    free = _problem(model, objective, form, False, query.tau_max is not None,
                    query.radius is not None, task_kind) if feasible else prob
    # least_slip_push with d . a_obj >= a_min: first the torque eliminated (closed form);
    # kept where no limit binds at its answer (then it is a KKT point of the full problem)
    pre = None
    if objective == "least_slip_push" and task_kind == "a_min" and query.a_min > 0:
        pre = _problem(model, objective, "reduced", False, False, False, task_kind)
        pre_scale = query.a_min / math.sqrt(scale)
    runs, sols = [], []
    for s, (qs, ts) in enumerate(zip(S, staus)):
        p = _params(query, qs[:3], scale, clearance)
        sol = None
        if pre is not None:
            sol = _run(model, pre, objective, "reduced", query, qs, ts,
                       _params(query, qs[:3], pre_scale, clearance), lo, hi)
            qa = np.concatenate([qs[:3], sol[0][:na]])
            if not (sol[4] and _starts.inner_optimum(model, objective, model.maps(qa[None]),
                                                      query)[0][0] > -1e299
                    and (not feasible or not _geometry_problem(model, qa, clearance))):
                sol = None
        if sol is not None:
            geometric = ""
        else:
            sol = _run(model, free, objective, form, query, qs, ts, p, lo, hi)
            geometric = ""
        if feasible and sol[4] and sol[7] is not pre:
            geometric = _geometry_problem(model, np.concatenate([qs[:3], sol[0][:na]]),
                                          clearance)
        if feasible and (not sol[4] or geometric):
            sol = _run(model, prob, objective, form, query, qs, ts, p, lo, hi)
            geometric = "constrained"
        x, _, cert, v, ok, status, iters, _ = sol
        runs.append({"start": s, "form": "reduced" if sol[7] is pre else form,
                     "ipopt_status": status, "iterations": iters,
                     "value": _f(v), "ok": bool(ok),
                     "geometry": ("imposed" if geometric else "inactive") if feasible
                     else "not imposed"})
        sols.append(sol)
    good = [i for i, sol in enumerate(sols) if sol[4]]
    sign = -1.0 if objective == "least_slip_push" else 1.0
    if not good:
        pick = min(range(len(sols)), key=lambda i: (sols[i][2]["primal_infeasibility"],
                                                    tuple(np.round(sols[i][0][:na], 9))))
    else:
        vbest = max(sign * sols[i][3] for i in good)
        near = [i for i in good if sign * sols[i][3] >= vbest - 1e-9 * max(1.0, abs(vbest))]
        # a total order on the solutions (not on the starts): the same pick for any order
        pick = min(near, key=lambda i: (tuple(np.round(sols[i][0][:na], 6)),
                                        -sign * sols[i][3], tuple(sols[i][0][:na])))
    x, p, cert, v_nlp, ok, status, iters, used = sols[pick]
    x = np.concatenate([np.clip(x[:na], lo, hi), x[na:]])  # (IPOPT's rounding at a bound)
    q = np.concatenate([S[pick][:3], x[:na]])
    cert = dict(cert, ipopt_status=status, iterations=iters)

    # exact torque and forward check at the answer --------------------------------------
    tau, analysis, value, reason = _answer(model, objective, form, query, q, x, used)
    if Q0 is None and symmetric and good:
        # the starts skip mirror images: the answer is given as the mirror pair's first in
        # the joint angles' order (the one a start in either basin would have reported)
        xm = x.copy()
        xm[:na] = -x[:na]
        if used.has_tau:
            xm[na:2 * na] = -x[na:2 * na]
        qm = np.concatenate([q[:3], xm[:na]])
        if (tuple(np.round(qm[3:], 6)) < tuple(np.round(q[3:], 6))
                and not (feasible and _geometry_problem(model, qm, clearance))):
            mirror_answer = _answer(model, objective, form, query, qm, xm, used)
            if (mirror_answer[2] is not None and value is not None and not mirror_answer[3]
                    and abs(mirror_answer[2] - value) <= 1e-9 * max(1.0, abs(value))):
                x, q = xm, qm
                tau, analysis, value, reason = mirror_answer
    cert["regularization_gap"] = float(v_nlp - value) if value is not None else None
    if not good:
        st = "infeasible" if all(sol[2]["primal_infeasibility"] > 1e-6 for sol in sols) \
            else "failed"
        reason = reason or (f"no start reached a point meeting every constraint (IPOPT: "
                            f"{', '.join(sorted({sol[5] for sol in sols}))})")
    else:
        st = "optimal"
        if not reason and feasible:
            reason = _geometry_problem(model, q, clearance)
        tol = REGULARIZED_TOL if objective == "least_slip_push" else CHECK_TOL
        if not reason and abs(v_nlp - value) > tol * max(1.0 if objective == "max_sr"
                                                          else abs(value), 1e-300):
            reason = (f"forward check: the exact value {value:.9g} differs from IPOPT's "
                      f"{v_nlp:.9g}")
        if reason:  # (no torque does the task at the answer: as no start reaching one)
            st = "infeasible" if reason.startswith(_NO_TORQUE) else "failed"
        elif objective in ("max_sr", "max_a_obj") and _sliding.bounded(model):
            found = _sliding.search(model, objective, query, q, value, lo, hi, feasible,
                                    clearance)
            if isinstance(found, str):
                st, reason = "stick_only", found
            else:
                moved, cert["sliding_search"] = found
                if moved is not None:  # sliding wheels do better: their shape and torque
                    q, tau, analysis, value = moved
                rec = cert["sliding_search"]
                if not rec["converged"]:  # (its best point, not shown a local optimum)
                    st = "failed"
                    reason = (f"the search over sliding wheel states stopped after "
                              f"{rec['rounds']} rounds with its step at {rec['step']:.3g} rad "
                              f"(above {_sliding.STEP:g}): its best shape is returned")
    return OptimizeShapeResult(
        objective=objective, q=q, tau=tau, value=value if value is not None else math.nan,
        status=st, reason=reason, analysis=analysis, certificate=cert, starts=S,
        start_values=np.array([_to_objective(objective, form, s) * (sign if objective ==
                               "least_slip_push" else 1.0) if abs(s) < 1e300 else math.nan
                               for s in svals]),
        start_index=int(pick), grid_best=grid_best, grid_best_value=grid_best_value,
        runs=runs, form=form, time=time.perf_counter() - t0,
        limits=of_query(query, np.stack([lo, hi], axis=1), jl_from))


def _run(model, prob, objective, form, query, qs, ts, p, lo, hi):
    """One IPOPT run of ``prob`` from start ``qs`` (torque ``ts``):
    ``(x, p, certificate, value, ok, status, iterations, prob)``."""
    na = model.n_joints
    lbx = np.full(prob.nx, -np.inf)
    ubx = np.full(prob.nx, np.inf)
    lbx[:na], ubx[:na] = lo, hi
    parts = [qs[3:]]
    if prob.has_tau:
        if query.tau_max is not None:
            lbx[na:2 * na], ubx[na:2 * na] = -query.tau_max, query.tau_max
        parts.append(np.clip(ts, lbx[na:2 * na], ubx[na:2 * na]))
    if prob.pairs:
        parts.append(_starts.initial_slabs(model, qs))
    x, lam_g, lam_x, status, iters = prob.solve(np.concatenate(parts), p, lbx, ubx)
    cert = prob.certificate(x, p, lam_g, lam_x, lbx, ubx)
    v = _to_objective(objective, form, prob.value(x, p), query.a_min)
    ok = status in _SUCCESS and cert["primal_infeasibility"] <= 1e-8 and math.isfinite(v)
    return x, p, cert, v, ok, status, iters, prob


def _answer(model, objective, form, query, q, x, prob):
    """Torque at the answer, the forward analysis, the exact value and a problem (or '')."""
    from ..optimize import optimize

    na = model.n_joints
    kw = {"tau_max": query.tau_max, "radius": query.radius}
    if objective == "max_a_obj":
        if form == "joint":
            tau = x[na:2 * na].copy()
        else:
            _, taus = _starts.inner_optimum(model, objective, model.maps(q[None]), query)
            tau = taus[0]
        an = model.forward(q, tau)
        reason = ""
    else:
        kw.update(direction=query.direction, a_min=query.a_min, a_obj=query.a_obj)
        if objective != "least_slip_push":
            kw.pop("a_min"), kw.pop("a_obj")
        if objective == "max_sr":
            kw.pop("direction")
        res = optimize(model, q, objective, **kw)
        tau, an = res.tau, res.analysis
        reason = "" if res.status == "optimal" else \
            f"{_NO_TORQUE if res.status == 'infeasible' else _AT_ANSWER + res.status}: " \
            f"{res.reason}"
    if not reason and not bool(an.contact):
        reason = "forward check: the contact separates at the answer"
    ws = np.asarray(an.wheel_state)
    if not reason and np.any(np.isin(ws, ("slide+", "slide-"))):
        reason = "forward check: a wheel slides at the answer"
    if objective == "max_sr":
        value = float(an.sr)
    elif objective == "max_a_obj":
        value = float(an.norm_a_obj)
    elif objective == "least_slip_push":
        value = float(an.norm_qdd)
    else:
        d = query.direction
        if d is None:
            mp = model.maps(q)
            c = mp["lam_from_tau"][0]
            a_dir = mp["a_obj_from_tau"] @ c / (c @ c)
            d = a_dir / max(np.linalg.norm(a_dir), 1e-300)
        value = float(d @ an.a_obj)
    return tau, an, value, reason


def _geometry_problem(model, q, clearance) -> str:
    from ..geometry import feasibility

    fz = feasibility(model, q, clearance=clearance)
    if fz.self_distance < clearance - GEOMETRY_TOL or fz.self_distance <= 0.0:  # (0: crossing)
        return (f"geometry check: non-adjacent links {fz.self_distance:.3g} m apart "
                f"(clearance {clearance:.3g} m)")
    if fz.penetration > GEOMETRY_TOL:
        return f"geometry check: a link enters the object by {fz.penetration:.3g} m"
    return ""
