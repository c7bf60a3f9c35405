"""Many runs in one call: a parameter study over initial states, torques or gaits.

:func:`simulate_batch` runs :func:`~snakecg.simulate.simulate` once per row of its batched
arguments and gathers each run's outcome into arrays (:class:`RunBatch`). Every run is
integrated by the same code as a single call (the compiled segments where the run allows it),
so a batch of one equals the single call. Runs are independent: with ``processes > 1`` they are
spread over worker processes, each of which loads the model once from its scene (a loaded
model does not pickle; its :class:`~snakecg.Scene` does) and answers a share of the runs. For
studies that outgrow one machine, split the batch and gather the :class:`RunBatch` es.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field

import numpy as np

from .._inputs import as_batch
from ..errors import InputError
from .simulator import simulate

__all__ = ["RunBatch", "simulate_batch"]

#: Most runs of one batch (each keeps its summary, ~5 kB, and optionally its trajectory).
MAX_RUNS = 10**6


@dataclass
class RunBatch:
    """The outcome of :func:`simulate_batch`, one row per run.

    ``status`` (N,) the runs' ``summary["status"]`` (``completed``, ``penetration``, ...);
    ``t_end`` (N,) the time each run reached; ``q_end`` (N, n_s) and ``q_obj_end`` (N, 3) the
    final snake coordinates and object pose; ``object_displacement`` (N, 3) and
    ``com_displacement`` (N, 2) from start to end; ``sr_mean`` (N,) the time-averaged
    slippage ratio; ``energy_residual`` (N,) the energy balance's residual (J); ``summaries``
    the runs' whole summaries; ``trajectories`` the runs' :class:`Trajectory` objects when
    asked for (``keep_trajectories=True``), else empty.
    """

    status: np.ndarray
    t_end: np.ndarray
    q_end: np.ndarray
    q_obj_end: np.ndarray
    object_displacement: np.ndarray
    com_displacement: np.ndarray
    sr_mean: np.ndarray
    energy_residual: np.ndarray
    summaries: list = field(repr=False)
    trajectories: list = field(default_factory=list, repr=False)

    def __len__(self) -> int:
        return int(self.status.shape[0])

    @property
    def completed(self) -> np.ndarray:
        """Whether each run reached its duration with nothing to report."""
        return self.status == "completed"


def _rows(name: str, value, n: int, width: int, runs: int | None, what: str):
    """``value`` as ``(runs, width)`` rows (one row broadcast to every run) or None."""
    if value is None:
        return None, runs
    arr, batched = as_batch(name, value, width, what=what)
    if batched:
        if runs is not None and arr.shape[0] != runs and runs != 1:
            raise InputError(f"{name} has {arr.shape[0]} rows, other arguments {runs}: give one "
                             f"row per run or one row for every run")
        runs = arr.shape[0] if runs in (None, 1) else runs
    return (arr, batched), runs


def _laws(tau, n_a: int):
    """``tau`` as one law per run (a list) or as constant torques ``(N, n_a)``."""
    if isinstance(tau, (list, tuple)) and tau and all(callable(t) for t in tau):
        return list(tau)
    if callable(tau):
        return [tau]
    return None


def simulate_batch(model, q0, tau, duration, *, v0=None, q_obj0=None, rho=None,
                   processes: int | None = None, keep_trajectories: bool = False,
                   progress: bool = True, **options) -> RunBatch:
    """Run :func:`~snakecg.simulate.simulate` once per row and gather the outcomes.

    Parameters
    ----------
    q0 : (n_s,) or (N, n_s) initial coordinates.
    tau : the torques: constant ``(n_a,)`` or ``(N, n_a)`` (one row per run), one torque law,
        or a list of N laws (``tau(t)`` or ``tau(t, state)``, e.g. one
        :func:`~snakecg.simulate.serpenoid_controller` per gait parameter).
    duration : seconds of every run.
    v0 : (n_s,) or (N, n_s) initial velocities (default at rest). ``q_obj0`` (3,) or (N, 3)
        and ``rho`` (2,) or (N, 2): the object's pose and contact point (together; default
        the scene's placement).
    processes : worker processes (default None: every run in this process). With more than
        one, the torque laws must pickle (the laws of :mod:`snakecg.simulate.gaits` do) and,
        as for any use of :mod:`multiprocessing` with the ``spawn`` start method, a script
        must call this under ``if __name__ == "__main__":`` (the workers import the script).
    keep_trajectories : keep every run's whole :class:`Trajectory` (memory grows with N).
    options : any other keyword of :func:`~snakecg.simulate.simulate` (``control_period``,
        ``geometry_check``, ``output_dt``, ...), the same for every run.

    Rows broadcast: one row of an argument serves every run. Bad arguments are refused before
    any run starts.
    """
    n_s, n_a = int(model.n_coordinates), int(model.n_joints)
    runs: int | None = None
    laws = _laws(tau, n_a)
    if laws is not None and len(laws) > 1:
        runs = len(laws)
    shape_q = f" ({n_s} coordinates per run)"
    q_rows, runs = _rows("q0", q0, n_s, n_s, runs, shape_q)
    v_rows, runs = _rows("v0", v0, n_s, n_s, runs, f" ({n_s} velocities per run)")
    o_rows, runs = _rows("q_obj0", q_obj0, 3, 3, runs, " (x, y, psi per run)")
    r_rows, runs = _rows("rho", rho, 2, 2, runs, " (2 numbers per run)")
    t_rows = None
    if laws is None:
        t_rows, runs = _rows("tau", tau, n_a, n_a, runs, f" (one torque per joint, n_a = {n_a})")
    runs = 1 if runs is None else runs
    if runs > MAX_RUNS:
        raise InputError(f"a batch of {runs} runs is more than {MAX_RUNS}; split it")
    if (o_rows is None) != (r_rows is None):
        raise InputError("q_obj0 and rho go together: give both or neither")
    if processes is not None and (isinstance(processes, bool)
                                  or not isinstance(processes, (int, np.integer))
                                  or processes < 1):
        raise InputError(f"processes must be an integer >= 1 or None, got {processes!r}")

    def pick(rows, i):
        if rows is None:
            return None
        arr, batched = rows
        return arr[i if batched and arr.shape[0] > 1 else 0]

    jobs = []
    for i in range(runs):
        law = laws[i if len(laws) > 1 else 0] if laws is not None else pick(t_rows, i)
        jobs.append((pick(q_rows, i), law, pick(v_rows, i), pick(o_rows, i), pick(r_rows, i)))
    if processes is None:
        processes = 1
    processes = min(int(processes), runs, 4 * (os.cpu_count() or 1))
    records = _run_all(model, jobs, float(duration), options, int(processes), progress,
                       bool(keep_trajectories))
    return _gather(records)


def _one(model, job, duration, options, keep):
    """One run, as the record the batch keeps of it (the trajectory only when kept)."""
    q, law, v, q_obj, rho = job
    traj = simulate(model, q, law, duration, v, q_obj0=q_obj, rho=rho, **options)
    return {"summary": traj.summary, "t_end": float(traj.t[-1]), "q_end": traj.q[-1].copy(),
            "q_obj_end": traj.q_obj[-1].copy(), "trajectory": traj if keep else None}


_WORKER: dict = {}


def _worker_init(model_type, scene, duration, options, keep):
    # the caller's model class builds the worker's (this package never imports the facade)
    _WORKER["model"] = model_type(scene, progress=False)
    _WORKER["args"] = (duration, options, keep)


def _worker_run(job):
    return _one(_WORKER["model"], job, *_WORKER["args"])


def _run_all(model, jobs, duration, options, processes, progress, keep):
    from ..progress import progress_bar, progress_reporter, stage

    report = progress_reporter() if progress and len(jobs) > 1 else None
    first = _one(model, jobs[0], duration, options, keep)  # checks every option, once
    out = [first]
    rest = jobs[1:]
    bar = progress_bar(len(jobs), "runs", enabled=progress)
    bar.update(1)
    with stage(report, f"simulating {len(jobs)} runs of {duration:g} s",
               f"{len(jobs)} runs simulated"):
        if processes <= 1 or not rest:
            for job in rest:
                out.append(_one(model, job, duration, options, keep))
                bar.update(1)
        else:
            import multiprocessing as mp
            from concurrent.futures import ProcessPoolExecutor

            ctx = mp.get_context("spawn")
            with ProcessPoolExecutor(processes, mp_context=ctx, initializer=_worker_init,
                                     initargs=(type(model), model.scene, duration, options,
                                               keep)) as pool:
                chunk = max(1, math.ceil(len(rest) / (4 * processes)))
                for record in pool.map(_worker_run, rest, chunksize=chunk):
                    out.append(record)
                    bar.update(1)
    bar.close()
    return out


def _gather(records) -> RunBatch:
    summaries = [r["summary"] for r in records]
    return RunBatch(
        status=np.array([s["status"] for s in summaries]),
        t_end=np.array([r["t_end"] for r in records]),
        q_end=np.array([r["q_end"] for r in records]),
        q_obj_end=np.array([r["q_obj_end"] for r in records]),
        object_displacement=np.array([[s["object_displacement"][k] for k in ("x", "y", "psi")]
                                      for s in summaries], dtype=float),
        com_displacement=np.array([[s["snake_com_displacement"][k] for k in ("x", "y")]
                                   for s in summaries], dtype=float),
        sr_mean=np.array([np.nan if s["sr_mean"] is None else s["sr_mean"]
                          for s in summaries], dtype=float),
        energy_residual=np.array([s["energy"]["balance_residual"] for s in summaries],
                                 dtype=float),
        summaries=summaries,
        trajectories=[r["trajectory"] for r in records if r["trajectory"] is not None],
    )
