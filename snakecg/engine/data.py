"""One model's data: every workspace of the engine's steps, in the manner of Pinocchio's
``Data``.

The model (:class:`~snakecg.SceneModel`) is immutable: its parameters, its compiled library,
its sizes. Everything a step writes or derives once and reuses lives in a :class:`Data`:

* the forward step's one-sample buffers: the input vector ``(q, v, tau, q_obj, v_obj, f_obj,
  rho)``, the output row and the pointer arrays the C reads, built once;
* ``derived``: the constants the feature steps derive from the model on first use and reuse
  (optimize's defaults, the simulation's constants and placement arguments, the contact
  check's shapes, the shape search's problems), by step name;
* ``simulation_pool``: the compiled simulation's workspaces (buffers and C structs), lent to
  one run at a time.

**Threads.** One :class:`Data` per thread: ``model.data()`` is the model's own, which a call
uses when it is free (the forward step takes it under a non-blocking lock; a second thread
that finds it busy makes a fresh one, so sharing a model between threads is safe but slower);
a thread that calls at a high rate makes its own with ``model.create_data()`` and passes it as
``data=``. Nothing is kept at module level or on the model's ``__dict__``.
"""

from __future__ import annotations

import threading

import numpy as np

from .binding import Call, address, int64s, pointers
from .layout import INPUTS, Layout

__all__ = ["Data"]


class Data:
    """The workspaces of one caller of a :class:`~snakecg.SceneModel` (Pinocchio's ``Data``;
    see the module doc): the forward step's one-sample buffers, the feature steps' derived
    constants and the simulation's workspaces. One per thread: ``model.create_data()``, passed
    as ``data=``; ``model.data()`` is the model's own."""

    __slots__ = ("n_coordinates", "n_joints", "inputs", "q", "tau", "out", "call",
                 "call_address", "lock", "owner", "derived", "simulation_pool", "_pointers",
                 "_strides")

    def __init__(self, layout: Layout):
        ns, na = layout.n_coordinates, layout.n_joints
        sizes = {"q": ns, "v": ns, "tau": na, "q_obj": 3, "v_obj": 3, "f_obj": 3, "rho": 2}
        self.n_coordinates, self.n_joints = ns, na
        self.inputs = np.zeros(sum(sizes.values()))  # v, v_obj, f_obj stay 0 (at rest)
        offsets, k = {}, 0
        for name in INPUTS:
            offsets[name] = k
            k += sizes[name]
        self.q = self.inputs[offsets["q"]: offsets["q"] + ns]
        self.tau = self.inputs[offsets["tau"]: offsets["tau"] + na]
        base = self.inputs.ctypes.data
        # q_obj NULL: the C places the object from q
        self._pointers = pointers(0 if name in ("q_obj", "rho") else base + 8 * offsets[name]
                                  for name in INPUTS)
        self._strides = int64s(len(INPUTS))  # zero: one sample
        self.out = np.zeros(layout.out_width)
        self.call = Call(1, 0, 0, 0, address(self._pointers), address(self._strides),
                         self.out.ctypes.data)
        self.call_address = address(self.call)
        self.lock = threading.Lock()
        self.owner = None
        self.derived: dict = {}
        """What the feature steps derive from the model once, by step name."""
        self.simulation_pool: list = []
        """The compiled simulation's workspaces not lent to a run
        (:mod:`snakecg.simulate.workspace`)."""

    def bind(self, model) -> Data:
        """Point the one-sample call at ``model``'s scene vector and solver constants."""
        self.call.scene, self.call.max_iter = model.scene_address, model.max_iter
        self.call.constants = model.core.constants_address if model.core is not None else 0
        self.owner = model
        return self

    def __repr__(self) -> str:
        return f"<snakecg.Data for n_s = {self.n_coordinates}, n_a = {self.n_joints}>"
