"""The rare stretches of a simulation answered by the compiled engine itself (integrate.c,
events.c with rows.c's rules), never by the Python engine of ``backend="casadi"``
(``Dynamics``, ``Events``, solve_ivp: refused here while the C runs):

* dependent held rows (two ideal wheels on one joint, the joint straight: their rows
  coincide): the right-hand side with the Tikhonov term against the independent dense model
  of ``tests/reference.py`` with the duplicate row dropped (the accelerations are unique), and
  against the Python engine; a short run in C against the physical laws (the held rows'
  velocities stay zero, the kinetic energy gained is the torques' work) and against
  ``backend="casadi"``;
* an active set that has not settled (one pass allowed): the settle enumerates in C and agrees
  with the Python engine's enumeration on random states, and the states satisfy the
  complementarity conditions by the dense model's enumeration;
* what cannot be answered (a failed evaluation) raises ``SimulationError`` with the time.
"""

from __future__ import annotations

import numpy as np
import pytest
from reference import Reference
from test_simulate_settle import Q3, _pair, _same, _settle, _state, no_python_engine

import snakecg
import snakecg.solver as solver
from snakecg.simulate.inputs import check_arguments
from snakecg.simulate.modes import Mode
from snakecg.simulate.records import SimulationError
from snakecg.simulate.simulator import Simulator
from snakecg.solver import ABSENT, HELD, LOST, SLIDE_POS

STRAIGHT = np.array([0.0, 0.0, 0.0, 0.5, 0.0, -0.8])  # joint 2 straight
TAU = np.array([0.1, -0.05, 0.08])


@pytest.fixture(scope="module")
def dependent():
    """Ideal wheels at both ends of joint 2 (links 2 and 3): dependent rows when straight."""
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="ideal_wheels", kappa=10,
                          wheel_offset=(0, 0.075, -0.075, 0))
    model = snakecg.load(scene)
    if model.core is None:
        pytest.fail("the compiled backend is needed here: the C build failed")
    return scene, model, Reference(scene)


def _simulator(model, q0, tau, T, **kw):
    args = dict(v_obj0=None, q_obj0=None, rho=None, f_obj=None, control_period=None,
                method="DOP853", rtol=1e-9, atol=1e-11, max_step=None, fixed_step=None,
                stabilization=10.0, output_dt=None, max_events=1000)
    args.update(kw)
    return Simulator(check_arguments(model, q0, tau, T, None, **args))


def test_dependent_rows_settle_and_rates_in_c(dependent, monkeypatch):
    """At rest with joint 2 straight: the start's settle in C (projection and decision with
    the dependent rows) gives the Python engine's state and mode; the right-hand side there
    (Tikhonov term) has the accelerations of the dense model with the duplicate row dropped
    (to 1e-8) and the Python engine's (to 1e-9), and the two wheels' forces sum to the
    dropped model's one."""
    scene, model, ref = dependent
    sim = _simulator(model, STRAIGHT, TAU, 0.01)
    cfg = sim.settings
    y = np.concatenate([cfg.q0, cfg.q_obj0, np.zeros(9), np.zeros(3)])
    sys_ = ref.system(cfg.q0, TAU, q_obj=cfg.q_obj0, rho=cfg.rho)
    assert np.abs(sys_["A"][2] - sys_["A"][3]).max() <= 1e-12 * np.abs(sys_["A"][2]).max()
    from snakecg.simulate.events import Events

    with no_python_engine(monkeypatch):
        y_c, mode_c, ev_c, _ = _settle(sim.events, y, None, {}, True)
        r = sim.compiled.samples(y_c, mode_c, TAU)
    assert sim.dyn.singular >= 1  # the C counted the dependent rows
    y_p, mode_p, _, _ = _settle(Events(sim.dyn, sim.torques, sim.events.gtol), y, None, {},
                                True)
    assert (mode_c.state == mode_p.state).all() and list(mode_c.state) == [1, 0, 1, 1, 1]
    assert np.abs(y_c - y_p).max() <= 1e-12 and ev_c == []
    assert r["ok"][0]
    # the dense model with row 3 (the duplicate of row 2) dropped; at rest A V = 0, and the
    # Baumgarte terms are -alpha^2 g on the contact
    H = [0, 2, 4]
    alpha = cfg.alpha
    sys1 = ref.system(y_c[:6], TAU, q_obj=y_c[6:9], rho=cfg.rho)
    w_H = np.zeros(3)
    w_H[0] = -alpha**2 * sys1["gap"]
    lam = np.zeros(5)
    Gc, b = sys1["Gc"], sys1["b"]
    lam[H] = np.linalg.solve(Gc[np.ix_(H, H)], w_H - b[H])
    out = ref.outcome(sys1, lam)
    acc = np.concatenate([out["qdd"], out["a_obj"]])
    got = r["ydot"][0, 9:18]
    assert np.abs(got - acc).max() <= 1e-8 * np.abs(acc).max(), np.abs(got - acc).max()
    lc = r["lam"][0]
    assert abs(lc[2] + lc[3] - lam[2]) <= 1e-8 * np.abs(lam).max()
    assert np.abs(lc[[0, 4]] - lam[[0, 4]]).max() <= 1e-8 * np.abs(lam).max()
    py = sim.dyn.rates(0.0, y_c, mode_c, lambda *_: TAU)
    assert np.abs(got - py[0][9:18]).max() <= 1e-9 * np.abs(acc).max()
    sim.compiled.release()


def test_dependent_rows_run_in_c_keeps_the_physical_laws(dependent, monkeypatch):
    """The first 0.5 ms from the straight joint (joint 2 bends to 4e-6 rad: the held rows stay
    dependent by the pivot ratio, the stretch the Python engine did before), wholly in C (the
    Python engine refused): the dependent rows are regularized (counted); the held rows'
    velocities stay zero (the dense model's rows, to 1e-7 of the largest velocity; 3e-8
    measured) and the kinetic energy gained is the torques' work (the dense model's mass
    matrix) to 1e-2 of it: no impact, no friction, no object wrench. (Measured 3e-3: the
    Tikhonov term leaves the nearly dependent rows' large forces a velocity of order 1e-9 to
    work on, the accuracy the rule states, not float64's.)"""
    scene, model, ref = dependent
    with no_python_engine(monkeypatch):
        tr = model.simulate(STRAIGHT, TAU, 5e-4, geometry_check="off", output_dt=2.5e-5)
    s = tr.summary
    assert s["status"].startswith("completed") and tr.events == []
    assert s["integrator"]["compiled_segments"] and s["integrator"]["singular_samples"] > 0
    assert 0 < abs(tr.q[-1, 4]) < 1e-5
    ke = []
    vmax = max(np.abs(tr.v).max(), np.abs(tr.v_obj).max())
    for i in range(len(tr.t)):
        sys_ = ref.system(tr.q[i], TAU, tr.v[i], tr.v_obj[i], q_obj=tr.q_obj[i], rho=tr.rho)
        av = (sys_["A"] @ sys_["V"])[ref.present]  # the contact and the wheels, all held
        assert np.abs(av).max() <= 1e-7 * vmax, (tr.t[i], av)
        ke.append(0.5 * sys_["V"] @ sys_["I"] @ sys_["V"])
    W = np.asarray(tr.work_tau)  # the integral of tau . qdot_joints
    gain = np.asarray(ke) - ke[0]
    assert W[-1] > 0 and np.abs(gain - (W - W[0])).max() <= 1e-2 * W[-1]


def test_dependent_rows_run_agrees_with_the_python_engine(dependent, monkeypatch):
    """The first 0.5 ms from the straight joint (the dependent stretch): the run in C and the
    run of ``backend="casadi"`` (the Python engine, the same Tikhonov rule) agree to 1e-9
    (m, rad, m/s, rad/s; measured 1e-13 on the positions, 7e-10 on the velocities), and both
    counted the regularized samples."""
    scene, model, _ = dependent
    with no_python_engine(monkeypatch):
        a = model.simulate(STRAIGHT, TAU, 5e-4, geometry_check="off", output_dt=2.5e-5)
    b = snakecg.load(scene, backend="casadi").simulate(STRAIGHT, TAU, 5e-4,
                                                        geometry_check="off", output_dt=2.5e-5)
    assert a.t.shape == b.t.shape and np.array_equal(a.t, b.t)
    for name in ("q", "v", "q_obj", "v_obj"):
        x, z = getattr(a, name), getattr(b, name)
        assert np.abs(x - z).max() <= 1e-9 * max(1.0, np.abs(z).max()), name
    for tr in (a, b):
        assert tr.summary["integrator"]["singular_samples"] > 0


def test_casadi_one_sample_input_is_reset_by_set(dependent):
    """The Python engine's one-sample evaluation on ``backend="casadi"``: an input given to
    one call and reset with ``set`` (the Tikhonov weight after a regularized sample) is not
    used again; the next call answers as the compiled backend's does (pivot ratio, forces)."""
    from snakecg.simulate.dynamics import Dynamics

    scene, model, _ = dependent
    q = np.array([0.0, 0.0, 0.0, 0.5, 0.3, -0.8])
    outs = []
    for m in (model, snakecg.load(scene, backend="casadi")):
        q_obj, rho, _ = m.place(q[None, :], 1)
        cd = Dynamics(m, rho[0], np.zeros(3), 10.0).cd
        args = dict(q=q, v=np.zeros(6), tau=TAU, q_obj=q_obj[0], v_obj=np.zeros(3),
                    free=np.array([1.0, 0, 1, 1, 1]), lam_fixed=np.zeros(5))
        cd.one(**args, regularization=1e-3)
        cd.set(regularization=0.0)
        o = cd.one(**args)
        outs.append((float(o["pivot_ratio"][0]), np.array(o["lam"])))
    (pc, lc), (pp, lp) = outs
    assert pc == pytest.approx(pp, rel=1e-12) and 0.01 < pc < 1
    assert np.abs(lc - lp).max() <= 1e-12 * np.abs(lc).max()


@pytest.mark.parametrize("scenario", ["wheels", "ideal_wheels"])
def test_unsettled_active_sets_are_enumerated_in_c(scenario, monkeypatch):
    """One active-set pass only: the samples that have not settled are enumerated, in C as
    by the Python engine (its own enumeration counted): the same new state and mode on random
    states, modes and forced rows."""
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario, kappa=10.0)
    sm = snakecg.load(scene)
    enumerated = []
    real = solver._enumerate

    def counted(*args):
        enumerated.append(1)
        return real(*args)

    monkeypatch.setattr(solver, "default_max_iter", lambda nc: 1)
    monkeypatch.setattr(solver, "_enumerate", counted)
    rng = np.random.default_rng(23)
    bounds, present = sm.bounds, sm.present
    held = np.where(present, HELD, ABSENT)
    lost = held.copy()
    lost[0] = LOST
    bounded = [r for r in range(1, sm.n_constraints) if present[r] and np.isfinite(bounds[r])]
    prevs = [None, Mode(held, bounds, False), Mode(lost, bounds, False)]
    for trial in range(24):
        tau = rng.normal(size=3) * 0.5
        sim, ev_c, ev_p = _pair(sm, tau)
        sim.compiled.st.max_iter = 1
        y = _state(sim, rng, speed=[0.0, 0.05, 0.5][trial % 3])
        prev = prevs[trial % 3]
        forced = {bounded[0]: SLIDE_POS} if bounded and prev is not None and trial % 4 == 1 \
            else {}
        with no_python_engine(monkeypatch):
            a = _settle(ev_c, y, prev, forced, True)
        b = _settle(ev_p, y, prev, forced, True)
        _same(a, b)
        sim.compiled.release()
    assert len(enumerated) >= 3, len(enumerated)  # the cases are the rare ones


def test_a_failed_segment_raises_with_its_time(monkeypatch):
    """A segment whose evaluation fails (SEG_FAILED) ends the run with SimulationError saying
    when and why; no Python engine takes over."""
    from snakecg.engine.segment import RUN_FAILED, SEG_FAILED

    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=10.0))
    sim = _simulator(sm, Q3, np.array([0.05, 0.0, -0.02]), 0.05)
    sim.compiled._run = lambda address: RUN_FAILED
    with no_python_engine(monkeypatch), pytest.raises(SimulationError,
                                                      match="integration failed at t = 0 s"):
        sim.run()
    sim = _simulator(sm, Q3, np.array([0.05, 0.0, -0.02]), 0.05)
    sim.compiled._run = lambda address: 2  # RUN_PYTHON: the loop over the C segments
    sim.compiled._fn = lambda address: SEG_FAILED
    with pytest.raises(SimulationError, match="derivative is not finite"):
        sim.run()
