"""The runtime core: the per-sample contact/wheel solve in compiled code.

``forward.c`` (one fixed C file of the runtime) is compiled into every model's library beside
the generated functions (:func:`snakecg.native.compile_model`); :class:`Core` calls its
``core_forward`` through ctypes. One call evaluates a whole batch: placement, the active-set
iteration of :mod:`snakecg.solver`'s rules, the conditioning and the physical checks, per
sample, with the loop in C. Samples it cannot answer exactly come back marked for the
reference path (:mod:`snakecg.rows`, :mod:`snakecg.solver`).

:class:`Data` is the workspace of one caller, in the manner of Pinocchio's ``Data``: the
one-sample input and output buffers with their addresses, built once. A model holds a default
one, used under a non-blocking lock (a second thread that finds it busy gets a fresh one), so
models are safe to share between threads without hidden thread-local state.
"""

from __future__ import annotations

import ctypes
import threading

import numpy as np

from ..rows import WEAK
from ..solver import FORCE_LIMIT, PIVOT_TOL, REL_TOL
from .layout import INPUTS, Layout
from .segment import contact_depth_function, segment_functions
from .optimal import OptimalKernel
from .sphere import SphereKernel

__all__ = ["Core", "Data", "Layout", "CONSTANTS", "STATUS_EXACT", "STATUS_FALLBACK"]

#: Pivot ratio below which the mass matrix counts as numerically singular (snakecg.rows.finish).
MASS_TOL = 1e-13
#: Rounding allowed in the physical checks (norms >= 0, 0 <= sr <= 1; snakecg.rows._sane).
SANE_TOL = 1e-12
#: The solver constants passed to the C, in the order of its ``sc_constants``.
CONSTANTS = np.array([PIVOT_TOL, WEAK, REL_TOL, MASS_TOL, SANE_TOL, FORCE_LIMIT])
STATUS_EXACT, STATUS_FALLBACK = 0, 1

_P = ctypes.c_void_p
_I = ctypes.c_longlong


class Core:
    """``core_forward`` of one compiled model library."""

    def __init__(self, lib: ctypes.CDLL, manifest: dict):
        self.forward_only(lib, manifest)
        (self.integrate_segment, self.mode_samples, self.settle,
         self.run) = segment_functions(lib, manifest["prefix"])
        """integrate.c's ``core_integrate_segment`` and ``core_mode_samples``, settle.c's
        ``core_settle``, run.c's ``core_run`` (:mod:`snakecg.core.segment`)."""
        self.contact_depth = contact_depth_function(lib, manifest["prefix"])
        """integrate.c's ``core_contact_depth``: the simulation's contact check at states."""
        self.sphere = SphereKernel(lib, manifest["prefix"])
        """sphere.c's faces and KKT candidates (:mod:`snakecg.core.sphere`)."""
        self.optimal = OptimalKernel(lib, manifest["prefix"])
        """optimal.c's one-call optimal-torque query (:mod:`snakecg.core.optimal`)."""

    @classmethod
    def forward_library(cls, lib: ctypes.CDLL, manifest: dict) -> Core:
        """The core of a library that has forward.c alone (a spatial model's contact
        library): ``core_forward`` and the state rule, nothing of the simulation."""
        core = cls.__new__(cls)
        core.forward_only(lib, manifest)
        return core

    def forward_only(self, lib: ctypes.CDLL, manifest: dict) -> None:
        """Bind forward.c's functions (:meth:`forward_library`, and the first step of the
        constructor)."""
        self.layout = Layout.of(manifest)
        fn = getattr(lib, f"{manifest['prefix']}core_forward")
        fn.argtypes = [_I, _P, _P, _I, _P, _P, _P]
        fn.restype = ctypes.c_int
        self._fn = fn
        packed = getattr(lib, f"{manifest['prefix']}core_forward_call")
        packed.argtypes = [_P]
        packed.restype = ctypes.c_int
        self.call_packed = packed
        """``core_forward_call(&call)``: the same with the arguments in a :class:`Call`."""
        rules = getattr(lib, f"{manifest['prefix']}core_next_states")
        rules.argtypes = [_P, _P, _P, _P, _P, ctypes.c_double]
        rules.restype = ctypes.c_int
        self._rules = rules
        self._constants = CONSTANTS.copy()
        self.constants_address = self._constants.ctypes.data

    def next_states(self, state, lam, w, G, bounds) -> tuple[np.ndarray, bool]:
        """The C's row-state update for one sample (the rules of
        :func:`snakecg.solver._violations` with its tolerances): the next states and whether
        a row moved. For tests; the solve itself runs inside :meth:`__call__`."""
        nc = self.layout.n_constraints
        st = np.array(state, dtype=float).reshape(nc)
        arrays = [np.ascontiguousarray(x, dtype=float) for x in (lam, w, G, bounds)]
        if [a.size for a in arrays] != [nc, nc, nc * nc, nc]:
            raise ValueError(f"next_states takes n_c = {nc} rows")
        G_col = np.asfortranarray(arrays[2].reshape(nc, nc))  # column-major, as generated
        moved = self._rules(st.ctypes.data, arrays[0].ctypes.data, arrays[1].ctypes.data,
                            G_col.ctypes.data, arrays[3].ctypes.data, REL_TOL)
        return st.astype(np.int8), bool(moved)

    def __call__(self, n: int, scene_address: int, max_iter: int, inputs_address: int,
                 strides_address: int, out_address: int) -> int:
        """One C call over ``n`` samples (releases the GIL); the C's status (0, -1 out of
        memory, ``-(2 + i)`` bad input at sample ``i``)."""
        return self._fn(n, scene_address, self.constants_address, max_iter, inputs_address,
                        strides_address, out_address)


class Call(ctypes.Structure):
    """The arguments of one ``core_forward`` call, for ``core_forward_call``."""

    _fields_ = [("n", _I), ("scene", _P), ("constants", _P), ("max_iter", _I), ("inputs", _P),
                ("strides", _P), ("out", _P)]


class Data:
    """The workspace of one caller of a :class:`~snakecg.SceneModel` (Pinocchio's ``Data``):
    the one-sample input buffer (``q, v, tau, q_obj, v_obj, f_obj, rho``), the output row and
    the pointer arrays the C reads, built once. Create one per thread with
    ``model.create_data()`` and pass it as ``data=``; a model used without one takes its
    default workspace when free and a fresh one otherwise."""

    __slots__ = ("n_coordinates", "n_joints", "inputs", "q", "tau", "out", "call",
                 "call_address", "lock", "owner", "_pointers", "_strides")

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
        self._pointers = (_P * len(INPUTS))(*[0 if name in ("q_obj", "rho")
                                              else base + 8 * offsets[name] for name in INPUTS])
        self._strides = (_I * len(INPUTS))()  # zero: one sample
        self.out = np.zeros(layout.out_width)
        self.call = Call(1, 0, 0, 0, ctypes.addressof(self._pointers),
                         ctypes.addressof(self._strides), self.out.ctypes.data)
        self.call_address = ctypes.addressof(self.call)
        self.lock = threading.Lock()
        self.owner = None

    def bind(self, model) -> Data:
        """Point the one-sample call at ``model``'s scene vector and solver constants."""
        self.call.scene, self.call.max_iter = model.scene_address, model.max_iter
        self.call.constants = model.core.constants_address if model.core is not None else 0
        self.owner = model
        return self

    def __repr__(self) -> str:
        return f"<snakecg.Data for n_s = {self.n_coordinates}, n_a = {self.n_joints}>"
