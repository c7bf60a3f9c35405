"""The one thread rule of the engine's batched calls.

A batch runs on one thread unless ``SNAKECG_THREADS`` asks for more; then it is split into
contiguous chunks of at least ``parallel_min`` samples each (the step's own threshold,
measured by ``benchmarks/bench_threads.py``), run on a shared pool (ctypes releases the GIL
during the C call). Results never depend on the split: every sample is computed by the same
code on its own.

Why one thread by default: on a machine whose cores are busy with other work, a second thread
waits for a core, and a batch split across threads then took up to eight times as long as on
one thread (batched ``M`` at 20 joints: 0.34 to 4.85 us per configuration over three runs, one
thread a steady 0.60 us). A default that can be slower than one thread is a cost the caller
did not ask for; a caller with idle cores sets ``SNAKECG_THREADS``.

One :class:`~snakecg.engine.data.Data` per thread is the threading rule of the models
themselves; the pool here only splits one call's batch.
"""

from __future__ import annotations

import os
from concurrent.futures import ThreadPoolExecutor

__all__ = ["PARALLEL_MIN", "asked_threads", "pool", "threads"]

#: Samples per thread below which a generated function's batch is not split.
PARALLEL_MIN = 2048
#: Most threads the pool ever holds.
MAX_THREADS = 8
_POOL: ThreadPoolExecutor | None = None


def asked_threads() -> int:
    """``SNAKECG_THREADS`` (at least 1, at most :data:`MAX_THREADS`); 1 when unset or not an
    integer."""
    raw = os.environ.get("SNAKECG_THREADS")
    if not raw:
        return 1
    try:
        return max(1, min(int(raw), MAX_THREADS))
    except ValueError:
        return 1


def threads(n: int, parallel_min: int) -> int:
    """Threads for a batch of ``n``: :func:`asked_threads`, fewer so that each gets
    ``parallel_min`` samples at least (at least 1)."""
    return max(1, min(asked_threads(), n // max(1, parallel_min)))


def pool() -> ThreadPoolExecutor:
    """The shared worker threads of batched calls."""
    global _POOL
    if _POOL is None:
        _POOL = ThreadPoolExecutor(max_workers=MAX_THREADS, thread_name_prefix="snakecg")
    return _POOL
