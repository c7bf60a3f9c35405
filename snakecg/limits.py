"""A robot's joint limits: their validation, and the defaults they give to the queries.

A :class:`~snakecg.Robot` may carry

* ``joint_limits``: the range ``lower < q_j < upper`` (rad) of every joint angle, as one
  ``(lower, upper)`` pair for every joint or one pair per joint;
* ``effort_limits``: the largest torque ``|tau_j| <= effort_j`` (N m) of every joint, as one
  positive number for every joint or one per joint.

Both come from a URDF's ``<limit lower upper effort>``, from a robot file's ``[robot]``
table, or from the arguments of ``Robot(...)``. They are the defaults of the queries that
take such limits: the ``joint_limits`` of :func:`snakecg.shape.optimize_shape` and of a
sweep's grid (:func:`default_joint_limits`), and the torque box ``tau_max`` of
:func:`snakecg.optimize.optimize` and ``optimize_shape`` (:func:`resolve_tau_max`). Every
answer records which limits bound it and where they came from (:func:`describe`).
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from ._inputs import short_repr as _r

__all__ = ["ROBOT", "PAPER_JOINT_RANGE", "check_joint_limits", "check_effort_limits",
           "default_joint_limits", "resolve_joint_limits", "resolve_tau_max", "describe",
           "of_query"]

#: The value of a query's ``tau_max`` or ``joint_limits`` that means "the robot's own".
ROBOT = "robot"
#: The joint range (rad) of the paper's grids, +-135 degrees: the default of a robot that
#: states no joint limits.
PAPER_JOINT_RANGE = (-0.75 * math.pi, 0.75 * math.pi)


def _real(v) -> bool:
    return isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_))


def _sequence(v) -> bool:
    return isinstance(v, (list, tuple)) or (isinstance(v, np.ndarray) and v.ndim >= 1)


def check_joint_limits(value, n_joints: int | None, problems: list[str]):
    """``value`` (None, one ``(lower, upper)`` pair, or ``n_joints`` pairs; rad) as a tuple of
    ``n_joints`` float pairs, or None; every problem is appended to ``problems``."""
    if value is None:
        return None
    form = (f"one (lower, upper) pair for every joint or {n_joints} pairs (rad)"
            if n_joints is not None else "one (lower, upper) pair or one pair per joint (rad)")
    if not _sequence(value):
        problems.append(f"joint_limits must be {form}, got {_r(value)}")
        return None
    items = list(value)
    if len(items) == 2 and all(_real(v) for v in items):
        pairs = [tuple(items)] * (n_joints or 1)
        one = True
    elif all(_sequence(p) for p in items):
        pairs = [tuple(p) for p in items]
        one = False
    else:
        problems.append(f"joint_limits must be {form}, got {_r(value)}")
        return None
    bad = []
    for j, p in enumerate(pairs, start=1):
        where = "" if one else f" (joint {j})"
        if len(p) != 2 or not all(_real(v) for v in p):
            bad.append(f"{_r(p)}{where} is not a pair of numbers")
            continue
        lo, hi = float(p[0]), float(p[1])
        if not (math.isfinite(lo) and math.isfinite(hi)):
            bad.append(f"{_r(p)}{where} is not finite")
        elif not lo < hi:
            bad.append(f"lower {lo:g} >= upper {hi:g}{where}")
        if one:
            break
    if bad:
        shown = "; ".join(bad[:4]) + (f"; and {len(bad) - 4} more" if len(bad) > 4 else "")
        problems.append(f"joint_limits must hold pairs lower < upper (rad): {shown}")
        return None
    if not one and n_joints is not None and len(pairs) != n_joints:
        problems.append(f"joint_limits has {len(pairs)} pair(s), expected one pair or "
                        f"{n_joints} (one per joint)")
        return None
    if n_joints is None:
        return None
    return tuple((float(lo), float(hi)) for lo, hi in pairs)


def check_effort_limits(value, n_joints: int | None, problems: list[str]):
    """``value`` (None, one positive number, or ``n_joints`` of them; N m) as a tuple of
    ``n_joints`` floats, or None; every problem is appended to ``problems``."""
    if value is None:
        return None
    if _real(value):
        items, one = [value], True
    elif _sequence(value) and np.ndim(value) == 1:
        items, one = list(value), False
    else:
        problems.append(f"effort_limits must be one positive number (N m) for every joint or "
                        f"{n_joints or 'one per joint'}, got {_r(value)}")
        return None
    bad = [f"{_r(v)}" + ("" if one else f" (joint {j})") for j, v in enumerate(items, start=1)
           if not _real(v) or not math.isfinite(float(v)) or float(v) <= 0]
    if bad:
        shown = ", ".join(bad[:4]) + (f" and {len(bad) - 4} more" if len(bad) > 4 else "")
        problems.append(f"effort_limits must be positive finite torques (N m), got {shown}")
        return None
    if not one and n_joints is not None and len(items) != n_joints:
        problems.append(f"effort_limits has {len(items)} value(s), expected one number or "
                        f"{n_joints} (one per joint)")
        return None
    if n_joints is None:
        return None
    return tuple(float(items[0]) for _ in range(n_joints)) if one else tuple(map(float, items))


def default_joint_limits(robot) -> tuple[np.ndarray, str]:
    """The joint range ``(n_a, 2)`` (rad) of a query that was given none, and its source:
    the robot's ``joint_limits`` (``"robot"``) within ``[-pi, pi]`` (a relative angle
    beyond that is the same shape again), or the paper's +-135 degrees (``"paper"``) when the
    robot states none."""
    n = robot.joints
    if robot.joint_limits is None:
        return np.tile(np.array(PAPER_JOINT_RANGE), (n, 1)), "paper"
    jl = np.array(robot.joint_limits, dtype=float)
    return np.clip(jl, -math.pi, math.pi), "robot"


def resolve_joint_limits(robot, joint_limits):
    """``(joint_limits, source)``: :func:`default_joint_limits` for ``"robot"``, else the
    value as given (``"argument"``; validated by the query)."""
    if isinstance(joint_limits, str) and joint_limits == ROBOT:
        return default_joint_limits(robot)
    return joint_limits, "argument"


def resolve_tau_max(robot, tau_max):
    """``(tau_max, source)``: the robot's ``effort_limits`` for ``tau_max == "robot"``
    (``(None, None)`` when it has none), else the value as given (``"argument"``; None: no
    box). The value is validated by the query."""
    if isinstance(tau_max, str) and tau_max == ROBOT:
        if robot.effort_limits is None:
            return None, None
        return np.array(robot.effort_limits, dtype=float), "robot"
    return tau_max, (None if tau_max is None else "argument")


#: What the sources mean, as the answers spell them out.
SOURCES = {
    "robot": "the robot's limits",
    "argument": "given to the query",
    "paper": "the paper's +-135 deg (the robot states no joint limits)",
}


def describe(*, joint_limits=None, joint_limits_from=None, tau_max=None, tau_max_from=None,
             radius=None) -> dict:
    """The limits an answer was bound by, JSON-ready: the joint range (rad, per joint) and
    its source, the torque box (N m, per joint; None: none) and its source, and the
    ellipsoid's radius (eq. 31; None: none)."""
    out = {}
    if joint_limits is not None:
        out["joint_limits"] = [[float(lo), float(hi)] for lo, hi in np.asarray(joint_limits)]
        out["joint_limits_from"] = joint_limits_from
    out["tau_max"] = None if tau_max is None else [float(t) for t in np.ravel(tau_max)]
    out["tau_max_from"] = tau_max_from if tau_max is not None else None
    out["radius"] = None if radius is None else float(radius)
    return out


def of_query(query, joint_limits=None, joint_limits_from=None) -> dict:
    """:func:`describe` of a validated torque query (``snakecg.optimize.query.Query``) and,
    for a shape query, its joint range."""
    return describe(joint_limits=joint_limits, joint_limits_from=joint_limits_from,
                    tau_max=query.tau_max, tau_max_from=query.tau_max_from,
                    radius=query.radius)
