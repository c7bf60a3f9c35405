"""The bytes of a sweep store's chunk files: what an array's chunk file holds, its digest,
and reading one back verified and bounded.

A chunk file of a sweep store holds one chunk of one array, encoded as the array's Zarr
metadata says: its values' little-endian bytes in C order (the ``bytes`` codec alone: every
array of formats 1 and 2, the torques and the digest array of format 3), or those bytes
compressed by Blosc (the ``bytes`` codec then the ``blosc`` codec: the other arrays of
format 3, see :data:`COMPRESSION`). The last chunk of an array is stored whole, padded with the array's
fill value, as Zarr stores edge chunks.

Everything that reads a store's data (:func:`snakecg.sweeps.summary`, ``figure``, ``read``,
and a resumed sweep) reads the chunk files through :func:`read_file`, never through Zarr's
codecs: the file's size is checked before it is read, its digest before it is decoded, and a
compressed file's header must state exactly the chunk's size, so a damaged or hostile file
is refused with the array and the chunk named, and no file expands beyond its chunk.
"""

from __future__ import annotations

import os
import struct
import threading
from collections import deque
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError

__all__ = ["COMPRESSION", "compressed", "ChunkSpec", "spec_of", "encode", "decode", "file_digest",
           "read_file", "chunk_key", "leave_page_cache", "BLOSC_OVERHEAD"]

#: The Blosc compression of the arrays of stores of format 3 (``None``: raw bytes), but for
#: the torques (:func:`compressed`). LZ4 with bit shuffling, about 0.5 ms of CPU per MB:
#: the joint angles of a grid shrink 4-50 times, the flags 15-500 times, the least kept
#: values of sr and of |a_obj|^2 (bounded wheels) 15-95 times, |qdd|^2's maxima 2.6 times;
#: the torques 1.0-1.2 times, so they stay raw (70-80 % of the bytes, not worth the CPU).
COMPRESSION = {"cname": "lz4", "clevel": 5, "shuffle": "bitshuffle"}


def compressed(name: str) -> bool:
    """Whether array ``name`` of a new store is compressed (:data:`COMPRESSION`): all but
    the torques."""
    return COMPRESSION is not None and not name.startswith("tau_")
#: Bytes a Blosc (version 1) frame adds to its data at most: its header.
BLOSC_OVERHEAD = 16
_BLOSC_SHUFFLE = {"noshuffle": 0, "shuffle": 1, "bitshuffle": 2}


@dataclass(frozen=True)
class ChunkSpec:
    """What one chunk file of an array must hold: ``rows`` configurations of ``row``
    values each of ``dtype`` (little-endian), raw or compressed by Blosc (``blosc``: its
    cname, clevel, shuffle)."""

    name: str
    dtype: np.dtype
    rows: int
    row: tuple
    fill: object = field(compare=False)  # NaN: compared by key()
    blosc: tuple | None = None

    def key(self) -> tuple:
        """Everything the spec says, the fill value by its repr (NaN equals NaN)."""
        return (self, repr(self.fill))

    @property
    def nbytes(self) -> int:
        return self.rows * int(np.prod(self.row, dtype=np.int64)) * self.dtype.itemsize

    @property
    def shape(self) -> tuple:
        return (self.rows, *self.row)


def spec_of(array, name: str) -> ChunkSpec:
    """The :class:`ChunkSpec` of an open Zarr array of a sweep store, from its metadata;
    raises :class:`InputError` naming the array if its metadata is not that of a sweep
    store (a Zarr v3 array of float64 or bool on a regular grid of chunks whole in every
    dimension but the first, default chunk keys, and the ``bytes`` codec, optionally
    followed by ``blosc``)."""
    from zarr.codecs import BloscCodec, BytesCodec

    meta = array.metadata
    problems = []
    dtype = np.dtype(array.dtype) if getattr(meta, "zarr_format", None) == 3 else None
    if dtype is None or dtype.kind not in "fbui" or dtype.itemsize not in (1, 8):
        problems.append(f"data type {array.dtype}")
    shape = getattr(meta.chunk_grid, "chunk_shape", None)
    if shape is None or tuple(shape[1:]) != tuple(array.shape[1:]) or shape[0] < 1:
        problems.append(f"chunks {shape} of an array of shape {array.shape}")
    enc = getattr(meta, "chunk_key_encoding", None)
    if getattr(enc, "name", None) != "default" or getattr(enc, "separator", None) != "/":
        problems.append("chunk keys other than Zarr's default")
    codecs = list(getattr(meta, "codecs", None) or ())
    blosc = None
    if not codecs or not isinstance(codecs[0], BytesCodec) or len(codecs) > 2:
        problems.append(f"codecs {[type(c).__name__ for c in codecs]}")
    else:
        endian = getattr(codecs[0].endian, "value", codecs[0].endian)
        if not (endian == "little" or (endian is None and dtype is not None
                                       and dtype.itemsize == 1)):
            problems.append(f"byte order {endian}")
        if len(codecs) == 2:
            c = codecs[1]
            if not isinstance(c, BloscCodec):
                problems.append(f"codec {type(c).__name__}")
            else:
                blosc = (c.cname.value, int(c.clevel), c.shuffle.value)
    if problems:
        raise InputError(f"array {name} is not an array of a sweep store ({'; '.join(problems)});"
                         f" the store is damaged or was edited")
    fill = meta.fill_value
    return ChunkSpec(name, dtype.newbyteorder("<"), int(shape[0]), tuple(shape[1:]),
                     fill, blosc)


def chunk_key(index: int, ndim: int) -> str:
    """Zarr's default key of chunk ``index`` along the first dimension."""
    return "c/" + "/".join([str(index)] + ["0"] * (ndim - 1))


def _blosc(spec: ChunkSpec):
    from numcodecs import Blosc

    cname, clevel, shuffle = spec.blosc
    return Blosc.from_config({"cname": cname, "clevel": clevel,
                              "shuffle": _BLOSC_SHUFFLE[shuffle], "blocksize": 0,
                              "typesize": spec.dtype.itemsize})


def encode(values: np.ndarray, spec: ChunkSpec):
    """The chunk file of ``values`` (``(n, *row)``, ``n <= rows``; a short chunk is padded
    with the fill value to the whole chunk, as Zarr stores edge chunks): raw little-endian
    bytes, or those bytes compressed as the array's ``blosc`` codec does (byte for byte
    Zarr's own encoding)."""
    raw = np.ascontiguousarray(values, dtype=spec.dtype)
    if raw.shape[0] != spec.rows:
        full = np.empty(spec.shape, dtype=spec.dtype)
        full[:raw.shape[0]] = raw
        full[raw.shape[0]:] = spec.fill
        raw = full
    flat = raw.reshape(-1).view(np.uint8)
    if spec.blosc is None:
        return flat
    return _blosc(spec).encode(flat)


def file_digest(data) -> int:
    """Digest of a chunk file's bytes (format 3): XXH3-64 read as a little-endian integer,
    lowest bit set (never 0)."""
    import xxhash

    return int.from_bytes(xxhash.xxh3_64(data).digest(), "little") | 1


def _damaged(store, spec: ChunkSpec, index: int, what: str) -> InputError:
    start = index * spec.rows
    return InputError(f"{store!s}: array {spec.name}, chunk {index} (configurations from "
                      f"{start:,}) {what}: the store is damaged; rerun the sweep that made "
                      f"it (it computes such chunks again) or make a new one")


def read_file(path: str, spec: ChunkSpec, index: int, *, store="store", digest=None):
    """The bytes of chunk file ``path`` of chunk ``index``, read bounded: at most the
    chunk's size (plus a Blosc header when compressed) is read, and with ``digest`` (format
    3) checked against it. Raises :class:`InputError` naming the array and the chunk if the
    file is missing, shorter or longer than it can be, or does not match its digest."""
    most = spec.nbytes + (BLOSC_OVERHEAD if spec.blosc else 0)
    try:
        with open(path, "rb") as f:
            data = f.read(most + 1)
    except FileNotFoundError:
        raise _damaged(store, spec, index, "has no file") from None
    except OSError as exc:
        raise _damaged(store, spec, index, f"cannot be read ({exc.strerror})") from None
    if len(data) > most:
        raise _damaged(store, spec, index, f"is longer than a chunk can be ({most:,} bytes)")
    if spec.blosc is None and len(data) != spec.nbytes:
        raise _damaged(store, spec, index, f"is truncated ({len(data):,} of "
                                           f"{spec.nbytes:,} bytes)")
    if digest is not None and file_digest(data) != int(digest):
        raise _damaged(store, spec, index, "does not match its recorded digest")
    return data


def decode(data, spec: ChunkSpec, index: int, *, store="store") -> np.ndarray:
    """The values ``(rows, *row)`` of a chunk file read by :func:`read_file`. A compressed
    file must be a Blosc frame whose header states the chunk's exact size and the file's
    own length; it is decompressed into a buffer of that size, never more."""
    if spec.blosc is None:
        if len(data) != spec.nbytes:
            raise _damaged(store, spec, index, f"is truncated ({len(data):,} of "
                                               f"{spec.nbytes:,} bytes)")
        return np.frombuffer(data, dtype=spec.dtype).reshape(spec.shape)
    if len(data) < BLOSC_OVERHEAD:
        raise _damaged(store, spec, index, f"is truncated ({len(data)} bytes)")
    # Blosc 1 header: version, codec version, flags, type size, then uint32 little-endian
    # uncompressed size, block size and compressed size
    nbytes, _, cbytes = struct.unpack_from("<III", data, 4)
    if nbytes != spec.nbytes:
        raise _damaged(store, spec, index, f"claims {nbytes:,} bytes of values, a chunk has "
                                           f"{spec.nbytes:,}")
    if cbytes != len(data):
        raise _damaged(store, spec, index, f"is truncated or padded ({len(data):,} bytes, "
                                           f"its header says {cbytes:,})")
    out = np.empty(spec.nbytes, dtype=np.uint8)
    try:
        _blosc(spec).decode(data, out=out)
    except Exception as exc:  # noqa: BLE001 - whatever Blosc says, the file is damaged
        raise _damaged(store, spec, index, f"cannot be decompressed "
                                           f"({' '.join(str(exc).split())[:100]})") from None
    return out.view(spec.dtype).reshape(spec.shape)


#: The files of the chunks this process wrote last, in the local file system: their pages
#: are released from the page cache as the next chunks are written (:func:`leave_page_cache`).
_RECENT: deque = deque(maxlen=3)
_RECENT_LOCK = threading.Lock()


def leave_page_cache(files: list[str]) -> None:
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
