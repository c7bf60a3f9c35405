"""The compiled general-scene solve (``snakecg/core/scene_solve.c``) through ctypes: the one
place that binds it. The library knows no robot, so it is compiled once per compiler (not per
model) into the cache (``<cache>/build/scene_solve-<key>/scene_solve.so``), under a lock and
renamed into place atomically.

:func:`solve` takes stacked per-sample problems (inertia, applied force, rows and their
blocks) and returns forces, accelerations, row accelerations, block states and the
certificate of every sample in one C call.
"""

from __future__ import annotations

import ctypes
import hashlib
import os
import tempfile
from pathlib import Path

import numpy as np

from ..errors import BuildError

__all__ = ["FREE", "UNILATERAL", "BOX", "DISC", "SPLIT", "HELD", "ZERO", "SLIDE", "SLIDE_POS",
           "SLIDE_NEG", "INFO", "solve", "library"]

#: block kinds (scene_solve.c)
FREE, UNILATERAL, BOX, DISC, SPLIT = 0, 1, 2, 3, 4
#: block states: held / stick, zero (a contact that opens, a friction set of size 0),
#: sliding on the set's boundary (a bounded wheel: SLIDE_POS / SLIDE_NEG by the force's sign)
HELD, ZERO, SLIDE, SLIDE_POS, SLIDE_NEG = 0, 1, 2, 3, 4
#: the certificate's fields, in order
INFO = ("status", "dependent", "primal", "dual", "complementarity", "sweeps", "passes",
        "rank_defect")
#: sample status
SOLVED, NOT_CONVERGED, SINGULAR_MASS = 0, 1, 2
#: Gauss-Seidel sweeps allowed per sample before it is reported unsolved (NaN, status 1)
MAX_SWEEPS = 200000

SOURCE = Path(__file__).resolve().parent.parent / "core" / "scene_solve.c"
HEADERS = (SOURCE.with_name("linalg.h"), SOURCE.with_name("scene_sets.h"))
_LIB: list = []
_P = ctypes.c_void_p
_I = ctypes.c_longlong


def library():
    """The compiled library (built once into the cache, then loaded)."""
    if _LIB:
        return _LIB[0]
    from ..artifacts import cache_dir, held_lock, make_private_dir
    from ..native import CORE_FLAGS, _compiler_id, _no_compiler, _run, find_compiler

    cc = find_compiler()
    if cc is None:
        raise _no_compiler()
    h = hashlib.sha256()
    for p in (SOURCE, *HEADERS):
        h.update(p.name.encode() + hashlib.sha256(p.read_bytes()).digest())
    h.update(_compiler_id(cc).encode() + " ".join(CORE_FLAGS).encode())
    folder = make_private_dir(cache_dir() / "build" / f"scene_solve-{h.hexdigest()[:20]}")
    lib = folder / "scene_solve.so"
    if not lib.exists():
        with held_lock(folder / ".lock", "compiling the scene solve"):
            if not lib.exists():
                fd, tmp = tempfile.mkstemp(suffix=".so", dir=folder)
                os.close(fd)
                try:
                    _run([cc, *CORE_FLAGS, "-std=c99", "-shared", "-I", str(SOURCE.parent),
                          str(SOURCE), "-o", tmp, "-lm"])
                    os.replace(tmp, lib)
                finally:
                    if os.path.exists(tmp):
                        os.unlink(tmp)
    try:
        dll = ctypes.CDLL(str(lib))
    except OSError as exc:  # pragma: no cover - a damaged cache entry
        raise BuildError(f"could not load {lib}: {exc}; delete it to rebuild") from exc
    fn = dll.scene_solve
    fn.argtypes = [_I, _I, _I, _I, _P, _P, _P, _P, _P, _P, _P, _P, _I, _P, _P, _P, _P, _P]
    fn.restype = ctypes.c_int
    _LIB.append(fn)
    return fn


def _c(a, dtype):
    return np.ascontiguousarray(a, dtype=dtype)


def solve(M, f, A, m, kind, start, par, *, max_sweeps: int = MAX_SWEEPS) -> dict:
    """Solve ``N`` stacked problems: ``M`` ``(N, n, n)``, ``f`` ``(N, n)``, ``A``
    ``(N, mmax, n)``, ``m`` ``(N,)`` rows used, ``kind``/``start`` ``(N, nbmax)`` (blocks
    used: entries before the first ``-1`` kind), ``par`` ``(N, nbmax, 3)``. Returns ``lam``,
    ``w`` ``(N, mmax)``, ``a`` ``(N, n)``, ``state`` ``(N, nbmax)`` (int), ``info``
    ``{name: (N,)}``."""
    fn = library()
    M, f, A = _c(M, np.float64), _c(f, np.float64), _c(A, np.float64)
    kind, start, par = _c(kind, np.int64), _c(start, np.int64), _c(par, np.float64)
    N, n = f.shape
    mmax = A.shape[1]
    nbmax = kind.shape[1]
    nb = _c(np.sum(kind >= 0, axis=1), np.int64)
    m = _c(m, np.int64)
    lam = np.zeros((N, mmax))
    w = np.zeros((N, mmax))
    a = np.zeros((N, n))
    state = np.zeros((N, max(nbmax, 1)))
    info = np.zeros((N, len(INFO)))
    rc = fn(N, n, mmax, nbmax, m.ctypes.data, nb.ctypes.data, M.ctypes.data, f.ctypes.data,
            A.ctypes.data, kind.ctypes.data, start.ctypes.data, par.ctypes.data, max_sweeps,
            lam.ctypes.data, a.ctypes.data, w.ctypes.data, state.ctypes.data, info.ctypes.data)
    if rc == -1:
        raise MemoryError("the scene solve ran out of memory")
    if rc != 0:
        raise ValueError(f"scene_solve refused its sizes (n={n}, rows={mmax}, blocks={nbmax})")
    return {"lam": lam, "w": w, "a": a, "state": state[:, :nbmax].astype(np.int64),
            "info": {k: info[:, i] for i, k in enumerate(INFO)}}
