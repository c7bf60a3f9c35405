"""The arguments of :func:`~snakecg.simulate.simulate` checked (each error names the argument
and the expected form), and the limits that keep a run's memory and time bounded."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._inputs import as_batch, to_float
from ..errors import InputError, SnakecgError
from ..kinds import is_scene_model
from ..solver import FORCE_LIMIT, check_input_range
from .compiled import placement
from .torques import torque_law

__all__ = ["DURATION_MAX", "DURATION_MIN", "METHODS", "MAX_OUTPUT_SAMPLES", "MAX_PERIODS",
           "MAX_STEPS", "MAX_FRAMES", "RTOL_MIN",
           "STABILIZATION_MAX", "Settings", "check_arguments", "check_count", "positive",
           "single"]

METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")  # scipy.integrate.solve_ivp
#: Most output samples of one run (duration / output_dt; each sample holds ~1 kB of arrays).
MAX_OUTPUT_SAMPLES = 10**6
#: Most controller periods (duration / control_period; each one solves a torque query) and
#: most steps of the integrator allowed by max_step or fixed_step (duration / step).
MAX_PERIODS = 10**6
MAX_STEPS = 10**7
#: Most frames of an animation (each one is an image of ~100 kB held until the GIF is written).
MAX_FRAMES = 2000
#: Smallest relative tolerance solve_ivp can honour (100 machine epsilons; it raises smaller
#: ones to this with a warning) and largest Baumgarte rate (1/s: beyond it the correction
#: makes the equations stiff and the explicit integrators crawl).
RTOL_MIN = 100 * float(np.finfo(float).eps)
STABILIZATION_MAX = 1e6
#: Shortest and longest run (s). Below a nanosecond the default output spacing (duration /
#: 400) and the event tolerances (1e-12 of the duration) are below what the times resolve;
#: above 1e6 s an event within 1e-6 s of the last counts as no progress.
DURATION_MIN, DURATION_MAX = 1e-9, 1e6


def positive(name, value, *, allow_none=False, allow_zero=False):
    """``value`` as a finite float ``> 0`` (``>= 0`` with ``allow_zero``; ``None`` passes
    with ``allow_none``)."""
    if type(value) is float and 0.0 < value < math.inf:
        return value  # already what the checks below would give
    if value is None and allow_none:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
        raise InputError(f"{name} must be a number, got {value!r}")
    v = to_float(value)
    if not math.isfinite(v) or v < 0 or (v == 0 and not allow_zero):
        raise InputError(f"{name} must be a finite number {'>= 0' if allow_zero else '> 0'},"
                         f" got {value!r}")
    return v


def check_count(name, duration, step, limit, what):
    """``duration / step`` (a number of samples, periods or steps) within ``limit``."""
    if step is None:
        return
    count = duration / step
    if not count <= limit:
        raise InputError(f"{name} = {step:g} s gives {count:.3g} {what} over {duration:g} s, "
                         f"above the limit of {limit:g}; give {name} >= {duration / limit:.3g} s")


def single(name, value, size, what):
    """One vector of ``size`` finite numbers (a copy)."""
    if type(value) is np.ndarray and value.dtype == np.float64 and value.shape == (size,) \
            and np.isfinite(value).all():
        return value.copy()  # already what the checks below would give
    try:
        shape = np.shape(value)
    except (TypeError, ValueError):
        shape = None
    if shape != (size,):
        raise InputError(f"{name} has shape {shape}, expected ({size},){what}")
    arr, _ = as_batch(name, value, size, what=what)
    return arr[0].copy()


@dataclass
class Settings:
    """The checked arguments of one run (see :func:`~snakecg.simulate.simulate`)."""

    model: Any
    q0: np.ndarray
    v0: np.ndarray
    q_obj0: np.ndarray
    v_obj0: np.ndarray
    rho: np.ndarray
    f_obj: np.ndarray
    duration: float
    kind: str  # of the torque law: "constant", "time" or "feedback"
    law: Any
    control_period: float | None
    method: Any
    rtol: float
    atol: float
    max_step: float | None
    fixed_step: float | None
    alpha: float  # Baumgarte rate (1/s)
    output_dt: float
    max_events: int
    integrator: str = "auto"  # "auto", "compiled" or "scipy" (snakecg.simulate.compiled)
    geometry_check: str = "stop"  # "stop", "report" or "off" (snakecg.simulate.contact_check)


def _classes():
    """SciPy's ``OdeSolver`` (imported on first use)."""
    global _CLASSES
    if _CLASSES is None:
        try:
            from scipy.integrate import OdeSolver
        except ImportError:  # pragma: no cover - scipy is a dependency of the simulation
            raise SnakecgError("snakecg.simulate needs SciPy (its solve_ivp integrates the "
                               "dynamics): pip install scipy") from None
        _CLASSES = OdeSolver
    return _CLASSES


_CLASSES = None


def check_arguments(model, q0, tau, duration, v0, *, v_obj0, q_obj0, rho, f_obj,
                    control_period, method, rtol, atol, max_step, fixed_step, stabilization,
                    output_dt, max_events, integrator="auto",
                    geometry_check="stop") -> Settings:
    """The arguments of :func:`~snakecg.simulate.simulate` checked, in order, with the
    defaults filled in (the object's placement from the scene when ``q_obj0`` and ``rho``
    are not given)."""
    OdeSolver = _classes()
    if not is_scene_model(model):
        raise InputError("simulate needs a model loaded from a snakecg.Scene "
                         "(snakecg.load(scene)), got " + type(model).__name__)
    ns, na = model.n_coordinates, model.n_joints
    what = f" = (n_joints + 3,) for a {na}-joint robot"
    q0 = single("q0", q0, ns, what)
    v0_default, v_obj0_default, f_default = v0 is None, v_obj0 is None, f_obj is None
    v0 = np.zeros(ns) if v0 is None else single("v0", v0, ns, what)
    v_obj0 = np.zeros(3) if v_obj0 is None else single("v_obj0", v_obj0, 3, "")
    if (q_obj0 is None) != (rho is None):
        raise InputError("q_obj0 and rho go together: give both or neither (default: the "
                         "scene's placement of the object against the contact link)")
    if q_obj0 is None:  # the scene's placement at the checked q0
        q_obj0, rho = placement(model, q0)
    else:
        q_obj0 = single("q_obj0", q_obj0, 3, "")
        rho = single("rho", rho, 2, "")
    f_obj = np.zeros(3) if f_obj is None else single("f_obj", f_obj, 3, "")
    duration = positive("duration", duration)
    if not DURATION_MIN <= duration <= DURATION_MAX:
        raise InputError(f"duration must be from {DURATION_MIN:g} to {DURATION_MAX:g} s, got "
                         f"{duration!r}")
    kind, law = torque_law(tau, na)
    # forces and velocities within float64's range, as forward checks them (the arrays
    # given, the defaults are zeros; a few numbers each: tested in Python, the message from
    # check_input_range)
    for k, a, default, limit in (
            ("v", v0, v0_default, FORCE_LIMIT ** 0.5),
            ("v_obj", v_obj0, v_obj0_default, FORCE_LIMIT ** 0.5),
            ("f_obj", f_obj, f_default, FORCE_LIMIT), ("tau", law, kind != "constant",
                                                       FORCE_LIMIT)):
        if not default and max(map(abs, a.tolist())) > limit:
            check_input_range({k: (a, False)})
    period = positive("control_period", control_period, allow_none=True)
    if period is not None and kind == "constant":
        period = None
    if not ((isinstance(method, str) and method in METHODS)
            or (isinstance(method, type) and issubclass(method, OdeSolver))):
        raise InputError(f"method must be one of {', '.join(METHODS)} (scipy solve_ivp) "
                         f"or an OdeSolver class, got {method!r:.60}")
    rtol_ = positive("rtol", rtol)
    if not RTOL_MIN <= rtol_ <= 1:
        raise InputError(f"rtol must be from {RTOL_MIN:.3g} (100 machine epsilons, what "
                         f"solve_ivp can honour) to 1, got {rtol!r}")
    atol = positive("atol", atol)
    max_step = positive("max_step", max_step, allow_none=True)
    fixed_step = positive("fixed_step", fixed_step, allow_none=True)
    alpha = positive("stabilization", stabilization, allow_zero=True)
    if alpha > STABILIZATION_MAX:
        raise InputError(f"stabilization must be at most {STABILIZATION_MAX:g} 1/s (the "
                         f"limit: a larger rate makes the equations stiff), got "
                         f"{stabilization!r}")
    if output_dt is None:
        output_dt = duration / 400
    output_dt = positive("output_dt", output_dt)
    check_count("output_dt", duration, output_dt, MAX_OUTPUT_SAMPLES, "output samples")
    check_count("control_period", duration, period, MAX_PERIODS,
                "controller periods (one torque query each)")
    check_count("max_step", duration, max_step, MAX_STEPS, "integrator steps")
    check_count("fixed_step", duration, fixed_step, MAX_STEPS, "integrator steps")
    if isinstance(max_events, bool) or not isinstance(max_events, (int, np.integer)) \
            or max_events < 0:
        raise InputError(f"max_events must be an integer >= 0, got {max_events!r}")
    if not (isinstance(integrator, str) and integrator in ("auto", "compiled", "scipy")):
        raise InputError(f"integrator must be 'auto', 'compiled' or 'scipy', got "
                         f"{integrator!r:.60}")
    if not (isinstance(geometry_check, str) and geometry_check in ("stop", "report", "off")):
        raise InputError(f"geometry_check must be 'stop', 'report' or 'off', got "
                         f"{geometry_check!r:.60}")
    _check_mass_matrix(model, q0)
    return Settings(model=model, q0=q0, v0=v0, q_obj0=q_obj0, v_obj0=v_obj0, rho=rho,
                    f_obj=f_obj, duration=duration, kind=kind, law=law, control_period=period,
                    method=method, rtol=rtol_, atol=atol, max_step=max_step,
                    fixed_step=fixed_step, alpha=alpha, output_dt=output_dt,
                    max_events=int(max_events), integrator=integrator,
                    geometry_check=geometry_check)


def _check_mass_matrix(model, q0) -> None:
    """Refuse a robot whose mass matrix is numerically singular at ``q0`` (the forward
    solve's own test, whose answer there is NaN with that reason): no integrator can step such
    a system, it would only shrink its steps."""
    from ..engine.rules import MASS_SINGULAR, reason_of

    res = model.forward(q0, np.zeros(model.n_joints))
    if res.singular and res.reason == reason_of(MASS_SINGULAR):
        raise InputError("robot: the mass matrix is numerically singular at q0 in float64 "
                         "(masses, lengths or inertias too far apart); a simulation cannot "
                         "step it")
