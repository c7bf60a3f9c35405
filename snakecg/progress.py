"""Progress display for long work: shown on a terminal and in a Jupyter notebook, quiet
otherwise.

``SNAKECG_PROGRESS=1`` forces it on and ``SNAKECG_PROGRESS=0`` off, so pipes, files and CI
logs stay clean. Steps (derivation, compilation) print one line each through
:func:`progress_reporter`; sweeps use tqdm through :func:`progress_bar` (in a notebook,
tqdm's widget when ipywidgets is installed, else its text bar); long batches of
``model.extremes`` go in chunks through :func:`in_chunks`. ``snakecg.load`` reports model
builds by default (:func:`resolve`).
"""

from __future__ import annotations

import os
import sys
import time

__all__ = ["progress_enabled", "progress_reporter", "progress_bar", "in_notebook", "resolve",
           "in_chunks"]


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
    """Whether to show progress on ``stream`` (default stderr): a terminal, unless
    ``SNAKECG_PROGRESS`` says otherwise (``1`` on, ``0`` off)."""
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
    """The ``progress`` argument of ``snakecg.load``: ``None`` (default) reports on a terminal
    or in a notebook (:func:`progress_reporter`), ``False`` never, a callable is used."""
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
