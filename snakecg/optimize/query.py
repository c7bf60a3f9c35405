"""Input validation of :func:`snakecg.optimize.optimize`: one frozen :class:`Query` per call."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..kinds import is_scene_model
from ..limits import ROBOT
from .result import OBJECTIVES


@dataclass(frozen=True)
class Query:
    objective: str
    tau_max: np.ndarray | None  # (n,) or None
    radius: float | None
    direction: np.ndarray | None  # unit (3,) or None
    a_min: float | None
    a_obj: np.ndarray | None  # (3,)
    slide: np.ndarray  # (n_c,) bool: rows allowed to slide
    tau_max_from: str | None = None  # "robot" (its effort limits), "argument" or None


def _finite_vector(name, value, sizes, what):
    if isinstance(value, (str, bytes)) or (isinstance(value, (list, tuple)) and any(
            isinstance(v, (str, bytes, bool, np.bool_)) for v in value)):
        raise InputError(f"{name} must be {what}, got {value!r:.60} (not numbers)")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be {what}, got {value!r}") from None
    if arr.ndim != 1 or arr.shape[0] not in sizes:
        raise InputError(f"{name} has shape {arr.shape}, expected {what}")
    if not np.all(np.isfinite(arr)):
        raise InputError(f"{name} must be finite, got {arr.tolist()}")
    return arr


def validate(model, objective, tau_max, radius, direction, a_min, a_obj, allow_slide):
    if not is_scene_model(model):
        raise InputError(
            f"model must be a snakecg.SceneModel (snakecg.load(scene)), got {type(model).__name__}"
        )
    if not isinstance(objective, str) or objective.replace("-", "_") not in OBJECTIVES:
        raise InputError(
            f"objective must be one of {', '.join(OBJECTIVES)} (dashes allowed), got {objective!r}"
        )
    objective = objective.replace("-", "_")
    na = model.n_joints
    source = "argument"
    if tau_max.__class__ is str and tau_max == ROBOT:
        tau_max, source = _robot_tau_max(model)
    if type(tau_max) is float and math.isfinite(tau_max) and tau_max > 0:
        tau_max = np.full(na, tau_max)  # the common case, checked
    elif tau_max is not None and source == "argument":
        if np.ndim(tau_max) == 0 and not _is_number(tau_max):
            raise InputError(f"tau_max must be a positive number (N m), {na} of them (one per "
                             f"joint), {ROBOT!r} (the robot's effort limits) or None (no "
                             f"torque box); got {tau_max!r:.60} of type "
                             f"{type(tau_max).__name__}")
        if np.ndim(tau_max) == 0:
            tau_max = np.full(na, tau_max, dtype=float) if _is_number(tau_max) else tau_max
        tm = _finite_vector("tau_max", tau_max, (na,),
                            f"a positive number or {na} positive numbers (N m), one per joint")
        if np.any(tm <= 0):
            raise InputError(f"tau_max must be positive (N m), got {tm.tolist()}")
        tau_max = tm
    if radius is not None:
        if not _is_number(radius) or not np.isfinite(radius) or radius <= 0:
            raise InputError(f"radius must be a positive number (the ellipsoid "
                             f"tau^T B^T M_s^-1 B tau <= radius^2 of eq. 31), got {radius!r}")
        radius = float(radius)
    if tau_max is None and radius is None:
        radius = 1.0  # the paper's input region, eq. (31)
    # task arguments
    given = {k for k, v in (("direction", direction), ("a_min", a_min), ("a_obj", a_obj))
             if v is not None}
    allowed = {"max_sr": set(), "least_slip_push": {"direction", "a_min", "a_obj"},
               "strongest_push": {"direction"}}[objective]
    extra = given - allowed
    if extra:
        raise InputError(f"{', '.join(sorted(extra))} do(es) not apply to objective "
                         f"{objective!r} (it takes: {', '.join(sorted(allowed)) or 'no task'})")
    d = None
    if (type(direction) is np.ndarray and direction.dtype == np.float64
            and direction.shape in ((2,), (3,))):  # the common case, on floats
        dl = direction.tolist()
        nd = math.sqrt(sum(x * x for x in dl))
        if math.isfinite(nd) and nd > 0:
            d = np.array(dl + [0.0] * (3 - len(dl))) / nd
            direction = None
    if direction is not None:
        d = _finite_vector("direction", direction, (2, 3),
                           "(dx, dy) or (dx, dy, dalpha): the direction of the object's "
                           "acceleration, world frame")
        if np.linalg.norm(d) == 0:
            raise InputError("direction must be non-zero")
        d = np.r_[d, 0.0] if d.shape[0] == 2 else d
        d = d / np.linalg.norm(d)
    if a_min is not None:
        if not _is_number(a_min) or not np.isfinite(a_min) or a_min < 0:
            raise InputError(f"a_min must be a number >= 0 (m/s^2), got {a_min!r}")
        a_min = float(a_min)
    ao = None
    if a_obj is not None:
        ao = _finite_vector("a_obj", a_obj, (3,),
                            "(a_x, a_y, alpha): the object's planar acceleration (m/s^2, rad/s^2)")
    if objective == "least_slip_push":
        if ao is not None and (d is not None or a_min is not None):
            raise InputError("least_slip_push takes either a_obj (a full planar acceleration) "
                             "or direction and a_min, not both")
        if ao is None and (d is None or a_min is None):
            raise InputError("least_slip_push needs a task: direction=(dx, dy) and a_min "
                             "(m/s^2), or a_obj=(a_x, a_y, alpha)")
    # wheels allowed to slide
    if allow_slide is False or allow_slide is None:  # the common case: nothing slides
        derived = model.data().derived
        none = derived.get("optimize.no_slide")
        if none is None:
            none = np.zeros(model.n_constraints, dtype=bool)
            none.setflags(write=False)
            derived["optimize.no_slide"] = none
        return Query(objective, tau_max, radius, d, a_min, ao, none,
                     None if tau_max is None else source)
    bounded = model.present & np.isfinite(model.bounds)
    bounded[0] = False
    slide = np.zeros(model.n_constraints, dtype=bool)
    if allow_slide is True:
        slide = bounded.copy()
    elif allow_slide is False or allow_slide is None:
        pass
    else:
        try:
            links = [int(x) for x in allow_slide]
            if any(int(x) != x for x in allow_slide):
                raise ValueError
        except (TypeError, ValueError):
            raise InputError(f"allow_slide must be True, False or a list of link numbers, "
                             f"got {allow_slide!r}") from None
        for i in links:
            if not 1 <= i <= model.n_links or not bounded[i]:
                have = [int(r) for r in np.flatnonzero(bounded)]
                raise InputError(
                    f"allow_slide: link {i} has no wheel with a friction bound (links with one:"
                    f" {have or 'none'}; only the 'wheels' scenario bounds wheel forces)")
            slide[i] = True
    if slide.any() and objective != "max_sr":
        raise InputError("allow_slide applies to objective 'max_sr' only; push tasks keep "
                         "every wheel within its friction bound")
    return Query(objective, tau_max, radius, d, a_min, ao, slide,
                 None if tau_max is None else source)


def _robot_tau_max(model):
    """The torque box of the robot's effort limits (read-only, kept in the model's data), and
    its source; ``(None, None)`` for a robot without effort limits."""
    derived = model.data().derived
    cached = derived.get("optimize.effort_limits")
    if cached is None:
        e = model.robot.effort_limits
        arr = None if e is None else np.array(e, dtype=float)
        if arr is not None:
            arr.setflags(write=False)
        cached = derived["optimize.effort_limits"] = (arr, None if e is None else "robot")
    return cached


def _is_number(x) -> bool:
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool)


