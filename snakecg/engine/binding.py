"""The one binding of the compiled engine: every ``ctypes`` use of snakecg's runtime.

A model's shared library holds the generated functions (their batched drivers
``<prefix>batch_<name>`` and CasADi's signature functions) and the engine's entry points
(``<prefix>core_*``, snakecg/engine/engine.h). This module loads the library, declares every
entry point's prototype (:data:`PROTOTYPES`) and mirrors every struct the C reads
(:class:`Call`, :class:`Segment`, :class:`Settle`, :class:`Run`, :class:`Geometry`) field by
field. The rest of the runtime passes addresses only: numpy arrays' ``.ctypes.data``, and the
pointer and stride arrays made here (:func:`pointers`, :func:`int64s`, :func:`address`).

ctypes releases the GIL during every call, so the batches split across threads run in
parallel.
"""

from __future__ import annotations

import ctypes
from pathlib import Path

__all__ = [
    "Call",
    "Geometry",
    "Library",
    "PROTOTYPES",
    "Run",
    "SceneCall",
    "SceneStateCall",
    "SceneStep",
    "SceneRunCall",
    "SCENE_LAWS",
    "Segment",
    "Settle",
    "address",
    "copied",
    "empty_pointers",
    "int64s",
    "pointers",
]

_P = ctypes.c_void_p
_I = ctypes.c_longlong
_D = ctypes.c_double
_INT = ctypes.c_int

#: Every entry point of the engine: name (after the model's prefix) -> (argument types,
#: result type), as declared in engine.h and the file that defines it.
PROTOTYPES: dict[str, tuple[list, object]] = {
    # forward.c
    "core_forward": ([_I, _P, _P, _I, _P, _P, _P], _INT),
    "core_forward_call": ([_P], _INT),
    "core_next_states": ([_P, _P, _P, _P, _P, _D], _INT),
    # integrate.c, events.c, run.c, geometry.c
    "core_integrate_segment": ([_P], _INT),
    "core_mode_samples": ([_P, _I, _P, _P], _INT),
    "core_settle": ([_P], _INT),
    "core_run": ([_P], _INT),
    "core_contact_depth": ([_P, _I, _P, _P, _P], _INT),
    "core_contact_first": ([_P, _I, _P, _I, _D, _P], _INT),
    # pieces.c, sphere.c
    "core_pieces": ([_I] * 5 + [_P] * 20, _I),
    "core_sphere_faces": ([_I, _I, _I, _I] + [_P] * 8 + [_D] + [_P] * 8, _INT),
    "core_sphere_cut": ([_I, _I, _I, _I, _I] + [_P] * 8, _I),
    "core_sphere_meets": ([_I, _I, _I, _I] + [_P] * 6 + [_D, _P], _INT),
    # maps.c, optimal.c
    "core_state_maps": ([_P, _P, _P, _P], _INT),
    "core_optimal": ([_I, _P, _P, _I, _P, _P, _P], _INT),
    "core_optimal_check": ([_I, _P, _P], _INT),
    "core_qp_solve": ([_I, _I] + [_P] * 6 + [_D, _D, _P, _P, _P], _INT),
    "core_kkt_certificate": ([_I, _P, _P, _P, _I, _P, _P, _P, _P, _D, _I, _D, _D, _P, _P, _P],
                             _INT),
    "core_eigen_symmetric": ([_I, _P, _P, _P], _INT),
    # scene_solve.c
    "core_scene_solve": ([_I, _I, _I, _I] + [_P] * 8 + [_I] + [_P] * 5, _INT),
    # scene_rows.c
    "core_scene_forward": ([_P, _I, _P, _I, _P, _I, _P, _I, _I, _I] + [_P] * 5 + [_I], _INT),
    "core_scene_forward_call": ([_P], _INT),
    "core_scene_solve_b": ([_I, _I, _I, _I] + [_P] * 9 + [_I] + [_P] * 5, _INT),
    "core_scene_solve_s": ([_I, _I, _I] + [_P] * 7 + [_I] + [_P] * 6, _INT),
    # scene_primal.c (the warm start's primal piece: its switch and counts, for measurement)
    "core_scene_primal": ([_I, _P], _INT),
    # scene_tiny.c (the solve compiled for tiny problems: its switch and counts, for measurement)
    "core_scene_tiny": ([_I, _P], _INT),
    "core_scene_rows": ([_P], _INT),
    "core_scene_gaps": ([_P], _INT),
    # scene_place.c
    "core_scene_place": ([_P, _I, _P, _P], _INT),
    "core_scene_place_q": ([_P, _P, _P], _INT),
    # scene_step.c, scene_run.c
    "core_scene_step": ([_P], _INT),
    "core_scene_run": ([_P], _INT),
    "core_scene_run_batch": ([_P, _I, _P], _INT),
    "core_scene_law": ([_I, _P, _D, _P, _P, _D, _P], _INT),
}
#: A generated function's batched driver: (n, inputs, strides, outputs).
_BATCH = ([_I, ctypes.POINTER(_P), ctypes.POINTER(_I), ctypes.POINTER(_P)], _INT)


class Library:
    """A model's loaded shared library: its engine entry points and batched drivers with
    their prototypes declared."""

    def __init__(self, path: Path | str, prefix: str):
        self.path = Path(path)
        self.prefix = prefix
        self._lib = ctypes.CDLL(str(path))

    def _declare(self, symbol: str, argtypes, restype):
        fn = getattr(self._lib, symbol)
        fn.argtypes, fn.restype = argtypes, restype
        return fn

    def entry(self, name: str):
        """The engine's ``<prefix><name>`` (one of :data:`PROTOTYPES`); AttributeError for a
        library built without it."""
        argtypes, restype = PROTOTYPES[name]
        return self._declare(f"{self.prefix}{name}", argtypes, restype)

    def entry_or_none(self, name: str):
        try:
            return self.entry(name)
        except AttributeError:
            return None

    def batch(self, name: str):
        """The batched driver ``<prefix>batch_<name>`` of generated function ``name``."""
        return self._declare(f"{self.prefix}batch_{name}", *_BATCH)

    def signature(self, symbol: str):
        """CasADi's signature functions of a generated function: ``n_in()``, ``n_out()`` and
        ``sparsity_in(k)``/``sparsity_out(k)`` as (rows, cols) ((-1, -1) for none)."""
        n_in = self._declare(f"{symbol}_n_in", [], _I)
        n_out = self._declare(f"{symbol}_n_out", [], _I)
        sp_in = self._declare(f"{symbol}_sparsity_in", [_I], ctypes.POINTER(_I))
        sp_out = self._declare(f"{symbol}_sparsity_out", [_I], ctypes.POINTER(_I))

        def size(fn):
            def get(k):
                p = fn(k)
                return (int(p[0]), int(p[1])) if p else (-1, -1)
            return get
        return int(n_in()), int(n_out()), size(sp_in), size(sp_out)


def pointers(values) -> ctypes.Array:
    """A C array of ``void *`` holding ``values`` (addresses; 0 or None for NULL)."""
    values = list(values)
    return (_P * len(values))(*values)


def empty_pointers(n: int) -> ctypes.Array:
    """A C array of ``n`` NULL ``void *`` (filled by the caller)."""
    return (_P * n)()


def int64s(n: int) -> ctypes.Array:
    """A C array of ``n`` zero ``long long`` (the strides of a batched call)."""
    return (_I * n)()


def copied(array: ctypes.Array) -> ctypes.Array:
    """A copy of a C array made here (a template filled per call)."""
    return type(array).from_buffer_copy(array)


def address(obj) -> int:
    """The address of a struct or C array made here."""
    return ctypes.addressof(obj)


def array_address(arr) -> int:
    """The address of a writable C-contiguous NumPy array's data (its ``ctypes.data``, read
    through the buffer protocol: about 0.3 us against 1.3 us)."""
    return ctypes.addressof(ctypes.c_char.from_buffer(arr))


class Call(ctypes.Structure):
    """The arguments of one ``core_forward`` call, for ``core_forward_call``."""

    _fields_ = [("n", _I), ("scene", _P), ("constants", _P), ("max_iter", _I), ("inputs", _P),
                ("strides", _P), ("out", _P)]


class Segment(ctypes.Structure):
    """``sc_segment`` of engine.h (integrate.c)."""

    _fields_ = [("scene", _P), ("tau", _P), ("f_obj", _P), ("rho", _P), ("state", _P),
                ("ev_kind", _P), ("ev_row", _P), ("n_ev", _I), ("contact_index", _I),
                ("c_k", _D), ("l_k", _D), ("alpha", _D), ("pivot_tol", _D),
                ("regularization", _D), ("rtol", _D), ("atol", _D), ("max_step", _D),
                ("t0", _D), ("t1", _D), ("y0", _P), ("t_eval", _P), ("n_eval", _I),
                ("geo", _P), ("budget", _D), ("resume", _I), ("y_eval", _P), ("n_out", _I),
                ("t_end", _D), ("y_end", _P), ("event", _I), ("nfev", _I), ("nsteps", _I),
                ("nrejected", _I), ("nsingular", _I), ("h_next", _D), ("status", _I)]


class SceneCall(ctypes.Structure):
    """The arguments of one ``core_scene_forward`` call, for ``core_scene_forward_call``
    (scene_rows.c's ``sc_scene_call``; ``keep``: the engine's scratch kept from the first
    call to the next, null at first; a call with ``n = 0`` frees it)."""

    _fields_ = [("pk", _P), ("n", _I), ("q", _P), ("sq", _I), ("tau", _P), ("st", _I),
                ("fo", _P), ("sf", _I), ("ccap", _I), ("mcap", _I), ("out", _P), ("A", _P),
                ("lam", _P), ("w", _P), ("state", _P), ("chunk", _I), ("keep", _P)]


class SceneStateCall(ctypes.Structure):
    """The arguments of ``core_scene_rows`` and ``core_scene_gaps`` (scene_rows.c's
    ``sc_scene_state``): a general scene's rows, or its pairs' distances, at a state."""

    _fields_ = [("pk", _P), ("q", _P), ("qo", _P), ("tol", _D), ("margin", _D), ("ccap", _I),
                ("mcap", _I), ("pair_a", _I), ("pair_b", _I), ("out", _P), ("M", _P),
                ("A", _P), ("par", _P), ("kind", _P), ("start", _P)]


class SceneStep(ctypes.Structure):
    """The arguments of ``core_scene_step`` (scene_step.c's ``sc_scene_step``): one time step
    of a general scene."""

    _fields_ = [("pk", _P), ("tol", _D), ("h", _D), ("impact_speed", _D), ("tau", _P),
                ("fo", _P), ("x", _P), ("V", _P), ("ccap", _I), ("mcap", _I), ("M", _P),
                ("A", _P), ("par", _P), ("out", _P), ("kind", _P), ("start", _P), ("M1", _P),
                ("A1", _P), ("par1", _P), ("out1", _P), ("kind1", _P), ("start1", _P),
                ("Vp", _P), ("lam", _P), ("info", _P), ("ilam", _P), ("iinfo", _P),
                ("acc", _P), ("status", _I), ("from_", _P), ("nfrom", _I),
                ("hold", _I), ("quick", _I)]


#: the torque laws ``core_scene_run`` and ``core_scene_law`` evaluate (scene_run.c's LAW_*)
SCENE_LAWS = {"constant": 0, "table": 1, "hold": 2, "serpenoid_pd": 3, "caller": 4}


class SceneRunCall(ctypes.Structure):
    """The arguments of ``core_scene_run`` (scene_run.c's ``sc_scene_run``): a general
    scene's run, many steps per call."""

    _fields_ = [("st", _P), ("gs", _P), ("gcap", _I), ("duration", _D), ("dt", _D),
                ("h_min", _D), ("tau_limit", _D), ("law", _I), ("nlp", _I), ("lp", _P),
                ("every", _I), ("rec", _P), ("cap", _I), ("nrec", _I), ("pause", _I),
                ("stop_at_impacts", _I), ("work", _P), ("t", _D), ("nstep", _I),
                ("phase", _I), ("impacts", _I), ("min_gap", _D), ("bad", _D * 5),
                ("geo", _P), ("geo_tol", _D), ("nkept", _I), ("geo_k", _I), ("geo_pair", _I),
                ("geo_depth", _D)]


class Geometry(ctypes.Structure):
    """``sc_geometry`` of engine.h (geometry.c): the contact check of a run."""

    _fields_ = [("mode", _I), ("tol", _D), ("half", _D), ("radius", _D), ("length", _P),
                ("com1", _D), ("found", _I), ("t", _D), ("depth", _D), ("pair", _I),
                ("y", _P)]


class Settle(ctypes.Structure):
    """``sc_settle`` of engine.h (events.c)."""

    _fields_ = [("scene", _P), ("tau", _P), ("f_obj", _P), ("rho", _P), ("contact_index", _I),
                ("c_k", _D), ("l_k", _D), ("pivot_tol", _D), ("rel_tol", _D),
                ("regularization", _D), ("max_iter", _I), ("y", _P), ("prev", _P), ("forced", _P),
                ("contact_candidate", _I), ("vtol", _D), ("y_out", _P), ("state", _P),
                ("forced_out", _P), ("impact", _I), ("impact_velocity", _D),
                ("impact_ke", _D), ("impact_de", _D), ("impact_lam", _P), ("n_impact", _I),
                ("n_projected", _I), ("drift", _D), ("drift_row", _I),
                ("projection_ke", _D), ("projection_de", _D), ("projection_lam", _P),
                ("nsingular", _I), ("status", _I)]


class Run(ctypes.Structure):
    """``sc_run`` of run.c."""

    _fields_ = [("sg", _P), ("st", _P), ("T", _D), ("gtol", _D), ("grid", _P),
                ("n_grid", _I), ("max_events", _I), ("t", _D), ("y", _P), ("off_link", _I),
                ("loss", _D), ("cap", _I), ("t_out", _P), ("y_out", _P), ("mode_out", _P),
                ("loss_out", _P), ("n_out", _I), ("cap_modes", _I), ("modes", _P),
                ("n_modes", _I), ("cap_events", _I), ("events", _P), ("n_events", _I),
                ("stuck", _I), ("samples", _P), ("segments", _I), ("nfev", _I), ("nsteps", _I),
                ("nsingular", _I), ("segment_cpu", _D), ("start", _I), ("start_out", _P),
                ("budget", _D), ("resume", _I), ("mode", _I), ("i0", _I), ("n_sampled", _I),
                ("status", _I)]
