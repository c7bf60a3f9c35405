"""One configuration in one compiled call: the common queries answered by the runtime core's
``optimal.c`` (:mod:`snakecg.core.optimal`) on the all-held maps, which ``maps.c`` builds in
the same call from the generated ``place_object`` and ``contact_system`` (the code the forward
check runs next; the same maps as ``interaction_maps`` to rounding), and that ends with the
exact forward solve at the answer (``core_forward``, as :meth:`SceneModel.forward` runs it).

The C performs what the Python path does for the same cases (``max_sr`` with every wheel
sticking in its rank-one closed form; the push tasks with box limits only by the dense dual
active set), with the same certificate on the original problem; the answer then goes through
the same forward check (:mod:`snakecg.optimize.finish`). Anything
else — a structural infeasibility, a closed form that does not apply, the active set giving
up, a certificate that fails or needs non-negative least squares, a busy workspace, a model
without compiled code — returns None, and the Python path answers the query from the start
(with its words for the reason, and its cold re-solve)."""

from __future__ import annotations

import ctypes
import threading

import numpy as np

from ..core import STATUS_EXACT
from ..core.optimal import OUT
from ..solver import PIVOT_TOL
from .certificate import TOLERANCE
from .fast import wheels
from .finish import one_result
from .problems import Answer
from .result import CONTACT, ELLIPSOID, Certificate, joint_name
from .solvers import _COLD

__all__ = ["quick"]

_KEY = "_snakecg_optimize_quick"
_NO_SLIDE = "_snakecg_optimize_no_slide"  # query.validate's shared "nothing slides"


class _Workspace:
    """The ``op_call`` of one model: its scene vector, the configuration's buffer, the maps'
    buffer, the model's bounded wheels, the query's buffers and the output vector."""

    def __init__(self, model):
        from ..core.optimal import MAX_DIM, Query, maps_size

        n, nc = model.n_joints, model.n_constraints
        if n > MAX_DIM:
            raise LookupError("too many joints for the compiled query")
        wl = wheels(model)
        self.qbuf = np.zeros(model.n_coordinates)
        self.maps = np.zeros(maps_size(n, nc))
        self.wheel_row = np.array([i for i, _, _ in wl], dtype=np.int64)
        self.wheel_ub = np.array([ub for _, ub, _ in wl], dtype=float)
        sc = model.scene
        self.Io = np.array([sc.object_mass, sc.object_mass, sc.object_inertia], dtype=float)
        self.tau_max = np.zeros(n)
        self.direction = np.zeros(3)
        self.a_obj = np.zeros(3)
        self.out = np.zeros(OUT["tau"] + 2 * n + 3 + len(wl) + 8)
        self.row = np.zeros(model.columns.width)  # the forward solve's result row
        # model.scene_address stays valid: this workspace lives in the model's __dict__
        self.q = Query(0, n, nc, len(wl), model.scene_address, self.qbuf.ctypes.data,
                       self.maps.ctypes.data, self.wheel_row.ctypes.data,
                       self.wheel_ub.ctypes.data, self.Io.ctypes.data, PIVOT_TOL, 0.0, None,
                       None, 0.0, None, self.out.ctypes.data, model.core.constants_address,
                       model.max_iter, self.row.ctypes.data)
        self.status = model.columns.status
        self.address = ctypes.addressof(self.q)
        self.call = model.core.optimal.call
        self.tau_max_address = self.tau_max.ctypes.data
        self.direction_address = self.direction.ctypes.data
        self.a_obj_address = self.a_obj.ctypes.data
        # binding codes to names (snakecg.core.optimal): task, contact, ellipsoid, joints, wheels
        self.names = (["", CONTACT, ELLIPSOID] + [joint_name(j + 1) for j in range(n)]
                      + [name for _, _, name in wl])
        self.n = n
        self.lock = threading.Lock()


# certificate._verdict's tolerances (the C's residuals are >= 0 except the gap)
_TOL_ST, _TOL_PF, _TOL_CO, _TOL_GAP = (TOLERANCE[k] for k in (
    "stationarity", "primal_feasibility", "complementarity", "duality_gap"))
_KINDS = {"max_sr": 0, "least_slip_push": 1, "strongest_push": 2}
_T = OUT["tau"]
_FORWARD = OUT["forward"]


def _workspace(model):
    ws = model.__dict__.get(_KEY)
    if ws is None:
        try:
            if model.core is None:
                raise LookupError("no compiled runtime core")
            ws = _Workspace(model)
        except (LookupError, AttributeError):
            ws = False  # this model answers every query on the Python path
        model.__dict__[_KEY] = ws
    return ws


def _vector(buf, address, value):
    """The address of ``value`` copied into ``buf``; None (a null pointer) when the query has
    no such value."""
    if value is None:
        return None
    buf[:] = value
    return address


def quick(model, query, q, t0):
    """The :class:`~snakecg.optimize.OptimizeResult` of one configuration ``q`` answered by
    the compiled query, or None (the Python path then answers)."""
    objective = query.objective
    if objective == "max_sr":
        if query.slide is not model.__dict__.get(_NO_SLIDE) and query.slide.any():
            return None
    elif query.tau_max is None or query.radius is not None:
        return None
    if _COLD.get() is not None:
        return None
    ws = _workspace(model)
    if not ws or not ws.lock.acquire(False):
        return None
    try:
        ws.qbuf[:] = q
        c = ws.q
        c.kind = _KINDS[objective]
        c.radius = query.radius if query.radius is not None else 0.0
        c.tau_max = _vector(ws.tau_max, ws.tau_max_address, query.tau_max)
        c.direction = _vector(ws.direction, ws.direction_address, query.direction)
        c.a_min = query.a_min if query.a_min is not None else 0.0
        c.a_obj = _vector(ws.a_obj, ws.a_obj_address, query.a_obj)
        if ws.call(ws.address) != 0:
            return None
        out = ws.out.tolist()
        # the forward solve at the answer ran in the same call (core_forward, as
        # SceneModel.forward runs it); a row it left to the reference path goes there
        raw = (ws.row.copy() if out[_FORWARD] == 0 and ws.row[ws.status] == STATUS_EXACT
               else None)
    finally:
        ws.lock.release()
    n = ws.n
    if objective == "max_sr":
        kind, solver, iters, claim = ("generalized eigenproblem",
                                      "generalized eigenproblem (rank-one closed form)", 0,
                                      ("eigen",))
    elif objective == "least_slip_push":
        kind, solver, iters = "kkt (convex QP)", "dual active set", 1
        claim = ("push", out[13], query.a_obj is not None, False)
    else:
        kind, solver, iters = "kkt (LP)", "dual active set (LP)", 1
        if out[11]:
            solver += "; least-slip tie-break dual active set"
            iters += 1
        claim = ("push", None, False, True)
    st, pf, co, gap = out[6:10]
    if not (abs(st) <= _TOL_ST and abs(pf) <= _TOL_PF and abs(co) <= _TOL_CO
            and abs(gap) <= _TOL_GAP):
        return None  # the Python path: the same answer and certificate, then a cold re-solve
    cert = Certificate(kind, True, st, pf, co, gap, _TOL_ST, False, "")
    names = ws.names
    nb = int(out[12])
    binding = tuple(dict.fromkeys(
        nm for nm in (names[int(b)] for b in out[_T + n:_T + n + nb]) if nm))
    a = Answer(np.array(out[_T:_T + n]), "optimal", "", binding, solver, iters, out[1],
               claim=claim)
    e = out[10] if query.radius is not None else None
    return one_result(model, query, q, a, cert, out[3:6], e, t0, raw)
