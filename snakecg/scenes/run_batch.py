"""Many runs of one general scene in one call: a study over initial states, torques or gait
parameters (:func:`simulate_scene_batch`), each run by the engine's loop
(``snakecg/engine/scene_run.c``'s ``core_scene_run_batch``) to its end, with its status and
metrics (:class:`SceneBatch`). Every run is the same code as a single
:func:`~snakecg.scenes.stepping.simulate_scene` (the single call returns to Python for its
record and events and goes on exactly where it stopped), so a run of a batch ends where the
single call ends, bit for bit. ``SNAKECG_THREADS`` splits the runs over threads
(:mod:`snakecg.engine.threads`); the answers never depend on the split.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..engine.threads import pool, threads
from ..errors import InputError
from .run_record import ST_HELD
from .stepping import (STEP_DONE, _check_args, _model_tolerance, _Runner, _Stepper, ending,
                       engine_law)

__all__ = ["SceneBatch", "simulate_scene_batch"]

#: Most runs of one batch.
MAX_RUNS = 100_000


@dataclass
class SceneBatch:
    """The outcome of :func:`simulate_scene_batch`, one row per run.

    ``status`` (N,) as a single run's (``completed``, ``penetration``, ``not_converged``, or
    ``invalid_torque`` where a law's torque was not finite or beyond the force limit: a single
    run raises there), ``message`` (N,) why it stopped (empty when completed, but where the gap
    stabilisation did more than 1 % of the torques' work); ``t_end`` (N,) the time reached,
    ``steps`` (N,), ``held_steps`` (N,: the steps that held their overlaps rather than push
    them out, as a single run's) and ``impacts`` (N,) counts; ``q_end`` (N, n_s),
    ``q_obj_end`` (N, n_objects, 3) the final state; ``com_displacement`` (N, 2) of the
    snake's centre of mass and ``object_displacement`` (N, n_objects, 3) from start to end;
    ``deepest_overlap`` (N,) the deepest a contact went into a body over the run (m, 0 when
    none did; at most the tolerance in a completed run); ``tolerance`` the contact tolerance.
    """

    status: np.ndarray
    message: np.ndarray
    t_end: np.ndarray
    steps: np.ndarray
    held_steps: np.ndarray
    impacts: np.ndarray
    q_end: np.ndarray
    q_obj_end: np.ndarray
    com_displacement: np.ndarray
    object_displacement: np.ndarray
    deepest_overlap: np.ndarray
    tolerance: float

    def __len__(self) -> int:
        return int(self.status.shape[0])

    @property
    def completed(self) -> np.ndarray:
        """Whether each run reached its duration."""
        return self.status == "completed"


def _per_run(name, value, shape, runs):
    """``value`` as ``runs`` rows of ``shape`` (one given for every run, or one per run), or
    None."""
    if value is None:
        return None
    arr = np.asarray(value, dtype=float) if not isinstance(value, (str, bytes)) else None
    size = int(np.prod(shape))
    if arr is not None and arr.size == size and np.all(np.isfinite(arr)):
        return np.broadcast_to(arr.reshape(shape), (runs,) + shape)
    if arr is not None and arr.size == runs * size and np.all(np.isfinite(arr)):
        return arr.reshape((runs,) + shape)
    raise InputError(f"simulate_scene_batch: {name} must be {size} finite numbers (shape "
                     f"{shape}) for every run, or {runs} such rows, got shape {np.shape(value)}")


def _laws(tau, n_a: int, runs: int | None):
    """One ``(name, parameters)`` per run (:func:`~snakecg.scenes.stepping.engine_law`): a
    constant, ``(N, n_a)`` constants, a law the engine evaluates, or a list of these."""
    from ..simulate.torques import torque_law

    def one(value):
        kind, law = torque_law(value, n_a)
        name, params = engine_law(kind, law, n_a)
        if name == "caller":
            raise InputError("simulate_scene_batch: tau must be constants, a TorqueTable or a "
                             "SerpenoidPD (laws the engine evaluates), or a list of them; "
                             f"{value!r:.60} is a law of its own: run simulate_scene for it")
        return name, params

    if tau is None:
        return [("constant", np.zeros(n_a))], runs
    if isinstance(tau, (list, tuple)) and tau and not all(
            isinstance(v, (int, float, np.number)) for v in tau):
        laws = [one(np.asarray(v, dtype=float) if isinstance(v, (list, tuple)) else v)
                for v in tau]
    elif not callable(tau) and np.ndim(tau) == 2:
        laws = [one(np.ascontiguousarray(row, dtype=float)) for row in np.asarray(tau)]
    else:
        return [one(tau)], runs
    if runs not in (None, 1, len(laws)) and len(laws) != 1:
        raise InputError(f"simulate_scene_batch: tau has {len(laws)} laws, the other "
                         f"arguments {runs} runs: give one per run or one for every run")
    return laws, (len(laws) if runs in (None, 1) else runs)


def _runs_of(q0, v0, q_obj0, v_obj0, ns, no) -> int | None:
    """The runs that ``q0``, ``v0``, ``q_obj0``, ``v_obj0`` ask for (None: one row each)."""
    found = set()
    for value, size in ((q0, ns), (v0, ns), (q_obj0, 3 * no), (v_obj0, 3 * no)):
        if value is not None and size and np.size(value) > size and np.size(value) % size == 0:
            found.add(np.size(value) // size)
    if len(found) > 1:
        raise InputError(f"simulate_scene_batch: q0, v0, q_obj0 and v_obj0 ask for different "
                         f"numbers "
                         f"of runs ({sorted(found)})")
    return found.pop() if found else None


def simulate_scene_batch(model, q0, duration, *, v0=None, tau=None, dt=1e-3, q_obj0=None,
                         v_obj0=None, f_obj=None, tolerance=None) -> SceneBatch:
    """Run the general scene of ``model`` from many initial states or with many torque laws
    for ``duration`` seconds each, in the engine: the arguments of
    :func:`~snakecg.scenes.stepping.simulate_scene`, each one row for every run or one row
    per run: ``q0`` ``(n_s,)`` or ``(N, n_s)``, ``v0`` likewise, ``q_obj0``/``v_obj0``
    ``(n_objects, 3)`` or ``(N, n_objects, 3)``, ``tau`` a constant ``(n_a,)``, constants
    ``(N, n_a)``, a :class:`~snakecg.simulate.TorqueTable` or
    :class:`~snakecg.simulate.SerpenoidPD`, or a list of N of these (a law of the caller's own
    runs in :func:`~snakecg.scenes.stepping.simulate_scene` only). ``f_obj``, ``dt`` and
    ``tolerance`` are the batch's. Returns a :class:`SceneBatch`."""
    ns, no, na = model.n_coordinates, model.scene.n_objects, model.n_joints
    runs = _runs_of(q0, v0, q_obj0, v_obj0, ns, no)
    laws, runs = _laws(tau, na, runs)
    runs = runs or 1
    if runs > MAX_RUNS:
        raise InputError(f"simulate_scene_batch: {runs} runs, more than {MAX_RUNS}; split "
                         "the batch")
    Q = _per_run("q0", q0, (ns,), runs) if q0 is not None else None
    if Q is None:
        raise InputError(f"simulate_scene_batch: q0 is required: {ns} numbers or ({runs}, "
                         f"{ns})")
    V = _per_run("v0", v0, (ns,), runs)
    QO = _per_run("q_obj0", q_obj0, (no, 3), runs)
    VO = _per_run("v_obj0", v_obj0, (no, 3), runs)
    # the batch's own arguments, checked as a single run's
    _, _, _, _, fo = _check_args(model, Q[0], None, duration, dt, None, None, f_obj,
                                 tolerance)
    tol = _model_tolerance(model, tolerance)
    status = np.full(runs, "", dtype=object)
    message = np.full(runs, "", dtype=object)
    t_end, steps, impacts = np.zeros(runs), np.zeros(runs, dtype=int), np.zeros(runs, dtype=int)
    held = np.zeros(runs, dtype=int)
    q_end, q_obj_end = np.zeros((runs, ns)), np.zeros((runs, no, 3))
    q_obj_start, deepest = np.zeros((runs, no, 3)), np.zeros(runs)
    keep, going = [], []
    placed = model.object_poses(Q) if QO is None else QO  # the engine's placement, one call
    for i in range(runs):
        name, params = laws[i if len(laws) > 1 else 0]
        st = _Stepper(model, tol, fo.reshape(-1))
        code = st.begin(Q[i], placed[i], None if V is None else V[i],
                        None if VO is None else VO[i])
        q_obj_start[i] = st.x[ns:].reshape(no, 3)
        if code != STEP_DONE:
            status[i], message[i] = "penetration", st.engine.refusal(st.out)
            q_end[i], q_obj_end[i] = Q[i], q_obj_start[i]
            deepest[i] = np.nan if st.out[0] else 0.0
            continue
        run = _Runner(st, duration, dt, name, params, 0, 0, stop_at_impacts=False, pause=0)
        if name == "constant":
            st.tau[:na] = params
        keep.append(run)
        going.append(i)
    codes = np.zeros(len(keep), dtype=np.int64)
    ptrs = np.array([r._address for r in keep], dtype=np.uint64)
    fn = model.core.scene_run_batch
    n_threads = threads(len(keep), 1)

    def job(lo, hi):
        fn(ptrs.ctypes.data + 8 * lo, hi - lo, codes.ctypes.data + 8 * lo)

    if n_threads <= 1:
        job(0, len(keep))
    else:
        bounds = np.linspace(0, len(keep), n_threads + 1).astype(int)
        for f in [pool().submit(job, int(lo), int(hi)) for lo, hi in zip(bounds[:-1],
                                                                       bounds[1:])]:
            f.result()
    for run, i, code in zip(keep, going, codes):
        code = int(code)
        if code < 0:
            status[i], message[i] = "failed", f"the engine's run refused ({code})"
        else:
            status[i], message[i], _ = ending(code, run, model.scene)
        st, a = run.st, run.args
        t_end[i], steps[i], impacts[i] = a.t, a.nstep, a.impacts
        held[i] = int(st.acc[ST_HELD])
        q_end[i], q_obj_end[i] = st.x[:ns], st.x[ns:].reshape(no, 3)
        deepest[i] = max(0.0, -a.min_gap)
    com0, com1 = model.com(Q), model.com(q_end)
    return SceneBatch(status=status.astype(str), message=message.astype(str), t_end=t_end,
                      steps=steps, held_steps=held, impacts=impacts, q_end=q_end,
                      q_obj_end=q_obj_end,
                      com_displacement=np.asarray(com1) - np.asarray(com0),
                      object_displacement=q_obj_end - q_obj_start, deepest_overlap=deepest,
                      tolerance=tol)
