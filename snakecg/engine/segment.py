"""The Python side of ``integrate.c``, ``events.c`` and ``run.c``: one integration segment
of a simulation, what happens at an event, and a whole run with a constant torque, in C.

:class:`Segment` mirrors the C struct ``sc_segment`` field by field (inputs, then outputs),
:class:`Settle` ``sc_settle``, :class:`Run` ``sc_run``; :func:`segment_functions` binds
``core_integrate_segment``, ``core_mode_samples``, ``core_settle`` and ``core_run`` of a
compiled model library. The caller (:mod:`snakecg.simulate.compiled`) owns the arrays whose
addresses it stores in them.
"""

from __future__ import annotations

import ctypes

__all__ = [
    "EVENT_CODES",
    "SEG_BAD_INPUT",
    "SEG_END",
    "SEG_EVENT",
    "SEG_MEMORY",
    "SEG_PAUSED",
    "SEG_PYTHON",
    "SEG_TOO_SMALL",
    "GEO_OFF",
    "GEO_RECORD",
    "GEO_STOP",
    "Geometry",
    "PAUSE_AFTER",
    "RUN_COMPLETED",
    "RUN_GEOMETRY",
    "RUN_PAUSED",
    "RUN_STOPPED",
    "SEG_GEOMETRY",
    "contact_depth_function",
    "Run",
    "SETTLE_DONE",
    "Segment",
    "Settle",
    "segment_functions",
]

_P = ctypes.c_void_p
_I = ctypes.c_longlong
_D = ctypes.c_double

#: The event functions the C evaluates (``EV_*`` of integrate.c), by the ``quantity`` that
#: :meth:`snakecg.simulate.events.Events.functions` gives each of its functions.
EVENT_CODES = {"lam_contact": 0, "s": 1, "l_k - s": 2, "gap": 3, "bound - |lam|": 4,
               "sliding velocity": 5}
#: Segment status (``SEG_*`` of integrate.c).
SEG_END, SEG_EVENT, SEG_TOO_SMALL, SEG_PYTHON, SEG_MEMORY, SEG_BAD_INPUT = 0, 1, -1, -2, -3, -4
#: The segment stopped at the contact check's first violation (``GEO_STOP``).
SEG_GEOMETRY = 2
#: A segment or run that used up its wall-clock budget (``budget``): called again with
#: ``resume`` as the call left it, it goes on where it stopped.
SEG_PAUSED = 3
#: The contact check's modes (``SC_GEO_*`` of engine.h): off, stop at the first violation,
#: record it and go on.
GEO_OFF, GEO_STOP, GEO_RECORD = 0, 1, 2
#: Settle status (``SETTLE_*`` of events.c): done; anything else hands it to Python.
SETTLE_DONE = 0
#: Run status (``RUN_*`` of run.c): completed, stopped (events), stopped at the contact
#: check's first violation, paused (as SEG_PAUSED); anything else: Python.
RUN_COMPLETED, RUN_STOPPED, RUN_GEOMETRY, RUN_PAUSED = 0, 1, 3, 4
#: Wall-clock seconds a compiled segment or run goes on before it returns to Python (which
#: then handles a Ctrl-C, or calls again to go on): a long run stays interruptible.
PAUSE_AFTER = 0.1


class Segment(ctypes.Structure):
    """``sc_segment`` of integrate.c."""

    _fields_ = [("scene", _P), ("tau", _P), ("f_obj", _P), ("rho", _P), ("state", _P),
                ("ev_kind", _P), ("ev_row", _P), ("n_ev", _I), ("contact_index", _I),
                ("c_k", _D), ("l_k", _D), ("alpha", _D), ("pivot_tol", _D), ("rtol", _D),
                ("atol", _D), ("max_step", _D), ("t0", _D), ("t1", _D), ("y0", _P),
                ("t_eval", _P), ("n_eval", _I), ("geo", _P), ("budget", _D), ("resume", _I),
                ("y_eval", _P), ("n_out", _I), ("t_end", _D), ("y_end", _P), ("event", _I),
                ("nfev", _I), ("nsteps", _I), ("nrejected", _I), ("h_next", _D), ("status", _I)]


class Geometry(ctypes.Structure):
    """``sc_geometry`` of engine.h: the contact check of a run (mode ``GEO_*``)."""

    _fields_ = [("mode", _I), ("tol", _D), ("half", _D), ("radius", _D), ("length", _P),
                ("com1", _D), ("found", _I), ("t", _D), ("depth", _D), ("pair", _I),
                ("y", _P)]


class Settle(ctypes.Structure):
    """``sc_settle`` of events.c."""

    _fields_ = [("scene", _P), ("tau", _P), ("f_obj", _P), ("rho", _P), ("contact_index", _I),
                ("c_k", _D), ("l_k", _D), ("pivot_tol", _D), ("rel_tol", _D),
                ("max_iter", _I), ("y", _P), ("prev", _P), ("forced", _P),
                ("contact_candidate", _I), ("vtol", _D), ("y_out", _P), ("state", _P),
                ("forced_out", _P), ("impact", _I), ("impact_velocity", _D),
                ("impact_ke", _D), ("impact_de", _D), ("impact_lam", _P), ("n_impact", _I),
                ("n_projected", _I), ("drift", _D), ("drift_row", _I),
                ("projection_ke", _D), ("projection_de", _D), ("projection_lam", _P),
                ("status", _I)]


class Run(ctypes.Structure):
    """``sc_run`` of run.c."""

    _fields_ = [("sg", _P), ("st", _P), ("T", _D), ("gtol", _D), ("grid", _P),
                ("n_grid", _I), ("max_events", _I), ("t", _D), ("y", _P), ("off_link", _I),
                ("loss", _D), ("cap", _I), ("t_out", _P), ("y_out", _P), ("mode_out", _P),
                ("loss_out", _P), ("n_out", _I), ("cap_modes", _I), ("modes", _P),
                ("n_modes", _I), ("cap_events", _I), ("events", _P), ("n_events", _I),
                ("stuck", _I), ("samples", _P), ("segments", _I), ("nfev", _I), ("nsteps", _I),
                ("segment_cpu", _D), ("start", _I), ("start_out", _P), ("budget", _D),
                ("resume", _I), ("mode", _I), ("i0", _I), ("n_sampled", _I), ("status", _I)]


def segment_functions(lib: ctypes.CDLL, prefix: str):
    """``(integrate, samples, settle, run)``: ``core_integrate_segment(&segment)``,
    ``core_mode_samples(&segment, n, Y, out)``, ``core_settle(&settle)`` and
    ``core_run(&run)`` of ``lib``, or ``None`` each for a library built without them."""
    try:
        integrate = getattr(lib, f"{prefix}core_integrate_segment")
        samples = getattr(lib, f"{prefix}core_mode_samples")
        settle = getattr(lib, f"{prefix}core_settle")
        run = getattr(lib, f"{prefix}core_run")
    except AttributeError:
        return None, None, None, None
    integrate.argtypes = [_P]
    integrate.restype = ctypes.c_int
    samples.argtypes = [_P, _I, _P, _P]
    samples.restype = ctypes.c_int
    settle.argtypes = [_P]
    settle.restype = ctypes.c_int
    run.argtypes = [_P]
    run.restype = ctypes.c_int
    return integrate, samples, settle, run


def contact_depth_function(lib: ctypes.CDLL, prefix: str):
    """``core_contact_depth(&geometry, n, Y, depth, pair)`` of ``lib`` (integrate.c: the
    largest overlap of ``n`` states and its pair), or ``None`` for a library built without
    it."""
    fn = getattr(lib, f"{prefix}core_contact_depth", None)
    if fn is not None:
        fn.argtypes = [_P, _I, _P, _P, _P]
        fn.restype = ctypes.c_int
    return fn
