"""Validation of numeric inputs at the API boundary.

Every public function checks its arguments here before any work: numbers are real (not
complex, not booleans), finite, representable as a float (an integer beyond float range is
refused, not an ``OverflowError``) and inside the limits the argument allows; arrays have
the expected shape; a batch whose working memory would exceed the limit is refused or
evaluated in chunks (:data:`CHUNK_ROWS`).
"""

from __future__ import annotations

import math
import numbers
import os

import numpy as np

from .errors import InputError

#: Rows of a batch evaluated at once by ``forward`` and ``extremes`` (bounded working memory).
CHUNK_ROWS = 65536
#: Largest magnitude of a task or limit (radius, a_min, a_obj, tau_max): these enter squares
#: and products with the model's matrices, which must stay within double precision.
MAX_MAGNITUDE = 1e100
#: Largest magnitude of a robot's or scene's parameter (masses, lengths, inertias, sizes,
#: positions): the model multiplies them (m l^2, its inverse, the norms' squares), which
#: must stay within double precision.
MAX_PARAMETER = 1e50


def beyond_parameter_limit(name: str, got: str) -> str:
    """The problem of a parameter beyond :data:`MAX_PARAMETER` (``got``: its value, quoted)."""
    return (f"{name} must be at most {MAX_PARAMETER:g} in magnitude (the model's products of "
            f"it must stay within double precision), got {got}")
#: Longest quoted value in a message (longer ones are cut, with their length stated).
_MAX_REPR = 60


def short_repr(value) -> str:
    """``repr(value)``, cut to a few dozen characters (a 400-digit integer, a huge list...)."""
    try:
        text = repr(value)
    except Exception:  # pragma: no cover - a hostile __repr__
        text = f"<{type(value).__name__}>"
    if len(text) <= _MAX_REPR:
        return text
    return f"{text[:_MAX_REPR - 20]}...({len(text)} characters)"


def to_float(value) -> float:
    """``float(value)`` for a real number; ``+-inf`` for an integer beyond float range."""
    try:
        return float(value)
    except OverflowError:
        return math.inf if value > 0 else -math.inf


def is_real(value) -> bool:
    """A real number that is not a boolean (Python, NumPy and ``numbers.Real`` types)."""
    return isinstance(value, numbers.Real) and not isinstance(value, (bool, np.bool_))


def number(name: str, value, *, lo=None, hi=None, lo_open=False, hi_open=False,
           unit: str = "", allow_none: bool = False):
    """``value`` as a finite float within ``[lo, hi]`` (open ends with ``lo_open``/``hi_open``).

    The message names the argument, the expected form and the limit that was crossed.
    """
    if value is None and allow_none:
        return None
    u = f" {unit}" if unit else ""
    if not is_real(value):
        raise InputError(f"{name} must be a real number{u}, got {short_repr(value)}")
    v = to_float(value)
    if not math.isfinite(v):
        raise InputError(f"{name} must be a finite number{u}, got {short_repr(value)}")
    if lo is not None and (v < lo or (lo_open and v == lo)):
        op = ">" if lo_open else ">="
        raise InputError(f"{name} must be {op} {lo:g}{u}, got {short_repr(value)}")
    if hi is not None and (v > hi or (hi_open and v == hi)):
        op = "<" if hi_open else "<="
        raise InputError(f"{name} must be {op} {hi:g}{u} (the limit), got {short_repr(value)}")
    return v


def integer(name: str, value, *, lo=None, hi=None, allow_none: bool = False, why: str = ""):
    """``value`` as an int within ``[lo, hi]`` (``why`` explains the upper limit)."""
    if value is None and allow_none:
        return None
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise InputError(f"{name} must be an integer, got {short_repr(value)}")
    v = int(value)
    if lo is not None and v < lo:
        raise InputError(f"{name} must be an integer >= {lo}, got {short_repr(value)}")
    if hi is not None and v > hi:
        raise InputError(f"{name} must be at most {hi}{why}, got {short_repr(value)}")
    return v


def all_finite(arr: np.ndarray) -> bool:
    """Whether every number of the float array ``arr`` is finite (up to 64 numbers: one pass
    in Python, several times cheaper than NumPy's ufunc and reduction on so few)."""
    if arr.size > 64:
        return bool(np.isfinite(arr).all())
    return all(map(math.isfinite, arr.ravel().tolist()))


def as_batch(name: str, value, size: int, *, what: str = "",
             check_finite: bool = True) -> tuple[np.ndarray, bool]:
    """``value`` as a C-contiguous float64 ``(N, size)`` array, and whether it was batched.

    Accepts shape ``(size,)`` (one sample) or ``(N, size)``. Raises :class:`InputError`
    naming the argument and the expected form, on complex or non-numeric values, on
    integers beyond float range, and on NaN or infinity (``check_finite=False``: left to a
    caller that checks them in its own pass and calls again with the check for the message).
    """
    if isinstance(value, (str, bytes)):
        raise InputError(f"{name} must be numeric with shape ({size},) or (N, {size}){what}, "
                         f"got {short_repr(value)}")
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError, OverflowError):
        raw = None
    if raw is not None and (np.iscomplexobj(raw) or (raw.dtype == object and any(
            isinstance(x, (complex, np.complexfloating)) for x in raw.ravel()[:10**6]))):
        raise InputError(f"{name} must be real, got a complex array; pass the real part "
                         f"explicitly if that is what you mean")
    try:
        if raw is None or raw.dtype.kind in "USV":
            raise TypeError
        arr = np.asarray(raw, dtype=float)
    except OverflowError:
        raise InputError(f"{name} holds an integer beyond float range; expected finite "
                         f"numbers with shape ({size},) or (N, {size}){what}") from None
    except (TypeError, ValueError):
        raise InputError(f"{name} must be numeric with shape ({size},) or (N, {size}){what}, "
                         f"got {short_repr(value)}") from None
    if arr.ndim == 1 and arr.shape[0] == size:
        batched = False
        arr = arr.reshape(1, size)
    elif arr.ndim == 2 and arr.shape[1] == size and arr.shape[0] >= 1:
        batched = True
    else:
        raise InputError(
            f"{name} has shape {arr.shape}, expected ({size},) or (N, {size}){what}"
        )
    if check_finite and not np.all(np.isfinite(arr)):
        bad = tuple(int(i) for i in np.argwhere(~np.isfinite(arr))[0])
        raise InputError(f"{name} must be finite, found {arr[bad]} at index {bad}")
    return np.ascontiguousarray(arr), batched


def broadcast_batches(**named: tuple[np.ndarray, bool]) -> int:
    """Common batch size of several ``as_batch`` results (1-sample inputs broadcast)."""
    sizes = {k: a.shape[0] for k, (a, batched) in named.items() if batched}
    distinct = set(sizes.values())
    if len(distinct) > 1:
        desc = ", ".join(f"{k}: {n}" for k, n in sizes.items())
        raise InputError(f"batch sizes differ ({desc}); give the same N or a single sample")
    return distinct.pop() if distinct else 1


def expand(arr: np.ndarray, n: int) -> np.ndarray:
    """A ``(1, size)`` array repeated to ``(n, size)`` (no copy needed for n == 1)."""
    if arr.shape[0] == n:
        return arr
    return np.ascontiguousarray(np.broadcast_to(arr, (n, arr.shape[1])))


def memory_limit() -> int:
    """Bytes a single call may allocate for its results: ``SNAKECG_MAX_MEMORY`` (bytes, or
    with a ``K``/``M``/``G`` suffix), default half of the physical memory (at least 1 GB)."""
    text = os.environ.get("SNAKECG_MAX_MEMORY", "").strip()
    if text:
        scale = {"k": 2**10, "m": 2**20, "g": 2**30}.get(text[-1].lower(), 1)
        digits = text[:-1] if scale > 1 else text
        try:
            value = float(digits) * scale
        except ValueError:
            value = math.nan
        if not (math.isfinite(value) and value > 0):
            raise InputError(f"SNAKECG_MAX_MEMORY must be a positive size in bytes (e.g. "
                             f"4G, 512M), got {text!r}")
        return int(value)
    try:
        total = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (ValueError, OSError, AttributeError):  # pragma: no cover - not POSIX
        total = 8 * 2**30
    return max(2**30, total // 2)


def check_batch_memory(name: str, rows: int, bytes_per_row: int, *, what: str) -> None:
    """Refuse a batch whose results alone would need more than :func:`memory_limit`."""
    need = rows * bytes_per_row
    limit = memory_limit()
    if need > limit:
        per_call = max(1, limit // max(1, bytes_per_row))
        raise InputError(
            f"{name}: a batch of {rows} rows needs about {need / 2**30:.3g} GB for the {what}"
            f" ({bytes_per_row} bytes per row), above the limit of {limit / 2**30:.3g} GB;"
            f" split it into batches of at most {per_call} rows (or raise SNAKECG_MAX_MEMORY)"
        )
