"""A generated function bound to fixed inputs and evaluated on one sample through
preallocated buffers (:class:`BoundFunction`): the one-sample calls of the simulator's event
handling and the optimiser, where the general path's per-call numpy and ctypes overhead
would dominate the C."""

from __future__ import annotations

import numpy as np

from .engine.binding import int64s, pointers
from .errors import BuildError
from .kernels import outputs_type

__all__ = ["BoundFunction"]


class BoundFunction:
    """A generated function bound to fixed inputs, evaluated on one sample (``one``) through
    preallocated buffers and the compiled batch driver (about 1 us a call instead of ~40 us
    for the general-purpose path), or on ``n`` samples (``many``) through the backend.

    Outputs are given in their logical shapes: ``(rows,)`` for a column, ``(rows, cols)``
    otherwise (``many``: with a leading ``n``), as :class:`~snakecg.kernels.Outputs`
    (``out["lam"]``; positional indexing still works).
    """

    def __init__(self, backend, name: str, constants: dict[str, np.ndarray]):
        sig = backend.signatures[name]
        self.name = name
        self.backend = backend
        self.in_names = list(sig.in_names)
        self.in_sizes = dict(zip(sig.in_names, sig.in_sizes))
        self.out_shapes = list(sig.out_shapes)
        self.out_names = list(sig.out_names)
        self._outputs = outputs_type(name, sig.out_names)
        self.const = {k: np.ascontiguousarray(np.ravel(np.asarray(v, dtype=float)))
                      for k, v in constants.items()}
        fns = getattr(backend, "_fns", None)
        self._fast = None
        self._last: dict[str, np.ndarray] = {}
        if getattr(backend, "kind", None) == "compiled" and isinstance(fns, dict) and name in fns:
            bufs = {}
            for k in self.in_names:
                bufs[k] = (self.const[k].copy() if k in self.const
                           else np.zeros(self.in_sizes[k]))
            outs = [np.zeros(r * c) for r, c in self.out_shapes]
            self._bufs = bufs
            self._argp = pointers(bufs[k].ctypes.data for k in self.in_names)
            self._strides = int64s(len(bufs))  # all zero: one sample
            self._resp = pointers(o.ctypes.data for o in outs)
            self._outs = outs
            self._views = self._outputs([o if c == 1 else o.reshape(c, r).T
                                         for (r, c), o in zip(self.out_shapes, outs)])
            self._fast = fns[name]

    def set(self, **var) -> None:
        """Set inputs of the one-sample buffers (or the constants of the general path)."""
        for k, val in var.items():
            if self._fast is not None:
                self._bufs[k][:] = val
            else:  # (and no longer the value the last one-sample call was given)
                self.const[k] = np.ascontiguousarray(np.ravel(np.asarray(val, dtype=float)))
                self._last.pop(k, None)

    def one(self, **var):
        """Evaluate on one sample; the returned arrays are overwritten by the next call."""
        if self._fast is not None:
            bufs = self._bufs
            for k, val in var.items():
                bufs[k][:] = val
            status = self._fast(1, self._argp, self._strides, self._resp)
            if status != 0:
                raise BuildError(f"{self.name}: evaluation failed (status {status})")
            return self._views
        self._last.update(var)
        outs = self.many(1, **self._last)
        return self._outputs([o[0] for o in outs])

    def many(self, n: int, **var):
        args = []
        for k in self.in_names:
            a = var[k] if k in var else self.const[k]
            a = np.ascontiguousarray(a, dtype=float)
            if a.ndim > 1:
                a = a.reshape(a.shape[0], -1)
            args.append(a)
        outs = self.backend(self.name, n, args)
        res = []
        for (r, c), o in zip(self.out_shapes, outs):
            res.append(np.ascontiguousarray(o[:, :, 0]) if c == 1 else np.ascontiguousarray(o))
        return self._outputs(res)
