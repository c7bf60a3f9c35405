"""The search over sliding wheel states of :func:`snakecg.shape.optimize_shape`: the NLP keeps
every wheel sticking; from its answer, a compass search on the exact per-shape extremes
(every wheel state, :func:`snakecg.piecewise.wheel_extremes`) moves the shape where sliding
wheels do better (``max_sr`` and ``max_a_obj``, bounded wheels)."""

from __future__ import annotations

import numpy as np


def bounded(model) -> bool:
    """The model has wheels with a friction bound (scenario 2)."""
    return bool(np.any(model.present[1:] & np.isfinite(model.bounds[1:])))


#: Smallest step (rad) of the search over sliding wheel states, its first (and longest) step
#: and its rounds at most (a round: every joint +-h, one batch of exact extremes).
STEP = 1e-7
START = 0.05
ROUNDS = 2000


def search(model, objective, query, q, value, lo, hi, feasible, clearance):
    """The answer with sliding wheels searched too (``max_sr``, ``max_a_obj``, bounded wheels).

    The NLP keeps every wheel sticking; a sliding wheel adds a fixed force and can raise the
    objective. Where the exact piecewise extremes apply (the unit ellipsoid, n_a <= 4:
    :func:`snakecg.piecewise.wheel_extremes`, every wheel state, certified per shape), the
    shape is refined by a compass search on that exact per-shape optimum (every joint +-h,
    h halved down to :data:`STEP` where no move improves, a joint's h doubled up to
    :data:`START` where its move does), from the NLP's answer. Returns ``(moved,
    record)`` (``moved``: ``(q, tau, analysis, value)`` where sliding wheels do better, None
    where they do not; ``record["converged"]``: the step reached :data:`STEP` within
    :data:`ROUNDS` rounds), or a reason (why the search does not apply: the status is
    then ``stick_only``)."""
    from ..analysis import EXACT_WHEELS_MAX_JOINTS

    metric = "sr" if objective == "max_sr" else "norm_a_obj"
    na = model.n_joints
    why = (f"{na} joints" if na > EXACT_WHEELS_MAX_JOINTS else
           "a torque box" if query.tau_max is not None else
           f"radius {query.radius:g}" if query.radius is not None and query.radius != 1.0
           else "")
    if why:
        return (f"sliding wheel states are not searched (every wheel sticks at the answer): "
                f"the exact piecewise search covers the unit ellipsoid up to "
                f"{EXACT_WHEELS_MAX_JOINTS} joints, not {why}")

    def evaluate(shapes):
        Qs = np.hstack([np.broadcast_to(q[:3], (len(shapes), 3)), shapes])
        ex = model.extremes(Qs, exact=True)
        v = np.where(ex.certified, ex.max[metric], -np.inf)
        if feasible:
            from ..geometry import feasibility

            v = np.where(feasibility(model, Qs, clearance=clearance).feasible, v, -np.inf)
        return v, ex.tau_max[metric]

    x = q[3:].copy()
    v, t = evaluate(x[None])
    best, tau = float(v[0]), t[0]
    if not np.isfinite(best):
        return "the exact piecewise extremes are not certified at the answer"
    h = np.full(na, START)
    rounds = 0
    while np.max(h) > STEP and rounds < ROUNDS:
        rounds += 1
        moves = []
        for j in range(na):
            for sgn in (1.0, -1.0):
                c = x.copy()
                c[j] = np.clip(c[j] + sgn * h[j], lo[j], hi[j])
                moves.append(c)
        v, t = evaluate(np.array(moves))
        k = int(np.argmax(v))
        if v[k] > best + 1e-11 * abs(best):
            x, best, tau = moves[k], float(v[k]), t[k]
            h[k // 2] = min(2.0 * h[k // 2], START)  # (that joint: a longer step next)
        else:
            h = 0.5 * h
    record = {"stick_value": value, "rounds": rounds, "step": float(np.max(h)),
              "converged": bool(np.max(h) <= STEP)}
    if best <= value + 1e-12 * max(1.0, abs(value)):  # sliding does not beat the answer
        return None, record
    qn = np.concatenate([q[:3], x])
    an = model.forward(qn, tau)
    return (qn, tau, an, float(getattr(an, metric))), record
