"""The compiled integration segments (snakecg/engine/integrate.c via snakecg.simulate.compiled)
against the solve_ivp path and independent references.

* the right-hand side within a mode against the dense numpy model of ``tests/reference.py``
  (held rows solved from its ``G_c``, ``b`` with the Baumgarte terms written out here; row
  velocities ``A V`` from its rows), in every kind of mode;
* whole runs (impacts, contact separation, the contact point leaving the link, breakaway,
  sticking again) against ``integrator="scipy"`` (solve_ivp's DOP853): the same events, event
  times within 1e-9 s, the same samples within 1e-9 m;
* the compiled runs at the default tolerances against solve_ivp at rtol = 1e-12: within
  1e-9 m.
"""

from __future__ import annotations

import numpy as np
import pytest
from reference import Reference

import snakecg
from snakecg.errors import InputError
from snakecg.simulate.inputs import check_arguments
from snakecg.simulate.modes import Mode
from snakecg.simulate.simulator import Simulator
from snakecg.solver import ABSENT, HELD, LOST, SLIDE_NEG, SLIDE_POS

Q3 = np.array([0.0, 0.0, 0.0, 0.5, -0.6, 0.4])
TAU3 = np.array([0.05, 0.0, -0.02])
Q2 = np.array([0.0, 0.0, 0.0, 0.5, -0.6])
NORMAL = np.array([0.0, 1.0])  # contact normal of link 1 at theta = 0, object on the left


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(joints=3, scenario="frictionless", kappa=10.0):
        key = (joints, scenario, kappa)
        if key not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario, kappa=kappa)
            cache[key] = (snakecg.load(scene), Reference(scene))
        return cache[key]

    return get


def _simulator(sm, q0, tau, **kw):
    args = {"v_obj0": None, "q_obj0": None, "rho": None, "f_obj": None,
            "control_period": None, "method": "DOP853", "rtol": 1e-9, "atol": 1e-11,
            "max_step": None, "fixed_step": None, "stabilization": 10.0, "output_dt": None,
            "max_events": 1000}
    args.update(kw)
    return Simulator(check_arguments(sm, q0, tau, 0.1, None, **args))


def _reference_rates(ref, y, state, tau, rho, alpha):
    """ydot, lam, A V of the dense reference in the mode ``state``: sliding wheels at
    +-bound, held rows with w_H = -2 alpha (A V)_H (- alpha^2 g for the contact)."""
    ns = ref.ns
    nx = ns + 3
    q, qo, v, vo = y[:ns], y[ns:nx], y[nx:nx + ns], y[nx + ns:2 * nx]
    sys_ = ref.system(q, tau, v, vo, None, qo, rho)
    AV = sys_["A"] @ sys_["V"]
    lam = np.zeros(ref.nc)
    lam[state == SLIDE_POS] = ref.bounds[state == SLIDE_POS]
    lam[state == SLIDE_NEG] = -ref.bounds[state == SLIDE_NEG]
    H = state == HELD
    w_H = -2 * alpha * AV[H]
    if H[0]:
        w_H[0] -= alpha**2 * sys_["gap"]
    Gc, b = sys_["Gc"], sys_["b"]
    lam[H] = np.linalg.solve(Gc[np.ix_(H, H)], w_H - b[H] - Gc[np.ix_(H, ~H)] @ lam[~H])
    out = ref.outcome(sys_, lam)
    slide = (state == SLIDE_POS) | (state == SLIDE_NEG)
    ydot = np.concatenate([v, vo, out["qdd"], out["a_obj"],
                           [tau @ v[3:], lam[slide] @ AV[slide], 0.0]])
    return ydot, lam, AV, sys_["gap"]


MODES = {
    "frictionless": [(HELD, ABSENT, ABSENT, ABSENT, ABSENT), (LOST, ABSENT, ABSENT, ABSENT,
                                                               ABSENT)],
    "wheels": [(HELD, HELD, HELD, HELD, HELD), (HELD, SLIDE_POS, HELD, SLIDE_NEG, HELD),
               (LOST, HELD, SLIDE_NEG, HELD, HELD)],
    "ideal_wheels": [(HELD, HELD, HELD, HELD, HELD), (LOST, HELD, HELD, HELD, HELD)],
}


@pytest.mark.parametrize("scenario", list(MODES))
def test_right_hand_side_against_dense_reference(models, scenario):
    """The C right-hand side of a mode, at perturbed states off the constraints (so the
    Baumgarte terms act), equals the dense reference's and the Python path's."""
    sm, ref = models(3, scenario)
    sim = _simulator(sm, Q3, TAU3)
    assert sim.compiled is not None
    dyn = sim.dyn
    rng = np.random.default_rng(7)
    for st in MODES[scenario]:
        state = np.array([s if sm.present[r] else ABSENT for r, s in enumerate(st)], np.int8)
        mode = Mode(state, sm.bounds, False)
        for _ in range(3):
            q = Q3 + rng.normal(0, 0.05, 6)
            qo, _, _ = sm.place_object(q)
            qo = qo + rng.normal(0, 1e-3, 3)
            y = np.concatenate([q, qo, rng.normal(0, 0.1, 6), rng.normal(0, 0.05, 3),
                                np.zeros(3)])
            got = sim.compiled.samples(y[None, :], mode, TAU3)
            assert got["ok"].all()
            ydot, lam, AV = got["ydot"][0], got["lam"][0], got["AV"][0]
            gap, s = got["gap"][0], got["s"][0]
            r_ydot, r_lam, r_AV, r_gap = _reference_rates(ref, y, state, TAU3, sim.dyn.rho,
                                                          10.0)
            scale = np.abs(r_ydot).max()
            np.testing.assert_allclose(ydot, r_ydot, rtol=0, atol=1e-8 * scale)
            np.testing.assert_allclose(lam, r_lam, rtol=0, atol=1e-8 * np.abs(r_lam).max())
            np.testing.assert_allclose(AV, r_AV, rtol=0, atol=1e-12)
            assert gap == pytest.approx(r_gap, abs=1e-13)
            # the Python right-hand side (solve_ivp's path): same equations, to rounding
            p_ydot, _, p_gap, p_s, p_AV, extras = dyn.rates(0.0, y, mode,
                                                            lambda t, y, m: TAU3)
            np.testing.assert_allclose(ydot, p_ydot, rtol=0, atol=1e-11 * scale)
            np.testing.assert_allclose(AV, p_AV, rtol=0, atol=1e-14)
            assert s == p_s and gap == p_gap
            # eqs. (26), (27), (30) from the reference's mass matrix and object inertia
            qdd, a_obj = r_ydot[9:15], r_ydot[15:18]
            nq = qdd @ ref.mass_matrix(y[:6]) @ qdd
            na = a_obj @ (np.array([ref.m_obj, ref.m_obj, ref.I_obj_rot]) * a_obj)
            assert got["norm_qdd"][0] == pytest.approx(nq, rel=1e-7)
            assert got["norm_a_obj"][0] == pytest.approx(na, rel=1e-7, abs=1e-14)
            assert got["sr"][0] == pytest.approx(na / (na + nq), rel=1e-7, abs=1e-14)
            assert got["sr"][0] == pytest.approx(extras[1], rel=1e-9, abs=1e-15)


def _thrown(sm, speed=0.2, gap0=0.0103):
    # gap0 / speed = 0.0515 s: the impact falls between output samples (at a sample's time the
    # two integrators may place it on either side of the sample by rounding)
    q_obj, rho, _ = sm.place_object(Q3)
    return {"q_obj0": q_obj + np.r_[gap0 * NORMAL, 0], "rho": rho,
            "v_obj0": np.r_[-speed * NORMAL, 0]}


def _hard_push(sm, radius=4.0):
    """The benchmark's push: bent snake, torque on the input ellipsoid scaled by radius."""
    q0 = np.concatenate([[0.0, 0.0, 0.0], np.deg2rad([30.0, -35.0, 25.0])])
    direction = np.array([1.0, 0.0, -0.4])
    N = sm.maps(q0)["input_metric"]
    tau = radius * direction / np.sqrt(direction @ N @ direction)
    if not sm.forward(q0, tau).contact:
        tau = -tau
    return q0, tau


def _ramp(tau, t1):
    return lambda t: tau * (1 - t / t1)


def _cases(models):
    """(name, model, q0, tau, duration, keywords, expected event kinds). The pushes turn the
    contact link against the object, which it enters at once (test_simulate_penetration.py):
    the contact check reports it and the runs go on."""
    out = []
    sm, _ = models(3, "frictionless")
    out.append(("impact", sm, Q3, np.zeros(3), 0.1, _thrown(sm), {"impact"}))
    sm, _ = models(3, "ideal_wheels")
    out.append(("impact, ideal wheels", sm, Q3, np.zeros(3), 0.06, _thrown(sm), {"impact"}))
    sm, _ = models(2, "frictionless")
    out.append(("separation", sm, Q2, _ramp(np.array([0.05, -0.02]), 0.05), 0.12,
                {"control_period": 0.002}, {"separation"}))
    sm, _ = models(3, "frictionless")
    q0, tau = _hard_push(sm)
    out.append(("off link", sm, q0, tau, 0.5, {}, {"off_link"}))
    sm, _ = models(3, "wheels")
    q0, tau = _hard_push(sm)
    out.append(("breakaway", sm, q0, tau, 0.5, {}, {"breakaway"}))
    L = sm.maps(Q3)["lam_from_tau"] @ TAU3
    scale = 1.0 / np.max(np.abs(L[2:]) / sm.bounds[2:])

    def pulse(t):
        return 1.5 * scale * TAU3 if t < 0.05 else np.zeros(3)

    out.append(("stick", sm, Q3, pulse, 0.2, {"control_period": 0.05}, {"stick"}))
    sm, _ = models(3, "wheels")
    q0, tau = _hard_push(sm, 2.0)
    out.append(("wrench on the object, max_step", sm, q0, tau, 0.3,
                {"f_obj": np.array([0.05, -0.08, 0.002]), "max_step": 0.01}, set()))
    return [(*c[:5], {"geometry_check": "report", **c[5]}, c[6]) for c in out]


def _positions(sm, traj):
    """Link COM positions and the object's position at every sample (m)."""
    P = sm.link_poses(traj.q)[:, :, :2]
    return np.concatenate([P.reshape(len(traj.t), -1), traj.q_obj[:, :2]], axis=1)


def test_compiled_runs_match_solve_ivp(models):
    """Every scenario: the compiled segments give solve_ivp's events (kinds, rows, order) at
    the same times to 1e-9 s and the same samples to 1e-9 m, and evaluate the right-hand side
    about as often (the same steps)."""
    for name, sm, q0, tau, T, kw, kinds in _cases(models):
        a = sm.simulate(q0, tau, T, integrator="scipy", output_dt=T / 50, **kw)
        b = sm.simulate(q0, tau, T, integrator="compiled", output_dt=T / 50, **kw)
        assert b.summary["integrator"]["compiled_segments"], name
        assert not a.summary["integrator"]["compiled_segments"], name
        assert kinds <= {e.kind for e in a.events}, (name, a.events)
        assert [(e.kind, e.row) for e in a.events] == [(e.kind, e.row) for e in b.events], name
        ta, tb = np.array([e.t for e in a.events]), np.array([e.t for e in b.events])
        assert np.abs(ta - tb).max(initial=0) <= 1e-9, (name, ta - tb)
        assert a.t.shape == b.t.shape, name
        assert np.abs(a.t - b.t).max() <= 1e-9, name
        err = np.abs(_positions(sm, a) - _positions(sm, b)).max()
        assert err <= 1e-9, (name, err)
        assert np.abs(a.q_obj - b.q_obj).max() <= 1e-9, name
        # velocities, work integrals and the per-sample forces and metrics (assembled from
        # the compiled samples against the Python right-hand side)
        for field in ("v", "v_obj", "work_tau", "work_friction", "work_object", "lam", "qdd",
                      "sr", "row_velocity", "gap", "kinetic_energy"):
            x, z = getattr(a, field), getattr(b, field)
            assert np.abs(x - z).max() <= 1e-7 * max(1.0, np.abs(x).max()), (name, field)
        assert (a.contact == b.contact).all() and (a.wheel_state == b.wheel_state).all()
        na, nb = (x.summary["integrator"]["rhs_evaluations"] for x in (a, b))
        assert abs(na - nb) <= 0.1 * na, (name, na, nb)


def test_compiled_runs_against_tight_tolerance(models):
    """The compiled segments at the default tolerances against solve_ivp at rtol = 1e-12,
    atol = 1e-14: every link COM and the object within 1e-9 m at the end."""
    for name, sm, q0, tau, T, kw, kinds in _cases(models):
        tight = sm.simulate(q0, tau, T, integrator="scipy", rtol=1e-12, atol=1e-14,
                            output_dt=T, **kw)
        run = sm.simulate(q0, tau, T, integrator="compiled", output_dt=T, **kw)
        assert [e.kind for e in run.events] == [e.kind for e in tight.events], name
        err = np.abs(_positions(sm, run)[-1] - _positions(sm, tight)[-1]).max()
        assert err <= 1e-9, (name, err)


def test_auto_chooses_the_compiled_segments_when_it_can(models):
    """``integrator="auto"`` compiles constant and held torques with DOP853; a law evaluated
    continuously, another method or fixed steps go through solve_ivp; ``"compiled"`` says
    why it cannot."""
    sm, _ = models(3, "frictionless")
    law = _ramp(TAU3, 0.2)
    assert sm.simulate(Q3, TAU3, 0.02).summary["integrator"]["compiled_segments"]
    assert sm.simulate(Q3, law, 0.02, control_period=0.01).summary["integrator"][
        "compiled_segments"]
    for kw in ({"method": "RK45"}, {"fixed_step": 1e-3}):
        assert not sm.simulate(Q3, TAU3, 0.02, **kw).summary["integrator"]["compiled_segments"]
    assert not sm.simulate(Q3, law, 0.02).summary["integrator"]["compiled_segments"]
    with pytest.raises(InputError, match="integrator='compiled'.*RK45"):
        sm.simulate(Q3, TAU3, 0.02, method="RK45", integrator="compiled")
    with pytest.raises(InputError, match="continuously"):
        sm.simulate(Q3, law, 0.02, integrator="compiled")
    with pytest.raises(InputError, match="integrator must be"):
        sm.simulate(Q3, TAU3, 0.02, integrator="fast")


def test_failed_segment_raises_instead_of_switching_engines(models, monkeypatch):
    """A segment the C cannot answer (SEG_FAILED: a failed evaluation, a derivative that is
    not finite) ends the run with SimulationError saying when; solve_ivp never takes over."""
    import scipy.integrate

    from snakecg.engine.segment import RUN_PYTHON, SEG_FAILED
    from snakecg.simulate.records import SimulationError

    sm, _ = models(3, "wheels")
    q0, tau = _hard_push(sm)
    sim = _simulator(sm, q0, tau, output_dt=0.01)
    sim.settings.duration = 0.3
    sim.compiled._run = lambda address: RUN_PYTHON  # the Python loop over the C segments
    sim.compiled._fn = lambda address: SEG_FAILED

    def refuse(*args, **kwargs):
        raise AssertionError("solve_ivp took over a compiled segment")

    monkeypatch.setattr(scipy.integrate, "solve_ivp", refuse)
    with pytest.raises(SimulationError, match="integration failed at t = .* s: .*not finite"):
        sim.run()
    assert sim.compiled.runs_handed_back == 1
