"""Integration segments in compiled code: the right-hand side of a mode, the DOP853 steps,
the output times and the event functions of a segment in one C call
(``core_integrate_segment`` of the model library's ``integrate.c``), answering what
:func:`scipy.integrate.solve_ivp` answers to :class:`~snakecg.simulate.simulator.Simulator`;
and what happens at an event (impacts, projections, the new active set) in one C call
(``core_settle`` of ``events.c``), answering what
:meth:`~snakecg.simulate.events.Events.settle` computes in Python.

Used for ``method="DOP853"`` without ``fixed_step`` when the torque is constant over each
segment (a constant, or a law held over ``control_period``) and the model has a compiled
library; the rest goes through solve_ivp. The C answers the rare stretches itself (dependent
held rows by the Tikhonov rule of the forward solve, an active set that does not settle by
enumeration); what it cannot answer (a failed evaluation, a derivative that is not finite)
raises :class:`~snakecg.simulate.records.SimulationError` with the time and the reason. The
Python engine (:class:`~snakecg.simulate.dynamics.Dynamics`,
:class:`~snakecg.simulate.events.Events`) is never called for it.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

from ..engine.binding import copied, empty_pointers, int64s, pointers
from ..engine.segment import (
    FAILED_REASON,
    PAUSE_AFTER,
    RUN_COMPLETED,
    RUN_FAILED,
    RUN_GEOMETRY,
    RUN_PAUSED,
    RUN_STOPPED,
    SEG_END,
    SEG_EVENT,
    SEG_FAILED,
    SEG_GEOMETRY,
    SEG_MEMORY,
    SEG_PAUSED,
    SEG_TOO_SMALL,
    SETTLE_DONE,
    SETTLE_MEMORY,
)
from .records import SimulationError
from .workspace import give, take

__all__ = ["CompiledSegments", "compiled_reason"]

INTEGRATORS = ("auto", "compiled", "scipy")
#: Events a whole run in C (core_run) has room for; a run with more is done by the Python loop.
RUN_EVENTS = 256
#: Samples evaluated in one C call (between two, Python handles a Ctrl-C).
SAMPLE_CHUNK = 4096
_TOO_SMALL = "Required step size is less than spacing between numbers."  # solve_ivp's words


def compiled_reason(settings) -> str | None:
    """Why the run ``settings`` cannot use the compiled segments (``None`` when it can)."""
    core = getattr(settings.model, "core", None)
    if core is None or getattr(core, "integrate_segment", None) is None:
        return "the model has no compiled library (backend other than the compiled one)"
    if settings.method != "DOP853":
        return f"method {settings.method!r} (the compiled segments are DOP853)"
    if settings.fixed_step is not None:
        return "fixed_step (the compiled segments take adaptive steps)"
    if settings.kind != "constant" and settings.control_period is None:
        return ("a torque law evaluated continuously (the compiled segments need a torque "
                "constant over each segment: a constant, or control_period)")
    return None


def placement(model, q0):
    """The scene's placement of the object at the checked ``q0`` (n_s,): ``(q_obj0, rho)``,
    new arrays, as :meth:`snakecg.SceneModel.place` gives them, through the compiled batch
    driver of ``place_object`` with its constant inputs packed once per model."""
    be = model.backend
    # the batch driver of the compiled library (a CasADi backend's functions are CasADi's)
    fn = getattr(be, "_fns", {}).get("place_object") if getattr(be, "kind", None) == \
        "compiled" else None
    if fn is None:
        q_obj0, rho, _ = model.place(q0[None, :], 1)
        return q_obj0[0].copy(), rho[0].copy()
    derived = model.data().derived
    fixed = derived.get("simulate.place")
    if fixed is None:
        sig = be.signatures["place_object"]
        values = {"K": model.parameters, "contact_link": model._contact_link,
                  "contact_offset": [model.scene.contact_offset],
                  "object_distance": [model.scene.object_distance], "side": model._side}
        packed = np.concatenate([np.ravel(np.asarray(values[k], dtype=float))
                                 for k in sig.in_names if k != "q"])
        argp, off = empty_pointers(len(sig.in_names)), 0
        for i, (k, size) in enumerate(zip(sig.in_names, sig.in_sizes)):
            if k != "q":
                argp[i] = packed.ctypes.data + 8 * off
                off += size
        sizes = [r * c for r, c in sig.out_shapes]  # q_obj (3), rho (2), contact point (2)
        # the template of the pointer arrays (copied at each call: the q and output pointers
        # are the call's), the strides (all 0: one sample), where q and the outputs go
        fixed = derived["simulate.place"] = (packed, argp, int64s(len(argp)),
                                 sig.in_names.index("q"), len(q0),
                                 np.cumsum([len(q0), *sizes[:-1]]).tolist(), sum(sizes))
    _, template, strides, k, ns, offsets, n_out = fixed
    # q0 and the outputs in one new array
    buf = np.empty(ns + n_out)
    buf[:ns] = q0
    base = buf.ctypes.data
    argp = copied(template)
    argp[k] = base
    resp = pointers(base + 8 * o for o in offsets)
    if fn(1, argp, strides, resp) != 0:
        q_obj0, rho, _ = model.place(q0[None, :], 1)
        return q_obj0[0].copy(), rho[0].copy()
    return buf[ns:ns + 3].copy(), buf[ns + 3:ns + 5].copy()


def _failed(memory: bool, t) -> None:
    """Raise for a compiled segment, settle or run that failed (at the time ``t``, if known)."""
    if memory:
        raise MemoryError("the compiled simulation could not allocate its workspace")
    at = f" at t = {t:.6g} s" if t is not None else ""
    raise SimulationError(f"integration failed{at}: {FAILED_REASON}")


class CompiledSegments:
    """The compiled segment integrator of one run on the equations ``dyn``
    (:class:`~snakecg.simulate.dynamics.Dynamics`) with the checked ``settings`` and the
    contact check ``check`` (:class:`~snakecg.simulate.contact_check.RunCheck`, run by the C
    in every segment)."""

    def __init__(self, dyn, settings, check):
        model = settings.model
        self.dyn = dyn
        self._model = model  # keeps the scene vector alive
        # the model's buffers and structs (a workspace of its pool, given back by release())
        ws = self.ws = take(model)
        self.__dict__.update(ws.shared)
        self.f_obj[:] = dyn.f_obj
        self.rho[:] = dyn.rho
        seg = self.seg
        seg.alpha = dyn.alpha
        seg.rtol, seg.atol = settings.rtol, settings.atol
        seg.max_step = math.inf if settings.max_step is None else settings.max_step
        seg.geo = check.address
        self._check = check  # keeps the struct that seg.geo points at alive
        self.t_eval = np.zeros(0)
        self.y_eval = np.zeros((0, dyn.ny))
        self.steps = 0
        self.runs_handed_back = 0  # whole runs (core_run) done by the Python loop instead
        self.started = False  # a run handed back after its start (run_all)

    def release(self) -> None:
        """Give the workspace back to the model's pool (at the end of the run: nothing may be
        computed with this object afterwards)."""
        ws, self.ws = self.ws, None
        if ws is not None:
            ws.seg.geo = None
            give(self._model, ws)

    def run(self, t0, t1, y, mode, tau, specs, t_eval):
        """One segment from ``(t0, y)`` to ``t1`` in ``mode`` with the torque ``tau`` and the
        terminal events ``specs`` (:meth:`~snakecg.simulate.events.Events.specs`), output
        at ``t_eval``: an object with ``status`` (solve_ivp's: 0, 1 at an event, -1),
        ``message``, the output ``t`` (m,) and ``y`` (m, n_y), ``fired`` (``[(spec, t_e,
        y_e)]`` of the event) and ``stopped`` (``(t, y)`` where the contact check stopped
        it, else ``None``). A failed evaluation or a derivative that is not finite raises
        :class:`~snakecg.simulate.records.SimulationError`."""
        seg, dyn = self.seg, self.dyn
        self.ev_kind[:len(specs)] = specs.codes
        self.ev_row[:len(specs)] = specs.rows
        self.y0[:] = y
        self.tau[:] = tau
        self.state[:] = mode.state
        n = len(t_eval)
        if n > len(self.y_eval):
            self.y_eval = np.zeros((n, dyn.ny))
        self.t_eval = np.ascontiguousarray(t_eval, dtype=float)
        # (set at every call: core_run points them at its own arrays)
        seg.t_eval, seg.n_eval, seg.y_eval = (self.t_eval.ctypes.data, n,
                                              self.y_eval.ctypes.data)
        seg.n_ev, seg.t0, seg.t1 = len(specs), t0, t1
        seg.budget, seg.resume = PAUSE_AFTER, 0
        status = self._fn(self._address)
        while status == SEG_PAUSED:  # back in Python now and then: a Ctrl-C raises here
            dyn.nfev += seg.nfev
            self.steps += seg.nsteps
            seg.resume = 1
            status = self._fn(self._address)
        dyn.nfev += seg.nfev
        dyn.singular += seg.nsingular
        self.steps += seg.nsteps
        if status not in (SEG_END, SEG_EVENT, SEG_TOO_SMALL, SEG_GEOMETRY):
            _failed(status == SEG_MEMORY, seg.t_end if status == SEG_FAILED else t0)
        m = seg.n_out
        fired = []
        if status == SEG_EVENT:
            fired = [(specs[seg.event], seg.t_end, self.y_end.copy())]
        stopped = (seg.t_end, self.y_end.copy()) if status == SEG_GEOMETRY else None
        return SimpleNamespace(
            t=self.t_eval[:m], y=self.y_eval[:m].copy(),
            status={SEG_END: 0, SEG_EVENT: 1, SEG_TOO_SMALL: -1, SEG_GEOMETRY: 0}[status],
            message=_TOO_SMALL if status == SEG_TOO_SMALL else "", fired=fired,
            stopped=stopped)

    def run_all(self, y, mode, loss, tau, grid, T, gtol, max_events):
        """The whole run from the state ``y`` in ``mode`` (after the start's settle, the
        energy ``loss`` removed there) with the constant torque ``tau`` to ``T``, output at
        ``grid`` (increasing, the last is ``T``), in C (``core_run``, called again while it
        pauses): the filled
        :class:`~snakecg.engine.segment.Run` (the workspace's: read it before the next run) and
        its arrays (``t``, ``y``, ``mode``, ``loss`` and the quantities ``samples`` (as
        :meth:`samples_into`) of each sample, the ``modes`` and the ``events``, see run.c),
        or ``None`` when the Python loop must do the run (no room for its samples, modes or
        events, a too small step, a penetrating start); a failed evaluation raises
        :class:`~snakecg.simulate.records.SimulationError`.

        With ``mode=None``, ``y`` is the initial state and the C does the start as well
        (the contact's gap and position, the start's settle): ``arrays.start`` is then what it
        recorded (:data:`~snakecg.simulate.workspace.START_WIDTH`), the first mode the start's
        and ``loss`` is not read. ``started`` tells, after a run handed back, whether the C
        got past the start (the Python loop would hand back the same run again)."""
        ny, nc = self.dyn.ny, self.dyn.nc
        n_grid = len(grid)
        cap_events = min(int(max_events), RUN_EVENTS) + 1
        cap = n_grid + 2 * cap_events + 2
        width = ny + 2 * nc + 6
        # one after the other in the workspace's buffer: t, mode, loss (cap each), y (cap x
        # ny), samples (cap x width), modes, events, then the grid
        o_y = 3 * cap
        o_samples = o_y + cap * ny
        o_modes = o_samples + cap * width
        o_events = o_modes + (cap_events + 1) * (nc + 1)
        o_grid = o_events + cap_events * (11 + nc)
        buf, base = self.ws.run_buffer(o_grid + n_grid)
        buf[o_grid:o_grid + n_grid] = grid
        self.tau[:] = tau
        self.y_start[:] = y
        R = self.ws.run
        if mode is not None:
            self.state[:] = mode.state  # the start's mode, then the current one
            R.off_link, R.loss, R.start = int(mode.off_link), loss, 0
        else:
            R.start = 1
        R.T, R.gtol, R.grid, R.n_grid = T, gtol, base + 8 * o_grid, n_grid
        R.max_events, R.t = int(max_events), 0.0
        R.cap, R.t_out, R.mode_out, R.loss_out = cap, base, base + 8 * cap, base + 16 * cap
        R.y_out, R.samples = base + 8 * o_y, base + 8 * o_samples
        R.cap_modes, R.modes = cap_events + 1, base + 8 * o_modes
        R.cap_events, R.events = cap_events, base + 8 * o_events
        R.n_modes = 0
        R.budget, R.resume = PAUSE_AFTER, 0
        status = self._run(self.ws.run_address)
        while status == RUN_PAUSED:  # back in Python now and then: a Ctrl-C raises here
            status = self._run(self.ws.run_address)
        self.dyn.singular += R.nsingular
        if status == RUN_FAILED:
            _failed(False, R.t)
        if status not in (RUN_COMPLETED, RUN_STOPPED, RUN_GEOMETRY):
            self.started = R.n_modes > 0
            return None
        n = R.n_out
        # what the trajectory keeps is copied out of the workspace (t, y, loss)
        arrays = SimpleNamespace(
            t=buf[:n].copy(), y=buf[o_y:o_y + n * ny].reshape(n, ny).copy(),
            mode=buf[cap:cap + n], loss=buf[2 * cap:2 * cap + n].copy(),
            modes=buf[o_modes:o_modes + R.n_modes * (nc + 1)].reshape(-1, nc + 1),
            events=buf[o_events:o_events + R.n_events * (11 + nc)].reshape(-1, 11 + nc),
            samples=buf[o_samples:o_samples + n * width].reshape(n, width),
            start=self.start_out if mode is None else None)
        self.steps += R.nsteps
        self.dyn.nfev += R.nfev
        return R, arrays

    def modes_of(self, table, mode_of) -> list:
        """The modes of the rows (row states, then off_link) of a whole run's ``table``:
        ``mode_of(state, off_link)`` (:meth:`~snakecg.simulate.events.Events.mode`) of each,
        remembered by the workspace (the model's bounds are its)."""
        known, nc, out = self.ws.modes, self.dyn.nc, []
        for row in table:
            key = row.tobytes()
            mode = known.get(key)
            if mode is None:
                if len(known) >= 4096:
                    known.clear()
                mode = known[key] = mode_of(row[:nc], bool(row[nc]))
            out.append(mode)
        return out

    def settle(self, y, prev, forced: dict, contact_candidate: bool, tau):
        """``core_settle`` at the state ``y`` after the mode ``prev`` (``None`` at the start)
        with the rows ``forced`` (row: state code) and the torque ``tau``: the
        :class:`~snakecg.engine.segment.Settle` it filled (outputs in ``s_y_out``,
        ``s_state``, ``s_impact_lam``, ``s_projection_lam``); a failed evaluation raises
        :class:`~snakecg.simulate.records.SimulationError` (see events.c)."""
        st = self.st
        self.s_y[:] = y
        self.tau[:] = tau
        if prev is None:
            st.prev = None
        else:
            self.s_prev[:] = prev.state
            st.prev = self._prev_address
        self.s_forced.fill(-1.0)
        for r, code in forced.items():
            self.s_forced[r] = code
        st.contact_candidate = 1 if contact_candidate else 0
        status = self._settle(self._settle_address)
        self.dyn.singular += st.nsingular
        if status != SETTLE_DONE:
            _failed(status == SETTLE_MEMORY, None)
        return st

    def gap_and_s(self, y):
        """The contact's ``gap`` and position ``s`` along the link at the state ``y`` (of
        ``contact_system``: the same in every mode); a failed evaluation raises
        :class:`~snakecg.simulate.records.SimulationError`."""
        nc = self.dyn.nc
        out = np.zeros((1, self.dyn.ny + 2 * nc + 6))
        self.tau.fill(0.0)
        self.state.fill(0.0)  # no row held: nothing to factor
        y = np.ascontiguousarray(y, dtype=float)
        if self._samples(self._address, 1, y.ctypes.data, out.ctypes.data) != 0:
            _failed(True, None)
        if out[0, -1] != 0:
            _failed(False, 0.0)
        return float(out[0, -6]), float(out[0, -5])

    def point(self, y, mode, tau):
        """``(lam, s)`` at the state ``y`` in ``mode`` with the torque ``tau`` (as the
        right-hand side evaluates them); a failed evaluation raises
        :class:`~snakecg.simulate.records.SimulationError`."""
        r = self.samples(y, mode, tau)
        if not r["ok"][0]:
            _failed(False, None)
        return r["lam"][0].copy(), float(r["s"][0])

    def kinematics(self, Q):
        """``M_s`` (n, n_s, n_s) and the link poses (n, n_l, 3) at the configurations ``Q``
        (n, n_s): the generated ``mass_matrix`` and ``link_poses`` through their compiled
        batch drivers on the run's own arrays (what :meth:`snakecg.SceneModel.mass_matrix`
        and :meth:`~snakecg.SceneModel.link_poses` give, without their checks), or ``None``
        when an evaluation failed. Reads nothing of the workspace that a run writes (also
        used after the run, when a deferred field of its trajectory is first read)."""
        Q = np.ascontiguousarray(Q, dtype=float)
        n = len(Q)
        ns, nl = self.dyn.ns, self.dyn.nl
        buf = np.empty(n * (ns * ns + 3 * nl))
        q, base = Q.ctypes.data, buf.ctypes.data
        outs = (base, base + 8 * n * ns * ns)
        for (fn, K, k, strides), out in zip(self._kin, outs):
            argp = empty_pointers(2)
            argp[k], argp[1 - k] = q, K
            if fn(n, argp, strides, pointers([out])) != 0:
                return None
        M = buf[:n * ns * ns].reshape(n, ns, ns).transpose(0, 2, 1)
        return M, buf[n * ns * ns:].reshape(n, nl, 3)

    def samples_into(self, Y, mode, tau, out) -> None:
        """The trajectory's quantities at the states ``Y`` (n, n_y) in ``mode`` with the torque
        ``tau``, evaluated by the C into ``out`` (n, n_y + 2 n_c + 6), C-contiguous rows:
        ``ydot`` (n_y), ``lam``, ``A V`` (n_c), ``gap``, ``s``, ``sr``, ``norm_a_obj``,
        ``norm_qdd`` and the status (0, or ``SEG_FAILED`` where the evaluation failed or is
        not finite: the rest of the row is NaN)."""
        Y = np.ascontiguousarray(Y, dtype=float)
        n = len(Y)
        self.tau[:] = tau
        self.state[:] = mode.state
        width = out.shape[1]
        for i in range(0, n, SAMPLE_CHUNK):  # in chunks: a Ctrl-C is handled between two
            m = min(SAMPLE_CHUNK, n - i)
            if self._samples(self._address, m, Y.ctypes.data + 8 * i * Y.shape[1],
                             out.ctypes.data + 8 * i * width) != 0:
                raise MemoryError("the compiled samples could not allocate their workspace")

    def samples(self, Y, mode, tau):
        """:meth:`samples_into` as a dict of ``ydot`` (n, n_y), ``lam``, ``AV`` (n, n_c),
        ``gap``, ``s``, ``sr``, ``norm_a_obj``, ``norm_qdd`` (n,) and ``ok`` (n,) (False
        where the evaluation failed: NaN)."""
        dyn = self.dyn
        ny, nc = dyn.ny, dyn.nc
        Y = np.ascontiguousarray(Y, dtype=float).reshape(-1, ny)
        out = np.zeros((len(Y), ny + 2 * nc + 6))
        self.samples_into(Y, mode, tau, out)
        e = out[:, ny:]
        return {"ydot": out[:, :ny], "lam": e[:, :nc], "AV": e[:, nc:2 * nc],
                "gap": e[:, 2 * nc], "s": e[:, 2 * nc + 1], "sr": e[:, 2 * nc + 2],
                "norm_a_obj": e[:, 2 * nc + 3], "norm_qdd": e[:, 2 * nc + 4],
                "ok": e[:, 2 * nc + 5] == 0}
