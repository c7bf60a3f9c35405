"""A simulation metric in a sweep: every configuration of the sweep is also the start of a
push, simulated for the same time with the same constant joint torques, and what the run did
(how far the object and the snake's centre of mass moved, the mean slippage ratio, how the
run ended) is stored beside the extremes.

The runs are :func:`snakecg.simulate.simulate` with its defaults (the compiled integrator,
the geometry checked at every sample: a start that is not physically possible ends at once
with status ``penetration`` or ``self_contact``). Each run is independent, so a sweep of them
spreads over a Dask cluster like any other.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

__all__ = ["SIM_ARRAYS", "SIM_UNITS", "SIM_LONG", "STATUS_CODES", "check_simulation",
           "evaluate_simulation", "seconds_per_run"]

#: The arrays a simulation adds to a store, one value per configuration.
SIM_ARRAYS = ("sim_status", "sim_t_end", "sim_object_dx", "sim_object_dy", "sim_object_dpsi",
              "sim_com_dx", "sim_com_dy", "sim_sr_mean")
#: How a run ended (``sim_status``; CF ``flag_values`` / ``flag_meanings``): a run's
#: ``summary["status"]`` by its first word.
#: ``refused``: the simulator refused the start (a shape whose links cross or enter the
#: object is not a state to start from); the run's other values are NaN.
STATUS_CODES = {"completed": 0, "penetration": 1, "self_contact": 2, "stopped": 3,
                "refused": 4, "other": 5}
SIM_UNITS = {"sim_status": "1", "sim_t_end": "s", "sim_object_dx": "m", "sim_object_dy": "m",
             "sim_object_dpsi": "rad", "sim_com_dx": "m", "sim_com_dy": "m",
             "sim_sr_mean": "1"}
SIM_LONG = {
    "sim_status": "how the push from this configuration ended (flag_meanings)",
    "sim_t_end": "time the push reached (its duration when completed)",
    "sim_object_dx": "object's displacement along x over the push",
    "sim_object_dy": "object's displacement along y over the push",
    "sim_object_dpsi": "object's rotation over the push",
    "sim_com_dx": "snake's centre of mass displacement along x over the push",
    "sim_com_dy": "snake's centre of mass displacement along y over the push",
    "sim_sr_mean": "time-averaged slippage ratio sr (eq. 30) over the push",
}
#: Longest push a sweep simulates (s): a run keeps its samples in memory.
MAX_DURATION = 60.0


def check_simulation(simulate, n_joints: int) -> dict | None:
    """``simulate`` (None, or a mapping with ``duration`` in s and constant joint torques
    ``tau``, one per joint) validated, as the plain dict the store's attributes record."""
    if simulate is None:
        return None
    if not isinstance(simulate, dict) or set(simulate) != {"duration", "tau"}:
        raise InputError(f"simulate must be None or a dict with the keys 'duration' (s) and "
                         f"'tau' (constant joint torques, {n_joints} values, N m), got "
                         f"{simulate!r}")
    d = simulate["duration"]
    if (isinstance(d, bool) or not isinstance(d, (int, float, np.integer, np.floating))
            or not math.isfinite(d) or not 0 < d <= MAX_DURATION):
        raise InputError(f"simulate['duration'] must be a number of seconds in "
                         f"(0, {MAX_DURATION:g}], got {d!r}")
    try:
        tau = np.asarray(simulate["tau"], dtype=float)
    except (TypeError, ValueError):
        tau = None
    if tau is None or tau.shape != (n_joints,) or not np.all(np.isfinite(tau)) \
            or np.any(np.abs(tau) > 1e6):
        raise InputError(f"simulate['tau'] must be {n_joints} finite joint torques (N m, "
                         f"|tau| <= 1e6), got {simulate['tau']!r}")
    return {"duration": float(d), "tau": [float(t) for t in tau]}


def seconds_per_run(spec: dict) -> float:
    """Estimated single-core seconds of one run: the compiled integrator pushes about a
    thousand times faster than real time, and each run costs about a millisecond of Python
    around it (measured on the paper's scenes, 3 joints)."""
    return 1e-3 + spec["duration"] / 1000.0


def _code(status: str) -> int:
    word = str(status).split()[0] if str(status).split() else "other"
    return STATUS_CODES.get(word, STATUS_CODES["other"])


def evaluate_simulation(model, q: np.ndarray, spec: dict) -> dict[str, np.ndarray]:
    """The simulation arrays of configurations ``q`` ``(n, n_s)``: one push per
    configuration, from rest, with the torques and duration of ``spec``. A start the
    simulator refuses (an input error: the shape is not physically possible) is stored as
    NaN with status ``refused``."""
    from ..simulate import simulate

    n = len(q)
    out = {name: np.full(n, np.nan) for name in SIM_ARRAYS}
    tau = np.asarray(spec["tau"], dtype=float)
    for i in range(n):
        try:
            traj = simulate(model, q[i], tau, spec["duration"])
        except InputError:
            out["sim_status"][i] = STATUS_CODES["refused"]
            continue
        s = traj.summary
        out["sim_status"][i] = _code(s["status"])
        out["sim_t_end"][i] = float(traj.t[-1])
        for k in ("x", "y", "psi"):
            key = "dpsi" if k == "psi" else f"d{k}"
            out[f"sim_object_{key}"][i] = s["object_displacement"][k]
        for k in ("x", "y"):
            out[f"sim_com_d{k}"][i] = s["snake_com_displacement"][k]
        out["sim_sr_mean"][i] = np.nan if s["sr_mean"] is None else s["sr_mean"]
    return out
