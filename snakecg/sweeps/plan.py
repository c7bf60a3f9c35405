"""What a sweep evaluates: a configuration grid or seeded samples, cut into chunks.

A :class:`Plan` is small and picklable (it travels to every Dask worker); the configurations
of a chunk are computed from it on demand, so a grid of 28^6 points is never held in memory.

* Grid: one 1-D array of joint angles (rad) per joint; configuration ``i`` is the
  ``i``-th point of the Cartesian product in C order (the last joint varies fastest), the
  order of :func:`snakecg.analysis.joint_grid`.
* Samples: ``count`` configurations uniform in a box of joint angles, from ``seed``; the
  samples are drawn in fixed blocks of :data:`SAMPLE_BLOCK` configurations, block ``b`` from
  the stream ``numpy.random.default_rng([seed, b])``, so configuration ``i`` does not depend
  on the chunk size or on which worker computes it.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .store import configuration_bytes

__all__ = ["Plan", "grid_plan", "samples_plan", "joint_values", "default_grid",
           "default_bounds", "default_chunk",
           "spread_chunk", "configuration_seconds", "result_bytes", "plan_from_meta",
           "SAMPLE_BLOCK", "PAPER_RANGE_DEG", "PAPER_STEP_DEG", "CHUNK_SECONDS",
           "MAX_CHUNK_BYTES", "MAX_CHUNKS", "CHUNKS_PER_WORKER", "CONFIGURATION_SECONDS",
           "joint_count", "check_size", "MAX_EXPLICIT_CHUNKS", "MAX_TASK_BYTES",
           "MAX_POINTS_PER_JOINT"]

#: Samples are drawn in blocks of this many configurations (one random stream per block).
SAMPLE_BLOCK = 4096
#: The paper's joint range and step (degrees): 28 values per joint.
PAPER_RANGE_DEG = (-135.0, 135.0)
PAPER_STEP_DEG = 10.0
#: A default chunk is about this many seconds of single-core work (:func:`default_chunk`):
#: long enough that a chunk's scheduling and Zarr write are a few percent of it, short
#: enough that the last chunks of a sweep leave little idle time.
CHUNK_SECONDS = 1.5
#: ... and holds at most this many bytes of results (every array of the store): the last
#: chunk's transfer and write end the sweep after its computing is done, and the data path
#: costs about 1-3 ms per MB (16 MiB: 49,152 configurations of 3 joints, 0.2 s of
#: frictionless work).
MAX_CHUNK_BYTES = 16 * 2**20
#: A sweep of more configurations than ``MAX_CHUNKS`` default chunks gets larger chunks, so
#: that it has at most this many (Dask tasks, and Zarr chunk files per array).
MAX_CHUNKS = 65536
#: An explicit chunk size may make at most this many chunks (16 times the default's most):
#: each is a Dask task and a file per array.
MAX_EXPLICIT_CHUNKS = 16 * MAX_CHUNKS
#: A chunk holds at most this many bytes of results, whatever the sweep's size (each is
#: computed and held in memory at once by one worker): a sweep so large that even
#: :data:`MAX_CHUNKS` chunks would be larger is refused (:func:`check_size`).
MAX_TASK_BYTES = 2**30
#: A grid has at most this many values per joint (they are recorded in the attributes).
MAX_POINTS_PER_JOINT = 100_000
#: With two or more workers a new store's default chunk is cut so that every worker gets at
#: least this many chunks (and the chunk count is a multiple of the workers), but not below
#: a quarter of :func:`default_chunk` (:func:`spread_chunk`).
CHUNKS_PER_WORKER = 4
#: Single-core CPU seconds per configuration of what a sweep computes (``extremes``,
#: ``com_polar``, ``feasibility``), measured on 1 to 6 joints (one C thread, a 2-core Xeon VM);
#: above 6 joints extrapolated as ``(n_a / 6) ** 4`` (bounded wheels, sampled extremes) and
#: ``(n_a / 6) ** 3`` (the exact eigenproblem of the other two) times the 6-joint cost.
CONFIGURATION_SECONDS = {
    "wheels": {1: 7.2e-6, 2: 20e-6, 3: 115e-6, 4: 960e-6, 5: 2.7e-3, 6: 3.7e-3},
    "frictionless": {1: 0.7e-6, 2: 2.1e-6, 3: 4.4e-6, 4: 16e-6, 5: 25e-6, 6: 34e-6},
    "ideal_wheels": {1: 0.7e-6, 2: 2.1e-6, 3: 4.4e-6, 4: 16e-6, 5: 25e-6, 6: 34e-6},
}
_GROWTH = {"wheels": 4, "frictionless": 3, "ideal_wheels": 3}


def configuration_seconds(scenario: str, n_joints: int) -> float:
    """Estimated single-core seconds per configuration (:data:`CONFIGURATION_SECONDS`)."""
    table = _scenario_table(scenario)
    n = _joint_count(n_joints)
    top = max(table)
    if n <= top:
        return table[n]
    return table[top] * (n / top) ** _GROWTH[scenario]


def result_bytes(n_joints: int) -> int:
    """Bytes of the store's arrays per configuration (:func:`.store.configuration_bytes`:
    ``9 n_a + 10`` float64 values and one boolean)."""
    return configuration_bytes(_joint_count(n_joints))


def _nice(x: float) -> int:
    """The number of the form 2^k or 3 * 2^k nearest to ``x`` (ratio-wise), at least 1."""
    if x <= 1:
        return 1
    k = math.floor(math.log2(x))
    candidates = [2 ** k, 3 * 2 ** (k - 1) if k >= 1 else 1, 2 ** (k + 1)]
    return min(candidates, key=lambda c: abs(math.log(c / x)))


def _nice_below(x: float) -> int:
    """The largest number of the form 2^k or 3 * 2^k at most ``x`` (at least 1)."""
    if x < 2:
        return 1
    k = math.floor(math.log2(x))
    return 3 * 2 ** (k - 1) if k >= 1 and 3 * 2 ** (k - 1) <= x else 2 ** k


def default_chunk(scenario: str, n_joints: int, configurations: int | None = None,
                  extra_seconds: float = 0.0) -> int:
    """The default chunk size (configurations) of a sweep of ``scenario`` with ``n_joints``
    joints: :data:`CHUNK_SECONDS` of single-core work at the cost of
    :func:`configuration_seconds`, rounded to the nearest 2^k or 3 * 2^k, and at most
    :data:`MAX_CHUNK_BYTES` of results (then the largest such number below that). Bounded
    wheels: 98,304 configurations for 1 joint, 65,536 for 2, 12,288 for 3, 1,536 for 4,
    512 for 5, 384 for 6, 128 for 8; the other two scenarios 98,304 for 1 joint, 65,536 for
    2, 49,152 for 3, 32,768 for 4 and 5, 24,576 for 6, 16,384 for 8 (the byte cap binds up
    to 7 joints), 8,192 for 10. With
    ``configurations`` (the sweep's size), raised to ``ceil(configurations / MAX_CHUNKS)`` if
    that is larger (at most :data:`MAX_CHUNKS` chunks). Not capped at the sweep's size (a
    sweep smaller than a chunk is one chunk). ``extra_seconds``: single-core seconds each
    configuration costs besides the extremes (a simulated push,
    :func:`.simulation.seconds_per_run`)."""
    chunk = max(1, _nice(CHUNK_SECONDS / (configuration_seconds(scenario, n_joints)
                                          + extra_seconds)))
    cap = MAX_CHUNK_BYTES / result_bytes(n_joints)
    if chunk > cap:
        chunk = _nice_below(cap)
    if configurations is not None:
        chunk = max(chunk, -(-int(configurations) // MAX_CHUNKS))
    return chunk


def spread_chunk(chunk: int, size: int, workers: int) -> int:
    """The chunk size of a new sweep of ``size`` configurations on ``workers`` concurrent
    workers (threads), from its :func:`default_chunk` ``chunk``: with two or more workers,
    the chunk count is raised to :data:`CHUNKS_PER_WORKER` per worker, then to a multiple of
    ``workers`` (down to one where up is not possible), as far as chunks stay at least a
    quarter of ``chunk``: the last chunks then leave little idle time, and no chunk is so
    small that its overhead outweighs that. The chunks are equal but for the last (a regular
    Zarr chunking). Never more than ``size``."""
    if workers < 2 or size <= 1:
        return max(1, min(chunk, size))
    floor = max(1, chunk // 4)
    most = max(1, size // floor)               # chunks of at least `floor` configurations
    n = max(-(-size // chunk), min(CHUNKS_PER_WORKER * workers, most))
    up = -(-n // workers) * workers
    if up <= most:
        n = up
    elif n > workers:                          # else round down to a multiple
        n -= n % workers
    return max(1, min(-(-size // n), size))


def _scenario_table(scenario: str) -> dict:
    try:
        return CONFIGURATION_SECONDS[scenario]
    except (KeyError, TypeError):
        raise InputError(f"scenario must be one of {', '.join(CONFIGURATION_SECONDS)}, "
                         f"got {scenario!r}") from None


def _joint_count(n_joints) -> int:
    if not _is_int(n_joints) or n_joints < 1:
        raise InputError(f"n_joints must be an integer >= 1, got {n_joints!r}")
    return int(n_joints)


def joint_count(lo_deg: float, hi_deg: float, step_deg: float) -> int:
    """How many values :func:`joint_values` gives for these arguments, computed without
    building them (checked first, so a tiny step is refused before any memory is taken)."""
    for name, v in (("lo", lo_deg), ("hi", hi_deg), ("step", step_deg)):
        if not _is_real(v) or not math.isfinite(v):
            raise InputError(f"joint range {name} must be a finite number of degrees, got {v!r}")
    if step_deg <= 0:
        raise InputError(f"joint step must be > 0 degrees, got {step_deg!r}")
    if hi_deg < lo_deg:
        raise InputError(f"joint range {lo_deg:g}:{hi_deg:g} is empty (lo > hi): a grid of "
                         f"zero points; give LO:HI with LO <= HI")
    span = (float(hi_deg) + 1e-9 - float(lo_deg)) / float(step_deg)
    if not math.isfinite(span) or span > MAX_POINTS_PER_JOINT:
        raise InputError(f"joint range {lo_deg:g}:{hi_deg:g} every {step_deg:g} degrees has "
                         f"more than {MAX_POINTS_PER_JOINT:,} values per joint; give a larger "
                         f"step")
    # numpy.arange's length: ceil((stop - start) / step)
    return max(1, math.ceil(span))


def joint_values(lo_deg: float, hi_deg: float, step_deg: float) -> np.ndarray:
    """Joint angles (rad) from ``lo_deg`` to ``hi_deg`` inclusive every ``step_deg``, as
    :func:`snakecg.analysis.joint_grid` spaces them (-135..135 every 10: 28 values); at most
    :data:`MAX_POINTS_PER_JOINT` (:func:`joint_count`)."""
    joint_count(lo_deg, hi_deg, step_deg)
    return np.deg2rad(np.arange(lo_deg, hi_deg + 1e-9, step_deg))


def default_grid(robot) -> tuple[list[np.ndarray], str]:
    """A sweep's joint values when none are given, and where they come from: for a robot
    with ``joint_limits``, from each joint's lower to its upper limit (within +-pi), both
    included, evenly at most :data:`PAPER_STEP_DEG` apart (``"robot"``); for a robot
    without them, the paper's grid, -135..135 degrees every 10 (``"paper"``)."""
    from ..limits import default_joint_limits

    if robot.joint_limits is None:
        return [joint_values(*PAPER_RANGE_DEG, PAPER_STEP_DEG)] * robot.joints, "paper"
    step = math.radians(PAPER_STEP_DEG)
    limits, source = default_joint_limits(robot)
    return [np.linspace(lo, hi, int(math.ceil((hi - lo) / step - 1e-9)) + 1)
            for lo, hi in limits], source


def default_bounds(robot) -> tuple[tuple, str]:
    """The sampling box of a sweep's samples when none is given, and where it comes from:
    the robot's ``joint_limits`` within +-pi (``"robot"``), or the paper's -135..135 degrees
    (``"paper"``)."""
    from ..limits import default_joint_limits

    limits, source = default_joint_limits(robot)
    return tuple((float(lo), float(hi)) for lo, hi in limits), source


def _is_real(v) -> bool:
    return isinstance(v, numbers.Real) and not isinstance(v, bool)


def _is_int(v) -> bool:
    return isinstance(v, numbers.Integral) and not isinstance(v, bool)


@dataclass(frozen=True)
class Plan:
    """The configurations of a sweep and their chunking (see the module docstring)."""

    joints: int
    kind: str                     # "grid" | "samples"
    chunk: int
    values: tuple = ()            # grid: one tuple of joint angles (rad) per joint
    count: int = 0                # samples: how many
    seed: int = 0                 # samples: the seed
    bounds: tuple = ()            # samples: (lo, hi) rad per joint

    @property
    def shape(self) -> tuple[int, ...]:
        """Grid: points per joint; samples: ``(count,)``."""
        if self.kind == "grid":
            return tuple(len(v) for v in self.values)
        return (self.count,)

    @property
    def size(self) -> int:
        """Number of configurations."""
        return math.prod(self.shape) if self.kind == "grid" else self.count

    @property
    def n_chunks(self) -> int:
        return -(-self.size // self.chunk)

    def chunk_range(self, index: int) -> tuple[int, int]:
        """``(start, stop)`` configuration indices of chunk ``index``."""
        start = index * self.chunk
        return start, min(start + self.chunk, self.size)

    def joint_angles(self, start: int, stop: int) -> np.ndarray:
        """Joint angles ``(stop - start, joints)`` (rad) of configurations ``start..stop-1``."""
        if self.kind == "grid":
            idx = np.unravel_index(np.arange(start, stop, dtype=np.int64), self.shape)
            return np.stack([np.asarray(v, dtype=float)[i] for v, i in zip(self.values, idx)],
                            axis=1)
        lo = np.array([b[0] for b in self.bounds])
        hi = np.array([b[1] for b in self.bounds])
        parts = []
        for block in range(start // SAMPLE_BLOCK, (stop - 1) // SAMPLE_BLOCK + 1):
            u = np.random.default_rng([self.seed, block]).random((SAMPLE_BLOCK, self.joints))
            b0 = block * SAMPLE_BLOCK
            parts.append(u[max(start, b0) - b0:min(stop, b0 + SAMPLE_BLOCK) - b0])
        return lo + (hi - lo) * np.concatenate(parts, axis=0)

    def configurations(self, index: int) -> np.ndarray:
        """Full configurations ``(n, joints + 3)`` of chunk ``index`` (x = y = theta = 0)."""
        a = self.joint_angles(*self.chunk_range(index))
        return np.ascontiguousarray(np.hstack([np.zeros((a.shape[0], 3)), a]))

    def describe(self) -> dict:
        """JSON-ready description (stored in the sweep's attributes, compared on resume)."""
        if self.kind == "grid":
            return {"kind": "grid", "joint_values": [list(map(float, v)) for v in self.values],
                    "points_per_joint": list(self.shape)}
        return {"kind": "samples", "count": self.count, "seed": self.seed,
                "bounds": [list(map(float, b)) for b in self.bounds],
                "block": SAMPLE_BLOCK}


def check_size(size: int, joints: int) -> None:
    """Refuse a sweep of ``size`` configurations too large for one store: even in
    :data:`MAX_CHUNKS` chunks, each would hold more than :data:`MAX_TASK_BYTES` of results."""
    per = result_bytes(joints)
    if -(-size // MAX_CHUNKS) * per > MAX_TASK_BYTES:
        most = MAX_CHUNKS * (MAX_TASK_BYTES // per)
        raise InputError(f"{size:,} configurations are too many for one store (at most "
                         f"{most:,} for {joints} joints: {MAX_CHUNKS:,} chunks of at most "
                         f"{MAX_TASK_BYTES // 2**20:,} MiB of results); split the sweep")


def _chunk(chunk, scenario: str, joints: int, size: int) -> int:
    check_size(size, joints)
    if chunk is None:
        return max(1, min(default_chunk(scenario, joints, size), size))
    if not _is_int(chunk) or chunk < 1:
        raise InputError(f"chunk must be an integer >= 1 (configurations per chunk), "
                         f"got {chunk!r}")
    problems = []
    if min(chunk, size) * result_bytes(joints) > MAX_TASK_BYTES:
        problems.append(f"at most {MAX_TASK_BYTES // result_bytes(joints):,} configurations "
                        f"({MAX_TASK_BYTES // 2**20:,} MiB of results, held in memory by "
                        f"one worker)")
    if -(-size // min(chunk, size)) > MAX_EXPLICIT_CHUNKS:
        problems.append(f"at least {-(-size // MAX_EXPLICIT_CHUNKS):,} for these "
                        f"{size:,} configurations (at most {MAX_EXPLICIT_CHUNKS:,} chunks: "
                        f"each is a Dask task and a file per array)")
    if problems:
        raise InputError(f"chunk {chunk:,} is out of range: give {' and '.join(problems)}")
    return int(min(chunk, size))


def grid_plan(joints: int, grid, scenario: str, chunk=None) -> Plan:
    """A grid plan. ``grid``: None (the paper's -135..135 degrees every 10 on every joint),
    one 1-D sequence of joint angles (rad) for every joint, or one sequence per joint."""
    if grid is None:
        grid = joint_values(*PAPER_RANGE_DEG, PAPER_STEP_DEG)
    try:
        arr = np.asarray(grid, dtype=float)
        per_joint = [arr] * joints if arr.ndim == 1 else list(arr) if arr.ndim == 2 else None
    except OverflowError:  # an integer beyond float's range
        per_joint = None
    except (TypeError, ValueError):
        try:  # ragged: one sequence per joint
            per_joint = [np.asarray(v, dtype=float) for v in grid]
        except (TypeError, ValueError, OverflowError):
            per_joint = None
    if per_joint is None or any(v.ndim != 1 for v in per_joint):
        raise InputError("grid must be one 1-D sequence of joint angles (rad) for every joint,"
                         f" or {joints} such sequences (one per joint); got {grid!r}")
    if len(per_joint) != joints:
        raise InputError(f"grid has {len(per_joint)} joint value lists, expected {joints} "
                         f"(one per joint) or a single list for every joint")
    for j, v in enumerate(per_joint, start=1):
        if v.size > MAX_POINTS_PER_JOINT:
            raise InputError(f"grid of joint {j} has {v.size:,} values, more than "
                             f"{MAX_POINTS_PER_JOINT:,}")
        if v.size == 0:
            raise InputError(f"grid of joint {j} has no values: a grid of zero points")
        if not np.all(np.isfinite(v)):
            raise InputError(f"grid of joint {j} must hold finite angles (rad), got {v}")
    values = tuple(tuple(float(x) for x in v) for v in per_joint)
    size = math.prod(len(v) for v in values)
    return Plan(joints=joints, kind="grid", chunk=_chunk(chunk, scenario, joints, size),
                values=values)


def samples_plan(joints: int, count, seed, scenario: str, bounds=None, chunk=None) -> Plan:
    """A plan of ``count`` seeded samples, uniform in ``bounds``: None (the paper's range,
    -135..135 degrees, on every joint), one ``(lo, hi)`` pair (rad) for every joint, or one
    pair per joint."""
    if not _is_int(count) or count < 1:
        raise InputError(f"samples must be an integer >= 1 (number of configurations), "
                         f"got {count!r}")
    if not _is_int(seed) or seed < 0:
        raise InputError(f"seed must be an integer >= 0 with samples (the random stream), "
                         f"got {seed!r}")
    if bounds is None:
        bounds = tuple(np.deg2rad(PAPER_RANGE_DEG))
    try:
        b = np.asarray(bounds, dtype=float)
    except (TypeError, ValueError, OverflowError):
        b = None
    if b is not None and b.shape == (2,):
        b = np.tile(b, (joints, 1))
    if b is None or b.shape != (joints, 2) or not np.all(np.isfinite(b)) or np.any(
            b[:, 1] < b[:, 0]):
        raise InputError(f"bounds must be one (lo, hi) pair of joint angles (rad, lo <= hi) "
                         f"for every joint or {joints} such pairs, got {bounds!r}")
    return Plan(joints=joints, kind="samples", chunk=_chunk(chunk, scenario, joints, int(count)),
                count=int(count), seed=int(seed),
                bounds=tuple((float(lo), float(hi)) for lo, hi in b))


def plan_from_meta(meta, store="the store") -> Plan:
    """The plan recorded in a store's ``snakecg_sweep`` attribute, checked: every problem
    of an edited or damaged attribute is collected and raised at once as an
    :class:`InputError` naming the attribute."""
    problems = []

    def get(d, key, where):
        if not isinstance(d, dict) or key not in d:
            problems.append(f"{where}{key} is missing")
            return None
        return d[key]

    def integer(v, where, least):
        if not _is_int(v) or v < least:
            problems.append(f"{where} is {v!r}, expected an integer >= {least}")
            return None
        return int(v)

    robot = get(meta, "robot", "")
    joints = integer(get(robot, "joints", "robot."), "robot.joints", 1) \
        if isinstance(robot, dict) else None
    chunk = integer(get(meta, "chunk", ""), "chunk", 1)
    c = get(meta, "configurations", "")
    plan = None
    kind = c.get("kind") if isinstance(c, dict) else None
    if isinstance(c, dict) and kind not in ("grid", "samples"):
        problems.append(f"configurations.kind is {kind!r}, expected 'grid' or 'samples'")
    elif kind == "grid" and joints is not None and chunk is not None:
        values = get(c, "joint_values", "configurations.")
        if (not isinstance(values, list) or len(values) != joints
                or not all(isinstance(v, list) and v and len(v) <= MAX_POINTS_PER_JOINT
                           and all(_is_real(x) and math.isfinite(x) for x in v)
                           for v in values)):
            problems.append(f"configurations.joint_values is not {joints} lists of finite "
                            f"angles")
        else:
            plan = Plan(joints=joints, kind="grid", chunk=chunk,
                        values=tuple(tuple(float(x) for x in v) for v in values))
    elif kind == "samples" and joints is not None and chunk is not None:
        count = integer(get(c, "count", "configurations."), "configurations.count", 1)
        seed = integer(get(c, "seed", "configurations."), "configurations.seed", 0)
        bounds = get(c, "bounds", "configurations.")
        if (not isinstance(bounds, list) or len(bounds) != joints
                or not all(isinstance(b, list) and len(b) == 2
                           and all(_is_real(x) and math.isfinite(x) for x in b)
                           and b[0] <= b[1] for b in bounds)):
            problems.append(f"configurations.bounds is not {joints} (lo, hi) pairs")
        elif count is not None and seed is not None:
            plan = Plan(joints=joints, kind="samples", chunk=chunk, count=count, seed=seed,
                        bounds=tuple((float(lo), float(hi)) for lo, hi in bounds))
    if plan is not None:
        for key, want in (("n_configurations", plan.size), ("n_chunks", plan.n_chunks)):
            found = get(meta, key, "")
            if found is not None and found != want:
                problems.append(f"{key} is {found!r}, but the configurations and the "
                                f"chunk make {want:,}")
    if problems or plan is None:
        raise InputError(f"{store!s}: its attribute snakecg_sweep is damaged or was edited: "
                         f"{'; '.join(problems) or 'no plan'}")
    return plan
