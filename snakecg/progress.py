"""Progress display for long work, on standard error.

Steps (generating a model, compiling it, the stages of ``snakecg reproduce``) print one line
when they start and one when they end, with the elapsed time, through
:func:`progress_reporter` and :func:`stage`: on every stream, a terminal, a pipe, a log file
or a notebook's captured output alike, because a compile of tens of seconds must not look like
a hang anywhere. They are quiet only when asked: ``progress=False``, ``--quiet`` on the
command line, or ``SNAKECG_PROGRESS=0``.

Bars that redraw themselves (sweeps use tqdm through :func:`progress_bar`; long batches of
``model.extremes`` go in chunks through :func:`in_chunks`) are drawn on a terminal or in a
Jupyter notebook only (tqdm's widget when ipywidgets is installed, else its text bar);
``SNAKECG_PROGRESS=1`` forces them on. ``snakecg.load`` reports model builds by default
(:func:`resolve`).
"""

from __future__ import annotations

import os
import sys
import time
from contextlib import contextmanager

__all__ = ["progress_enabled", "progress_reporter", "progress_bar", "in_notebook", "resolve",
           "in_chunks", "quiet", "stage"]


def quiet() -> bool:
    """Whether progress was silenced for this process (``SNAKECG_PROGRESS=0``, which the
    command line's ``--quiet`` sets for the command's run)."""
    return os.environ.get("SNAKECG_PROGRESS", "").strip() == "0"


def in_notebook() -> bool:
    """Whether this runs in a Jupyter kernel (where standard error is no terminal, but the
    notebook shows what is written to it)."""
    ipython = sys.modules.get("IPython")
    if ipython is None:
        return False
    try:
        shell = ipython.get_ipython()
    except Exception:  # noqa: BLE001 - any IPython oddity means "not a notebook"
        return False
    if shell is None:
        return False
    return getattr(shell, "kernel", None) is not None or "IPKernelApp" in getattr(
        shell, "config", {})


def progress_enabled(stream=None) -> bool:
    """Whether to draw a progress *bar* on ``stream`` (default stderr): a terminal or a
    notebook, unless ``SNAKECG_PROGRESS`` says otherwise (``1`` on, ``0`` off). Step lines
    (:func:`progress_reporter`) go to every stream."""
    forced = os.environ.get("SNAKECG_PROGRESS", "").strip()
    if forced in ("0", "1"):
        return forced == "1"
    stream = sys.stderr if stream is None else stream
    try:
        if stream.isatty():
            return True
    except (AttributeError, ValueError):
        return False
    return stream is sys.stderr and in_notebook()


def progress_reporter(stream=None, *, prefix: str = "snakecg"):
    """A ``progress(message)`` callable for the library's long steps (derivation, rendering,
    compilation, the stages of a reproduction), printing ``snakecg [   3.2 s] message`` lines
    (seconds since the reporter was made) on ``stream`` (default stderr), whatever the
    stream is; ``None`` when progress is silenced (:func:`quiet`)."""
    if quiet():
        return None
    t0 = time.perf_counter()

    def step(message: str) -> None:
        out = sys.stderr if stream is None else stream  # sys.stderr as it is now (pytest)
        try:
            out.write(f"{prefix} [{time.perf_counter() - t0:6.1f} s] {message}\n")
            out.flush()
        except (OSError, ValueError):  # a closed or broken stream: progress is not worth dying
            pass

    return step


@contextmanager
def stage(progress, start: str, done: str):
    """One line ``start`` when the block begins and one ``done in 12.3 s`` when it ends (or
    ``start: failed after 12.3 s`` when it raises) through the ``progress`` callable; nothing
    when ``progress`` is None."""
    if progress is None:
        yield
        return
    t0 = time.perf_counter()
    progress(start)
    try:
        yield
    except BaseException:
        progress(f"{start}: failed after {time.perf_counter() - t0:.1f} s")
        raise
    progress(f"{done} in {time.perf_counter() - t0:.1f} s")


def progress_bar(total: int, desc: str, *, enabled: bool = True, stream=None):
    """A tqdm bar counting ``total`` steps of a sweep (``update``/``close``), disabled when
    ``enabled`` is false or progress is off for ``stream``."""
    from tqdm import tqdm

    stream = sys.stderr if stream is None else stream
    on = enabled and progress_enabled(stream)
    if on and stream is sys.stderr and in_notebook():
        try:
            from tqdm.notebook import IProgress
            from tqdm.notebook import tqdm as notebook_tqdm
        except ImportError:
            IProgress = None
        if IProgress is not None:  # ipywidgets is installed: tqdm's notebook widget
            return notebook_tqdm(total=total, desc=desc, unit="step", leave=False)
    return tqdm(total=total, desc=desc, unit="step", leave=False, file=stream, disable=not on)


def resolve(progress):
    """The ``progress`` argument of ``snakecg.load``: ``None`` (default) reports on standard
    error, whatever it is (:func:`progress_reporter`; silenced by ``SNAKECG_PROGRESS=0``),
    ``False`` never, a callable is used."""
    if progress is None:
        return progress_reporter()
    if progress is False:
        return None
    return progress


def in_chunks(fn, qa, chunk: int, desc: str, *, stream=None, always: bool = False):
    """``fn(qa)`` for a batch ``qa`` (N, n_s), evaluated ``chunk`` rows at a time with a
    progress bar when progress is shown and N > chunk (else in one call, unless ``always``:
    then in chunks, to bound the working memory, with a bar only where progress is shown);
    the chunks' results (dataclasses whose fields are dictionaries of arrays, arrays, counts or
    other values) are joined along the batch axis (counts summed, other values the first
    chunk's)."""
    import dataclasses

    import numpy as np

    n = qa.shape[0]
    shown = progress_enabled(stream)
    if n <= chunk or not (shown or always):
        return fn(qa)
    parts = []
    bar = progress_bar(n, desc, stream=stream) if shown else None
    try:
        for lo in range(0, n, chunk):
            parts.append(fn(qa[lo:lo + chunk]))
            if bar is not None:
                bar.update(min(chunk, n - lo))
    finally:
        if bar is not None:
            bar.close()
    first = parts[0]
    joined = {}
    for f in dataclasses.fields(first):
        v = getattr(first, f.name)
        if isinstance(v, dict):
            joined[f.name] = {k: np.concatenate([getattr(p, f.name)[k] for p in parts])
                              for k in v}
        elif isinstance(v, np.ndarray) and v.ndim >= 1 and v.shape[0] == len(qa[:chunk]):
            joined[f.name] = np.concatenate([getattr(p, f.name) for p in parts])
        elif isinstance(v, int) and not isinstance(v, bool):  # a count: the chunks' total
            joined[f.name] = sum(getattr(p, f.name) for p in parts)
        else:
            joined[f.name] = v
    return dataclasses.replace(first, **joined)
