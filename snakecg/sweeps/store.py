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
* ``chunk_digest`` ``(n_chunks,)`` uint64: 0 for a chunk not written yet, else a 64-bit
  digest of the chunk's data (XXH3, or BLAKE2b in stores of format 1: :data:`DIGESTS`). It
  is written only after all of the chunk's data, so a chunk counts as complete only when
  its data is all there; on resume every recorded chunk is read back and checked against
  its digest (a mismatch is computed again). The process that runs the sweep writes the
  digests of the chunks completed meanwhile about once a second.
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
import math
import os
import shutil
import threading
import uuid
from collections import deque
from pathlib import Path

import numpy as np

from ..analysis import METRICS
from ..errors import InputError

__all__ = ["array_names", "configuration_bytes", "create", "open_existing", "check_target",
           "digest", "handles", "write_data", "record", "completed", "store_id", "format_of",
           "FORMAT", "DIGESTS"]

#: Layout version of new stores (attribute ``snakecg_sweep.format``).
FORMAT = "snakecg.sweep/2"
#: The formats this version reads and resumes, and the digest each records in
#: ``chunk_digest``: the same layout, format 2 with a checksum ten times cheaper (XXH3-64,
#: about 0.1 ms per MB against 1 ms; a sweep of the cheap scenarios makes 70 MB of results
#: per second and core).
DIGESTS = {"snakecg.sweep/1": "blake2b-64", "snakecg.sweep/2": "xxh3-64"}
_DIGEST_BLOCK = 4096  # chunk_digest entries per Zarr chunk


def array_names() -> tuple[str, ...]:
    """Names of the per-configuration arrays, in the order the digest reads them."""
    names = ["q", "com_radius", "com_angle"]
    for m in METRICS:
        names += [f"max_{m}", f"tau_max_{m}", f"min_kept_{m}", f"tau_min_kept_{m}"]
    return tuple(names + ["feasible"])


def _per_configuration(name: str, joints: int) -> tuple[int, ...]:
    """Shape of one configuration's entry of array ``name``: a row of the joints (``q`` and
    the torques) or one value."""
    return (joints,) if name == "q" or name.startswith("tau_") else ()


def configuration_bytes(joints: int) -> int:
    """Bytes of one configuration in all the store's arrays (float64; ``feasible`` bool)."""
    return sum((1 if name == "feasible" else 8) * math.prod(_per_configuration(name, joints))
               for name in array_names())


def _zarr():
    try:
        import xxhash  # noqa: F401 - the digests of format 2
        import zarr
    except ModuleNotFoundError:
        raise InputError("sweeps need the sweep extra (Dask, Zarr and xxhash): "
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
            row = _per_configuration(name, joints)
            shape, chunks = (n_configurations, *row), (chunk, *row)
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
    if not isinstance(stored, dict) or stored.get("format") not in DIGESTS:
        raise InputError(f"{str(path)!r} is a Zarr store but not a snakecg sweep store "
                         f"(no attribute snakecg_sweep of format {' or '.join(DIGESTS)})")
    if meta is not None:
        want = _normalise(meta)
        diff = sorted(k for k in set(want) | set(stored) if want.get(k) != stored.get(k))
        if diff:
            raise InputError(
                f"the store {str(path)!r} was made with other arguments (they differ in: "
                f"{', '.join(diff)}); rerun with the arguments that made it to resume, or "
                f"give a new --out")
    return root


def digest(arrays: dict[str, np.ndarray], fmt: str = FORMAT) -> int:
    """Nonzero 64-bit digest of a chunk's arrays, the one store format ``fmt`` records
    (:data:`DIGESTS`): XXH3-64 (format 2) or BLAKE2b-64 (format 1) of the arrays' bytes in
    :func:`array_names` order (``feasible`` as one byte per configuration), read as a
    little-endian integer, lowest bit set."""
    if DIGESTS[fmt] == "xxh3-64":
        import xxhash

        h = xxhash.xxh3_64()
    else:
        h = hashlib.blake2b(digest_size=8)
    for name in array_names():
        dtype = np.uint8 if name == "feasible" else np.float64
        # the array's buffer itself (the same bytes as .tobytes(), without copying them)
        h.update(np.ascontiguousarray(arrays[name], dtype=dtype))
    return int.from_bytes(h.digest(), "little") | 1


def format_of(root) -> str:
    """The format of an open sweep store (one of :data:`DIGESTS`)."""
    return root.attrs["snakecg_sweep"]["format"]


def handles(root, *, digests: bool = True) -> dict:
    """The store's arrays opened once (opening one reads its metadata from the store);
    ``digests=False`` leaves out ``chunk_digest`` (a worker writing data only).

    Every chunk is written, even one that holds only the fill value (NaN, or false). Zarr's
    default compares each chunk with the fill value before writing it, to skip the chunks
    that hold nothing else; that comparison took a third of the CPU time of a write, and
    reads give the same values either way."""
    names = (*array_names(), "chunk_digest") if digests else array_names()
    return {name: _write_all(root[name]) for name in names}


def _write_all(array):
    with_config = getattr(array, "with_config", None)  # Zarr's runtime configuration
    return with_config({"write_empty_chunks": True}) if with_config else array


def store_id(root) -> str:
    """The store's identity (attribute ``store_id``, made once): a worker that writes data
    checks it, so that it never writes into another store at the same path."""
    sid = root.attrs.get("store_id")
    if not isinstance(sid, str):
        sid = uuid.uuid4().hex
        root.attrs["store_id"] = sid
    return sid


def write_data(opened: dict, start: int, stop: int, arrays: dict[str, np.ndarray],
               fmt: str = FORMAT) -> int:
    """Write a chunk's data (every array, in one round trip to Zarr's event loop: the
    arrays are written concurrently, each chunk file through a temporary file and a rename)
    and return its :func:`digest` for a store of format ``fmt``; the digest is not recorded
    here (:func:`record`).

    A whole chunk of an array stored as its raw bytes (:func:`_raw_bytes`, as :func:`create`
    makes every array) is handed to Zarr's store as those bytes under the chunk's key,
    without Zarr's selection and codec machinery (a fifth to a third less CPU time per
    chunk); others (the last, partial chunk; an array stored otherwise) go through the
    array."""
    import asyncio

    from zarr.core.buffer import default_buffer_prototype
    from zarr.core.sync import sync

    buffer = default_buffer_prototype().buffer

    def write(array, values):
        chunk = array.chunks[0]
        if start % chunk or stop - start != chunk or not _raw_bytes(array):
            return array.async_array.setitem(slice(start, stop), values)
        key = array.metadata.encode_chunk_key((start // chunk,) + (0,) * (array.ndim - 1))
        raw = np.ascontiguousarray(values, dtype=array.dtype.newbyteorder("<"))
        return (array.store_path / key).set(buffer.from_array_like(raw.reshape(-1).view(np.uint8)))

    async def _all():
        await asyncio.gather(*(write(opened[name], arrays[name]) for name in array_names()))

    sync(_all())
    _leave_page_cache(_chunk_files(opened, start))
    return digest(arrays, fmt)


#: The files of the chunks this process wrote last, in the local file system: their pages
#: are released from the page cache as the next chunks are written (:func:`_leave_page_cache`).
_RECENT: deque = deque(maxlen=3)
_RECENT_LOCK = threading.Lock()


def _chunk_files(opened: dict, start: int) -> list[str]:
    """Paths of the chunk files holding configuration ``start`` of every array, if the store
    is a local folder (else none)."""
    from zarr.storage import LocalStore

    files = []
    for name in array_names():
        array = opened[name]
        store = array.store_path.store
        if not isinstance(store, LocalStore):
            return []
        key = array.metadata.encode_chunk_key((start // array.chunks[0],)
                                              + (0,) * (array.ndim - 1))
        files.append(os.path.join(store.root, array.store_path.path, key))
    return files


def _leave_page_cache(files: list[str]) -> None:
    """Tell the kernel that the chunk files just written, and those of the last chunks
    before them, will not be read soon (``POSIX_FADV_DONTNEED``): it starts writing the
    new ones to disk and drops the pages of those already written. A sweep writes far more
    than it reads back; without this its files fill the page cache with pages it must first
    allocate, which on a VM that backs its memory lazily cost about ten times the write
    itself (see the performance notes), and which crowd out other files' pages on any
    machine. Reads are unchanged (from the disk instead of memory). A no-op where the
    call does not exist or the files are not on a local disk (tmpfs ignores it)."""
    if not files or not hasattr(os, "posix_fadvise"):
        return
    with _RECENT_LOCK:
        _RECENT.append(files)
        every = [f for chunk in _RECENT for f in chunk]
    for path in every:
        try:
            fd = os.open(path, os.O_RDONLY)
        except OSError:  # replaced meanwhile by a rerun of its task, or removed
            continue
        try:
            os.posix_fadvise(fd, 0, 0, os.POSIX_FADV_DONTNEED)
        except OSError:
            pass
        finally:
            os.close(fd)


def _raw_bytes(array) -> bool:
    """Whether the chunks of ``array`` are stored as their values' little-endian bytes in C
    order: a Zarr v3 array of fixed-size numbers whose only codec is the ``bytes`` codec
    (little-endian, or none for one-byte values), on a regular chunk grid, full in every
    dimension but the first."""
    from zarr.codecs import BytesCodec

    meta = array.metadata
    codecs = getattr(meta, "codecs", None)
    if getattr(meta, "zarr_format", None) != 3 or not codecs or len(codecs) != 1:
        return False
    codec = codecs[0]
    endian = getattr(codec.endian, "value", codec.endian)
    shape = getattr(meta.chunk_grid, "chunk_shape", None)
    return (isinstance(codec, BytesCodec) and array.dtype.kind in "fb"
            and (endian == "little" or (endian is None and array.dtype.itemsize == 1))
            and shape is not None and tuple(shape[1:]) == tuple(array.shape[1:]))


def record(opened: dict, digests: dict[int, int]) -> None:
    """Record the chunks ``digests`` (index -> digest) as complete, after all of their data
    is written, in one write per block of the ``chunk_digest`` array. Only the process that
    called the sweep records digests (never two at once)."""
    if digests:
        index = np.fromiter(digests, dtype=np.int64, count=len(digests))
        values = np.fromiter(digests.values(), dtype=np.uint64, count=len(digests))
        opened["chunk_digest"].vindex[index] = values


def read_chunk(root, start: int, stop: int, names=None) -> dict[str, np.ndarray]:
    return {name: root[name][start:stop] for name in (names or array_names())}


def completed(root, plan, *, verify: bool = True) -> np.ndarray:
    """Boolean ``(n_chunks,)``: which chunks are complete (digest recorded and, with
    ``verify``, matching the data read back)."""
    digests = root["chunk_digest"][:]
    done = digests != 0
    fmt = format_of(root)
    if verify:
        for i in np.flatnonzero(done):
            start, stop = plan.chunk_range(int(i))
            try:
                ok = digest(read_chunk(root, start, stop), fmt) == int(digests[i])
            except Exception:  # noqa: BLE001 - an unreadable chunk is computed again
                ok = False
            done[i] = ok
    return done
