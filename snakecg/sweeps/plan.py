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

__all__ = ["Plan", "grid_plan", "samples_plan", "joint_values", "DEFAULT_CHUNK",
           "default_chunk", "plan_from_meta", "SAMPLE_BLOCK", "PAPER_RANGE_DEG", "PAPER_STEP_DEG"]

#: Samples are drawn in blocks of this many configurations (one random stream per block).
SAMPLE_BLOCK = 4096
#: The paper's joint range and step (degrees): 28 values per joint.
PAPER_RANGE_DEG = (-135.0, 135.0)
PAPER_STEP_DEG = 10.0
#: Default configurations per chunk: a chunk is one Dask task and one Zarr chunk. Bounded
#: wheels cost milliseconds per configuration (a chunk is seconds of work); the exact
#: eigenproblem of the other two scenarios costs microseconds, so their chunks are larger.
DEFAULT_CHUNK = {"wheels": 1024, "frictionless": 32768, "ideal_wheels": 32768}


def default_chunk(scenario: str) -> int:
    """The documented default chunk size (configurations) for a scenario."""
    return DEFAULT_CHUNK[scenario]


def joint_values(lo_deg: float, hi_deg: float, step_deg: float) -> np.ndarray:
    """Joint angles (rad) from ``lo_deg`` to ``hi_deg`` inclusive every ``step_deg``, as
    :func:`snakecg.analysis.joint_grid` spaces them (-135..135 every 10: 28 values)."""
    for name, v in (("lo", lo_deg), ("hi", hi_deg), ("step", step_deg)):
        if not _is_real(v) or not math.isfinite(v):
            raise InputError(f"joint range {name} must be a finite number of degrees, got {v!r}")
    if step_deg <= 0:
        raise InputError(f"joint step must be > 0 degrees, got {step_deg!r}")
    if hi_deg < lo_deg:
        raise InputError(f"joint range {lo_deg:g}:{hi_deg:g} is empty (lo > hi): a grid of "
                         f"zero points; give LO:HI with LO <= HI")
    return np.deg2rad(np.arange(lo_deg, hi_deg + 1e-9, step_deg))


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


def _chunk(chunk, scenario: str, size: int) -> int:
    if chunk is None:
        return max(1, min(default_chunk(scenario), size))
    if not _is_int(chunk) or chunk < 1:
        raise InputError(f"chunk must be an integer >= 1 (configurations per chunk), "
                         f"got {chunk!r}")
    return int(min(chunk, size))


def grid_plan(joints: int, grid, scenario: str, chunk=None) -> Plan:
    """A grid plan. ``grid``: None (the paper's -135..135 degrees every 10 on every joint),
    one 1-D sequence of joint angles (rad) for every joint, or one sequence per joint."""
    if grid is None:
        grid = joint_values(*PAPER_RANGE_DEG, PAPER_STEP_DEG)
    try:
        arr = np.asarray(grid, dtype=float)
        per_joint = [arr] * joints if arr.ndim == 1 else list(arr) if arr.ndim == 2 else None
    except (TypeError, ValueError):
        try:  # ragged: one sequence per joint
            per_joint = [np.asarray(v, dtype=float) for v in grid]
        except (TypeError, ValueError):
            per_joint = None
    if per_joint is None or any(v.ndim != 1 for v in per_joint):
        raise InputError("grid must be one 1-D sequence of joint angles (rad) for every joint,"
                         f" or {joints} such sequences (one per joint); got {grid!r}")
    if len(per_joint) != joints:
        raise InputError(f"grid has {len(per_joint)} joint value lists, expected {joints} "
                         f"(one per joint) or a single list for every joint")
    for j, v in enumerate(per_joint, start=1):
        if v.size == 0:
            raise InputError(f"grid of joint {j} has no values: a grid of zero points")
        if not np.all(np.isfinite(v)):
            raise InputError(f"grid of joint {j} must hold finite angles (rad), got {v}")
    values = tuple(tuple(float(x) for x in v) for v in per_joint)
    size = math.prod(len(v) for v in values)
    return Plan(joints=joints, kind="grid", chunk=_chunk(chunk, scenario, size), values=values)


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
    except (TypeError, ValueError):
        b = None
    if b is not None and b.shape == (2,):
        b = np.tile(b, (joints, 1))
    if b is None or b.shape != (joints, 2) or not np.all(np.isfinite(b)) or np.any(
            b[:, 1] < b[:, 0]):
        raise InputError(f"bounds must be one (lo, hi) pair of joint angles (rad, lo <= hi) "
                         f"for every joint or {joints} such pairs, got {bounds!r}")
    return Plan(joints=joints, kind="samples", chunk=_chunk(chunk, scenario, int(count)),
                count=int(count), seed=int(seed),
                bounds=tuple((float(lo), float(hi)) for lo, hi in b))


def plan_from_meta(meta: dict) -> Plan:
    """The plan recorded in a store's ``snakecg_sweep`` attribute."""
    c = meta["configurations"]
    joints, chunk = int(meta["robot"]["joints"]), int(meta["chunk"])
    if c["kind"] == "grid":
        return Plan(joints=joints, kind="grid", chunk=chunk,
                    values=tuple(tuple(v) for v in c["joint_values"]))
    return Plan(joints=joints, kind="samples", chunk=chunk, count=int(c["count"]),
                seed=int(c["seed"]), bounds=tuple(tuple(b) for b in c["bounds"]))
