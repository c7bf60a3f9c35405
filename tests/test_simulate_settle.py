"""What the simulation does at an event, in C (snakecg/engine/events.c through
``CompiledSegments.settle``), against the Python reference path of
``snakecg.simulate.events.Events.settle`` (``snakecg.solver.solve_active_set``, numpy's LU
solve) and the dense numpy model of ``tests/reference.py``:

* on random states (closing, separating and sliding velocities, positions off the contact),
  after every kind of mode and with forced rows: the same new state to 1e-12, the same row
  states, the same event records and the same drift;
* a plastic impact against the dense model: the held rows' velocities vanish after it,
  ``I (V+ - V-) = A_R^T Lam`` (the impulse through the rows), the energy lost is
  ``1/2 (V-^T I V- - V+^T I V+)``;
* at rest the new active set is the one that satisfies the complementarity conditions by
  enumeration of the dense model;
* the trajectory's summary, computed on first access, against its arrays and the dense model
  (also in a copy and after pickling).
"""

from __future__ import annotations

import contextlib

import numpy as np
import pytest
from reference import Reference

import snakecg
from snakecg.simulate.events import Events
from snakecg.simulate.inputs import check_arguments
from snakecg.simulate.modes import Mode
from snakecg.simulate.simulator import Simulator
from snakecg.solver import ABSENT, HELD, LOST, SLIDE_NEG, SLIDE_POS

Q3 = np.array([0.0, 0.0, 0.0, 0.5, -0.6, 0.4])
NAMES = {HELD: "held", LOST: "lost", SLIDE_POS: "slide+", SLIDE_NEG: "slide-",
         ABSENT: "absent"}


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(scenario):
        if scenario not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario, kappa=10.0)
            cache[scenario] = (snakecg.load(scene), Reference(scene))
        return cache[scenario]

    return get


def _pair(sm, tau):
    """The event handling of one run with the compiled kernel, and the Python one."""
    sim = Simulator(check_arguments(
        sm, Q3, tau, 0.1, None, v_obj0=None, q_obj0=None, rho=None, f_obj=None,
        control_period=None, method="DOP853", rtol=1e-9, atol=1e-11, max_step=None,
        fixed_step=None, stabilization=10.0, output_dt=None, max_events=1000))
    assert sim.events.kernel is not None
    return sim, sim.events, Events(sim.dyn, sim.torques, sim.events.gtol)


def _state(sim, rng, speed, shift=0.0):
    """A state at Q3 with random velocities (scale ``speed``) and the object moved by
    ``shift`` (m) along a random direction."""
    cfg = sim.settings
    qo = cfg.q_obj0 + shift * rng.normal(size=3) * np.array([1.0, 1.0, 0.1])
    return np.concatenate([cfg.q0, qo, speed * rng.normal(size=6), speed * rng.normal(size=3),
                           np.zeros(3)])


def _same(a, b):
    (ya, ma, ea, da), (yb, mb, eb, db) = a, b
    assert np.abs(ya - yb).max() <= 1e-12 * max(1.0, np.abs(yb).max()), np.abs(ya - yb).max()
    assert (ma.state == mb.state).all() and ma.off_link == mb.off_link
    assert [(e.kind, e.row, e.before, e.after) for e in ea] == \
        [(e.kind, e.row, e.before, e.after) for e in eb]
    for x, z in zip(ea, eb):
        assert x.data.keys() == z.data.keys()
        for k in x.data:
            u, w = np.asarray(x.data[k], float), np.asarray(z.data[k], float)
            assert np.abs(u - w).max(initial=0) <= 1e-12 * max(1.0, np.abs(w).max(initial=0)), k
    assert abs(da - db) <= 1e-12 * max(1.0, abs(db))


def _refuse(*args, **kwargs):
    raise AssertionError("the compiled simulation reached the Python engine")


@contextlib.contextmanager
def no_python_engine(monkeypatch):
    """A context in which any call into the Python engine of the simulation (its right-hand
    side, linear maps, projections, active-set decisions, solve_ivp) fails the test."""
    import scipy.integrate

    from snakecg.simulate.dynamics import Dynamics

    with monkeypatch.context() as m:
        for cls, name in ((Dynamics, "rates"), (Dynamics, "linear_maps"),
                          (Dynamics, "project"), (Dynamics, "kinetic_energy"),
                          (Events, "decide"), (scipy.integrate, "solve_ivp")):
            m.setattr(cls, name, _refuse)
        yield


def _settle(ev, y, prev, forced, candidate):
    events = []
    y2, mode = ev.settle(0.0, y, prev, forced, contact_candidate=candidate, off_link=False,
                         events=events)
    return y2, mode, events, ev.drift_corrected


@pytest.mark.parametrize("scenario", ["frictionless", "wheels", "ideal_wheels"])
def test_compiled_settle_matches_python_reference(models, scenario, monkeypatch):
    sm, _ = models(scenario)
    rng = np.random.default_rng(7)
    nc = sm.n_constraints
    present, bounds = sm.present, sm.bounds
    bounded = [r for r in range(1, nc) if present[r] and np.isfinite(bounds[r])]
    held = np.where(present, HELD, ABSENT)
    prevs = [None, Mode(held, bounds, False)]
    lost = held.copy()
    lost[0] = LOST
    prevs.append(Mode(lost, bounds, False))
    if bounded:
        slide = held.copy()
        slide[bounded[0]] = SLIDE_POS
        prevs.append(Mode(slide, bounds, False))
    checked = 0
    kinds = set()
    for trial in range(48):
        tau = rng.normal(size=3) * 0.3
        sim, ev_c, ev_p = _pair(sm, tau)
        y = _state(sim, rng, speed=[0.0, 1e-9, 0.05, 0.5][trial % 4],
                   shift=1e-5 if trial % 3 == 0 else 0.0)
        prev = prevs[trial % len(prevs)]
        forced = {}
        if prev is not None and bounded and trial % 5 == 1:
            forced[bounded[-1]] = SLIDE_NEG
        if trial % 7 == 3:
            forced[0] = LOST
        candidate = trial % 6 != 5
        with no_python_engine(monkeypatch):
            a = _settle(ev_c, y, prev, forced, candidate)
        b = _settle(ev_p, y, prev, forced, candidate)
        _same(a, b)
        kinds |= {e.kind for e in a[2]}
        checked += 1
    assert "impact" in kinds or scenario != "frictionless", kinds


def test_compiled_impact_against_dense_reference(models, monkeypatch):
    """A contact closing at 0.3 m/s with ideal wheels: the impulse through the contact and the
    wheel rows (dense model: ``I dV = A_R^T Lam``), the rows' velocities zero after it, the
    energy lost ``1/2 dV^T I dV`` short of the kinetic energy before."""
    sm, ref = models("ideal_wheels")
    sim, ev_c, _ = _pair(sm, np.zeros(3))
    cfg = sim.settings
    rng = np.random.default_rng(3)
    v = 0.05 * rng.normal(size=6)
    sys0 = ref.system(cfg.q0, np.zeros(3), v, np.zeros(3), None, cfg.q_obj0, cfg.rho)
    # object velocity that closes the contact at 0.3 m/s: along -n from the row's own gradient
    A = sys0["A"]
    vo = -0.3 * A[0, 6:] / (A[0, 6:] @ A[0, 6:]) - (A[0, :6] @ v) * A[0, 6:] / (
        A[0, 6:] @ A[0, 6:])
    y = np.concatenate([cfg.q0, cfg.q_obj0, v, vo, np.zeros(3)])
    assert abs(np.concatenate([v, vo]) @ A[0] + 0.3) < 1e-12
    with no_python_engine(monkeypatch):
        y2, _, events, _ = _settle(ev_c, y, None, {}, True)
    assert events[0].kind == "impact"
    assert abs(events[0].data["closing_velocity"] + 0.3) <= 1e-9
    sys1 = ref.system(y2[:6], np.zeros(3), y2[9:15], y2[15:18], None, y2[6:9], cfg.rho)
    V0, V1 = np.concatenate([v, vo]), sys1["V"]
    R = np.flatnonzero(ref.present)
    assert np.abs(sys1["A"][R] @ V1).max() <= 1e-12
    lam = np.array([events[0].data["impulse"], *events[0].data["wheel_impulses"]])
    dV = V1 - V0
    I = sys0["I"]
    assert np.allclose(I @ dV, A[R].T @ lam, rtol=0, atol=1e-10 * np.abs(lam).max())
    loss = 0.5 * (V0 @ I @ V0 - V1 @ I @ V1)
    assert abs(events[0].data["energy_loss"] - loss) <= 1e-10 * loss
    assert abs(events[0].data["kinetic_energy_before"] - 0.5 * V0 @ I @ V0) <= 1e-12


@pytest.mark.parametrize("scenario", ["frictionless", "wheels", "ideal_wheels"])
def test_compiled_active_set_at_rest_against_enumeration(models, scenario, monkeypatch):
    """At rest and touching, the new mode is the active set that the dense model's
    enumeration finds (samples whose rows are decided by a clear margin)."""
    sm, ref = models(scenario)
    rng = np.random.default_rng(11)
    seen = set()
    for _ in range(30):
        tau = rng.normal(size=3) * 0.5
        sim, ev_c, _ = _pair(sm, tau)
        cfg = sim.settings
        sol = ref.solve(cfg.q0, tau, q_obj=cfg.q_obj0, rho=cfg.rho)
        if np.min(sol["margins"]) <= 1e-6 * max(1.0, np.abs(sol["lam"]).max()):
            continue
        y = np.concatenate([cfg.q0, cfg.q_obj0, np.zeros(9), np.zeros(3)])
        with no_python_engine(monkeypatch):
            _, mode, _, _ = _settle(ev_c, y, None, {}, True)
        assert [NAMES[int(s)] for s in mode.state] == sol["states"]
        seen.add(tuple(sol["states"]))
    assert len(seen) >= 2, seen


def test_summary_on_first_access(models):
    """The summary is computed when first read, from the trajectory's own arrays: the same
    numbers as the arrays give (object displacement, final kinetic energy, event counts), in
    a copy and after a pickle round trip as well."""
    import copy
    import json
    import pickle

    sm, ref = models("wheels")
    q0 = Q3
    tau = np.array([0.4, 0.0, -0.2])
    traj = sm.simulate(q0, tau, 0.2, output_dt=0.05)
    assert "summary" not in traj.__dict__  # not computed yet
    clone = pickle.loads(pickle.dumps(traj))
    assert "summary" in traj.__dict__  # pickling computed it first
    s = traj.summary
    assert clone.summary == s and copy.deepcopy(traj).summary == s
    json.dumps(s)
    d = traj.q_obj[-1] - traj.q_obj[0]
    assert s["object_displacement"]["x"] == d[0] and s["object_displacement"]["y"] == d[1]
    # final kinetic energy from the dense model's mass matrix
    M = ref.mass_matrix(traj.q[-1])
    ke = 0.5 * traj.v[-1] @ M @ traj.v[-1] + 0.5 * traj.v_obj[-1] @ (
        np.array([ref.m_obj, ref.m_obj, ref.I_obj_rot]) * traj.v_obj[-1])
    assert abs(s["energy"]["kinetic_final"] - ke) <= 1e-12 * max(1.0, ke)
    counts = {}
    for e in traj.events:
        counts[e.kind] = counts.get(e.kind, 0) + 1
    assert s["event_counts"] == counts


def test_compiled_kinematics_against_dense_reference(models):
    """The assembly's batch evaluation of M_s and the link poses on the run's arrays
    (``CompiledSegments.kinematics``) against the dense model at random configurations."""
    sm, ref = models("wheels")
    sim, _, _ = _pair(sm, np.zeros(3))
    Q = np.random.default_rng(5).normal(size=(7, 6))
    M, P = sim.compiled.kinematics(Q)
    for q, Mi, Pi in zip(Q, M, P):
        assert np.abs(Mi - ref.mass_matrix(q)).max() <= 1e-12 * np.abs(Mi).max()
        assert np.abs(Pi - ref.link_poses(q)).max() <= 1e-12


def _push(sm, ref, radius):
    """A push on the input ellipsoid (as benchmarks/bench_simulate.py) at Q3, keeping the
    contact at t = 0."""
    direction = np.array([1.0, 0.0, -0.4])
    N = sm.maps(Q3)["input_metric"]
    tau = radius * direction / np.sqrt(direction @ N @ direction)
    return tau if sm.forward(Q3, tau).contact else -tau


@pytest.mark.parametrize("scenario", ["frictionless", "wheels", "ideal_wheels"])
def test_compiled_run_matches_python_loop(models, scenario, monkeypatch):
    """The whole run in C (core_run) against the Python loop over the same compiled segments
    and settles: the same samples to 1e-12, the same events and summary, on pushes with
    impacts, separations, the contact point leaving the link, breakaways, sticking, initial
    velocities, and runs stopped by max_events."""
    sm, ref = models(scenario)
    rng = np.random.default_rng(17)
    cases = []
    report = {"geometry_check": "report"}  # (the link enters the object at once: go on)
    for radius in (1.0, 4.0, 8.0):
        tau = _push(sm, ref, radius)
        cases.append((tau, report))
        cases.append((tau, {"v0": 0.3 * rng.normal(size=6), "output_dt": 0.01, **report}))
    cases.append((_push(sm, ref, 8.0), {"max_events": 1, **report}))
    cases.append((_push(sm, ref, 4.0), {}))  # stopped there
    kinds = set()
    for tau, kw in cases:
        a = sm.simulate(Q3, tau, 0.5, integrator="compiled", **kw)
        with monkeypatch.context() as m:
            m.setattr(Simulator, "_run_compiled", lambda self, *args: None)
            b = sm.simulate(Q3, tau, 0.5, integrator="compiled", **kw)
        assert [(e.kind, e.row, e.before, e.after) for e in a.events] == \
            [(e.kind, e.row, e.before, e.after) for e in b.events]
        for x, z in zip(a.events, b.events):
            assert abs(x.t - z.t) <= 1e-15
            for k in x.data:
                assert np.allclose(x.data[k], z.data[k], rtol=1e-12, atol=1e-15)
        assert a.t.shape == b.t.shape
        for name, x in a.arrays().items():
            z = getattr(b, name)
            if x.dtype.kind == "f":
                assert np.allclose(x, z, rtol=1e-12, atol=1e-12, equal_nan=True), name
            else:
                assert (x == z).all(), name
        sa, sb = a.summary, b.summary
        for k in ("status", "initial_mode", "final_mode", "event_counts", "contact",
                  "violation"):
            assert sa[k] == sb[k], k
        ia, ib = sa["integrator"], sb["integrator"]
        assert (ia["segments"], ia["rhs_evaluations"]) == (ib["segments"], ib["rhs_evaluations"])
        kinds |= {e.kind for e in a.events}
        if kw.get("max_events") == 1:
            assert sa["status"] == "penetration" and len(a.events) <= 1
    assert len(kinds) >= 3, kinds


def test_placement_against_dense_reference(models):
    """The checks' placement of the object (``placement``: the compiled ``place_object`` with
    its constants packed once) against the dense model's placement, at random shapes."""
    from snakecg.simulate.compiled import placement

    sm, ref = models("ideal_wheels")
    rng = np.random.default_rng(9)
    for _ in range(10):
        q = np.concatenate([rng.normal(size=3), rng.uniform(-1.5, 1.5, size=3)])
        q_obj, rho = placement(sm, q)
        q_ref, rho_ref, _ = ref.place_object(q)
        assert np.abs(q_obj - q_ref).max() <= 1e-12 and np.abs(rho - rho_ref).max() <= 1e-12


def test_compiled_run_handed_back_midway(models, monkeypatch):
    """A whole run in C that runs out of room for its events midway is done again by the
    Python loop from the start (with the same compiled segments): the same trajectory as the
    Python loop alone."""
    import snakecg.simulate.compiled as compiled

    sm, ref = models("wheels")
    tau = _push(sm, ref, 8.0)
    report = {"geometry_check": "report"}  # (the link enters the object at once: go on)
    a = sm.simulate(Q3, tau, 0.5, integrator="compiled", **report)
    assert len(a.events) >= 2
    monkeypatch.setattr(compiled, "RUN_EVENTS", 0)  # room for one event
    b = sm.simulate(Q3, tau, 0.5, integrator="compiled", **report)
    with monkeypatch.context() as m:
        m.setattr(Simulator, "_run_compiled", lambda self, *args: None)
        c = sm.simulate(Q3, tau, 0.5, integrator="compiled", **report)
    for x in (a, b):
        assert [(e.kind, e.row, e.t) for e in x.events] == [(e.kind, e.row, e.t) for e in c.events]
        assert np.allclose(x.q, c.q, rtol=0, atol=1e-12) and np.allclose(x.lam, c.lam, rtol=1e-12,
                                                                          atol=1e-12)
