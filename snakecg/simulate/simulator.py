"""The integration: :func:`simulate` checks its arguments, then :class:`Simulator` integrates
mode by mode (terminal events, the mode re-solved at each event, the held torque re-sampled at
each control instant), each segment in compiled code
(:class:`~snakecg.simulate.compiled.CompiledSegments`) where it can and with
:func:`scipy.integrate.solve_ivp` otherwise, with the contact check
(:class:`~snakecg.simulate.contact_check.RunCheck`) on every segment and at every event, and
hands the samples to :func:`~snakecg.simulate.assembly.assemble`."""

from __future__ import annotations

import math
import time
from types import SimpleNamespace

import numpy as np

from ..engine.segment import RUN_STOPPED
from ..errors import InputError, SnakecgError
from ..solver import ABSENT, HELD, LOST
from .assembly import assemble, assemble_arrays
from .compiled import CompiledSegments, compiled_reason
from .contact_check import RunCheck
from .dynamics import N_WORK, Dynamics
from .events import Events
from .inputs import Settings, check_arguments
from .modes import transitions
from .records import SimEvent, SimulationError, Trajectory
from .torques import Torques
from .workspace import START_IMPACT

__all__ = ["Simulator", "simulate"]


class Simulator:
    """One run: the equations (:class:`~snakecg.simulate.dynamics.Dynamics`), the torques
    (:class:`~snakecg.simulate.torques.Torques`) and the event handling
    (:class:`~snakecg.simulate.events.Events`) of the checked ``settings``."""

    def __init__(self, settings: Settings):
        self.settings = settings
        self.model = settings.model
        self.dyn = Dynamics(settings.model, settings.rho, settings.f_obj, settings.alpha)
        self.torques = Torques(settings.kind, settings.law, self.dyn.na,
                               settings.control_period, self.dyn.state)
        gtol = 1e-9 * max(self.dyn.scene.robot.length)
        self.events = Events(self.dyn, self.torques, gtol)
        self.check = RunCheck(settings.model, settings.geometry_check, self.dyn.ns,
                              self.dyn.ny)
        # filled in by run()
        self.ke_initial = math.nan  # set by assemble()
        self.initial_mode = self.final_mode = ""
        self.segments = 0
        self.wall = 0.0
        self.segment_cpu = 0.0  # CPU seconds inside the segment integrations
        reason = compiled_reason(settings) if settings.integrator != "scipy" else "asked for"
        if settings.integrator == "compiled" and reason is not None:
            raise InputError(f"integrator='compiled' is not available for this run: {reason};"
                             " use integrator='auto' or 'scipy'")
        self.compiled = (CompiledSegments(self.dyn, settings, self.check) if reason is None
                         else None)
        self.events.kernel = self.compiled

    def _solver_options(self) -> dict:
        cfg = self.settings
        opts = dict(method=cfg.method, rtol=cfg.rtol, atol=cfg.atol)
        if cfg.fixed_step is not None:
            opts.update(rtol=1e30, atol=1e30, first_step=cfg.fixed_step,
                        max_step=cfg.fixed_step)
        elif cfg.max_step is not None:
            opts.update(max_step=cfg.max_step)
        return opts

    def _output_times(self) -> np.ndarray:
        T, dt = self.settings.duration, self.settings.output_dt
        if dt >= T:
            return np.array([T])
        grid = np.arange(1, int(math.floor(T / dt + 1e-9)) + 1) * dt
        grid = grid[grid < T - 1e-12 * T]
        return np.append(grid, T)

    def _solve_ivp(self, opts, t, t_end, y, mode, tau_fn, t_eval):
        """One segment by :func:`scipy.integrate.solve_ivp`: an object with ``status``,
        ``message``, the output ``t`` (m,) and ``y`` (m, n_y), ``fired``: ``(event
        function, t_e, y_e)`` of each terminal event that fired, and ``stopped``: ``(t, y)``
        where the contact check ended the segment, else ``None``."""
        from scipy.integrate import solve_ivp

        dyn, cfg, check = self.dyn, self.settings, self.check
        evs = self.events.functions(mode, tau_fn)
        geo = check.event() if check.active else None  # (evaluated at every step's end)

        def fun(tt, yy, m=mode, f=tau_fn):
            return dyn.rates(tt, yy, m, f)[0]

        if cfg.fixed_step is not None:
            opts["first_step"] = min(cfg.fixed_step, t_end - t)
        all_evs = (evs + [geo] if geo is not None else evs) or None

        def rerun():  # the same segment with its dense output
            return solve_ivp(fun, (t, t_end), y, t_eval=t_eval, events=all_evs,
                             dense_output=True, **opts)

        try:
            sol = solve_ivp(fun, (t, t_end), y, t_eval=t_eval, events=all_evs, **opts)
        except SnakecgError:
            raise
        except (ValueError, np.linalg.LinAlgError, ArithmeticError) as exc:
            raise SimulationError(f"integration failed at t = {t:.6g} s: {exc}") from exc
        ys = np.asarray(sol.y).reshape(dyn.ny, -1).T if len(sol.t) else np.zeros((0, dyn.ny))
        fired, stopped = [], None
        if sol.status == 1:
            fired = [(evs[i], float(te[0]), np.asarray(ye[0])) for i, (te, ye) in
                     enumerate(zip(sol.t_events[:len(evs)], sol.y_events)) if len(te)]
        if geo is not None:
            root = ((float(sol.t_events[-1][0]), np.asarray(sol.y_events[-1][0]))
                    if len(sol.t_events[-1]) else None)
            if check.solved(t, y, np.asarray(sol.t), ys, root, rerun) is not None \
                    and check.stops:
                stopped = (check.struct.t, check.violation.y)
        return SimpleNamespace(status=sol.status, message=sol.message, t=sol.t, y=ys,
                               fired=fired, stopped=stopped)

    def _run_compiled(self, y, mode, loss, grid, events, wall0):
        """The loop of :meth:`run` for a constant torque in C (``core_run``, see
        :meth:`CompiledSegments.run_all`), from the state ``y`` after the start's settle in
        ``mode``, or with ``mode=None`` from the initial state ``y``, the start included: its
        trajectory, or ``None`` when the Python loop must do the run (nothing of the run's
        state was changed then)."""
        cfg, handler = self.settings, self.events
        T = cfg.duration
        tau = self.settings.law  # the constant torque (Torques.function's)
        done = self.compiled.run_all(y, mode, loss, tau, grid, T, handler.gtol, cfg.max_events)
        if done is None:
            self.check.reset()  # (what the C found before it handed the run back)
            return None
        R, a = done
        nc = self.dyn.nc
        modes = self.compiled.modes_of(a.modes, handler.mode)
        if a.start is not None:  # Events.settle's records of the start
            self.initial_mode = after = modes[0].describe()
            o = a.start
            if o[START_IMPACT]:
                lam = o[START_IMPACT + 5:START_IMPACT + 5 + int(o[START_IMPACT + 4])]
                events.append(SimEvent(0.0, "impact", 0, "start", after, {
                    "closing_velocity": float(o[START_IMPACT + 1]), "impulse": float(lam[0]),
                    "wheel_impulses": lam[1:].tolist(),
                    "energy_loss": -float(o[START_IMPACT + 3]),
                    "kinetic_energy_before": float(o[START_IMPACT + 2])}))
            p = START_IMPACT + 5 + nc  # the projection
            if o[p] and o[p + 1] > o[p + 2]:  # drift above vtol: initial velocities
                events.append(SimEvent(0.0, "projection", int(o[p + 3]), "start", after, {
                    "impulses": o[p + 6:p + 6 + int(o[p])].tolist(),
                    "energy_loss": -float(o[p + 5]),
                    "kinetic_energy_before": float(o[p + 4])}))
        for ev in a.events:  # Events.handle's records: the transitions, then the impact
            t_e, before, after = float(ev[0]), modes[int(ev[3])], modes[int(ev[4])]
            events.extend(transitions(t_e, before, after, impact=bool(ev[5])))
            if ev[5]:
                lam = ev[11:11 + int(ev[10])]
                events.append(SimEvent(t_e, "impact", 0, before.describe(), after.describe(), {
                    "closing_velocity": float(ev[6]), "impulse": float(lam[0]),
                    "wheel_impulses": lam[1:].tolist(), "energy_loss": -float(ev[8]),
                    "kinetic_energy_before": float(ev[7])}))
            if ev[9] >= 0:
                handler.drift_corrected = max(handler.drift_corrected, float(ev[9]))
        status = "completed"
        if R.status == RUN_STOPPED:
            status = (f"stopped at t = {R.t:.6g} s after {R.n_events} events"
                      + (" (no progress between events)" if R.stuck > 20 else ""))
        self.segment_cpu += R.segment_cpu
        self.segments = R.segments
        self.final_mode = modes[int(a.mode[-1])].describe()
        self.wall = time.perf_counter() - wall0
        return assemble_arrays(self, a.t, a.y, a.loss, a.samples, tau, a.mode, modes, events,
                               self.check.status(status))

    def run(self) -> Trajectory:
        try:
            return self._run()
        finally:
            if self.compiled is not None:
                self.compiled.release()

    def _run(self) -> Trajectory:
        cfg, dyn, torques, handler = self.settings, self.dyn, self.torques, self.events
        wall0 = time.perf_counter()
        T = cfg.duration
        y = np.concatenate([cfg.q0, cfg.q_obj0, cfg.v0, cfg.v_obj0, np.zeros(N_WORK)])
        self.check.check_start(y)
        events: list[SimEvent] = []
        grid = self._output_times()
        whole = self.compiled is not None and cfg.kind == "constant"
        if whole:
            # the whole run in one C call, the start included (else the Python below)
            done = self._run_compiled(y, None, 0.0, grid, events, wall0)
            if done is not None:
                return done
            whole = not self.compiled.started  # handed back after its start: Python's loop
        # initial mode: the contact is a candidate when the object touches the link face
        gap, s = (self.compiled.gap_and_s(y) if self.compiled is not None
                  else dyn.linear_maps(y, np.zeros(dyn.na))[2:4])
        gtol = handler.gtol
        on_link = -gtol <= s <= dyn.l_k + gtol
        if gap < -gtol and on_link:
            raise InputError(f"the object penetrates the contact link at t = 0 (gap = {gap:.3g}"
                             " m); move it out along the contact normal")
        touching = abs(gap) <= gtol and on_link
        if cfg.control_period is not None:
            st = np.where(dyn.present, HELD, ABSENT)
            if not touching:
                st[0] = LOST
            torques.sample(0.0, y, handler.mode(st, not on_link))
        impact_loss = 0.0
        y, mode = handler.settle(0.0, y, None, {}, contact_candidate=touching,
                                 off_link=not on_link and abs(gap) <= gtol,
                                 events=events, impact_kind="impact")
        for e in events:
            impact_loss += e.data.get("energy_loss", 0.0)
        blocks = []  # samples in blocks (t (k,), y (k, n_y), mode, tau_fn, impact_loss)
        t = 0.0
        self.initial_mode = mode.describe()
        if whole:
            # the whole loop in one C call (the Python loop below when it hands it back)
            done = self._run_compiled(y, mode, impact_loss, grid, events, wall0)
            if done is not None:
                return done
        if self.compiled is not None and cfg.kind == "constant":
            self.compiled.runs_handed_back += 1
        blocks.append((np.array([t]), y[None, :].copy(), mode, torques.function(), impact_loss))
        status = "completed"
        n_events = 0
        segments = 0
        stuck = 0
        next_control = (cfg.control_period if cfg.control_period is not None else math.inf)
        opts = self._solver_options()
        check = self.check
        while t < T * (1 - 1e-13) and not check.at(t, y):  # (the state after the settle)
            t_end = min(T, next_control)
            if t_end - t <= 1e-12 * T:
                t_end = T if next_control >= T else t_end
            tau_fn = torques.function()
            # output times in (t, t_end), then t_end
            t_eval = np.append(grid[np.searchsorted(grid, t, "right"):
                                    np.searchsorted(grid, t_end, "left")], t_end)
            cpu0 = time.process_time()
            if self.compiled is not None:
                sol = self.compiled.run(t, t_end, y, mode, tau_fn(t, y, mode),
                                        handler.specs(mode), t_eval)
            else:
                sol = self._solve_ivp(opts, t, t_end, y, mode, tau_fn, t_eval)
            self.segment_cpu += time.process_time() - cpu0
            segments += 1
            if sol.status < 0:
                raise SimulationError(f"integration failed at t = {t:.6g} s: {sol.message}")
            stop = sol.stopped
            keep = np.asarray(sol.t) > t
            if stop is not None:  # the contact check's first violation ends the run
                keep &= np.asarray(sol.t) <= stop[0]
                if keep.any():
                    blocks.append((np.asarray(sol.t, dtype=float)[keep], sol.y[keep], mode,
                                   tau_fn, impact_loss))
                if blocks[-1][0][-1] < stop[0]:
                    blocks.append((np.array([stop[0]]), stop[1][None, :].copy(), mode, tau_fn,
                                   impact_loss))
                t = stop[0]
                break
            if keep.any():
                blocks.append((np.asarray(sol.t, dtype=float)[keep], sol.y[keep], mode, tau_fn,
                               impact_loss))
            if sol.status == 1:
                fired = sol.fired
                t_e = min(f[1] for f in fired)
                fired = [f for f in fired if f[1] <= t_e + 1e-12 * max(1.0, T)]
                y_e = fired[0][2].copy()
                stuck = stuck + 1 if t_e - t <= 1e-12 * max(1.0, T) else 0
                if blocks[-1][0][-1] < t_e:
                    blocks.append((np.array([t_e]), y_e[None, :].copy(), mode, tau_fn,
                                   impact_loss))
                n_before = len(events)
                y, mode = handler.handle(t_e, y_e, mode, [ev for ev, _, _ in fired], events)
                for e in events[n_before:]:
                    impact_loss += e.data.get("energy_loss", 0.0)
                n_events += 1
                t = t_e
                blocks.append((np.array([t]), y[None, :].copy(), mode, torques.function(),
                               impact_loss))
                if n_events >= cfg.max_events or stuck > 20:
                    check.at(t, y)
                    status = (f"stopped at t = {t:.6g} s after {n_events} events"
                              + (" (no progress between events)" if stuck > 20 else ""))
                    break
            else:
                t = t_end
                y = sol.y[-1].copy()
                if t >= next_control * (1 - 1e-13):
                    next_control += cfg.control_period
                    if t < T * (1 - 1e-13):
                        # the held torque jumps: the active set is solved again
                        torques.sample(t, y, mode)
                        n_before = len(events)
                        y, mode = handler.handle(t, y, mode, [], events)
                        for e in events[n_before:]:
                            impact_loss += e.data.get("energy_loss", 0.0)
                        if len(events) > n_before:
                            blocks.append((np.array([t]), y[None, :].copy(), mode,
                                           torques.function(), impact_loss))
        self.wall = time.perf_counter() - wall0
        self.segments = segments
        self.final_mode = mode.describe()
        return assemble(self, blocks, events, check.status(status))


def simulate(model, q0, tau, duration, v0=None, *, v_obj0=None, q_obj0=None, rho=None,
             f_obj=None, control_period=None, method="DOP853", rtol=1e-9, atol=1e-11,
             max_step=None, fixed_step=None, stabilization=10.0, output_dt=None,
             max_events=1000, integrator="auto", geometry_check="stop", contacts="paper",
             dt=None, tolerance=None, output_every=None):
    """Integrate the snake + object of ``model`` (a :class:`~snakecg.SceneModel`) from ``q0``.

    Parameters
    ----------
    q0, v0 : (n_s,) initial coordinates and velocities (``v0`` default: at rest).
    tau : the joint torques: a constant ``(n_a,)``, a function of time ``tau(t)``, or a
        feedback law ``tau(t, state)`` (:class:`State`), e.g.
        :func:`least_slip_push_controller`.
    duration : seconds to simulate.
    v_obj0 : the object's initial twist (default 0). ``q_obj0`` and ``rho`` (together): the
        object's pose and the contact point in its frame (default: the scene's placement,
        touching the contact link).
    f_obj : constant external wrench on the object (F_x, F_y, torque), default 0.
    control_period : hold a time function or feedback law constant over this period
        (zero-order hold, evaluated at the start of each period); default: evaluated
        continuously.
    method, rtol, atol, max_step : :func:`scipy.integrate.solve_ivp` settings.
    fixed_step : take steps of exactly this size (convergence studies); overrides the
        tolerances.
    stabilization : Baumgarte rate ``alpha`` (1/s) of the held rows; 0 switches it off.
    output_dt : spacing of the output samples (default ``duration / 400``); events add
        samples on both sides.
    max_events : stop (``summary["status"]`` says so) after this many events.
    integrator : ``"auto"`` (default): each segment in compiled code when the run allows it
        (``method="DOP853"``, no ``fixed_step``, a torque constant over each segment: a
        constant or a law with ``control_period``; the same steps, error norm, dense output
        and event location as solve_ivp's DOP853), solve_ivp otherwise; ``"compiled"``
        requires the compiled segments, ``"scipy"`` always uses solve_ivp.
    geometry_check : what the contact check does when two bodies (a link and the object, or
        two links that are not neighbours) overlap by more than its tolerance
        (:func:`snakecg.geometry.contact_tolerance`, 1e-6 of the longest link): ``"stop"``
        (default) ends the run there, with ``summary["status"]`` ``"penetration"`` or
        ``"self_contact"`` and ``Trajectory.violation`` saying when, which bodies and how
        deep; ``"report"`` reports it the same way and integrates on (the trajectory
        without the check); ``"off"`` checks nothing. An initial state that overlaps is
        refused (``InputError``) unless ``"off"``.
    contacts : ``"paper"`` (default): the paper's model above, one point contact fixed in the
        object against the contact link's face, integrated between events. ``"geometry"``:
        the scene as a general one with the object as its square plate, every contact found
        from the geometry at every step (a flush face holds at both ends, a corner takes
        over when the link turns, other links touch the plate), velocity-level time
        stepping (:func:`snakecg.scenes.paper.simulate_with_geometry`); it takes ``v0``,
        ``v_obj0``, ``q_obj0``, ``f_obj`` and its own ``dt`` (default 1e-3 s),
        ``tolerance`` and ``output_every``, and returns a
        :class:`~snakecg.scenes.run_record.SceneRun`.

    Returns a :class:`Trajectory` with the per-sample arrays, the events and ``summary``
    (``contacts="paper"``).
    """
    if contacts == "geometry":
        return _with_geometry(model, q0, tau, duration, v0, locals())
    if contacts != "paper":
        raise InputError(f"contacts must be 'paper' or 'geometry', got {contacts!r:.60}")
    for name, value in (("dt", dt), ("tolerance", tolerance), ("output_every", output_every)):
        if value is not None:
            raise InputError(f"{name} is an option of contacts='geometry' (time stepping); "
                             "the paper's model takes output_dt, rtol and atol")
    settings = check_arguments(
        model, q0, tau, duration, v0, v_obj0=v_obj0, q_obj0=q_obj0, rho=rho, f_obj=f_obj,
        control_period=control_period, method=method, rtol=rtol, atol=atol,
        max_step=max_step, fixed_step=fixed_step, stabilization=stabilization,
        output_dt=output_dt, max_events=max_events, integrator=integrator,
        geometry_check=geometry_check)
    return Simulator(settings).run()


#: The options of :func:`simulate` that only the paper's model takes.
_PAPER_ONLY = ("rho", "control_period", "method", "rtol", "atol", "max_step", "fixed_step",
               "stabilization", "output_dt", "max_events", "integrator", "geometry_check")


#: functions imported on first use (snakecg.scenes is not imported with this module; an import
#: inside every call costs about a microsecond)
_LAZY: dict = {}


def _geometry():
    """``is_scene_model`` and :func:`snakecg.scenes.paper.simulate_with_geometry`, imported
    once."""
    from ..kinds import is_scene_model
    from ..scenes.paper import simulate_with_geometry

    got = _LAZY["geometry"] = (is_scene_model, simulate_with_geometry)
    return got


def _with_geometry(model, q0, tau, duration, v0, given):
    """:func:`simulate` with ``contacts="geometry"``, its arguments ``given``: the paper's
    options must be left at their defaults."""
    is_scene_model, simulate_with_geometry = _LAZY.get("geometry") or _geometry()
    if not is_scene_model(model):
        raise InputError("contacts='geometry' simulates a loaded snakecg.Scene "
                         f"(snakecg.load(scene)), got {type(model).__name__}")
    defaults = simulate.__kwdefaults__  # the paper's options are keyword-only
    for name in _PAPER_ONLY:
        value, default = given[name], defaults[name]
        if value is not default and not (isinstance(value, (str, float, int))
                                         and value == default):
            raise InputError(f"{name} is an option of contacts='paper' (the paper's model "
                             "between events); contacts='geometry' takes dt, tolerance and "
                             "output_every")
    return simulate_with_geometry(model, q0, tau, duration, v0, q_obj0=given["q_obj0"],
                                  v_obj0=given["v_obj0"], f_obj=given["f_obj"],
                                  dt=given["dt"], tolerance=given["tolerance"],
                                  output_every=given["output_every"])
