"""The Zarr store of a sweep: layout, creation, compatibility, chunk records.

Layout (a Zarr v3 group, a folder ``STORE.zarr``), every array chunked like the computation
(``chunk`` configurations per chunk, all joints of a configuration in one chunk), with the
dimensions named (``configuration``, ``joint``) and units in each array's attributes, so that
``xarray.open_zarr(STORE)`` reads it as a Dataset (format 3):

* ``q`` ``(N, n_a)``: joint angles (degrees; radians in stores of formats 1 and 2), the
  Dataset's coordinate; ``joint`` ``(n_a,)``: the joint numbers 1..n_a (format 3);
  ``com_radius``, ``com_angle`` ``(N,)``: polar coordinates of the snake's COM w.r.t. the
  contact point (m, rad; see :func:`snakecg.analysis.com_polar`);
* for every metric ``m`` of :data:`snakecg.analysis.METRICS`: ``max_m`` / ``min_kept_m``
  ``(N,)`` and the torques attaining them ``tau_max_m`` / ``tau_min_kept_m`` ``(N, n_a)``
  (:class:`snakecg.analysis.Extremes` ``.max``, ``.min_kept`` and their ``tau_`` partners);
* ``feasible`` ``(N,)`` bool: the shape is physically possible
  (:func:`snakecg.geometry.feasibility` at the clearance recorded in the attributes);
* ``chunk_digest``: 0 for a chunk not written yet, else digests of the chunk's data
  (:data:`DIGESTS`). Format 3: ``(n_chunks, 20)``, one XXH3-64 per array of the bytes of
  its chunk file as stored (compressed); formats 1 and 2: ``(n_chunks,)``, one digest of
  the values of all arrays. A chunk's digests are written only after all of its data, so a
  chunk counts as complete only when its data is all there. Every read checks them
  (:class:`Reader`); a resumed sweep computes a chunk that does not match again.
* attributes ``snakecg_sweep``: robot, scene, grid or sampling, chunk, package version,
  array names, the feasibility check's clearance and whether the reductions default to
  feasible shapes only (the fingerprint a resumed sweep must match); ``completed_chunks`` and
  ``complete``, updated as the sweep goes; ``store_id``, a random identity made with the
  store (a worker that writes data checks it). Format 3 consolidates the arrays' metadata
  into the group's (what ``xarray.open_zarr`` reads first).

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
import uuid
import warnings
from pathlib import Path

import numpy as np

from ..analysis import METRICS
from ..errors import InputError
from . import chunks as _chunks
from .simulation import SIM_ARRAYS, SIM_LONG, SIM_UNITS, STATUS_CODES

__all__ = ["array_names", "names_of", "configuration_bytes", "create", "open_existing", "check_target",
           "digest", "handles", "write_data", "record", "completed", "store_id", "format_of",
           "Reader", "FORMAT", "DIGESTS", "UNITS"]

#: Layout version of new stores (attribute ``snakecg_sweep.format``).
FORMAT = "snakecg.sweep/3"
#: The formats this version reads and resumes, and the digests each records in
#: ``chunk_digest``: format 1 BLAKE2b-64 and format 2 XXH3-64 (ten times cheaper) of a
#: chunk's values; format 3 XXH3-64 of each array's chunk file (compressed, :mod:`.chunks`),
#: joint angles in degrees, named dimensions and units.
DIGESTS = {"snakecg.sweep/1": "blake2b-64", "snakecg.sweep/2": "xxh3-64",
           "snakecg.sweep/3": "xxh3-64 per array file"}
_DIGEST_BLOCK = 4096  # chunk_digest rows per Zarr chunk
#: Units of the arrays of a format-3 store (attribute ``units``, UDUNITS spelling). The
#: three squared norms are quadratic forms in the metric of their space (eqs. 26, 27 and
#: the constraint forces' G_c): kg m^2 s^-4 whatever the coordinates.
UNITS = {"q": "degree", "com_radius": "m", "com_angle": "rad", "max_sr": "1",
         "min_kept_sr": "1", "feasible": "1"}
for _m in METRICS:
    for _p in ("tau_max_", "tau_min_kept_"):
        UNITS[_p + _m] = "N m"
    if _m != "sr":
        UNITS["max_" + _m] = UNITS["min_kept_" + _m] = "kg m2 s-4"
_LONG = {"q": "joint angles", "com_radius": "distance of the snake's COM from the contact "
         "point", "com_angle": "angle of the COM from the contacting link's axis",
         "feasible": "the shape is physically possible"}


def array_names(meta: dict | None = None) -> tuple[str, ...]:
    """Names of the per-configuration arrays, in the order the digest reads them; a store
    whose attributes ``meta`` record a simulation (``meta["simulation"]``) has the arrays of
    :data:`.simulation.SIM_ARRAYS` after them."""
    names = ["q", "com_radius", "com_angle"]
    for m in METRICS:
        names += [f"max_{m}", f"tau_max_{m}", f"min_kept_{m}", f"tau_min_kept_{m}"]
    names.append("feasible")
    if meta and meta.get("simulation"):
        names += SIM_ARRAYS
    return tuple(names)


def names_of(root) -> tuple[str, ...]:
    """The per-configuration arrays of an open store (by its attributes)."""
    return array_names(dict(root.attrs).get("snakecg_sweep"))


def _per_configuration(name: str, joints: int) -> tuple[int, ...]:
    """Shape of one configuration's entry of array ``name``: a row of the joints (``q`` and
    the torques) or one value."""
    return (joints,) if name == "q" or name.startswith("tau_") else ()


_SYMBOL = {"norm_a_obj": "|a_obj|^2 (eq. 27)", "norm_qdd": "|qdd_s|^2 (eq. 26)",
           "norm_lambda": "|lambda|^2", "sr": "slippage ratio sr (eq. 30)"}


def _long_name(name: str) -> str:
    """The ``long_name`` attribute of array ``name`` (what xarray shows as its title)."""
    if name in _LONG:
        return _LONG[name]
    if name in SIM_LONG:
        return SIM_LONG[name]
    torque = name.startswith("tau_")
    m = name[4:] if torque else name
    if m.startswith("max_"):
        what = f"largest {_SYMBOL[m[4:]]} over the input ellipsoid"
    else:
        what = (f"smallest {_SYMBOL[m[9:]]} over the torques of the input ellipsoid that "
                f"keep the contact")
    return f"torque attaining the {what}" if torque else what


def configuration_bytes(joints: int, simulation: bool = False) -> int:
    """Bytes of one configuration in all the store's arrays (float64; ``feasible`` bool),
    with the simulation's arrays when ``simulation``."""
    names = array_names({"simulation": True} if simulation else None)
    return sum((1 if name == "feasible" else 8) * math.prod(_per_configuration(name, joints))
               for name in names)


def _zarr():
    try:
        import xxhash  # noqa: F401 - the digests of formats 2 and 3
        import zarr
    except ModuleNotFoundError:
        raise InputError("sweeps need the sweep extra (Dask, Zarr, xxhash and xarray): "
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


def _compressors(name: str):
    from zarr.codecs import BloscCodec

    c = _chunks.COMPRESSION
    if not _chunks.compressed(name):
        return None
    return [BloscCodec(cname=c["cname"], clevel=c["clevel"], shuffle=c["shuffle"])]


def create(path: Path, meta: dict, n_configurations: int, chunk: int, joints: int):
    """Create a store of format :data:`FORMAT` (under a temporary name, renamed into
    place) and open it."""
    zarr = _zarr()
    n_chunks = -(-n_configurations // chunk)
    names = array_names(meta)
    tmp = path.with_name(f".{path.name}.{uuid.uuid4().hex}.partial")
    try:
        root = zarr.open_group(str(tmp), mode="w-")
        for name in names:
            row = _per_configuration(name, joints)
            flag = name == "feasible"
            attrs = {"units": UNITS.get(name) or SIM_UNITS[name], "long_name": _long_name(name)}
            if name == "sim_status":  # CF: what each code means
                attrs["flag_values"] = list(STATUS_CODES.values())
                attrs["flag_meanings"] = " ".join(STATUS_CODES)
            if name != "q":
                attrs["coordinates"] = "q"  # xarray: q is every variable's coordinate
            root.create_array(name, shape=(n_configurations, *row), chunks=(chunk, *row),
                              dtype="bool" if flag else "float64",
                              fill_value=False if flag else np.nan,
                              compressors=_compressors(name), attributes=attrs,
                              dimension_names=("configuration", "joint")[:1 + len(row)])
        joint = root.create_array("joint", shape=(joints,), chunks=(joints,), dtype="int64",
                                  fill_value=0, compressors=None, dimension_names=("joint",),
                                  attributes={"long_name": "joint number"})
        joint[:] = np.arange(1, joints + 1)
        root.create_array("chunk_digest", shape=(n_chunks, len(names)),
                          chunks=(min(n_chunks, _DIGEST_BLOCK), len(names)), dtype="uint64",
                          fill_value=0, compressors=None, dimension_names=("chunk", "array"),
                          attributes={"arrays": list(names),
                                      "long_name": "XXH3-64 of each array's chunk file "
                                                   "(lowest bit set); 0: not written yet"})
        root.attrs.update({"snakecg_sweep": meta, "completed_chunks": 0, "complete": False,
                           "store_id": uuid.uuid4().hex})
        with warnings.catch_warnings():  # "not part of the Zarr 3 specification" (yet)
            warnings.simplefilter("ignore")
            zarr.consolidate_metadata(str(tmp))
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
    """Open a sweep store (through its consolidated metadata, if it has them, so that
    attribute updates keep them); with ``meta``, refuse one made with other arguments."""
    zarr = _zarr()
    try:
        root = zarr.open_group(str(path), mode=mode)
        stored = dict(root.attrs).get("snakecg_sweep")
    except Exception as exc:  # noqa: BLE001 - any unreadable store is the user's input
        raise InputError(f"{str(path)!r} is not a readable sweep store: "
                         f"{' '.join(str(exc).split()) or type(exc).__name__}") from None
    if not isinstance(stored, dict) or stored.get("format") not in DIGESTS:
        found = stored.get("format") if isinstance(stored, dict) else None
        raise InputError(f"{str(path)!r} is a Zarr store but not a sweep store this version "
                         f"reads (attribute snakecg_sweep.format is {found!r}, expected "
                         f"{' or '.join(DIGESTS)})")
    if meta is not None:
        want = _normalise(meta)
        diff = sorted(k for k in set(want) | set(stored) if want.get(k) != stored.get(k))
        if diff:
            raise InputError(
                f"the store {str(path)!r} was made with other arguments (they differ in: "
                f"{', '.join(diff)}); rerun with the arguments that made it to resume, or "
                f"give a new --out")
    return root


def digest(arrays: dict[str, np.ndarray], fmt: str = "snakecg.sweep/2", names=None) -> int:
    """Nonzero 64-bit digest of a chunk's values, the one stores of format 1 and 2 record
    (:data:`DIGESTS`): XXH3-64 (format 2) or BLAKE2b-64 (format 1) of the arrays' bytes in
    :func:`array_names` order (``feasible`` as one byte per configuration), read as a
    little-endian integer, lowest bit set. ``names``: the store's arrays (default
    :func:`array_names`; format-1 stores made before the ``feasible`` array lack it)."""
    if DIGESTS[fmt] == "xxh3-64":
        import xxhash

        h = xxhash.xxh3_64()
    else:
        h = hashlib.blake2b(digest_size=8)
    for name in names or array_names():
        dtype = np.uint8 if name == "feasible" else np.float64
        # the array's buffer itself (the same bytes as .tobytes(), without copying them)
        h.update(np.ascontiguousarray(arrays[name], dtype=dtype))
    return int.from_bytes(h.digest(), "little") | 1


def format_of(root) -> str:
    """The format of an open sweep store (one of :data:`DIGESTS`)."""
    return root.attrs["snakecg_sweep"]["format"]


def _per_file(fmt: str) -> bool:
    return fmt == "snakecg.sweep/3"


def handles(root, *, digests: bool = True) -> dict:
    """The store's arrays opened once (opening one reads its metadata from the store) and
    their :class:`~.chunks.ChunkSpec` (key ``"specs"``); ``digests=False`` leaves out
    ``chunk_digest`` (a worker writing data only)."""
    data = names_of(root)
    names = (*data, "chunk_digest") if digests else data
    opened = {name: root[name] for name in names}
    opened["specs"] = {name: _chunks.spec_of(opened[name], name) for name in data}
    opened["names"] = data
    return opened


def store_id(root) -> str:
    """The store's identity (attribute ``store_id``, made once): a worker that writes data
    checks it, so that it never writes into another store at the same path."""
    sid = root.attrs.get("store_id")
    if not isinstance(sid, str):
        sid = uuid.uuid4().hex
        root.attrs["store_id"] = sid
    return sid


def degrees(q: np.ndarray) -> np.ndarray:
    """Joint angles ``q`` (rad) in degrees as a store of format 3 holds them: each the
    degrees rounded to 9 decimals where those give ``q`` back exactly (the angles of a grid
    given in degrees: -120.0, not -119.99999999999999), else ``numpy.rad2deg``."""
    deg = np.rad2deg(q)
    rounded = np.round(deg, 9)
    return np.where(np.deg2rad(rounded) == q, rounded, deg)


def stored_values(arrays: dict[str, np.ndarray], fmt: str) -> dict[str, np.ndarray]:
    """A chunk's arrays as a store of format ``fmt`` holds them: format 3 keeps the joint
    angles in degrees (:func:`degrees`)."""
    if _per_file(fmt):
        return {**arrays, "q": degrees(arrays["q"])}
    return arrays


def write_data(opened: dict, start: int, stop: int, arrays: dict[str, np.ndarray],
               fmt: str = FORMAT):
    """Write a chunk's data (every array, in one round trip to Zarr's event loop: the
    arrays' chunk files are written concurrently, each through a temporary file and a
    rename) and return what its ``chunk_digest`` row records (:func:`record`): format 3
    the tuple of each file's XXH3-64, formats 1 and 2 the :func:`digest` of the values.

    Each chunk file is encoded here (:func:`.chunks.encode`: raw bytes, or Blosc as the
    array's metadata says, byte for byte Zarr's own encoding; the last chunk padded with
    the fill value) and handed to Zarr's store under the chunk's key, without Zarr's
    selection and codec machinery (a fifth to a third less CPU time per chunk)."""
    import asyncio

    from zarr.core.buffer import default_buffer_prototype
    from zarr.core.sync import sync

    buffer = default_buffer_prototype().buffer
    specs = opened["specs"]
    values = stored_values(arrays, fmt)
    index = start // specs["q"].rows
    names = opened["names"]
    files = {name: _chunks.encode(values[name], specs[name]) for name in names}

    async def _all():
        await asyncio.gather(*(
            (opened[name].store_path / _chunks.chunk_key(index, opened[name].ndim)).set(
                buffer.from_array_like(np.frombuffer(files[name], dtype=np.uint8)))
            for name in names))

    sync(_all())
    _chunks.leave_page_cache(_chunk_files(opened, index))
    if _per_file(fmt):
        return tuple(_chunks.file_digest(files[name]) for name in names)
    return digest(values, fmt, names)


def _chunk_files(opened: dict, index: int) -> list[str]:
    """Paths of chunk ``index``'s files of every array, if the store is a local folder
    (else none)."""
    from zarr.storage import LocalStore

    out = []
    for name in opened["names"]:
        array = opened[name]
        store = array.store_path.store
        if not isinstance(store, LocalStore):
            return []
        out.append(os.path.join(store.root, array.store_path.path,
                                _chunks.chunk_key(index, array.ndim)))
    return out


def record(opened: dict, digests: dict) -> None:
    """Record the chunks ``digests`` (index -> what :func:`write_data` returned) as
    complete, after all of their data is written, in one write per block of the
    ``chunk_digest`` array. Only the process that called the sweep records digests (never
    two at once)."""
    if digests:
        index = np.fromiter(digests, dtype=np.int64, count=len(digests))
        values = np.array(list(digests.values()), dtype=np.uint64)
        opened["chunk_digest"].oindex[index] = values


class Reader:
    """The chunks of a sweep store read back verified (every read of a store's data goes
    through one): the attributes, each array's metadata (its own ``zarr.json``, and the
    consolidated copy where there is one) and the digest table are checked when it is made;
    each chunk file is read bounded, checked against its digest and decoded by
    :mod:`.chunks`. A damaged store raises :class:`InputError` naming what is damaged: the
    attribute, the array, or the array and the chunk."""

    def __init__(self, path: Path, root, plan, meta: dict):
        zarr = _zarr()
        fmt = meta["format"]
        self.path, self.plan, self.fmt = Path(path), plan, fmt
        self.name = str(path)
        joints = plan.joints
        names = meta.get("arrays")
        every = list(array_names(meta))
        # stores of format 1 made before the feasible flag have every array but it
        early = [n for n in every if n != "feasible"] if fmt == "snakecg.sweep/1" else None
        if names != every and names != early:
            raise InputError(f"{self.name!r}: its attribute snakecg_sweep.arrays is "
                             f"{names!r}, expected {every}; the store was edited")
        self.names = tuple(names)
        try:
            plain = zarr.open_group(str(path), mode="r", use_consolidated=False)
        except Exception as exc:  # noqa: BLE001 - reported with the store's name
            raise InputError(f"{self.name!r}: its group metadata cannot be read "
                             f"({' '.join(str(exc).split())[:200]})") from None
        self.specs = {}
        wanted = [*self.names, "chunk_digest"] + (["joint"] if _per_file(fmt) else [])
        for name in wanted:
            spec = _open_spec(plain, name, self.name)
            if name in root and root is not plain:
                other = _open_spec(root, name, self.name)
                if other.key() != spec.key():
                    raise InputError(f"{self.name!r}: array {name}'s metadata differs from "
                                     f"the group's consolidated copy; the store was edited")
            self.specs[name] = spec
        self._check_layout(joints)
        self.digests = self._digest_table()

    def _check_layout(self, joints: int) -> None:
        plan, per_file = self.plan, _per_file(self.fmt)
        for name in self.names:
            s = self.specs[name]
            want = (np.dtype(bool) if name == "feasible" else np.dtype("<f8"),
                    plan.chunk, _per_configuration(name, joints))
            if (s.dtype, s.rows, s.row) != want or (s.blosc is not None and not per_file):
                raise InputError(f"{self.name!r}: array {name} is not laid out as the store's "
                                 f"attributes say (chunks of {plan.chunk} configurations, "
                                 f"{'raw' if not per_file else 'raw or Blosc'} "
                                 f"{want[0]}); the store is damaged or was edited")
        d = self.specs["chunk_digest"]
        row = (len(self.names),) if per_file else ()
        if d.dtype != np.dtype("<u8") or d.blosc is not None or d.row != row:
            raise InputError(f"{self.name!r}: array chunk_digest is not a digest table of "
                             f"format {self.fmt}; the store is damaged or was edited")
        if per_file:
            j = self.specs["joint"]
            data = _chunks.read_file(self._file("joint", 0), j, 0, store=self.name)
            if not np.array_equal(_chunks.decode(data, j, 0, store=self.name).reshape(-1),
                                  np.arange(1, joints + 1)):
                raise InputError(f"{self.name!r}: array joint does not hold the joint "
                                 f"numbers 1..{joints}; the store was edited")

    def _file(self, name: str, index: int) -> str:
        ndim = 1 + len(self.specs[name].row)
        return str(self.path / name / _chunks.chunk_key(index, ndim))

    def _digest_table(self) -> np.ndarray:
        s = self.specs["chunk_digest"]
        n = self.plan.n_chunks
        if s.rows != min(n, _DIGEST_BLOCK):
            raise InputError(f"{self.name!r}: array chunk_digest has blocks of {s.rows} rows,"
                             f" expected {min(n, _DIGEST_BLOCK)}; the store was edited")
        out = np.zeros((n, *s.row), dtype=np.uint64)
        for b in range(-(-n // s.rows)):
            path = self._file("chunk_digest", b)
            if not os.path.exists(path):
                continue  # no chunk of this block recorded yet
            data = _chunks.read_file(path, s, b, store=self.name)
            rows = _chunks.decode(data, s, b, store=self.name)
            out[b * s.rows:(b + 1) * s.rows] = rows[:min(s.rows, n - b * s.rows)]
        return out

    def recorded(self) -> np.ndarray:
        """Boolean ``(n_chunks,)``: the chunks recorded complete (every digest written)."""
        d = self.digests
        return (d != 0).all(axis=1) if d.ndim == 2 else d != 0

    def chunk(self, index: int, names=None) -> dict[str, np.ndarray]:
        """The values of the arrays ``names`` (default all) of recorded chunk ``index``
        (only its configurations), as stored (format 3: ``q`` in degrees), after every
        file of the chunk is checked against its digests: format 3 records one per file
        (each is read, checked, and decoded if asked for), formats 1 and 2 one of the
        values of all arrays (each is read and decoded to check it)."""
        per_file = _per_file(self.fmt)
        start, stop = self.plan.chunk_range(index)
        want = set(names or self.names)
        out = {}
        for k, name in enumerate(self.names):
            spec = self.specs[name]
            data = _chunks.read_file(self._file(name, index), spec, index, store=self.name,
                                     digest=self.digests[index, k] if per_file else None)
            if name in want or not per_file:
                out[name] = _chunks.decode(data, spec, index, store=self.name)[:stop - start]
        if not per_file and digest(out, self.fmt, self.names) != int(self.digests[index]):
            raise InputError(f"{self.name}: chunk {index} (configurations from {start:,}) "
                             f"does not match its recorded digest (one of its arrays was "
                             f"changed): the store is damaged; rerun the sweep that made it "
                             f"(it computes such chunks again) or make a new one")
        return {k: out[k] for k in (names or self.names)}

    def q_deg(self, data: dict) -> np.ndarray:
        """The joint angles (degrees) of a chunk read by :meth:`chunk`."""
        return data["q"] if _per_file(self.fmt) else np.rad2deg(data["q"])

    def q_rad(self, data: dict, planned: np.ndarray, index: int) -> np.ndarray:
        """The joint angles (rad) of chunk ``index`` read by :meth:`chunk`: ``planned``
        (the plan's, as computed), which the stored ones must be exactly (format 3: in
        degrees, :func:`degrees` of them)."""
        stored = data["q"]
        if not np.array_equal(degrees(planned) if _per_file(self.fmt) else planned, stored):
            start = index * self.plan.chunk
            raise InputError(f"{self.name}: array q, chunk {index} (configurations from "
                             f"{start:,}) does not hold the joint angles of the store's "
                             f"configurations: the store is damaged or was edited")
        return planned


def _open_spec(group, name: str, store: str):
    try:
        array = group[name]
    except Exception as exc:  # noqa: BLE001 - missing or unreadable zarr.json
        why = "is missing" if isinstance(exc, KeyError) else \
            f"cannot be read ({' '.join(str(exc).split())[:150]})"
        raise InputError(f"{store!r}: array {name} (its zarr.json) {why}; the store is "
                         f"damaged") from None
    try:
        return _chunks.spec_of(array, name)
    except InputError as exc:
        raise InputError(f"{store!r}: {exc}") from None


def completed(root, plan, *, verify: bool = True, path=None) -> np.ndarray:
    """Boolean ``(n_chunks,)``: which chunks are complete (digest recorded and, with
    ``verify``, matching the data read back; a chunk that does not is computed again). A
    store whose structure is damaged (attributes, an array's metadata, the digest table)
    raises :class:`InputError`."""
    path = Path(path) if path is not None else Path(root.store.root)
    reader = Reader(path, root, plan, root.attrs["snakecg_sweep"])
    done = reader.recorded()
    if verify:
        for i in np.flatnonzero(done):
            try:
                reader.chunk(int(i))
            except InputError:  # damaged: computed again
                done[i] = False
    return done
