"""The task keywords of an optimal-torque query, screened before any work: real numbers
(never complex), magnitudes within the range that squares and products of the model's
matrices allow, and a push direction rescaled so that its length cannot overflow (only the
direction matters). :func:`snakecg.optimize.optimize` checks the rest (shapes, signs)."""

from __future__ import annotations

import math

import numpy as np

from .._inputs import MAX_MAGNITUDE
from ..errors import InputError

__all__ = ["screen"]


def screen(kwargs: dict) -> dict:
    """``kwargs`` of :meth:`SceneModel.optimize` checked; ``direction`` rescaled (a copy)."""
    kwargs = dict(kwargs)
    for k in ("tau_max", "radius", "direction", "a_min", "a_obj", "allow_slide"):
        v = kwargs.get(k)
        if (v is not None and type(v) is not bool and type(v) is not float
                and not (type(v) is np.ndarray and v.dtype == np.float64)
                and np.iscomplexobj(v)):
            raise InputError(f"{k} must be real, got a complex value")
    for k in ("tau_max", "radius", "direction", "a_min", "a_obj"):
        v = kwargs.get(k)
        if v is None:
            continue
        if type(v) is float and (not abs(v) > MAX_MAGNITUDE or k == "direction"):
            continue  # a plain number within range
        if k == "direction" and type(v) is np.ndarray and v.dtype == np.float64:
            continue  # scaled below
        try:
            big = np.max(np.abs(np.asarray(kwargs.get(k, 0.0), dtype=float)), initial=0.0)
        except OverflowError:
            raise InputError(f"{k} holds an integer beyond float range; expected finite "
                             f"numbers") from None
        except (TypeError, ValueError):
            continue  # optimize() names the problem
        if k == "direction":
            continue
        if np.isfinite(big) and big > MAX_MAGNITUDE:
            raise InputError(f"{k} must be at most {MAX_MAGNITUDE:g} in magnitude (the "
                             f"limit: it enters squares and products), got {big:g}")
    d = kwargs.get("direction")
    if type(d) is np.ndarray and d.dtype == np.float64 and d.ndim == 1:  # on floats
        big = max(map(abs, d.tolist()), default=0.0)
        if math.isfinite(big) and big > 0:
            kwargs["direction"] = d / big
        d = None
    if d is not None:
        try:
            arr = np.asarray(d, dtype=float)
        except (TypeError, ValueError, OverflowError):
            arr = None
        if arr is not None and arr.ndim == 1 and np.all(np.isfinite(arr)) and arr.any():
            # only the direction matters: scaled so that its length cannot overflow
            kwargs["direction"] = arr / np.max(np.abs(arr))
    return kwargs
