""":func:`sweep`: per-configuration extremes of a scene over a grid or samples, on Dask,
chunk by chunk into a Zarr store, resumable."""

from __future__ import annotations

import dataclasses
import math
import sys
import time
import uuid
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import InputError, SnakecgError
from ..geometry import OBJECT_SIDE, PENETRATION_TOLERANCE, SELF_CLEARANCE
from ..robot import Scene
from . import store as _store
from .cluster import (
    ProgressLines,
    concurrency,
    connect,
    dashboard_of,
    end_bar,
    fills_machine,
    is_local,
    progress_mode,
    start_bar,
)
from .lock import store_lock
from .plan import (Plan, default_bounds, default_chunk, default_grid, grid_plan, samples_plan,
                   spread_chunk)
from .simulation import check_simulation, seconds_per_run
from .work import evaluate_and_write, evaluate_chunk

__all__ = ["sweep", "SweepResult", "LIMIT"]

#: Sweeps of more configurations than this are refused unless the limit is lifted
#: (``limit=None``, or ``--force`` on the command line).
LIMIT = 10_000_000
#: Seconds between writes of the digests of the chunks completed meanwhile, and updates of
#: the store's ``completed_chunks`` attribute, during a sweep (a chunk's digest is the record
#: that it is complete: one write of the digest array costs as much as the bookkeeping of a
#: chunk in the calling process, so it is written for many chunks at once; a sweep killed
#: in between computes at most this interval's chunks again on resume).
MARK_INTERVAL = 1.0


@dataclass
class SweepResult:
    """What a call of :func:`sweep` did: the store, its size, the chunks it computed now and
    the ones it found complete from an earlier run."""

    store: str
    configurations: int
    chunks: int
    chunk: int
    computed_chunks: int
    reused_chunks: int
    seconds: float
    dashboard: str | None = None
    #: Whether the store's reductions leave infeasible shapes out by default, and the
    #: clearance (m) of its ``feasible`` array.
    feasible_only: bool = False
    clearance: float = SELF_CLEARANCE
    #: The joint range the configurations span and where it comes from (``"robot"``: its
    #: joint limits; ``"paper"``: -135..135 degrees; ``"argument"``), and the input region
    #: of the extremes (the ellipsoid of eq. 31, radius 1): :func:`snakecg.limits.describe`.
    limits: dict = dataclasses.field(default_factory=dict)

    def to_dict(self) -> dict:
        return dataclasses.asdict(self)


def _meta(scene: Scene, plan: Plan, feasible: bool, clearance: float,
          fmt: str = _store.FORMAT, simulation: dict | None = None) -> dict:
    from .._version import __version__

    robot = dataclasses.asdict(scene.robot)
    fields = {f.name: getattr(scene, f.name) for f in dataclasses.fields(scene)
              if f.name != "robot"}
    meta = {
        "format": fmt, "version": __version__,
        "robot": robot, "scene": fields,
        "configurations": plan.describe(), "n_configurations": plan.size,
        "chunk": plan.chunk, "n_chunks": plan.n_chunks,
        "arrays": list(_store.array_names()),
        "per_configuration": "SceneModel.extremes(q) with its defaults, "
                             "SceneModel.com_polar(q) and snakecg.geometry.feasibility(model, "
                             "q, clearance=clearance).feasible, q = (0, 0, 0, joint angles)",
        # what the feasible array means (it is computed for every store) and whether the
        # reductions leave the infeasible configurations out by default
        "feasibility": {"clearance": clearance, "object_side": OBJECT_SIDE,
                        "penetration_tolerance": PENETRATION_TOLERANCE},
        "feasible_only": feasible,
    }
    if simulation:
        meta["simulation"] = {**simulation, "per_configuration": (
            "snakecg.simulate.simulate(model, q, tau, duration) with its defaults, from rest")}
    meta["arrays"] = list(_store.array_names(meta))
    return _store._normalise(meta)


def make_plan(scene: Scene, *, grid=None, samples=None, seed=None, bounds=None,
              chunk=None) -> Plan:
    """The :class:`~snakecg.sweeps.plan.Plan` of a sweep's arguments (validated)."""
    joints = scene.robot.joints
    if samples is not None:
        if grid is not None:
            raise InputError("give grid or samples, not both")
        if bounds is None:  # the robot's joint limits (or the paper's range)
            bounds = default_bounds(scene.robot)[0]
        return samples_plan(joints, samples, seed, scene.scenario, bounds, chunk)
    if seed is not None:
        raise InputError("seed goes with samples (seeded random configurations); a grid "
                         "has no seed")
    if bounds is not None:
        raise InputError("bounds go with samples; a grid gives its joint values itself")
    if grid is None:  # the robot's joint limits (or the paper's grid)
        grid = default_grid(scene.robot)[0]
    return grid_plan(joints, grid, scene.scenario, chunk)


def check_feasible(feasible, clearance) -> float:
    """The clearance (m) of a sweep's feasibility check, validated: ``clearance`` goes with
    ``feasible=True``; default :data:`snakecg.geometry.SELF_CLEARANCE`."""
    if not isinstance(feasible, bool):
        raise InputError(f"feasible must be True or False, got {feasible!r}")
    if clearance is None:
        return SELF_CLEARANCE
    if not feasible:
        raise InputError("clearance goes with feasible=True (the least distance between "
                         "non-adjacent links of a feasible shape); without it every shape "
                         "is kept")
    if (isinstance(clearance, bool) or not isinstance(clearance, (int, float, np.floating))
            or not _finite(clearance) or clearance < 0):
        raise InputError(f"clearance must be a finite number >= 0 (m, least distance between "
                         f"non-adjacent links), got {clearance!r}")
    return float(clearance)


def _finite(x) -> bool:
    try:
        return math.isfinite(x)
    except OverflowError:  # an integer beyond float's range
        return False


def sweep(scene, *, grid=None, samples=None, seed=None, store, client=None, chunk=None,
          progress=None, bounds=None, scheduler=None, workers=None, limit=LIMIT,
          verify=True, feasible=False, clearance=None, shared_store=None,
          simulate=None) -> SweepResult:
    """Evaluate :meth:`~snakecg.SceneModel.extremes` and the COM's polar coordinates for
    every configuration of a grid or of seeded samples, in chunks on Dask, into a Zarr store.

    * ``scene``: a :class:`~snakecg.Scene` (it pickles; each worker loads the model from its
      own cache).
    * ``grid``: joint angles (rad), one 1-D sequence for every joint or one per joint;
      default the robot's ``joint_limits``, every 10 degrees or a little less, both limits
      included, or for a robot without them the paper's -135..135 degrees every 10 (28
      values per joint, :func:`~snakecg.sweeps.plan.default_grid`). Or ``samples``
      configurations uniform in ``bounds`` (default the robot's joint limits or -135..135
      degrees, one ``(lo, hi)`` pair in rad or one per joint) from ``seed``.
    * ``store``: path of the Zarr store (a folder, e.g. ``sweep.zarr``). If it exists and was
      made with the same arguments, only the chunks missing from it are computed (each
      recorded chunk is first checked against its digests when ``verify``); a store made with
      other arguments is refused. A sweep into a store that another sweep is writing waits
      for it to end (it prints that it waits, unless progress is off), then resumes it.
    * Where it runs: ``client`` (a ``dask.distributed.Client``), or ``scheduler``
      (``tcp://HOST:PORT`` of a running cluster: a Dask scheduler must answer there within
      10 s, and have a worker within another 10 s), or else a local cluster of ``workers``
      processes (default one per core, at most 4 per core) started and shut down by this
      call, on 127.0.0.1 with TLS and temporary credentials: no other program or user can
      connect to it.
    * ``chunk``: configurations per chunk (one Dask task, one Zarr chunk). Default, for a
      new store: :func:`~snakecg.sweeps.plan.default_chunk` of the scenario and joint count
      (about 1.5 s of single-core work, at most 16 MiB of results), cut so that each worker
      gets at least 4 chunks and the chunk count is a multiple of the workers, as far as
      chunks stay at least a quarter of that (:func:`~snakecg.sweeps.plan.spread_chunk`);
      for an existing store: the chunk size it was made with.
    * ``progress``: None (Dask's progress bar when standard error is a terminal, else one
      line per tenth; ``SNAKECG_PROGRESS=0`` silences it), True, False, ``"bar"``,
      ``"lines"``.
    * ``limit``: refuse more configurations than this (None: no limit).
    * ``feasible``: False (default) keeps every shape, as the paper's grid does; True makes
      the store's reductions (:func:`~snakecg.sweeps.summary`,
      :func:`~snakecg.sweeps.figure`) leave out by default the shapes that are not physically
      possible. Every configuration is evaluated either way, and the store always holds a
      boolean ``feasible`` array (:func:`snakecg.geometry.feasibility`): non-adjacent links
      at least ``clearance`` apart and no link inside the object.
    * ``clearance``: that least distance [m], with ``feasible=True`` only; default
      :data:`snakecg.geometry.SELF_CLEARANCE` (1 cm, the default of
      ``snakecg reproduce --feasible-only`` too). Recorded in the store's attributes.
    * ``shared_store``: who writes the chunks' data. None (default): the workers, when they
      run on this machine (the local cluster this call starts, or a ``client`` of a
      ``distributed.LocalCluster``) and have a thread on every core of it (as the default
      local cluster does); else this process (on a local cluster with cores to spare, its
      writes overlap the workers' computing). True: the workers (they reach the store at
      its absolute path, e.g. on a shared file system; each checks it is the same store).
      False: this process. Either way only this process records the chunks' digests and
      the store's attributes.
    * ``simulate``: None, or ``{"duration": seconds, "tau": joint torques}``: every
      configuration is also the start of a push with these constant torques, simulated by
      :func:`snakecg.simulate.simulate` (its defaults, from rest), and the store holds what
      each run did (:data:`snakecg.sweeps.simulation.SIM_ARRAYS`: how it ended, the object's
      and the COM's displacements, the mean sr), recorded in its attributes.

    Returns a :class:`SweepResult`. Inputs are checked before any work; a bad one raises
    :class:`~snakecg.InputError` and writes nothing.
    """
    t0 = time.perf_counter()
    if not isinstance(scene, Scene):
        raise InputError(f"scene must be a snakecg.Scene, got {type(scene).__name__}")
    plan = make_plan(scene, grid=grid, samples=samples, seed=seed, bounds=bounds, chunk=chunk)
    clearance = check_feasible(feasible, clearance)
    simulation = check_simulation(simulate, scene.robot.joints)
    if limit is not None:
        if isinstance(limit, bool) or not isinstance(limit, int) or limit < 1:
            raise InputError(f"limit must be an integer >= 1 or None, got {limit!r}")
        if plan.size > limit:
            raise InputError(f"{plan.size:,} configurations exceed the limit of {limit:,}; "
                             f"lift it (limit=None, or --force) to run them")
    mode = progress_mode(progress)
    if sum(x is not None for x in (client, scheduler, workers)) > 1:
        raise InputError("give one of client, scheduler or workers")
    if scheduler is not None:
        from .cluster import check_scheduler

        check_scheduler(scheduler)
    elif workers is not None:
        from .cluster import check_workers

        check_workers(workers)
    if shared_store is not None and not isinstance(shared_store, bool):
        raise InputError(f"shared_store must be None (automatic), True or False, "
                         f"got {shared_store!r}")
    if not isinstance(store, (str, Path)) or not str(store).strip():
        raise InputError(f"store must be a path (e.g. 'sweep.zarr'), got {store!r}")
    path = Path(store)
    _store.check_target(path)
    with store_lock(path, quiet=mode == "off"):
        res = _run(scene, plan, path, chunk, client, scheduler, workers, mode, verify,
                   feasible, clearance, shared_store, t0, simulation)
    res.limits = _limits(scene, plan, grid is not None or bounds is not None)
    return res


def _run(scene, plan, path, chunk, client, scheduler, workers, mode, verify, feasible,
         clearance, shared_store, t0, simulation=None) -> SweepResult:
    state = _store.check_target(path)  # again: another sweep may have made it meanwhile
    root, done = None, np.zeros(plan.n_chunks, dtype=bool)
    if state == "existing":
        # resume with the store's own format, and chunk size unless one is given
        plan, fmt = _stored(path, plan, keep_chunk=chunk is None)
        root = _store.open_existing(path, _meta(scene, plan, feasible, clearance, fmt,
                                                simulation))
        done = _store.completed(root, plan, verify=verify, path=path)
    todo = [int(i) for i in np.flatnonzero(~done)]
    reused = plan.n_chunks - len(todo)
    if not todo:
        _mark(root, plan.n_chunks, plan.n_chunks)
        return SweepResult(str(path), plan.size, plan.n_chunks, plan.chunk, 0, reused,
                           time.perf_counter() - t0, None, feasible, clearance)
    c, close = connect(client=client, scheduler=scheduler, workers=workers)
    try:
        dashboard = dashboard_of(c)
        if dashboard and mode != "off":
            sys.stderr.write(f"snakecg sweep: Dask dashboard at {dashboard}\n")
        if root is None:
            if chunk is None:  # the default, spread over the workers there are
                extra = seconds_per_run(simulation) if simulation else 0.0
                plan = dataclasses.replace(plan, chunk=spread_chunk(
                    default_chunk(scene.scenario, plan.joints, plan.size, extra), plan.size,
                    concurrency(c)))
                todo = list(range(plan.n_chunks))
            root = _store.create(path, _meta(scene, plan, feasible, clearance,
                                             simulation=simulation),
                                 plan.size, plan.chunk, plan.joints)
        if shared_store is None:
            shared_store = ((client is None and scheduler is None) or is_local(c)) \
                and fills_machine(c)
        target = (str(path.resolve()), _store.store_id(root)) if shared_store else None
        _compute(c, scene, plan, root, todo, reused, mode, clearance, target, simulation)
    finally:
        close()
    return SweepResult(str(path), plan.size, plan.n_chunks, plan.chunk, len(todo), reused,
                       time.perf_counter() - t0, dashboard, feasible, clearance)


def _limits(scene: Scene, plan: Plan, given: bool) -> dict:
    """The joint range a sweep's configurations span, its source, and the input region."""
    from ..limits import describe

    spans = ([(min(v), max(v)) for v in plan.values] if plan.kind == "grid"
             else list(plan.bounds))
    source = ("argument" if given else
              "robot" if scene.robot.joint_limits is not None else "paper")
    return describe(joint_limits=spans, joint_limits_from=source, radius=1.0)


def _stored(path: Path, plan: Plan, keep_chunk: bool) -> tuple[Plan, str]:
    """The store's format (an older one resumes with the digests it has) and, with
    ``keep_chunk``, ``plan`` with the chunk size recorded in the store at ``path`` (a store
    made with an explicit chunk, or with the default spread over another number of workers,
    resumes without ``chunk``); unchanged if the store records none (the comparison refuses
    it)."""
    stored = _store.open_existing(path, mode="r").attrs["snakecg_sweep"]
    from .plan import plan_from_meta

    plan_from_meta(stored, str(path))  # an edited attribute is refused, saying which
    n = stored.get("chunk")
    if keep_chunk and isinstance(n, int) and not isinstance(n, bool) and n >= 1:
        plan = dataclasses.replace(plan, chunk=n)
    return plan, stored["format"]


def _mark(root, completed: int, total: int) -> None:
    root.attrs.update({"completed_chunks": int(completed), "complete": completed == total})


def _compute(client, scene, plan, root, todo, reused, mode, clearance, target,
             simulation=None) -> None:
    """Submit the chunks ``todo`` and record each as it completes. ``target``: ``(absolute
    path, store id)`` when the workers write the data (they return the digest only), None
    when this process writes it (they return the arrays)."""
    from distributed import as_completed
    from distributed.client import FutureCancelledError

    tag = uuid.uuid4().hex[:8]
    if target is None:
        futures = [client.submit(evaluate_chunk, scene, plan, i, clearance, simulation,
                                 key=f"snakecg-sweep-{tag}-{i}", pure=False) for i in todo]
    else:
        futures = [client.submit(evaluate_and_write, scene, plan, i, clearance, *target,
                                 simulation, key=f"snakecg-sweep-{tag}-{i}", pure=False) for i in todo]
    index = {f.key: i for f, i in zip(futures, todo)}
    lines = ProgressLines(plan.n_chunks, reused, plan.size) if mode == "lines" else None
    bar = start_bar(client, futures) if mode == "bar" else None
    completed = reused
    pending = set(todo)
    configurations_done = sum(plan.chunk_range(i)[1] - plan.chunk_range(i)[0]
                              for i in range(plan.n_chunks) if i not in pending)
    next_mark = time.monotonic() + MARK_INTERVAL
    # this process writes the digests, and the data only when the workers do not
    opened = _store.handles(root) if target is None else {"chunk_digest": root["chunk_digest"]}
    fmt = _store.format_of(root)
    digests: dict = {}  # completed chunks whose digests are not written yet
    try:
        for fut in as_completed(futures):
            i = index[fut.key]
            try:
                result = fut.result()
            except FutureCancelledError:
                raise SnakecgError(f"chunk {i} was cancelled (the cluster went away?)") \
                    from None
            except SnakecgError:
                raise
            except Exception as exc:  # noqa: BLE001 - KilledWorker, lost workers, ...
                raise SnakecgError(f"chunk {i} failed on the cluster: {type(exc).__name__}: "
                                   f"{' '.join(str(exc).split())[:300]}") from None
            start, stop = plan.chunk_range(i)
            if target is None:
                digests[i] = _store.write_data(opened, start, stop, result, fmt)
            else:  # the worker wrote the data; its digest makes the chunk complete
                digests[i] = result[0]
            fut.release()
            completed += 1
            configurations_done += stop - start
            if time.monotonic() >= next_mark or (lines is not None and lines.due()):
                _store.record(opened, digests)
                digests.clear()
                _mark(root, completed, plan.n_chunks)
                next_mark = time.monotonic() + MARK_INTERVAL
            if lines is not None:
                lines.update(configurations_done)
        _store.record(opened, digests)  # the chunks completed since the last write
        digests.clear()
        if bar is not None:
            end_bar(bar)
    finally:
        try:
            client.cancel([f for f in futures if not f.done()])
        except Exception:  # noqa: BLE001 - the cluster may be gone already
            pass
        try:  # after an error: keep the chunks completed before it, as far as possible
            _store.record(opened, digests)
        except Exception:  # noqa: BLE001 - the error that stopped the sweep is the one to see
            pass
        _mark(root, _recorded_count(root), plan.n_chunks)


def _recorded_count(root) -> int:
    """Chunks whose digests are recorded (all of a row's, in format 3)."""
    d = root["chunk_digest"][:]
    return int(np.count_nonzero((d != 0).all(axis=1) if d.ndim == 2 else d))
