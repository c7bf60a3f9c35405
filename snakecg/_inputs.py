"""Validation of numeric inputs at the API boundary."""

from __future__ import annotations

import numpy as np

from .errors import InputError


def as_batch(name: str, value, size: int, *, what: str = "") -> tuple[np.ndarray, bool]:
    """``value`` as a C-contiguous float64 ``(N, size)`` array, and whether it was batched.

    Accepts shape ``(size,)`` (one sample) or ``(N, size)``. Raises :class:`InputError`
    naming the argument and the expected form, and on NaN or infinity.
    """
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be numeric with shape ({size},) or (N, {size}){what}, "
                         f"got {value!r}") from None
    if arr.ndim == 1 and arr.shape[0] == size:
        batched = False
        arr = arr.reshape(1, size)
    elif arr.ndim == 2 and arr.shape[1] == size and arr.shape[0] >= 1:
        batched = True
    else:
        raise InputError(
            f"{name} has shape {arr.shape}, expected ({size},) or (N, {size}){what}"
        )
    if not np.all(np.isfinite(arr)):
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
