"""Progress display for long work: quiet unless standard error is a terminal.

``SNAKECG_PROGRESS=1`` forces it on and ``SNAKECG_PROGRESS=0`` off, so pipes, files and CI
logs stay clean. Steps (derivation, compilation) print one line each through
:func:`progress_reporter`; sweeps use tqdm through :func:`progress_bar`.
"""

from __future__ import annotations

import os
import sys
import time

__all__ = ["progress_enabled", "progress_reporter", "progress_bar"]


def progress_enabled(stream=None) -> bool:
    """Whether to show progress on ``stream`` (default stderr): a terminal, unless
    ``SNAKECG_PROGRESS`` says otherwise (``1`` on, ``0`` off)."""
    forced = os.environ.get("SNAKECG_PROGRESS", "").strip()
    if forced in ("0", "1"):
        return forced == "1"
    stream = sys.stderr if stream is None else stream
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


def progress_reporter(stream=None):
    """A ``progress(message)`` callable for the library's long steps (derivation, rendering,
    compilation), printing ``  [  3.2 s] message`` lines; ``None`` when progress is off."""
    stream = sys.stderr if stream is None else stream
    if not progress_enabled(stream):
        return None
    t0 = time.perf_counter()

    def step(message: str) -> None:
        stream.write(f"  [{time.perf_counter() - t0:6.1f} s] {message}\n")
        stream.flush()

    return step


def progress_bar(total: int, desc: str, *, enabled: bool = True, stream=None):
    """A tqdm bar counting ``total`` steps of a sweep (``update``/``close``), disabled when
    ``enabled`` is false or progress is off for ``stream``."""
    from tqdm import tqdm

    stream = sys.stderr if stream is None else stream
    return tqdm(total=total, desc=desc, unit="step", leave=False, file=stream,
                disable=not (enabled and progress_enabled(stream)))
