"""The Zarr store of a sweep: layout, creation, compatibility, chunk records.

Layout (a Zarr v3 group, a folder ``STORE.zarr``), every array chunked like the computation
(``chunk`` configurations per chunk, all joints of a configuration in one chunk):

* ``q`` ``(N, n_a)``: joint angles (rad); ``com_radius``, ``com_angle`` ``(N,)``: polar
  coordinates of the snake's COM w.r.t. the contact point (m, rad; see
  :func:`snakecg.analysis.com_polar`);
* for every metric ``m`` of :data:`snakecg.analysis.METRICS`: ``max_m`` / ``min_kept_m``
  ``(N,)`` and the torques attaining them ``tau_max_m`` / ``tau_min_kept_m`` ``(N, n_a)``
  (:class:`snakecg.analysis.Extremes` ``.max``, ``.min_kept`` and their ``tau_`` partners);
* ``feasible`` ``(N,)`` bool: the shape is physically possible
  (:func:`snakecg.geometry.feasibility` at the clearance recorded in the attributes); every
  configuration is evaluated either way, reductions may leave the infeasible ones out;
* ``chunk_digest`` ``(n_chunks,)`` uint64: 0 for a chunk not written yet, else a BLAKE2b
  digest of the chunk's data. It is written only after all of the chunk's data, so a chunk
  counts as complete only when its data is all there; on resume every recorded chunk is
  read back and checked against its digest (a mismatch is computed again).
* attributes ``snakecg_sweep``: robot, scene, grid or sampling, chunk, package version,
  array names, the feasibility check's clearance and whether the reductions default to
  feasible shapes only (the fingerprint a resumed sweep must match); ``completed_chunks`` and
  ``complete``, updated as the sweep goes; ``store_id``, a random identity made with the
  store (a worker that writes data checks it).

Who writes: the chunks' data is written by the workers when they share the store's file
system (by default: a local cluster with a thread on every core; see
:func:`snakecg.sweeps.run.sweep`, ``shared_store``), else by the process that runs the
sweep; the digests and the attributes only ever by the latter, so no two processes write
the same file at once (a chunk's data files are written by the one task computing it; a
task run again after a lost worker writes the same bytes).

Zarr's local store writes each key through a temporary file and a rename, and the group is
first built under a temporary name and renamed into place, so no file is ever half-written
and a store that fails to be created leaves nothing behind.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import uuid
from pathlib import Path

import numpy as np

from ..analysis import METRICS
from ..errors import InputError

__all__ = ["array_names", "create", "open_existing", "check_target", "digest", "handles",
           "write_data", "record", "write_chunk", "completed", "store_id", "FORMAT"]

#: Layout version of the store (attribute ``snakecg_sweep.format``).
FORMAT = "snakecg.sweep/1"
_DIGEST_BLOCK = 4096  # chunk_digest entries per Zarr chunk


def array_names() -> tuple[str, ...]:
    """Names of the per-configuration arrays, in the order the digest reads them."""
    names = ["q", "com_radius", "com_angle"]
    for m in METRICS:
        names += [f"max_{m}", f"tau_max_{m}", f"min_kept_{m}", f"tau_min_kept_{m}"]
    return tuple(names + ["feasible"])


def _zarr():
    try:
        import zarr
    except ModuleNotFoundError:
        raise InputError("sweeps need the sweep extra (Dask and Zarr): "
                         "pip install 'snakecg[sweep]'") from None
    return zarr


def check_target(path: Path) -> str:
    """``"new"`` if a store can be created at ``path``, ``"existing"`` if one is there;
    raises :class:`InputError` for anything else (before any work is done)."""
    if path.exists():
        if (path / "zarr.json").is_file():
            return "existing"
        what = "a file" if path.is_file() else "a folder that is not a Zarr store"
        raise InputError(f"--out {str(path)!r} is {what}; give a new path or a sweep store "
                         f"made by snakecg sweep")
    parent = path.parent if str(path.parent) else Path(".")
    if not parent.is_dir():
        raise InputError(f"--out {str(path)!r}: the folder {str(parent)!r} does not exist")
    if not os.access(parent, os.W_OK | os.X_OK):
        raise InputError(f"--out {str(path)!r}: the folder {str(parent)!r} is not writable")
    return "new"


def _normalise(obj):
    return json.loads(json.dumps(obj))


def create(path: Path, meta: dict, n_configurations: int, chunk: int, joints: int):
    """Create the store (under a temporary name, renamed into place) and open it."""
    zarr = _zarr()
    n_chunks = -(-n_configurations // chunk)
    tmp = path.with_name(f".{path.name}.{uuid.uuid4().hex}.partial")
    try:
        root = zarr.open_group(str(tmp), mode="w-")
        for name in array_names():
            wide = name == "q" or name.startswith("tau_")
            shape = (n_configurations, joints) if wide else (n_configurations,)
            chunks = (chunk, joints) if wide else (chunk,)
            flag = name == "feasible"
            root.create_array(name, shape=shape, chunks=chunks,
                              dtype="bool" if flag else "float64",
                              fill_value=False if flag else np.nan, compressors=None)
        root.create_array("chunk_digest", shape=(n_chunks,), chunks=(min(n_chunks,
                                                                         _DIGEST_BLOCK),),
                          dtype="uint64", fill_value=0, compressors=None)
        root.attrs.update({"snakecg_sweep": meta, "completed_chunks": 0, "complete": False,
                           "store_id": uuid.uuid4().hex})
        os.rename(tmp, path)
    except OSError as exc:  # unwritable, read-only file system, no space, ...
        shutil.rmtree(tmp, ignore_errors=True)
        raise InputError(f"--out {str(path)!r} cannot be written: "
                         f"{' '.join(str(exc).split())}") from None
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    return zarr.open_group(str(path), mode="r+")


def open_existing(path: Path, meta: dict | None = None, *, mode: str = "r+"):
    """Open a sweep store; with ``meta``, refuse one made with other arguments."""
    zarr = _zarr()
    try:
        root = zarr.open_group(str(path), mode=mode)
        stored = dict(root.attrs).get("snakecg_sweep")
    except Exception as exc:  # noqa: BLE001 - any unreadable store is the user's input
        raise InputError(f"{str(path)!r} is not a readable sweep store: "
                         f"{' '.join(str(exc).split()) or type(exc).__name__}") from None
    if not isinstance(stored, dict) or stored.get("format") != FORMAT:
        raise InputError(f"{str(path)!r} is a Zarr store but not a snakecg sweep store "
                         f"(no attribute snakecg_sweep of format {FORMAT})")
    if meta is not None:
        want = _normalise(meta)
        diff = sorted(k for k in set(want) | set(stored) if want.get(k) != stored.get(k))
        if diff:
            raise InputError(
                f"the store {str(path)!r} was made with other arguments (they differ in: "
                f"{', '.join(diff)}); rerun with the arguments that made it to resume, or "
                f"give a new --out")
    return root


def digest(arrays: dict[str, np.ndarray]) -> int:
    """Nonzero 64-bit BLAKE2b digest of a chunk's arrays (in :func:`array_names` order;
    ``feasible`` as one byte per configuration)."""
    h = hashlib.blake2b(digest_size=8)
    for name in array_names():
        dtype = np.uint8 if name == "feasible" else np.float64
        # the array's buffer itself (the same bytes as .tobytes(), without copying them:
        # the copy took as long as the hash)
        h.update(np.ascontiguousarray(arrays[name], dtype=dtype))
    return int.from_bytes(h.digest(), "little") | 1


def handles(root, *, digests: bool = True) -> dict:
    """The store's arrays opened once (opening one reads its metadata from the store);
    ``digests=False`` leaves out ``chunk_digest`` (a worker writing data only)."""
    names = (*array_names(), "chunk_digest") if digests else array_names()
    return {name: root[name] for name in names}


def store_id(root) -> str:
    """The store's identity (attribute ``store_id``, made once): a worker that writes data
    checks it, so that it never writes into another store at the same path."""
    sid = root.attrs.get("store_id")
    if not isinstance(sid, str):
        sid = uuid.uuid4().hex
        root.attrs["store_id"] = sid
    return sid


def write_data(opened: dict, start: int, stop: int, arrays: dict[str, np.ndarray]) -> int:
    """Write a chunk's data (every array, in one round trip to Zarr's event loop: the
    arrays are written concurrently, each chunk file through a temporary file and a rename)
    and return its :func:`digest`; the digest is not recorded here (:func:`record`)."""
    import asyncio

    from zarr.core.sync import sync

    async def _all():
        await asyncio.gather(*(opened[name].async_array.setitem(slice(start, stop),
                                                                arrays[name])
                               for name in array_names()))

    sync(_all())
    return digest(arrays)


def record(opened: dict, index: int, d: int) -> None:
    """Record chunk ``index`` as complete with digest ``d``, after all of its data is
    written. Only the process that called the sweep records digests (never two at once)."""
    opened["chunk_digest"][index] = np.uint64(d)


def write_chunk(root, index: int, start: int, stop: int, arrays: dict[str, np.ndarray],
                opened: dict | None = None) -> int:
    """Write a chunk's data, then its digest (the record that the chunk is complete).
    ``opened``: the arrays of :func:`handles`, else each is opened here."""
    opened = opened or handles(root)
    d = write_data(opened, start, stop, arrays)
    record(opened, index, d)
    return d


def read_chunk(root, start: int, stop: int, names=None) -> dict[str, np.ndarray]:
    return {name: root[name][start:stop] for name in (names or array_names())}


def completed(root, plan, *, verify: bool = True) -> np.ndarray:
    """Boolean ``(n_chunks,)``: which chunks are complete (digest recorded and, with
    ``verify``, matching the data read back)."""
    digests = root["chunk_digest"][:]
    done = digests != 0
    if verify:
        for i in np.flatnonzero(done):
            start, stop = plan.chunk_range(int(i))
            try:
                ok = digest(read_chunk(root, start, stop)) == int(digests[i])
            except Exception:  # noqa: BLE001 - an unreadable chunk is computed again
                ok = False
            done[i] = ok
    return done
