"""The work of one chunk, run on a Dask worker: load the model, evaluate the extremes.

A loaded model does not pickle; its :class:`~snakecg.Scene` does. Each worker process loads
the model from its own cache with :func:`snakecg.load` (generating and compiling it once per
machine, under the cache's lock) and keeps it for the chunks that follow.
"""

from __future__ import annotations

import threading

import numpy as np

from ..analysis import METRICS
from ..geometry import SELF_CLEARANCE, feasibility

__all__ = ["evaluate_chunk", "evaluate"]

_MODELS: dict = {}
_LOCK = threading.Lock()


def _model(scene):
    with _LOCK:
        model = _MODELS.get(scene)
        if model is None:
            from .. import load

            model = _MODELS[scene] = load(scene)
        return model


def evaluate(model, q: np.ndarray, clearance: float = SELF_CLEARANCE) -> dict[str, np.ndarray]:
    """Per-configuration arrays of the store for configurations ``q`` ``(n, n_a + 3)``:
    :meth:`~snakecg.SceneModel.extremes`, :meth:`~snakecg.SceneModel.com_polar` and
    :func:`~snakecg.geometry.feasibility` at ``clearance`` (m)."""
    ex = model.extremes(q)
    radius, angle = model.com_polar(q)
    out = {"q": q[:, 3:], "com_radius": radius, "com_angle": angle}
    for m in METRICS:
        out[f"max_{m}"] = ex.max[m]
        out[f"tau_max_{m}"] = ex.tau_max[m]
        out[f"min_kept_{m}"] = ex.min_kept[m]
        out[f"tau_min_kept_{m}"] = ex.tau_min_kept[m]
    out = {k: np.ascontiguousarray(v, dtype=np.float64) for k, v in out.items()}
    out["feasible"] = np.ascontiguousarray(feasibility(model, q, clearance=clearance).feasible,
                                           dtype=bool)
    return out


def evaluate_chunk(scene, plan, index: int, clearance: float = SELF_CLEARANCE
                   ) -> dict[str, np.ndarray]:
    """The store's arrays for chunk ``index`` of ``plan`` (runs on a worker)."""
    return evaluate(_model(scene), plan.configurations(index), clearance)
