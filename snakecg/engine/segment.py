"""The codes of ``integrate.c``, ``events.c`` and ``run.c`` (one integration segment of a
simulation, what happens at an event, a whole run with a constant torque), as engine.h and
run.c define them. Their structs and entry points are bound in :mod:`snakecg.engine.binding`;
the caller (:mod:`snakecg.simulate.compiled`) owns the arrays whose addresses it stores in
them.
"""

from __future__ import annotations

__all__ = [
    "EVENT_CODES",
    "SEG_BAD_INPUT",
    "SEG_END",
    "SEG_EVENT",
    "SEG_MEMORY",
    "SEG_PAUSED",
    "SEG_FAILED",
    "SEG_TOO_SMALL",
    "GEO_OFF",
    "GEO_RECORD",
    "GEO_STOP",
    "PAUSE_AFTER",
    "RUN_COMPLETED",
    "RUN_GEOMETRY",
    "RUN_PAUSED",
    "RUN_STOPPED",
    "SEG_GEOMETRY",
    "SETTLE_DONE",
    "SETTLE_FAILED",
    "SETTLE_MEMORY",
    "RUN_FAILED",
    "RUN_PYTHON",
    "FAILED_REASON",
]

#: The event functions the C evaluates (``EV_*`` of integrate.c), by the ``quantity`` that
#: :meth:`snakecg.simulate.events.Events.functions` gives each of its functions.
EVENT_CODES = {"lam_contact": 0, "s": 1, "l_k - s": 2, "gap": 3, "bound - |lam|": 4,
               "sliding velocity": 5}
#: Segment status (``SEG_*`` of integrate.c); ``SEG_FAILED``: an evaluation failed or a
#: derivative is not finite (the segment ends at the start of the step).
SEG_END, SEG_EVENT, SEG_TOO_SMALL, SEG_FAILED, SEG_MEMORY, SEG_BAD_INPUT = 0, 1, -1, -2, -3, -4
#: The segment stopped at the contact check's first violation (``GEO_STOP``).
SEG_GEOMETRY = 2
#: A segment or run that used up its wall-clock budget (``budget``): called again with
#: ``resume`` as the call left it, it goes on where it stopped.
SEG_PAUSED = 3
#: The contact check's modes (``SC_GEO_*`` of engine.h): off, stop at the first violation,
#: record it and go on.
GEO_OFF, GEO_STOP, GEO_RECORD = 0, 1, 2
#: Settle status (``SETTLE_*`` of events.c): done, an evaluation failed, no memory.
SETTLE_DONE, SETTLE_FAILED, SETTLE_MEMORY = 0, 1, 2
#: Run status (``RUN_*`` of run.c): completed, stopped (events), done again by the Python
#: loop over the same compiled segments (no room, a too small step, a penetrating start),
#: stopped at the contact check's first violation, paused (as SEG_PAUSED), failed (as
#: SEG_FAILED, at ``Run.t``).
RUN_COMPLETED, RUN_STOPPED, RUN_PYTHON, RUN_GEOMETRY, RUN_PAUSED, RUN_FAILED = 0, 1, 2, 3, 4, 5
#: Why a compiled segment, settle or run failed (SimulationError's message).
FAILED_REASON = ("the equations could not be evaluated in float64 or their derivative is not "
                 "finite (a numerically singular mass matrix, or a state or input too large)")
#: Wall-clock seconds a compiled segment or run goes on before it returns to Python (which
#: then handles a Ctrl-C, or calls again to go on): a long run stays interruptible.
PAUSE_AFTER = 0.1
