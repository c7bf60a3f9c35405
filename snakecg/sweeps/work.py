"""The work of one chunk, run on a Dask worker: load the model, evaluate the extremes, and
(when the worker shares the store's file system) write the chunk's data into the store.

A loaded model does not pickle; its :class:`~snakecg.Scene` does. Each worker process loads
the model from its own cache with :func:`snakecg.load` (generating and compiling it once per
machine, under the cache's lock) and keeps it for the chunks that follow; likewise the
store's arrays, opened once per store.
"""

from __future__ import annotations

import threading

import numpy as np

from ..analysis import METRICS
from ..errors import SnakecgError
from ..geometry import SELF_CLEARANCE, feasibility
from . import store as _store
from .simulation import evaluate_simulation

__all__ = ["evaluate_chunk", "evaluate", "evaluate_and_write", "BLOCK"]

_MODELS: dict = {}
_STORES: dict = {}   # (path, store id) -> the store's data arrays, opened
_KEEP_STORES = 4
_LOCK = threading.Lock()


def _model(scene):
    with _LOCK:
        model = _MODELS.get(scene)
        if model is None:
            from ..loading import load

            model = _MODELS[scene] = load(scene)
        return model


#: Configurations evaluated at a time within a chunk: the NumPy temporaries of
#: :meth:`~snakecg.SceneModel.extremes` over a block of a few thousand stay in the core's
#: caches (frictionless and ideal wheels at 3 and 4 joints: blocks of 2,048 to 4,096 took
#: 10-15 % less time per configuration than whole chunks of 65,536). Every configuration is
#: evaluated on its own, so the results do not depend on the blocks.
BLOCK = 4096


def evaluate(model, q: np.ndarray, clearance: float = SELF_CLEARANCE,
             simulation: dict | None = None) -> dict[str, np.ndarray]:
    """Per-configuration arrays of the store for configurations ``q`` ``(n, n_a + 3)``:
    :meth:`~snakecg.SceneModel.extremes`, :meth:`~snakecg.SceneModel.com_polar` and
    :func:`~snakecg.geometry.feasibility` at ``clearance`` (m), in blocks of
    :data:`BLOCK` configurations; with ``simulation`` (:func:`.simulation.
    check_simulation`), the push simulated from each (:func:`.simulation.
    evaluate_simulation`)."""
    if len(q) <= BLOCK:
        return _evaluate_block(model, q, clearance, simulation)
    out = None
    for start in range(0, len(q), BLOCK):
        part = _evaluate_block(model, q[start:start + BLOCK], clearance, simulation)
        if out is None:
            out = {k: np.empty((len(q), *v.shape[1:]), dtype=v.dtype) for k, v in part.items()}
        for k, v in part.items():
            out[k][start:start + len(v)] = v
    return out


def _evaluate_block(model, q: np.ndarray, clearance: float, simulation=None
                    ) -> dict[str, np.ndarray]:
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
    if simulation:
        out.update(evaluate_simulation(model, q, simulation))
    return out


def evaluate_chunk(scene, plan, index: int, clearance: float = SELF_CLEARANCE,
                   simulation: dict | None = None) -> dict[str, np.ndarray]:
    """The store's arrays for chunk ``index`` of ``plan`` (runs on a worker)."""
    return evaluate(_model(scene), plan.configurations(index), clearance, simulation)


def _opened(path: str, sid: str) -> tuple[dict, str]:
    """The data arrays of the store at ``path`` and its format, opened once per worker
    process and checked to be the store the sweep writes (its ``store_id``)."""
    with _LOCK:
        opened = _STORES.get((path, sid))
        if opened is None:
            import socket
            from pathlib import Path

            try:
                root = _store.open_existing(Path(path))
                found = root.attrs.get("store_id")
            except Exception as exc:  # noqa: BLE001 - reported with the way out
                found, why = None, " ".join(str(exc).split())[:200]
            else:
                why = f"its store_id is {found!r}, the sweep's {sid!r}"
            if found != sid:
                raise SnakecgError(
                    f"the worker on {socket.gethostname()} cannot write the store {path!r} "
                    f"({why}): it does not share the file system of the process that runs "
                    f"the sweep; give shared_store=False (the client writes)")
            opened = _store.handles(root, digests=False), _store.format_of(root)
            while len(_STORES) >= _KEEP_STORES:
                _STORES.pop(next(iter(_STORES)))
            _STORES[(path, sid)] = opened
        return opened


def evaluate_and_write(scene, plan, index: int, clearance: float, path: str, sid: str,
                       simulation: dict | None = None) -> tuple[int, int]:
    """Evaluate chunk ``index`` of ``plan`` and write its data into the store at ``path``
    (absolute; ``sid`` its ``store_id``); return ``(digest, configurations)``. The digest is
    recorded by the process that runs the sweep, after this returns: a chunk whose data is
    written but whose digest is not counts as missing and is computed again."""
    arrays = evaluate_chunk(scene, plan, index, clearance, simulation)
    start, stop = plan.chunk_range(index)
    opened, fmt = _opened(path, sid)
    return _store.write_data(opened, start, stop, arrays, fmt), stop - start
