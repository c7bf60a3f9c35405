"""The runtime core: the per-sample contact/wheel solve in compiled code.

``forward.c`` (one fixed C file of the runtime) is compiled into every model's library beside
the generated functions (:func:`snakecg.native.compile_model`); :class:`Core` calls its
``core_forward`` (bound in :mod:`snakecg.engine.binding`). One call evaluates a whole batch: placement, the active-set
iteration of :mod:`snakecg.solver`'s rules, the conditioning and the physical checks, per
sample, with the loop in C. The samples its fast path cannot answer exactly (dependent or weak
held rows, no convergence, a singular mass matrix) are answered in C too, by ``rows.c``: their
status is the code of :data:`snakecg.engine.rules.REASONS` (1: answered exactly there).

:class:`~snakecg.engine.data.Data` (:mod:`snakecg.engine.data`) is the workspace of one
caller, in the manner of Pinocchio's ``Data``.
"""

from __future__ import annotations

import numpy as np

from .binding import Library
from .data import Data
from .layout import Layout
from .optimal import OptimalKernel
from .rules import CONSTANTS, REL_TOL, STATUS_EXACT, STATUS_FALLBACK
from .sphere import SphereKernel

__all__ = ["Core", "Data", "Layout", "CONSTANTS", "STATUS_EXACT", "STATUS_FALLBACK"]


class Core:
    """The engine's entry points in one compiled model library (a
    :class:`~snakecg.engine.binding.Library`)."""

    def __init__(self, lib: Library, manifest: dict):
        self.forward_only(lib, manifest)
        self.integrate_segment, self.mode_samples, self.settle, self.run = (
            lib.entry_or_none(name) for name in ("core_integrate_segment", "core_mode_samples",
                                                 "core_settle", "core_run"))
        """integrate.c's ``core_integrate_segment`` and ``core_mode_samples``, events.c's
        ``core_settle``, run.c's ``core_run``."""
        self.scene_solve = lib.entry_or_none("core_scene_solve")
        """scene_solve.c's ``core_scene_solve``: the exact solve of general scenes' samples."""
        self.scene_forward, self.scene_forward_call = (
            lib.entry_or_none(name) for name in ("core_scene_forward", "core_scene_forward_call"))
        """scene_rows.c's ``core_scene_forward``: a general scene's forward solve of a batch
        (``core_scene_forward_call``: the same with its arguments in a ``SceneCall``)."""
        self.scene_rows, self.scene_gaps = (
            lib.entry_or_none(name) for name in ("core_scene_rows", "core_scene_gaps"))
        """scene_rows.c's ``core_scene_rows`` and ``core_scene_gaps``: a general scene's rows,
        and its pairs' distances, at a simulation's state (a ``SceneStateCall``)."""
        self.scene_place, self.scene_place_q = (
            lib.entry_or_none(name) for name in ("core_scene_place", "core_scene_place_q"))
        """scene_place.c's ``core_scene_place``: a general scene's objects placed at link
        poses (the placement of its forward); ``core_scene_place_q``: the same at one
        configuration (its link poses taken there)."""
        self.scene_step = lib.entry_or_none("core_scene_step")
        """scene_step.c's ``core_scene_step``: one time step of a general scene (a
        ``SceneStep``)."""
        self.scene_run, self.scene_run_batch, self.scene_law = (
            lib.entry_or_none(name) for name in ("core_scene_run", "core_scene_run_batch",
                                                 "core_scene_law"))
        """scene_run.c's ``core_scene_run``: a general scene's run, many steps per call (a
        ``SceneRunCall``), ``core_scene_run_batch``: many runs to their ends, and
        ``core_scene_law``: a torque law the runs evaluate (the serpenoid PD law's home)."""
        self.scene_solve_b = lib.entry_or_none("core_scene_solve_b")
        """scene_solve.c's ``core_scene_solve_b``: the same with row offsets (``w = A a + c``),
        the velocity-level step of :mod:`snakecg.scenes.stepping`."""
        self.scene_solve_s = lib.entry_or_none("core_scene_solve_s")
        """scene_solve.c's ``core_scene_solve_s``: one sample of ``core_scene_solve_b``, its
        active set tried first from given pieces (a time step's: the last step's)."""
        self.scene_primal = lib.entry_or_none("core_scene_primal")
        """scene_primal.c's ``core_scene_primal(mode, counts)``: the warm start's primal piece
        switched on (1: the snake alone's fastest copy, with FMA where the processor has it,
        within rounding of the others; 2: its plain copy; 3: its AVX copy, bit for bit the
        plain one) or off (0) for the process, and this thread's tries and answers."""
        self.scene_tiny = lib.entry_or_none("core_scene_tiny")
        """scene_tiny.c's ``core_scene_tiny(mode, counts)``: the solve compiled for tiny problems
        switched on (1: with FMA where the processor has AVX2 and FMA, within rounding of the
        plain copy; 2: its plain copy) or off (0) for the process, and the problems it tried
        and answered."""
        self.contact_depth, self.contact_first = (
            lib.entry_or_none(name) for name in ("core_contact_depth", "core_contact_first"))
        """geometry.c's ``core_contact_depth``: the simulation's contact check at states;
        ``core_contact_first``: the first state beyond a tolerance."""
        self.sphere = SphereKernel(lib)
        """sphere.c's faces and KKT candidates (:mod:`snakecg.engine.sphere`)."""
        self.optimal = OptimalKernel(lib, self.layout)
        """The optimal-torque queries in one call per batch (:mod:`snakecg.engine.optimal`)."""

    @classmethod
    def forward_library(cls, lib: Library, manifest: dict) -> Core:
        """The core of a library that has contact.c and forward.c alone (a spatial scene's
        contact library): ``core_forward`` and the state rule, nothing of the simulation or
        the optimal-torque queries."""
        core = cls.__new__(cls)
        core.forward_only(lib, manifest)
        return core

    def forward_only(self, lib: Library, manifest: dict) -> None:
        """Bind forward.c's entry points (:meth:`forward_library`, and the first step of the
        constructor)."""
        self.layout = Layout.of(manifest)
        self._fn = lib.entry("core_forward")
        self.call_packed = lib.entry("core_forward_call")
        """``core_forward_call(&call)``: the same with the arguments in a :class:`Call`."""
        self._rules = lib.entry("core_next_states")
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
