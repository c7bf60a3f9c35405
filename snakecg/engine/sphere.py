"""The Python side of ``sphere.c`` and ``pieces.c``: the exact bounded-wheel extremes' pieces,
their faces and the KKT candidates on them.

:class:`SphereKernel` binds the functions of ``sphere.c`` and ``pieces.c`` in a compiled model
library, the compiled path of :mod:`snakecg.pieces` and :mod:`snakecg.sphere_kkt`:

- :meth:`~SphereKernel.pieces`: each (configuration, state) pair's affine maps and conditions;

- :meth:`~SphereKernel.cut`: the faces of ``|S|`` conditions held at equality that meet the
  unit sphere, each as the smaller sphere ``u = u0 + Z y, |y| = r``;
- :meth:`~SphereKernel.meets`: whether a face's sphere meets its piece (the stationary points
  of a linear function on it);
- :meth:`~SphereKernel.candidates`: per face, the best feasible maximum and minimum of
  ``u^T A u + 2 g^T u + c`` over its stationary points, and the largest and smallest value over
  all of them.

NumPy's functions of :mod:`snakecg.pieces` and :mod:`snakecg.sphere_kkt` compute the same and
stay the reference and the path of models without a C compiler.
"""

from __future__ import annotations

import itertools

import numpy as np

__all__ = ["SphereKernel"]


def _c(a, dtype=np.float64):
    return np.ascontiguousarray(a, dtype=dtype)


def _row(a, row) -> int:
    """Address of row ``row`` of ``a`` (0 for None)."""
    return 0 if a is None else a.ctypes.data + a.strides[0] * int(row)


def _per_pair(A, g, c, cond):
    A, g, c, cond = _c(A), _c(g), _c(c), _c(cond)
    P, na = A.shape[0], A.shape[1]
    if A.shape != (P, na, na) or g.shape != (P, na) or c.shape != (P,) \
            or cond.ndim != 3 or cond.shape[0] != P or cond.shape[2] != na + 1:
        raise ValueError("sphere kernel: inconsistent per-pair shapes")
    return A, g, c, cond


class SphereKernel:
    """``core_pieces``, ``core_sphere_cut``, ``core_sphere_meets`` and ``core_sphere_faces``
    of one compiled model library."""

    def __init__(self, lib):
        self._pieces = lib.entry("core_pieces")
        self._faces = lib.entry("core_sphere_faces")
        self._cut = lib.entry("core_sphere_cut")
        self._meets = lib.entry("core_sphere_meets")

    def pieces(self, cfg, states, bounds, G, Bt, Q0, A0, Kq, Ka):
        """The pairs' affine maps and conditions (:func:`snakecg.pieces.piece`): ``cfg``
        (P,) indexes the per-configuration arrays ``G`` (n, nc, nc), ``Bt`` (n, nc, na),
        ``Q0`` (n, ns, na), ``A0`` (n, 3, na), ``Kq`` (n, ns, nc), ``Ka`` (n, 3, nc);
        ``states`` (P, nc) the row states. Returns ``Lam, lam0, W, w0, Q, q0, Aa, a0, cond,
        flip, row`` (conditions up to the most any pair uses), or None where a pair's held
        rows are singular (NumPy's path then decides)."""
        cfg, states = _c(cfg, np.int64), _c(states, np.int8)
        G, Bt, Q0, A0, Kq, Ka = (_c(x) for x in (G, Bt, Q0, A0, Kq, Ka))
        bounds = _c(bounds)
        n, nc, na = Bt.shape
        ns = Q0.shape[1]
        P = len(cfg)
        if (G.shape != (n, nc, nc) or Q0.shape != (n, ns, na) or A0.shape != (n, 3, na)
                or Kq.shape != (n, ns, nc) or Ka.shape != (n, 3, nc)
                or states.shape != (P, nc) or bounds.shape != (nc,)
                or (P and (cfg.min() < 0 or cfg.max() >= n))):
            raise ValueError("sphere kernel: inconsistent piece inputs")
        mfull = 2 + 4 * int(np.sum(np.isfinite(bounds[1:])))
        out = [np.empty((P, nc, na)), np.empty((P, nc)), np.empty((P, nc, na)),
               np.empty((P, nc)), np.empty((P, ns, na)), np.empty((P, ns)),
               np.empty((P, 3, na)), np.empty((P, 3)), np.empty((P, mfull, na + 1)),
               np.empty((P, mfull), np.int64), np.empty((P, mfull), np.int64)]
        m = self._pieces(P, na, nc, ns, mfull, cfg.ctypes.data, states.ctypes.data,
                         bounds.ctypes.data, G.ctypes.data, Bt.ctypes.data, Q0.ctypes.data,
                         A0.ctypes.data, Kq.ctypes.data, Ka.ctypes.data,
                         *(a.ctypes.data for a in out))
        if m == -1:
            raise ValueError("sphere kernel: sizes above the compiled limits")
        if m < -1:
            return None
        cond, flip, row = out[8][:, :m], out[9][:, :m], out[10][:, :m]
        return (*out[:8], np.ascontiguousarray(cond), flip.astype(np.intp),
                row.astype(np.intp))

    def cut(self, cond, used, s):
        """The faces of ``s`` conditions at equality (every combination of each pair's
        ``used`` conditions, in NumPy's order) that meet the unit sphere: ``pair`` (F,),
        ``slots`` (F, s), ``u0`` (F, na), ``Z`` (F, na, na - s), ``r`` (F,)."""
        cond = _c(cond)
        P, m, na = cond.shape[0], cond.shape[1], cond.shape[2] - 1
        used = _c(used, np.uint8)
        if used.shape != (P, m) or not 1 <= s < na:
            raise ValueError("sphere kernel: bad face batch")
        combos = np.array(list(itertools.combinations(range(m), s)), dtype=np.int64)
        cap = P * len(combos)
        pair, combo = np.empty(cap, np.int64), np.empty(cap, np.int64)
        u0, Z, r = np.empty((cap, na)), np.empty((cap, na, na - s)), np.empty(cap)
        F = self._cut(P, na, m, s, len(combos), combos.ctypes.data, cond.ctypes.data,
                      used.ctypes.data, pair.ctypes.data, combo.ctypes.data, u0.ctypes.data,
                      Z.ctypes.data, r.ctypes.data)
        if F < 0:
            raise ValueError(f"sphere kernel: a cut of {s} conditions in n_a = {na}")
        return pair[:F], combos[combo[:F]].astype(np.intp), u0[:F], Z[:F], r[:F]

    def meets(self, pair, u0, Z, r, cond, direction, feas_tol):
        """(F,) bool: a stationary point of ``direction . u`` on each face is feasible."""
        pair, u0, Z, r, cond = _c(pair, np.int64), _c(u0), _c(Z), _c(r), _c(cond)
        direction = _c(direction)
        F, na, k = Z.shape
        out = np.zeros(F, np.uint8)
        if F and self._meets(F, na, k, cond.shape[1], pair.ctypes.data, u0.ctypes.data,
                             Z.ctypes.data, r.ctypes.data, cond.ctypes.data,
                             direction.ctypes.data, float(feas_tol), out.ctypes.data):
            raise ValueError(f"sphere kernel: faces of n_a = {na} with a bad dimension")
        return out.view(bool)

    def candidates(self, pair, u0, Z, r, A, g, c, cond, feas_tol, *, identity=False,
                   skip=None, pool=None, workers=1):
        """Per face: ``vmax, umax, vmin, umin, vhi, vlo`` (see sphere.c), split over
        ``workers`` threads of ``pool``. ``A`` (P, na, na), ``g`` (P, na), ``c`` (P,),
        ``cond`` (P, m, na + 1) are per pair and ``pair`` (F,) indexes them; ``u0`` (F, na),
        ``Z`` (F, na, k), ``r`` (F,) are the faces, ignored with ``identity`` (the whole unit
        sphere). ``skip``: ``(hi, lo)`` (F,) each, or None: a face whose bounds cannot
        exceed ``hi`` nor fall below ``lo`` is not searched (``vmax``/``vmin`` infinite,
        ``vhi``/``vlo`` the bounds)."""
        pair = _c(pair, np.int64)
        F = len(pair)
        A, g, c, cond = _per_pair(A, g, c, cond)
        P, na, m = A.shape[0], A.shape[1], cond.shape[1]
        if F and (pair.min() < 0 or pair.max() >= P):
            raise ValueError("sphere kernel: pair index out of range")
        if identity:
            k = na
            u0 = Z = r = None
        else:
            u0, Z, r = _c(u0), _c(Z), _c(r)
            k = Z.shape[2]
            if u0.shape != (F, na) or Z.shape != (F, na, k) or r.shape != (F,):
                raise ValueError("sphere kernel: inconsistent face shapes")
        skip_hi = skip_lo = None
        if skip is not None:
            skip_hi, skip_lo = (_c(np.broadcast_to(x, (F,))) for x in skip)
        vmax, vmin, vhi, vlo = (np.empty(F) for _ in range(4))
        umax, umin = np.empty((F, na)), np.empty((F, na))
        if F == 0:
            return vmax, umax, vmin, umin, vhi, vlo

        def run(lo, hi):
            return self._faces(
                int(hi - lo), na, k, m, _row(pair, lo), _row(u0, lo), _row(Z, lo),
                _row(r, lo), A.ctypes.data, g.ctypes.data, c.ctypes.data, cond.ctypes.data,
                float(feas_tol), _row(skip_hi, lo), _row(skip_lo, lo), _row(vmax, lo),
                _row(umax, lo), _row(vmin, lo),
                _row(umin, lo), _row(vhi, lo), _row(vlo, lo))

        n_threads = max(1, min(workers, F)) if pool is not None else 1
        if n_threads == 1:
            status = [run(0, F)]
        else:
            edges = np.linspace(0, F, n_threads + 1).astype(int)
            status = list(pool.map(run, edges[:-1], edges[1:]))
        if any(s != 0 for s in status):
            raise ValueError(f"sphere kernel: n_a = {na} with face dimension {k}")
        return vmax, umax, vmin, umin, vhi, vlo
