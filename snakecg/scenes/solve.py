"""The engine's general-scene solve (``snakecg/engine/scene_solve.c``, compiled into every
model's library) called on stacked problems, and the codes it shares with Python.

:func:`solve` takes the model's engine (``model.core``) and stacked per-sample problems
(inertia, applied force, rows and their blocks) and returns forces, accelerations, row
accelerations, block states and the certificate of every sample in one C call.
"""

from __future__ import annotations

import numpy as np

from ..errors import BuildError

__all__ = ["FREE", "UNILATERAL", "BOX", "DISC", "SPLIT", "HELD", "ZERO", "SLIDE", "SLIDE_POS",
           "SLIDE_NEG", "INFO", "solve"]

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

def _c(a, dtype):
    return np.ascontiguousarray(a, dtype=dtype)


def solve(core, M, f, A, m, kind, start, par, *, c=None, max_sweeps: int = MAX_SWEEPS) -> dict:
    """Solve ``N`` stacked problems: ``M`` ``(N, n, n)``, ``f`` ``(N, n)``, ``A``
    ``(N, mmax, n)``, ``m`` ``(N,)`` rows used, ``kind``/``start`` ``(N, nbmax)`` (blocks
    used: entries before the first ``-1`` kind), ``par`` ``(N, nbmax, 3)``. Returns ``lam``,
    ``w`` ``(N, mmax)``, ``a`` ``(N, n)``, ``state`` ``(N, nbmax)`` (int), ``info``
    ``{name: (N,)}``. ``c`` ``(N, mmax)``: the rows' offsets (they read ``w = A a + c``;
    default none), the velocity-level step's gaps over h."""
    fn = getattr(core, "scene_solve" if c is None else "scene_solve_b", None)
    if fn is None:
        raise BuildError("a general scene is solved by the compiled engine; load it with a C "
                         "compiler (set CC) and the compiled backend")
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
    head = [N, n, mmax, nbmax, m.ctypes.data, nb.ctypes.data, M.ctypes.data, f.ctypes.data,
            A.ctypes.data]
    if c is not None:
        c = _c(np.broadcast_to(c, (N, mmax)), np.float64)
        head.append(c.ctypes.data)
    rc = fn(*head, kind.ctypes.data, start.ctypes.data, par.ctypes.data, max_sweeps,
            lam.ctypes.data, a.ctypes.data, w.ctypes.data, state.ctypes.data, info.ctypes.data)
    if rc == -1:
        raise MemoryError("the scene solve ran out of memory")
    if rc != 0:
        raise ValueError(f"scene_solve refused its sizes (n={n}, rows={mmax}, blocks={nbmax})")
    return {"lam": lam, "w": w, "a": a, "state": state[:, :nbmax].astype(np.int64),
            "info": {k: info[:, i] for i, k in enumerate(INFO)}}
