"""Simulation of a general scene over time: velocity-level time stepping on the scene's exact
solve (Moreau's midpoint-free scheme as in Stewart & Trinkle 1996, Anitescu & Potra 1997),
with contact onset found by root finding and inelastic impacts.

One step of length ``h`` from ``(x, V)`` (``x = (q, q_obj)``, ``V = (v, v_obj)``, the objects'
poses and twists in the world frame) solves

    min_{V+} 1/2 (V+ - V*)^T M (V+ - V*) + sum_k h sigma_{F_k}(A_k V+)
    s.t.  A_c V+ + g_c / h >= 0   (contacts: the gap stays >= 0 to first order)
          A_w V+ = 0              (ideal wheels)

with ``V* = V + h M^-1 (B tau - bias(q, v) + f_obj)`` and ``sigma_F`` the support function of
each ground friction set (a wheel's box, Coulomb's disc, the anisotropic split ellipse: the
sets of forces ``mu m_i g``, times ``h``: impulses; ``g_c`` taken as 0 within
:data:`GAP_BAND` of the tolerance, what the previous step's first-order closing leaves, which
dependent contacts of a jammed snake could not all meet; and 0 for an overlap where pushing
it out is a jam: where the step's kinetic energy above its free motion's is more than 10^4
times the energy of pushing each overlap out alone, or where no step length converges or a
shortened step is still too short, the step holds the overlaps, counted in the run's
``held_steps``). It is the rest problem of
:mod:`snakecg.scenes.solve` with ``a -> V+``, ``f -> M V*``, the sets' sizes times ``h`` and
the rows' offsets ``c = g_c / h`` (``core_scene_solve_b``): one exact solve for rest, steps and
impacts. Stick-slip and maximum dissipation come from it (a sliding block's impulse is on
its set's boundary, opposing the sliding velocity); a contact whose impulse would pull opens.

Then ``x+ = x + h V+``. Before the step is accepted the rows at ``x+`` are found from the
geometry (every pair of bodies that can touch: non-neighbour links, links with objects and
obstacles, objects with objects and obstacles); where a pair overlaps beyond ``tolerance``
the time it reaches ``-tolerance / 4`` along the step is found by Brent's method on the
engine's distance of the pair at the interpolated state ``x + s h V+`` and the step is taken
again, shortened to it. A pair that comes within the tolerance with a closing velocity gets
an inelastic impact: the same solve with ``h = 0`` (no friction impulse at the ground, its
forces being finite; ideal wheels take impulses; with contact friction each contact's
friction impulse within ``mu`` times its normal impulse, Coulomb's law on the velocities
after) and the rows ``A V+ >= 0``, with its certificate.
The rows are found from the geometry at every step, so contact points slide along edges and
links and a box's corner can take over.

A step is the compiled engine's (``snakecg/engine/scene_step.c``: the bias forces, the solve,
the rows at the step's end, the step's energy terms, the impact). Its solve's active set starts
from the last step's pieces (each friction block held, zero or sliding at its angle, each
contact held or open; contacts matched by their bodies), which consecutive steps almost always
share; where they do not, the solve goes on as from scratch. The answer is the same (the
certificate's): the environment variable ``SNAKECG_SCENE_COLD_START=1``, read when a run
starts, makes every solve start from scratch, for comparisons. So is the run's loop
(``snakecg/engine/scene_run.c``): the torque law where the engine knows it (a constant, a
:class:`~snakecg.simulate.TorqueTable`, a :class:`~snakecg.simulate.SerpenoidPD`), the root
finding of a refused step, the record into a buffer. A call returns to Python only for a
torque law of the caller's own (evaluated here at each step), an impact's event, a full record
buffer, a pause every :data:`PAUSE_STEPS` steps (progress, Ctrl-C) and the run's end.
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass

import numpy as np

from .._inputs import all_finite
from ..engine.binding import (SCENE_LAWS, SceneRunCall, SceneStateCall, SceneStep, address,
                              array_address)
from ..engine.rules import FORCE_LIMIT
from ..errors import BuildError, InputError
from .contacts import Rows, StateRows, read_rows
from .packing import BODY_KINDS, SP_SIZE, scene_size
from .run_record import (ST_CONTACT_WORK, ST_LOSS, ST_SLIDING_COS, ST_WIDTH, ST_WORK_TAU,
                         SceneEvent, SceneRun)
from .solve import INFO

__all__ = ["SceneState", "SceneEvent", "SceneRun", "simulate_scene"]

#: a completed run's message names the gap stabilisation's work where it exceeds this share of
#: the torques' (pushing overlaps out at gap / h in steps shortened to a contact's onset)
STABILISATION_SHARE = 0.01
#: the shortest step (s) the root finding may ask for before the run stops (penetration)
H_MIN = 1e-9
#: at most this many steps per run
MAX_STEPS = 5_000_000
#: a contact closes with an impact when its normal velocity is below this (m/s)
IMPACT_SPEED = 1e-9
#: seconds of wall time between progress lines
PROGRESS_EVERY = 5.0
#: the engine's run returns after this many steps (progress lines, Ctrl-C)
PAUSE_STEPS = 20_000
#: the engine's record buffer: rows kept before the run returns to hand them over
RECORD_ROWS = 4096
#: a contact's gap within this fraction of the tolerance from zero takes no offset (the
#: engine's scene_step.c GAP_BAND)
GAP_BAND = 1e-3
#: set (to anything but "" or "0") in the environment, every step's solve starts from scratch
#: instead of from the last step's pieces (the same answer: for comparisons and checks)
COLD_START_ENV = "SNAKECG_SCENE_COLD_START"
#: why the engine's run returned (scene_run.c's RUN_*)
(RUN_END, RUN_TAU, RUN_FULL, RUN_IMPACT, RUN_PAUSE, RUN_NOT_CONVERGED, RUN_IMPACT_NOT_CONVERGED,
 RUN_REFUSED, RUN_TOO_SHORT, RUN_TRIES_OUT, RUN_BAD_TAU) = range(11)


@dataclass
class SceneState:
    """What a feedback law ``tau(t, state)`` sees: ``t``, ``q``, ``v`` (n_s), ``q_obj``,
    ``v_obj`` (n_objects, 3)."""

    t: float
    q: np.ndarray
    v: np.ndarray
    q_obj: np.ndarray
    v_obj: np.ndarray


#: functions of packages imported on first use (snakecg.simulate, snakecg.progress: importing
#: this module does not import them; an import inside every call costs about a microsecond)
_LAZY: dict = {}


def _late(name: str):
    """``torque_law``, ``check_tau`` (snakecg.simulate.torques) or ``resolve``
    (snakecg.progress), imported once."""
    got = _LAZY.get(name)
    if got is None:
        from ..progress import resolve
        from ..simulate.torques import check_tau, torque_law

        _LAZY.update(torque_law=torque_law, check_tau=check_tau, resolve=resolve)
        got = _LAZY[name]
    return got


#: the engine's step's statuses (scene_step.c; 3 and up: the rows at the step's end refused,
#: STEP_OVERLAP where two shapes overlap beyond the tolerance)
STEP_DONE, STEP_NOT_CONVERGED, STEP_IMPACT_NOT_CONVERGED, STEP_OVERLAP = 0, 1, 2, 3


class _Stepper:
    """One run's workspace for the engine's time step (``core_scene_step``,
    ``snakecg/engine/scene_step.c``): the state ``x``, ``V``, the rows at it and at a step's
    end, the solves' outputs and the run's accumulators; the pairs' distances for the root
    finding (:class:`~snakecg.scenes.contacts.StateRows`)."""

    def __init__(self, model, tol, f_obj):
        core = model.core
        if getattr(core, "scene_step", None) is None:
            raise BuildError("a general scene is simulated by the compiled engine; load it "
                             "with a C compiler (set CC) and the compiled backend")
        self.model = model
        self.engine = eng = StateRows(model, tol)
        self.ns, self.no, self.n = eng.ns, eng.no, eng.n
        n, mcap = self.n, eng.mcap
        self.x, self.V, self.Vp = np.zeros(n), np.zeros(n), np.zeros(n)
        self.tau = np.zeros(max(1, model.n_joints))
        self.fo = np.zeros(max(1, 3 * self.no))
        self.fo[:3 * self.no] = f_obj
        # the rows at x and at a step's end: two buffers each, whose roles the engine swaps
        # at every accepted step (the properties below read which is which from the struct)
        self._two = tuple((make(), make()) for make in (
            lambda: np.zeros((n, n)), lambda: np.zeros((mcap, n)), lambda: np.zeros((mcap, 3)),
            lambda: np.zeros_like(eng.out), lambda: np.zeros(mcap, dtype=np.int64),
            lambda: np.zeros(mcap, dtype=np.int64)))
        self.lam, self.ilam = np.zeros(mcap), np.zeros(mcap)
        self.info, self.iinfo = np.zeros(len(INFO)), np.zeros(len(INFO))
        self.acc = np.zeros(ST_WIDTH)
        self.acc[ST_SLIDING_COS] = -1.0
        # the last step's pieces, the next solve's start, then that step's own forces, their
        # count and its length (this run's own: a batch's runs and a run handed over in pieces
        # go on from their own)
        self.pieces = np.zeros(6 * mcap + 2)
        cold = os.environ.get(COLD_START_ENV, "") not in ("", "0")
        ad = [a.ctypes.data for a in (
            self.tau, self.fo, self.x, self.V)]
        bufs = [a.ctypes.data for a in (
            *(p[0] for p in self._two), *(p[1] for p in self._two), self.Vp, self.lam,
            self.info, self.ilam, self.iinfo, self.acc)]
        self._first = bufs[0]  # (M's first buffer: where the struct's M points, unswapped)
        self._pieces = self.pieces.ctypes.data
        self.args = SceneStep(model._pk, float(tol), 0.0, IMPACT_SPEED, *ad, eng.ccap, mcap,
                              *bufs, 0, None if cold else self._pieces, 0)
        self._address = address(self.args)
        self._step, self._place, self._x = core.scene_step, core.scene_place_q, ad[2]
        self.runner = None  # the run's loop over this step (a pooled stepper keeps its own)

    def _rows_buffers(self, end: bool) -> tuple:
        """The buffers of the rows at x (M, A, par, out, kind, start), or with ``end`` at the
        last step's end: the first or the second of each pair as the engine left them."""
        second = (self.args.M != self._first) != end
        return tuple(p[second] for p in self._two)

    M = property(lambda self: self._rows_buffers(False)[0])
    A = property(lambda self: self._rows_buffers(False)[1])
    par = property(lambda self: self._rows_buffers(False)[2])
    out = property(lambda self: self._rows_buffers(False)[3])
    kind = property(lambda self: self._rows_buffers(False)[4])
    start = property(lambda self: self._rows_buffers(False)[5])
    out1 = property(lambda self: self._rows_buffers(True)[3])

    def reset(self, f_obj) -> None:
        """Ready for a new run (a pooled stepper, :func:`_take`): the wrench on the objects,
        the run's accumulators from zero, the warm start as the environment says now; the
        rest is written by :meth:`begin` (its rows, the pieces forgotten)."""
        self.fo[:3 * self.no] = f_obj
        self.acc[:] = 0.0
        self.acc[ST_SLIDING_COS] = -1.0
        cold = os.environ.get(COLD_START_ENV, "") not in ("", "0")
        self.args.from_ = None if cold else self._pieces
        self.args.nfrom = 0
        self.args.status = 0

    def place(self, q) -> None:
        """``q`` and the objects placed by the scene at it into the state ``x`` (the engine's
        placement, ``core_scene_place_q``: :meth:`~snakecg.scenes.model.GeneralSceneModel.
        object_poses`' numbers)."""
        self.x[:self.ns] = q
        if self._place(self.model._pk, self._x, self._x + 8 * self.ns):
            raise MemoryError("the scene's placement ran out of memory")

    def begin(self, q, qo, v, vo) -> int:
        """The run's start: the state (``qo``, ``vo``: ``(n_objects, 3)`` or flat; ``qo``
        None: the objects in ``x`` as they are, from :meth:`place`; ``v``, ``vo`` None: at
        rest) and the rows found there (:meth:`call` with ``h = 0``)."""
        ns = self.ns
        self.x[:ns] = q
        if qo is not None:
            self.x[ns:] = np.asarray(qo).reshape(-1)
        self.V[:ns] = 0.0 if v is None else v
        self.V[ns:] = 0.0 if vo is None else np.asarray(vo).reshape(-1)
        return self.call(0.0)

    def call(self, h: float) -> int:
        """One step of length ``h`` from ``x``, ``V`` with the torques in ``tau`` (``h = 0``:
        the rows at ``x`` alone): its status (``STEP_*``, or the refusal of the rows at the
        step's end: 3 overlap, 4 more contacts, 6 a generated function refused)."""
        self.args.h = h
        code = self._step(self._address)
        if code != 0:
            if code == -3:  # (a run's start is checked: a step overflowed)
                raise InputError("simulate: the state is not finite: it overflowed double "
                                 "precision (torques or velocities too large for this scene's "
                                 "masses and sizes: scale them down)")
            raise MemoryError("the scene's step ran out of memory") if code == -1 else \
                ValueError(f"core_scene_step refused its sizes ({code})")
        return int(self.args.status)

    def rows(self, end: bool = False) -> Rows:
        """The rows at the state (``end``: at the last step's end, before it is accepted)."""
        _, A, par, out, kind, start = self._rows_buffers(end)
        return read_rows(self.model, out, A, par, kind, start)


#: a run's default contact tolerance, in the scene's size
TOLERANCE_SHARE = 1e-5


def contact_tolerance(scene, tolerance) -> float:
    """A run's contact tolerance (m): ``tolerance``, by default :data:`TOLERANCE_SHARE`
    (``1e-5``) of the scene's size (:func:`~snakecg.scenes.packing.scene_size`)."""
    return TOLERANCE_SHARE * scene_size(scene) if tolerance is None else float(tolerance)


def _model_tolerance(model, tolerance) -> float:
    """:func:`contact_tolerance` of a loaded scene, its size read from the constants packed
    when it was loaded (the same number; summed there once, not at every run)."""
    if tolerance is None:
        return TOLERANCE_SHARE * float(model.packed.vector[SP_SIZE])
    return float(tolerance)


def _check_args(model, q0, v0, duration, dt, q_obj0, v_obj0, f_obj, tolerance):
    ns, no = model.n_coordinates, model.scene.n_objects
    problems = []

    def vec(name, value, shape, default):
        if value is None:
            return default
        arr = np.asarray(value, dtype=float) if not isinstance(value, (str, bytes)) else None
        if arr is None or arr.size != math.prod(shape) or not all_finite(arr):
            problems.append(f"{name} must be {math.prod(shape)} finite numbers "
                            f"(shape {shape}), got {value!r:.60}")
            return default
        return arr.reshape(shape).copy()

    q = vec("q0", q0, (ns,), np.zeros(ns))
    if q0 is None:
        problems.append(f"q0 is required: {ns} numbers (x, y, theta, q1..q{model.n_joints})")
    v = vec("v0", v0, (ns,), np.zeros(ns))
    vo = vec("v_obj0", v_obj0, (no, 3), np.zeros((no, 3)))
    fo = vec("f_obj", f_obj, (no, 3), np.zeros((no, 3)))
    qo = vec("q_obj0", q_obj0, (no, 3), None)
    for name, val, lo, hi in (("duration", duration, 0.0, 1e6), ("dt", dt, 1e-7, 1.0)):
        if not (isinstance(val, (int, float, np.floating)) and not isinstance(val, bool)
                and math.isfinite(val) and lo < val <= hi):
            problems.append(f"{name} must be a number in ({lo:g}, {hi:g}] (s), got {val!r:.60}")
    if tolerance is not None and not (isinstance(tolerance, (int, float)) and
                                      not isinstance(tolerance, bool) and 0 < tolerance < 0.01):
        problems.append(f"tolerance must be a number in (0, 0.01) (m), got {tolerance!r:.60}")
    for name, arr, lim in (("v0", v, FORCE_LIMIT ** 0.5), ("v_obj0", vo, FORCE_LIMIT ** 0.5),
                           ("f_obj", fo, FORCE_LIMIT)):  # (as forward's and the paper's run)
        if np.abs(arr).max(initial=0.0) > lim:
            problems.append(f"{name} must have every entry within +-{lim:.0e} (the energies are "
                            f"quadratic in them and would overflow float64), found "
                            f"{arr.flat[np.abs(arr).argmax()]:.3e}")
    if problems:
        raise InputError("simulate: " + "; ".join(problems))
    model.check_base(q)  # (a run's start; its later steps move it by its velocities)
    if isinstance(duration, (int, float)) and duration / dt > MAX_STEPS:
        raise InputError(f"simulate: duration / dt = {duration / dt:.3g} steps, more than "
                         f"{MAX_STEPS}; take a larger dt or a shorter run")
    return q, v, qo, vo, fo


class _Runner:
    """One run's loop in the engine (``core_scene_run``, ``snakecg/engine/scene_run.c``) over
    a :class:`_Stepper`: its arguments, the torque law's parameters, the record's buffer
    (``cap`` rows of ``t, x, V, tau, acc``; ``every``: keep every k-th step, 0 none) and the
    pairs' distances of the root finding (their own call and buffers). :meth:`reset` readies
    it for another run of the same stepper."""

    def __init__(self, st: _Stepper, duration, dt, law: str, params, every: int, cap: int,
                 stop_at_impacts: bool = True, pause: int | None = None):
        eng, model = st.engine, st.model
        self.st, self.na = st, model.n_joints
        self.width = 1 + 2 * st.n + self.na + ST_WIDTH
        self.gq, self.gqo = np.zeros(st.ns), np.zeros(max(1, 3 * st.no))
        self.gout = np.zeros(5 * eng.gcap)
        self.gs = SceneStateCall(model._pk, self.gq.ctypes.data, self.gqo.ctypes.data,
                                 eng.tol, 0.0, eng.gcap, eng.mcap, -1, -1,
                                 self.gout.ctypes.data, None, None, None, None, None)
        self.rec, self.lp = np.zeros((1, self.width)), np.zeros(1)
        self.work = np.zeros(2 * st.n + 5 * eng.gcap)
        self.args = SceneRunCall(st._address, address(self.gs), eng.gcap, 0.0, 0.0, H_MIN,
                                 FORCE_LIMIT, 0, 0, self.lp.ctypes.data, 0,
                                 self.rec.ctypes.data, 0, 0, 0, 0, self.work.ctypes.data)
        self._address = address(self.args)
        self._run = model.core.scene_run
        self.reset(duration, dt, law, params, every, cap, stop_at_impacts, pause)

    def reset(self, duration, dt, law: str, params, every: int, cap: int,
              stop_at_impacts: bool = True, pause: int | None = None) -> None:
        """A new run's arguments (those of the constructor), its time, steps and record from
        zero; the record's buffer kept where it has the room."""
        a = self.args
        lp = np.zeros(1) if params is None else np.asarray(params, dtype=float).reshape(-1)
        if self.lp.size < lp.size:  # (the parameters' buffer, kept where it has the room)
            self.lp = np.zeros(lp.size)
            a.lp = self.lp.ctypes.data
        self.lp[:lp.size] = lp
        rows = max(1, cap) if every else 1
        if self.rec.shape[0] < rows:
            self.rec = np.zeros((rows, self.width))
            a.rec = self.rec.ctypes.data
        a.duration, a.dt = float(duration), float(dt)
        a.law, a.nlp = SCENE_LAWS[law], lp.size
        a.every, a.cap, a.nrec = int(every), rows if every else 0, 0
        a.stop_at_impacts = int(stop_at_impacts)
        a.pause = PAUSE_STEPS if pause is None else int(pause)
        a.t, a.nstep, a.phase, a.impacts, a.min_gap = 0.0, 0, 0, 0, 0.0
        a.bad[:] = (0.0,) * 5
        a.geo, a.nkept, a.geo_k = None, 0, -1  # (no contact check: :func:`_simulate`'s)

    def go(self) -> int:
        """Go on with the run: why the engine returned (``RUN_*``)."""
        code = self._run(self._address)
        if code < 0:
            if code == -3:  # (its start was checked: the run overflowed on its way)
                raise InputError(f"simulate: the state is not finite at t = "
                                 f"{self.args.t:.6g} s: it overflowed double precision (torques "
                                 f"or velocities too large for this scene's masses and sizes: "
                                 f"scale them down)")
            raise MemoryError("the scene's run ran out of memory") if code == -1 else \
                ValueError(f"core_scene_run refused ({code})")
        return code

    def take(self) -> np.ndarray:
        """The record's rows since the last take (the buffer emptied): the buffer itself,
        handed over (not copied), and a new one of its size for the rows to come."""
        a = self.args
        k = int(a.nrec)
        rows = self.rec[:k]
        if k:
            self.rec = np.empty_like(self.rec)
            a.rec = array_address(self.rec)
        a.nrec = 0
        return rows


#: steppers (with their runners) kept per model for later runs (more at once are made and
#: dropped)
POOL_SIZE = 4
#: largest record buffer (bytes) a kept runner keeps (a run with more rows per return makes
#: its own)
KEEP_BYTES = 1 << 20


def _take(model, tol: float, f_obj) -> _Stepper:
    """A :class:`_Stepper` of ``model`` with the contact tolerance ``tol`` for one run: one
    from the model's pool, readied (:meth:`_Stepper.reset`), or a new one. The pool is the
    model's (``model._steppers``): its buffers and structs, lent to one run at a time (two
    runs at once, threads or a caller's law that runs another, hold two) and given back when
    the run ends, however it ends (the next run's :meth:`_Stepper.reset` and
    :meth:`_Stepper.begin` write everything a run reads)."""
    pool = getattr(model, "_steppers", ())
    for i in range(len(pool) - 1, -1, -1):
        if pool[i].engine.tol == tol:
            try:
                st = pool.pop(i)
            except IndexError:  # another thread took one
                break
            if st.engine.tol == tol:
                st.reset(f_obj)
                return st
            pool.append(st)
            break
    return _Stepper(model, tol, f_obj)


def _give(model, st: _Stepper) -> None:
    """``st`` back to the pool of ``model`` (dropped when the pool is full; its record's
    buffer dropped when above :data:`KEEP_BYTES`)."""
    pool = getattr(model, "_steppers", None)
    if pool is not None and len(pool) < POOL_SIZE:
        run = st.runner
        if run is not None and run.rec.nbytes > KEEP_BYTES:
            run.rec = np.zeros((1, run.width))
            run.args.rec, run.args.cap = run.rec.ctypes.data, 0
        pool.append(st)


def engine_law(kind: str, law, n_a: int):
    """``(name, parameters)`` of a torque law (:func:`snakecg.simulate.torques.torque_law`'s
    ``kind, law``) for the engine's run: ``constant`` (the torques), a law that carries its
    own parameters (``law.engine_law()``: a :class:`~snakecg.simulate.TorqueTable`, a
    :class:`~snakecg.simulate.SerpenoidPD`; a subclass, which may change the law, does not),
    else ``caller`` (evaluated in Python at each step)."""
    if kind == "constant":
        return "constant", np.asarray(law, dtype=float)
    from ..simulate.gaits import SerpenoidPD, TorqueTable

    if type(law) in (SerpenoidPD, TorqueTable):
        found = law.engine_law(n_a)
        if found is not None:
            return found
    return "caller", None


def simulate_scene(model, q0, duration, *, v0=None, tau=None, dt=1e-3, q_obj0=None,
                   v_obj0=None, f_obj=None, tolerance=None, output_every=1,
                   progress=False) -> SceneRun:
    """Simulate the general scene of ``model`` (a :class:`~snakecg.scenes.model.
    GeneralSceneModel`) from ``q0`` (``v0``: default at rest) for ``duration`` seconds.

    ``tau``: joint torques, a constant ``(n_a,)``, a function ``tau(t)`` or a feedback law
    ``tau(t, state)`` (:class:`SceneState`; e.g. :class:`snakecg.simulate.SerpenoidPD`), held
    over each step; default zero. A constant, a :class:`~snakecg.simulate.TorqueTable` and a
    :class:`~snakecg.simulate.SerpenoidPD` are evaluated by the engine, in its loop; any other
    callable by Python at each step. ``dt``: the step (s), shortened where a contact begins.
    ``q_obj0``/``v_obj0`` ``(n_objects, 3)``: the objects' poses and twists (default: placed by
    the scene, at rest); ``f_obj``: a constant wrench on every object. ``tolerance`` (m): the
    contact tolerance (default ``1e-5`` times the scene's size): contacts hold within it and
    nothing may penetrate beyond it. ``output_every``: keep every k-th step in the record.
    ``progress``: ``False`` (default) quiet, ``None`` a line on standard error every
    :data:`PROGRESS_EVERY` seconds of a long run (:func:`snakecg.progress.resolve`), or a
    ``progress(message)`` callable.
    """
    return _simulate(model, q0, duration, v0, tau, dt, q_obj0, v_obj0, f_obj, tolerance,
                     output_every, progress)[0]


def _simulate(model, q0, duration, v0, tau, dt, q_obj0, v_obj0, f_obj, tolerance,
              output_every, progress, check=None) -> tuple[SceneRun, tuple | None]:
    """:func:`simulate_scene` (its arguments in its order), and with ``check``
    (``check(tol)``: the address of a :class:`~snakecg.engine.binding.Geometry`, the paper's
    contact check of a scene with one object, its plate; at the run's tolerance ``tol``) that
    check of every sample kept, in the engine's loop from the links' cos and sin its step
    took: ``(run, first)``, ``first`` ``(index, overlap, pair)`` of the first sample whose
    largest overlap exceeds ``tol`` (``None``: none, or no check)."""
    q, v, qo, vo, fo = _check_args(model, q0, v0, duration, dt, q_obj0, v_obj0, f_obj,
                                   tolerance)
    if isinstance(output_every, bool) or not isinstance(output_every, (int, np.integer)) \
            or output_every < 1:
        raise InputError(f"simulate: output_every must be an integer >= 1, got "
                         f"{output_every!r:.60}")
    tol = _model_tolerance(model, tolerance)
    na = model.n_joints
    kind, law = _late("torque_law")(np.zeros(na) if tau is None else tau, na)
    name, params = engine_law(kind, law, na)
    st = _take(model, tol, fo.reshape(-1))
    try:
        return _run(model, st, q, v, qo, vo, duration, dt, output_every, kind, law, name,
                    params, progress, tol, None if check is None else check(tol))
    finally:
        _give(model, st)


def _run(model, st, q, v, qo, vo, duration, dt, output_every, kind, law, name, params,
         progress, tol, geo) -> tuple[SceneRun, tuple | None]:
    """:func:`_simulate`'s run on the stepper ``st``, its arguments checked; ``geo``: the
    address of the contact check, or ``None``."""
    check_tau = _late("check_tau")
    ns, na, scene = st.ns, model.n_joints, model.scene
    if qo is None:
        st.place(q)
    rec = SceneRun.start(model, tol, dt)

    def torque(t):
        if kind == "time":
            return check_tau(law(t), na, t)
        s = SceneState(t, st.x[:ns].copy(), st.V[:ns].copy(), st.x[ns:].reshape(-1, 3).copy(),
                       st.V[ns:].reshape(-1, 3).copy())
        return check_tau(law(t, s), na, t)

    acc = st.acc
    rec.follow(acc)
    code = st.begin(q, qo, v, vo)
    if code != STEP_DONE:  # the start's fault: refused before any step
        why = "is not physical" if code == STEP_OVERLAP else "is refused"
        raise InputError(f"simulate: the initial state {why}: {st.engine.refusal(st.out)} "
                         "(q0, q_obj0)")
    cap = int(min(RECORD_ROWS, duration / dt / output_every + 4))
    run = st.runner
    if run is None:
        run = st.runner = _Runner(st, duration, dt, name, params, int(output_every), cap)
    else:
        run.reset(duration, dt, name, params, int(output_every), cap)
    args = run.args
    if geo is not None:
        args.geo, args.geo_tol = geo, tol
    if name == "constant":
        st.tau[:na] = params
    elif name == "caller":
        st.tau[:na] = torque(0.0)
    report = _late("resolve")(progress)
    wall = time.perf_counter()
    while True:
        code = run.go()
        if code == RUN_PAUSE and report is not None and \
                time.perf_counter() - wall > PROGRESS_EVERY:
            wall = time.perf_counter()
            report(f"simulate: t = {args.t:.4g} s of {duration:g} s, {args.nstep} steps, "
                   f"{len(rec.events)} impacts")
        if code == RUN_TAU:
            st.tau[:na] = torque(args.t)
        elif code == RUN_FULL:
            rec.samples(run.take())
        elif code == RUN_IMPACT:
            rec.impact(args.t, acc[ST_LOSS], st.rows().contacts, st.ilam, st.iinfo)
        elif code != RUN_PAUSE:
            break
    rec.samples(run.take())
    if code == RUN_BAD_TAU:
        check_tau(st.tau[:na].copy(), na, args.t)  # raises: the law's torque is out of bounds
    status, message, bodies = ending(code, run, scene)
    first = ((int(args.geo_k), float(args.geo_depth), int(args.geo_pair))
             if geo is not None and args.geo_k >= 0 else None)
    return rec.finish(status, args.t, message, bodies=bodies), first


def ending(code: int, run: _Runner, scene):
    """``(status, message, bodies)`` of a run whose engine's loop returned ``code``
    (``RUN_*``, the run's end): ``completed``, ``not_converged`` or ``penetration`` with its
    bodies (``(kind, index)`` pairs, or None)."""
    st, t, tol = run.st, run.args.t, run.st.engine.tol
    if code == RUN_END:
        work, stab = float(st.acc[ST_WORK_TAU]), float(st.acc[ST_CONTACT_WORK])
        if stab > STABILISATION_SHARE * abs(work):  # (said, not hidden: the run did complete)
            return "completed", (f"the gap stabilisation did {stab:.3g} J of work against the "
                                 f"torques' {work:.3g} J: kinetic energy from pushing overlaps "
                                 "out; take a smaller dt"), None
        return "completed", "", None
    if code == RUN_BAD_TAU:
        return "invalid_torque", (f"the torque law's value at t = {t:.6g} s is not finite or "
                                  "beyond the force limit"), None
    if code == RUN_NOT_CONVERGED:
        return "not_converged", f"the step's solve did not converge at t = {t:.6g} s", None
    if code == RUN_IMPACT_NOT_CONVERGED:
        return "not_converged", f"the impact's solve did not converge at t = {t:.6g} s", None
    if code == RUN_REFUSED:  # the step's end refused, but no pair overlaps beyond tol
        return "penetration", st.engine.refusal(st.out1), None
    if code == RUN_TOO_SHORT:
        bad = run.args.bad
        a, b = (BODY_KINDS[int(bad[0])], int(bad[1])), (BODY_KINDS[int(bad[2])], int(bad[3]))
        return "penetration", (f"{scene.body_name(*a)} and {scene.body_name(*b)} would "
                               f"penetrate by {-bad[4]:.3g} m at t = {t:.6g} s (tolerance "
                               f"{tol:.3g} m)"), (a, b)
    if code == RUN_TRIES_OUT:
        return "penetration", ("the step could not be kept within the contact tolerance at "
                               f"t = {t:.6g} s"), None
    raise ValueError(f"core_scene_run returned {code}")
