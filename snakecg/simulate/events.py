"""Events: what ends an integration segment in a mode, and what happens at its end.

Each is a quantity becoming negative (an exact zero is no crossing: :data:`LEAST_POSITIVE`):

* contact held: ``lam_c`` crossing zero downwards -> the contact separates; the contact point
  leaving the link (``s`` outside ``[0, l_k]``) -> the contact is lost for good;
* contact separated: the gap reaching zero with the point on the link -> plastic impact
  (:meth:`Events.settle`);
* wheel sticking: ``|lam_i|`` reaching ``mu m_i g`` -> it breaks away;
* wheel sliding: ``u_i`` returning to zero -> it sticks again, or slides the other way.

At an event the new active set is the solution of the acceleration-level complementarity
problem (:func:`snakecg.solver.solve_active_set`) over the rows whose status is not fixed by
the velocities. With a compiled ``kernel`` (:class:`~snakecg.simulate.compiled.CompiledSegments`)
the same computation runs in C (``core_settle``), the Python here being the engine of
``backend="casadi"`` (held against the C by the tests).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..engine.segment import EVENT_CODES
from ..solver import ABSENT, HELD, LOST, SLIDE_NEG, SLIDE_POS, solve_active_set
from .modes import Mode, transitions
from .records import SimEvent

__all__ = ["EventSpec", "EventSpecs", "Events"]


#: What an event function returns for an exact zero (2^-1074, the least positive double; the
#: compiled segments' ``SC_LEAST_POSITIVE``): an event is its quantity becoming negative, and
#: one that stays at zero is no crossing (a contact held at rest with exactly no force, a
#: closed gap that does not move), where solve_ivp's test ``g >= 0`` before a step and
#: ``g <= 0`` after it would fire at once, and again after every event.
LEAST_POSITIVE = float(np.nextafter(0.0, 1.0))


def _not_crossed_at_zero(fn):
    """``fn`` with an exact zero returned as :data:`LEAST_POSITIVE`."""

    def event(t, y):
        g = fn(t, y)
        return g if g != 0.0 else LEAST_POSITIVE

    return event


class EventSpec(NamedTuple):
    """A terminal event of a mode: its ``kind`` (what happens when it fires), the constraint
    ``row`` and the ``quantity`` that crosses zero downwards (the compiled segments' code of
    it: :data:`snakecg.engine.segment.EVENT_CODES`)."""

    kind: str
    row: int
    quantity: str


class EventSpecs(list):
    """The :class:`EventSpec` of a mode, with their ``codes`` and ``rows`` as int64 arrays
    (what the compiled segments read)."""

    codes: np.ndarray
    rows: np.ndarray


class Events:
    """The event functions of a mode and the handling of events, on the equations ``dyn``
    (:class:`~snakecg.simulate.dynamics.Dynamics`) with the torques ``torques``
    (:class:`~snakecg.simulate.torques.Torques`). ``gtol`` (m): the gap and the contact
    position along the link within which the contact counts as touching / on the link.

    ``drift_corrected``: the largest ``|A V|`` of a held row projected away at an event.
    ``kernel``: the compiled segments of the run, or ``None`` (Python only).
    """

    def __init__(self, dyn, torques, gtol: float, kernel=None):
        self.dyn = dyn
        self.torques = torques
        self.gtol = gtol
        self.kernel = kernel
        self.drift_corrected = 0.0

    def mode(self, state, off_link: bool) -> Mode:
        """The :class:`Mode` of the row states ``state`` (:meth:`Mode.of`: built once)."""
        return Mode.of(state, self.dyn.bounds, off_link)

    def _point(self, t, y, mode):
        """``(lam, s)`` at ``(t, y)`` in ``mode``."""
        tau_fn = self.torques.function()
        if self.kernel is not None:
            self.dyn.nfev += 1
            return self.kernel.point(y, mode, tau_fn(t, y, mode))
        out = self.dyn.rates(t, y, mode, tau_fn)
        return out[1], out[3]

    # --- events of a mode -------------------------------------------------------------------
    def specs(self, mode: Mode) -> EventSpecs:
        """The terminal events of ``mode`` (all with direction -1): what ends a segment in
        it, as :class:`EventSpec` ``(kind, row, quantity)`` (kept on the mode)."""
        if mode.specs is not None:
            return mode.specs
        out = EventSpecs()
        if mode.contact_held:
            out += [EventSpec("separation", 0, "lam_contact"), EventSpec("off_link", 0, "s"),
                    EventSpec("off_link", 0, "l_k - s")]
        elif not mode.off_link:
            out.append(EventSpec("gap", 0, "gap"))
        bounds = self.dyn.bounds
        for r in range(1, self.dyn.nc):
            st = mode.state[r]
            if st == HELD and np.isfinite(bounds[r]):
                out.append(EventSpec("breakaway", r, "bound - |lam|"))
            elif st in (SLIDE_POS, SLIDE_NEG):
                out.append(EventSpec("slide_stop", r, "sliding velocity"))
        out.codes = np.array([EVENT_CODES[e.quantity] for e in out], dtype=np.int64)
        out.rows = np.array([e.row for e in out], dtype=np.int64)
        mode.specs = out
        return out

    def functions(self, mode: Mode, tau_fn) -> list:
        """The terminal event functions of ``mode`` (:meth:`specs`) for
        :func:`scipy.integrate.solve_ivp`, each with the ``kind``, ``row`` and ``quantity``
        of its spec."""
        rates = self.dyn.rates
        l_k = self.dyn.l_k
        bounds = self.dyn.bounds
        evs = []
        for spec in self.specs(mode):
            q, r = spec.quantity, spec.row
            if q == "lam_contact":
                fn = lambda t, y: rates(t, y, mode, tau_fn)[1][0]  # noqa: E731
            elif q == "s":
                fn = lambda t, y: rates(t, y, mode, tau_fn)[3]  # noqa: E731
            elif q == "l_k - s":
                fn = lambda t, y: l_k - rates(t, y, mode, tau_fn)[3]  # noqa: E731
            elif q == "gap":
                fn = lambda t, y: rates(t, y, mode, tau_fn)[2]  # noqa: E731
            elif q == "bound - |lam|":
                fn = (lambda t, y, r=r, b=bounds[r]:  # noqa: E731
                      b - abs(rates(t, y, mode, tau_fn)[1][r]))
            else:  # the sliding velocity's sign returning to zero
                d = -1.0 if mode.state[r] == SLIDE_POS else 1.0
                fn = lambda t, y, r=r, d=d: d * rates(t, y, mode, tau_fn)[4][r]  # noqa: E731
            fn = _not_crossed_at_zero(fn)
            fn.terminal = True
            fn.direction = -1
            fn.kind, fn.row, fn.quantity = spec
            evs.append(fn)
        return evs

    # --- at an event ------------------------------------------------------------------------
    def handle(self, t, y, mode: Mode, fired, events: list):
        """Apply the events ``fired`` at ``(t, y)``; return the new state and mode."""
        dyn = self.dyn
        forced: dict[int, int] = {}
        off_link = mode.off_link
        contact_candidate = mode.contact_held
        for ev in fired:
            if ev.kind == "separation":
                forced[0] = LOST
                contact_candidate = False
            elif ev.kind == "off_link":
                forced[0] = LOST
                contact_candidate = False
                off_link = True
            elif ev.kind == "gap":
                s = self._point(t, y, mode)[1]
                if -self.gtol <= s <= dyn.l_k + self.gtol:
                    contact_candidate = True
                else:  # the point crossed the link's line beyond its ends: it has passed
                    forced[0] = LOST  # the link, and is not looked for again (else the
                    off_link = True  # crossing, a no-op, fires again at once)
            elif ev.kind == "breakaway":
                lam = self._point(t, y, mode)[0]
                forced[ev.row] = SLIDE_POS if lam[ev.row] > 0 else SLIDE_NEG
        stopped = {ev.row for ev in fired if ev.kind == "slide_stop"}
        # sliding wheels that did not stop keep sliding
        for r in mode.slide_idx:
            if r not in forced and r not in stopped:
                forced[int(r)] = int(mode.state[r])
        n0 = len(events)
        y, new = self.settle(t, y, mode, forced, contact_candidate=contact_candidate,
                             off_link=off_link, events=events)
        events[n0:n0] = transitions(t, mode, new, impact=len(events) > n0)
        return y, new

    def settle(self, t, y, prev: Mode | None, forced: dict[int, int], *, contact_candidate,
               off_link, events: list, impact_kind="impact"):
        """Impacts, projections and the new mode at an event (or at the start).

        A contact that closes with a normal velocity takes a plastic impact: the impulse that
        removes it conserves momentum (ideal wheels take impulses too; wheels with bounded
        friction cannot, their force being finite), and the kinetic energy lost
        ``1/2 Lam^T G_FF Lam`` is recorded."""
        dyn = self.dyn
        nc = dyn.nc
        present, bounds = dyn.present, dyn.bounds
        before = prev.describe() if prev is not None else "start"
        probe = prev or self.mode(np.where(present, HELD, ABSENT), off_link)
        tau = np.asarray(self.torques.function()(t, y, probe), dtype=float)
        if self.kernel is not None:
            done = self.kernel.settle(y, prev, forced, contact_candidate, tau)
            return self._settled(t, done, prev, before, off_link, events, impact_kind)
        Q, G, gap, s, AV = dyn.linear_maps(y, tau)
        V = y[dyn.nx:2 * dyn.nx]
        vtol = 1e-8 * max(1.0, float(np.abs(V).max()))
        ideal = np.flatnonzero(present & ~np.isfinite(bounds))
        ideal = ideal[ideal > 0]
        bounded = np.flatnonzero(present & np.isfinite(bounds))
        bounded = bounded[bounded > 0]
        forced = dict(forced)
        records = []
        # rows held before the event carry only integration drift in A V (projected below);
        # a row that was not held is classified by its velocity
        held_before = (prev.state == HELD) if prev is not None else np.zeros(nc, dtype=bool)
        impact = False
        # contact: plastic impact when closing
        contact_in = bool(contact_candidate) and 0 not in forced
        if contact_in and not held_before[0] and AV[0] < -vtol:
            rows = np.concatenate(([0], ideal)).astype(int)
            ke0 = dyn.kinetic_energy(y)
            y, Lam, dE = dyn.project(y, tau, rows, positions=True)
            records.append((impact_kind, 0, {
                "closing_velocity": float(AV[0]), "impulse": float(Lam[0]),
                "wheel_impulses": Lam[1:].tolist(), "energy_loss": float(-dE),
                "kinetic_energy_before": ke0}))
            Q, G, gap, s, AV = dyn.linear_maps(y, tau)
            impact = True
        elif contact_in and not held_before[0] and AV[0] > vtol:
            forced[0] = LOST  # already moving apart
        elif not contact_in and 0 not in forced:
            forced[0] = LOST
        # bounded wheels: sliding when their lateral velocity is not zero (at the start, after
        # an impact, which they cannot resist with a finite force, or when not sticking before)
        for r in bounded:
            if r in forced or (held_before[r] and not impact):
                continue
            if abs(AV[r]) > vtol:
                forced[int(r)] = SLIDE_POS if AV[r] < 0 else SLIDE_NEG
        candidates = present.copy()
        for r in forced:
            candidates[r] = False
        # drift-level projection of every candidate row (and the initial velocities of
        # ideal wheels, which may take an impulse)
        rows = np.flatnonzero(candidates)
        if rows.size:
            ke0 = dyn.kinetic_energy(y)
            y2, Lam, dE = dyn.project(y, tau, rows, positions=bool(candidates[0]))
            drift = float(np.abs(AV[rows]).max())
            if prev is None and drift > vtol:
                # initial velocities against the held rows (e.g. ideal wheels): an impulse
                records.append(("projection", int(rows[np.argmax(np.abs(AV[rows]))]), {
                    "impulses": Lam.tolist(), "energy_loss": float(-dE),
                    "kinetic_energy_before": ke0}))
            elif prev is not None:
                self.drift_corrected = max(self.drift_corrected, drift)
            y = y2
        state = self.decide(y, tau, candidates, forced)
        mode = self.mode(state, off_link)
        for kind, row, data in records:
            events.append(SimEvent(float(t), kind, row, before, mode.describe(), data))
        return y, mode

    def _settled(self, t, st, prev, before, off_link, events, impact_kind):
        """:meth:`settle`'s records, state and mode from the compiled ``core_settle``'s
        answer ``st`` (a :class:`~snakecg.engine.segment.Settle`)."""
        k = self.kernel
        records = []
        if st.impact:
            lam = k.s_impact_lam[:st.n_impact]
            records.append((impact_kind, 0, {
                "closing_velocity": st.impact_velocity, "impulse": float(lam[0]),
                "wheel_impulses": lam[1:].tolist(), "energy_loss": -st.impact_de,
                "kinetic_energy_before": st.impact_ke}))
        if st.n_projected:
            if prev is None and st.drift > st.vtol:
                records.append(("projection", st.drift_row, {
                    "impulses": k.s_projection_lam[:st.n_projected].tolist(),
                    "energy_loss": -st.projection_de,
                    "kinetic_energy_before": st.projection_ke}))
            elif prev is not None:
                self.drift_corrected = max(self.drift_corrected, st.drift)
        mode = self.mode(k.s_state, off_link)
        for kind, row, data in records:
            events.append(SimEvent(float(t), kind, row, before, mode.describe(), data))
        return k.s_y_out.copy(), mode

    def decide(self, y, tau, candidates: np.ndarray, forced: dict[int, int]) -> np.ndarray:
        """Row states: the complementarity problem over ``candidates`` at acceleration level,
        the ``forced`` rows fixed (a sliding wheel's force, a separated contact)."""
        dyn = self.dyn
        q, qo, v, vo = dyn.split(y)
        nc = dyn.nc
        bounds = dyn.bounds
        fixed_lam = np.zeros(nc)
        for r, st in forced.items():
            if st == SLIDE_POS:
                fixed_lam[r] = bounds[r]
            elif st == SLIDE_NEG:
                fixed_lam[r] = -bounds[r]
        fmask = np.zeros(nc, dtype=bool)
        fmask[list(forced)] = True

        def call(idx, free, lam_fixed, reg):
            m = len(idx)
            lf = np.where(fmask[None, :], fixed_lam[None, :], lam_fixed)
            if m == 1:  # the one-sample buffers (the same compiled function, less Python)
                one = dyn.cd.one(q=q, v=v, tau=tau, q_obj=qo, v_obj=vo, free=free[0],
                                 lam_fixed=lf[0], regularization=float(reg[0]))
                outs = {name: np.array(o)[None] for name, o in zip(dyn.cd.out_names, one)}
                dyn.cd.set(regularization=0.0)
            else:
                outs = dyn.cd.many(m, q=q, v=v, tau=tau, q_obj=qo, v_obj=vo,
                                   free=np.ascontiguousarray(free),
                                   lam_fixed=np.ascontiguousarray(lf),
                                   regularization=np.asarray(reg, float).reshape(m, 1))
            res = {}
            for name, o in outs.items():
                res[name] = o[:, 0].copy() if o.ndim == 2 and o.shape[1] == 1 else o
            return res

        state = np.full(nc, ABSENT, dtype=np.int8)
        if candidates.any():
            sol = solve_active_set(call, 1, candidates, bounds)
            state = sol.state[0].astype(np.int8)
            if sol.singular[0]:
                dyn.singular += 1
        for r, st in forced.items():
            state[r] = st
        return state
