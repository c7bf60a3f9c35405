"""The Python side of ``optimal.c`` and ``maps.c``: one optimal-torque query on the all-held
maps of one configuration in one compiled call (:mod:`snakecg.optimize.quick`); the maps, the
dense dual active set and the symmetric top eigenvalue alone (for tests against independent
references).

:class:`Query` mirrors ``op_call`` field by field; :class:`OptimalKernel` binds the functions
of one compiled model library.
"""

from __future__ import annotations

import ctypes

import numpy as np

__all__ = ["OptimalKernel", "Query", "maps_size", "MAX_SR", "LEAST_SLIP", "STRONGEST", "MAX_DIM",
           "DENSE_MAX", "OUT"]

_P = ctypes.c_void_p
_I = ctypes.c_longlong
_D = ctypes.c_double

#: Query kinds (``op_call.kind``).
MAX_SR, LEAST_SLIP, STRONGEST = 0, 1, 2
#: Largest ``n_a`` of a query in the C (``OP_MAX``), and of its active set (``DENSE_MAX``,
#: the same as :data:`snakecg.optimize.active_set.DENSE_MAX`).
MAX_DIM, DENSE_MAX = 16, 4
#: Largest number of rows of a dense QP (``OP_ROWS``).
MAX_ROWS = 2 * MAX_DIM + 4
#: Positions in the output vector (``O_*`` of optimal.c); ``tau`` at ``OUT["tau"]``, then the
#: binding codes.
OUT = {"status": 0, "expected": 1, "k": 2, "a_dir": 3, "stationarity": 6, "primal": 7,
       "complementarity": 8, "gap": 9, "quad": 10, "tie": 11, "nb": 12, "lam_lo": 13,
       "gain": 14, "forward": 15, "tau": 16}
#: Binding codes: 0 the task row, 1 the contact, 2 the ellipsoid, 3 + j joint j (from 0),
#: 3 + n_a + w the w-th bounded wheel.
CODE_TASK, CODE_CONTACT, CODE_ELLIPSOID, CODE_JOINT = 0, 1, 2, 3


class Query(ctypes.Structure):
    """``op_call``: the model's scene vector and the configuration, the buffer of the maps,
    the model's bounded wheels, the query's limits and task, the output vector, and what the
    forward solve at the answer takes (``core_forward``'s constants and iteration limit, the
    output row)."""

    _fields_ = [("kind", _I), ("n", _I), ("nc", _I), ("nw", _I),
                ("scene", _P), ("q", _P), ("maps", _P),
                ("wheel_row", _P), ("wheel_ub", _P), ("Io", _P),
                ("pivot_tol", _D), ("radius", _D), ("tau_max", _P), ("direction", _P),
                ("a_min", _D), ("a_obj", _P), ("out", _P),
                ("constants", _P), ("max_iter", _I), ("row", _P)]


def maps_size(n_joints: int, n_constraints: int) -> int:
    """Length of the maps' buffer (``core_held_maps``): ``L`` (n_c x n_a), ``A`` (3 x n_a),
    ``Xi``, ``Omega``, ``N`` (n_a x n_a each), row-major, then the pivot ratio."""
    return n_constraints * n_joints + 3 * n_joints + 3 * n_joints * n_joints + 1


class OptimalKernel:
    """``core_optimal``, ``core_dense_qp`` and ``core_top_eigenvalue`` of one compiled model
    library."""

    def __init__(self, lib: ctypes.CDLL, prefix: str):
        fn = getattr(lib, f"{prefix}core_optimal")
        fn.argtypes = [_P]
        fn.restype = ctypes.c_int
        self.call = fn
        """``core_optimal(&query)``: 0 when answered, else the code of what the Python path
        must answer (optimal.c ``OP_*``)."""
        fn = getattr(lib, f"{prefix}core_dense_qp")
        fn.argtypes = [_I, _I] + [_P] * 7
        fn.restype = ctypes.c_int
        self._qp = fn
        fn = getattr(lib, f"{prefix}core_held_maps")
        fn.argtypes = [_P, _P, _D, _P]
        fn.restype = ctypes.c_int
        self._maps = fn
        fn = getattr(lib, f"{prefix}core_top_eigenvalue")
        fn.argtypes = [_I, _P]
        fn.restype = _D
        self._top = fn

    def dense_qp(self, H, g, A, lo, hi):
        """``min 1/2 x^T H x + g^T x`` s.t. ``lo <= A x <= hi`` by the C's dense dual active
        set (``H`` positive definite, at most ``DENSE_MAX`` variables and ``MAX_ROWS`` rows):
        ``(x, lam)`` with ``lam`` the rows' multipliers, or None when it gives up."""
        H, g, A, lo, hi = (np.ascontiguousarray(a, dtype=float) for a in (H, g, A, lo, hi))
        n = g.size
        A = A.reshape(-1, n)
        R = A.shape[0]
        if H.shape != (n, n) or lo.shape != (R,) or hi.shape != (R,):
            raise ValueError("dense_qp: inconsistent shapes")
        if not 1 <= n <= DENSE_MAX or R > MAX_ROWS:
            raise ValueError(f"dense_qp takes 1..{DENSE_MAX} variables and {MAX_ROWS} rows")
        x = np.zeros(n)
        lam = np.zeros(R)
        ok = self._qp(n, R, H.ctypes.data, g.ctypes.data, A.ctypes.data, lo.ctypes.data,
                      hi.ctypes.data, x.ctypes.data, lam.ctypes.data)
        return (x, lam) if ok == 1 else None

    def held_maps(self, model, q, pivot_tol: float):
        """maps.c's all-held maps at ``q`` (a model of this library): ``(code, maps)`` with
        ``maps`` a dict of ``L``, ``A``, ``Xi``, ``Omega``, ``N``, ``pivot_ratio`` and
        ``code`` 0 when they are defined (1: a call failed, 2: dependent rows, 3: not
        finite)."""
        n, nc = model.n_joints, model.n_constraints
        q = np.ascontiguousarray(q, dtype=float)
        if q.shape != (model.n_coordinates,):
            raise ValueError(f"held_maps takes one configuration of {model.n_coordinates}")
        buf = np.zeros(maps_size(n, nc))
        code = self._maps(model.scene_address, q.ctypes.data, pivot_tol, buf.ctypes.data)
        k = 0
        out = {}
        for name, shape in (("L", (nc, n)), ("A", (3, n)), ("Xi", (n, n)), ("Omega", (n, n)),
                            ("N", (n, n))):
            size = shape[0] * shape[1]
            out[name] = buf[k:k + size].reshape(shape)
            k += size
        out["pivot_ratio"] = float(buf[k])
        return int(code), out

    def top_eigenvalue(self, S) -> float:
        """Largest eigenvalue of a symmetric matrix (cyclic Jacobi, at most ``MAX_DIM``)."""
        S = np.ascontiguousarray(S, dtype=float)
        n = S.shape[0]
        if S.shape != (n, n) or not 1 <= n <= MAX_DIM:
            raise ValueError(f"top_eigenvalue takes a square matrix of size 1..{MAX_DIM}")
        return float(self._top(n, S.ctypes.data))
