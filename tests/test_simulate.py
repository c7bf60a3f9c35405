"""Pushing over time (issue #8): physical laws, convergence and independent references.

References, none of which shares code with ``snakecg.simulate``:

* the dense numpy model of ``tests/reference.py`` (kinematics from positions, complex-step
  Jacobians): the snake's COM and linear momentum, the kinetic energy, the gap and the rows'
  velocities ``A V`` (contact gap rate, lateral wheel velocities), the Delassus matrix;
* physical laws: conservation of linear momentum without ground friction (the contact force
  is internal), work of a constant torque ``tau . dq_joints`` = kinetic energy gained when
  every constraint is workless, the plastic-impact energy loss ``1/2 (A V)^T G^-1 (A V)``;
* an independent integration of the instant analysis (``SceneModel.forward``, the library's
  active-set solver, in ``scipy.integrate.solve_ivp``) for the times of the transitions;
* the measured order of the fixed-step integrators against a tight reference run.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from reference import Reference
from scipy.integrate import solve_ivp

import snakecg
from snakecg import cli
from snakecg.simulate import SimulationError, State, save_figures, simulate

Q3 = np.array([0.0, 0.0, 0.0, 0.5, -0.6, 0.4])
#: Most runs here test the model's equations over pushes in which the contact link turns
#: against the object. The model keeps the contact point fixed in the object, so the link
#: enters the object within a millisecond (test_simulate_penetration.py): the contact check
#: reports it (the status) and the equations are integrated on, unchanged.
EQUATIONS = {"geometry_check": "report"}
TAU3 = np.array([0.05, 0.0, -0.02])
Q2 = np.array([0.0, 0.0, 0.0, 0.5, -0.6])


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(joints=3, scenario="frictionless", kappa=10.0, **kw):
        key = (joints, scenario, kappa, tuple(sorted(kw.items())))
        if key not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario, kappa=kappa,
                                  **kw)
            cache[key] = (snakecg.load(scene), Reference(scene))
        return cache[key]

    return get


# ------------------------------------------------------------------------------------------
# helpers written from the reference model
# ------------------------------------------------------------------------------------------
def snake_com(ref: Reference, q):
    P = ref.link_poses(q)
    return ref.mass @ P[:, :2] / ref.mass.sum()


def linear_momentum(ref: Reference, q, v, v_obj):
    J = ref.jacobians(q)  # (n_l, 3, n_s)
    vel = np.einsum("lij,j->li", J, v)[:, :2]
    return ref.mass @ vel + ref.m_obj * np.asarray(v_obj)[:2]


def kinetic_energy(ref: Reference, q, v, v_obj):
    M = ref.mass_matrix(q)
    mo = np.array([ref.m_obj, ref.m_obj, ref.I_obj_rot])
    return 0.5 * v @ M @ v + 0.5 * np.sum(mo * np.asarray(v_obj) ** 2)


def row_velocities(ref: Reference, traj, i):
    x = np.concatenate([traj.q[i], traj.q_obj[i]])
    V = np.concatenate([traj.v[i], traj.v_obj[i]])
    return ref.rows(x, traj.rho) @ V


# ------------------------------------------------------------------------------------------
# conservation laws
# ------------------------------------------------------------------------------------------
def test_frictionless_momentum_com_relation(models):
    """No ground friction: total linear momentum is conserved, so from rest the snake's COM
    moves by -kappa m / M_snake times the object's displacement, at every sample."""
    sm, ref = models(3, "frictionless", 10.0)
    traj = sm.simulate(Q3, TAU3, 0.5, output_dt=0.05, **EQUATIONS)
    assert traj.summary["status"] == "penetration" and traj.t[-1] == 0.5
    assert traj.contact.all() and not traj.events  # held throughout: a real push
    d_obj = traj.q_obj[:, :2] - traj.q_obj[0, :2]
    assert np.hypot(*d_obj[-1]) > 5e-3  # the object moved several mm
    com0 = snake_com(ref, traj.q[0])
    d_com = np.array([snake_com(ref, q) - com0 for q in traj.q])
    ratio = ref.m_obj / ref.mass.sum()
    np.testing.assert_allclose(d_com, -ratio * d_obj, rtol=0, atol=1e-9)


def test_momentum_conserved_through_impact(models):
    """An object thrown at the resting snake: the plastic impact and the contact force are
    internal, so the momentum stays m_obj v_obj0 before, at and after the impact."""
    sm, ref = models(3, "frictionless", 10.0)
    q_obj, rho, _ = sm.place_object(Q3)
    n = np.array([0.0, 1.0])  # contact normal of link 1 at theta = 0, object on the left
    speed, gap0 = 0.2, 0.01
    traj = sm.simulate(Q3, np.zeros(3), 0.3, q_obj0=q_obj + np.r_[gap0 * n, 0], rho=rho,
                       v_obj0=np.r_[-speed * n, 0], output_dt=0.02)
    assert [e.kind for e in traj.events][:1] == ["impact"]
    P0 = ref.m_obj * speed * -n
    for i in range(traj.n_samples):
        P = linear_momentum(ref, traj.q[i], traj.v[i], traj.v_obj[i])
        np.testing.assert_allclose(P, P0, rtol=0, atol=1e-9)


@pytest.mark.parametrize("scenario", ["frictionless", "ideal_wheels"])
def test_work_of_constant_torque_equals_kinetic_energy(models, scenario):
    """Conservative scenarios (held contact, ideal wheels: workless constraints): the work of
    a constant torque, tau . (q_joints(t) - q_joints(0)), equals the kinetic energy gained."""
    sm, ref = models(3, scenario, 10.0)
    tau = 2 * TAU3
    traj = sm.simulate(Q3, tau, 0.4, output_dt=0.1, **EQUATIONS)
    assert traj.contact.all() and not traj.events
    for i in range(traj.n_samples):
        work = tau @ (traj.q[i, 3:] - traj.q[0, 3:])
        ke = kinetic_energy(ref, traj.q[i], traj.v[i], traj.v_obj[i])
        assert abs(ke - work) <= 1e-9 * max(work, 1e-3), (traj.t[i], ke, work)
    assert traj.kinetic_energy[-1] > 1e-3
    assert abs(traj.summary["energy"]["balance_residual"]) < 1e-10


def test_impact_is_plastic_and_dissipates_the_computed_energy(models):
    """Plastic impact at t = gap/speed (the snake is at rest and unforced until then): the
    normal relative velocity vanishes, and the kinetic energy lost is 1/2 gdot^2 / G_cc with
    G_cc = A_c I^-1 A_c^T of the reference model."""
    sm, ref = models(3, "frictionless", 10.0)
    q_obj, rho, _ = sm.place_object(Q3)
    n = np.array([0.0, 1.0])
    speed, gap0 = 0.2, 0.01
    traj = sm.simulate(Q3, np.zeros(3), 0.1, q_obj0=q_obj + np.r_[gap0 * n, 0], rho=rho,
                       v_obj0=np.r_[-speed * n, 0])
    ev = traj.events[0]
    assert ev.kind == "impact"
    assert abs(ev.t - gap0 / speed) < 1e-12
    i = np.flatnonzero(traj.t == ev.t)
    before, after = i[0], i[-1]
    sys_ = ref.system(traj.q[before], np.zeros(3), traj.v[before], traj.v_obj[before], None,
                      traj.q_obj[before], rho)
    gdot = (sys_["A"] @ sys_["V"])[0]
    assert gdot == pytest.approx(-speed, rel=1e-12)
    loss = 0.5 * gdot**2 / sys_["Gc"][0, 0]
    assert ev.data["energy_loss"] == pytest.approx(loss, rel=1e-10)
    ke_b = kinetic_energy(ref, traj.q[before], traj.v[before], traj.v_obj[before])
    ke_a = kinetic_energy(ref, traj.q[after], traj.v[after], traj.v_obj[after])
    assert ke_b - ke_a == pytest.approx(loss, rel=1e-9)
    assert abs(row_velocities(ref, traj, after)[0]) < 1e-12
    assert traj.summary["energy"]["impact_loss"] == pytest.approx(loss, rel=1e-12)
    assert abs(traj.summary["energy"]["balance_residual"]) < 1e-10


def test_impact_with_ideal_wheels_takes_wheel_impulses(models):
    """With bilateral ideal wheels the impact problem holds every row: after it the gap rate
    and every lateral wheel velocity vanish, the loss is 1/2 (A V)_F^T G_FF^-1 (A V)_F."""
    sm, ref = models(3, "ideal_wheels", 10.0)
    q_obj, rho, _ = sm.place_object(Q3)
    n = np.array([0.0, 1.0])
    traj = sm.simulate(Q3, np.zeros(3), 0.06, q_obj0=q_obj + np.r_[0.01 * n, 0], rho=rho,
                       v_obj0=np.r_[-0.2 * n, 0])
    ev = traj.events[0]
    assert ev.kind == "impact"
    i = np.flatnonzero(traj.t == ev.t)
    sys_ = ref.system(traj.q[i[0]], np.zeros(3), traj.v[i[0]], traj.v_obj[i[0]], None,
                      traj.q_obj[i[0]], rho)
    F = np.flatnonzero(ref.present)
    AV = (sys_["A"] @ sys_["V"])[F]
    loss = 0.5 * AV @ np.linalg.solve(sys_["Gc"][np.ix_(F, F)], AV)
    assert ev.data["energy_loss"] == pytest.approx(loss, rel=1e-9)
    assert np.abs(row_velocities(ref, traj, i[-1])[F]).max() < 1e-12


def test_initial_velocity_against_ideal_wheels_is_projected(models):
    """Initial snake velocities that violate ideal wheels: the wheels take an impulse at
    t = 0 (mass-weighted projection, a plastic impact of the wheels), reported as an event
    with the loss 1/2 (A V)_F^T G_FF^-1 (A V)_F of the reference model."""
    sm, ref = models(3, "ideal_wheels", 10.0)
    v0 = np.array([0.1, 0.05, 0.0, 0.0, 0.2, 0.0])
    traj = sm.simulate(Q3, TAU3, 0.05, v0=v0)
    at0 = [e for e in traj.events if e.t == 0.0]
    q_obj, rho, _ = sm.place_object(Q3)
    sys_ = ref.system(Q3, TAU3, v0, np.zeros(3), None, q_obj, rho)
    AV_all = sys_["A"] @ sys_["V"]
    # the contact takes part if it is closing (then it is a plastic impact at t = 0)
    F = np.flatnonzero(ref.present & ((np.arange(ref.nc) > 0) | (AV_all[0] < 0)))
    assert [e.kind for e in at0] == (["impact"] if AV_all[0] < 0 else ["projection"])
    AV = AV_all[F]
    assert np.abs(AV_all[2:]).max() > 1e-2  # really inconsistent with the wheels
    loss = 0.5 * AV @ np.linalg.solve(sys_["Gc"][np.ix_(F, F)], AV)
    assert sum(e.data["energy_loss"] for e in at0) == pytest.approx(loss, rel=1e-9)
    assert np.abs(row_velocities(ref, traj, 0)[F]).max() < 1e-12
    assert abs(traj.summary["energy"]["balance_residual"]) < 1e-10


# ------------------------------------------------------------------------------------------
# constraints
# ------------------------------------------------------------------------------------------
def test_ideal_wheels_residuals_bounded_and_reported(models):
    """Ideal wheels: the lateral wheel velocities and the contact gap, recomputed with the
    reference model at every sample, stay at integration-error level; the summary reports
    them (its maxima match the recomputed ones)."""
    sm, ref = models(3, "ideal_wheels", 10.0)
    traj = sm.simulate(Q3, 3 * TAU3, 0.5, output_dt=0.025, **EQUATIONS)
    assert traj.contact.all()
    u = np.array([row_velocities(ref, traj, i)[2:] for i in range(traj.n_samples)])
    gap = np.array([ref.gap(np.concatenate([traj.q[i], traj.q_obj[i]]), traj.rho)
                    for i in range(traj.n_samples)])
    assert np.abs(u).max() < 1e-8
    assert np.abs(gap).max() < 1e-10
    res = traj.summary["constraint_residual"]
    assert res["wheel_lateral_velocity"] == pytest.approx(np.abs(u).max(), rel=1e-3, abs=1e-15)
    assert res["gap"] == pytest.approx(np.abs(gap).max(), rel=1e-3, abs=1e-15)
    # the motion is real: the snake turns by a sizeable angle
    assert np.abs(traj.q[-1, 3:] - traj.q[0, 3:]).max() > 0.05


# ------------------------------------------------------------------------------------------
# convergence
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("method,order,steps", [("RK23", 3, (0.01, 0.005, 0.0025)),
                                                ("RK45", 5, (0.02, 0.01, 0.005))])
def test_measured_convergence_order(models, method, order, steps):
    """Fixed steps h, h/2, h/4 against a tight adaptive reference: the error at t = 0.2 s
    falls as h^p with the method's order p."""
    sm, _ = models(3, "frictionless", 10.0)
    T = 0.2
    ref = sm.simulate(Q3, TAU3, T, rtol=1e-13, atol=1e-15, output_dt=T, **EQUATIONS)

    def error(tr):
        return max(np.abs(tr.q[-1] - ref.q[-1]).max(), np.abs(tr.q_obj[-1] - ref.q_obj[-1]).max())

    errs = np.array([error(sm.simulate(Q3, TAU3, T, method=method, fixed_step=h, output_dt=T,
                                       **EQUATIONS)) for h in steps])
    p = np.log2(errs[:-1] / errs[1:])
    assert np.all(np.abs(p - order) < 0.5), (errs, p)
    assert errs[-1] > 1e-12  # still far above the reference's own error


def test_tolerance_convergence(models):
    """Adaptive runs approach the reference as the tolerance tightens."""
    sm, _ = models(3, "wheels", 10.0)
    T = 0.3
    ref = sm.simulate(Q3, TAU3, T, rtol=1e-13, atol=1e-15, output_dt=T, **EQUATIONS)
    errs = []
    for rtol in (1e-5, 1e-7, 1e-9):
        tr = sm.simulate(Q3, TAU3, T, rtol=rtol, atol=rtol * 1e-2, output_dt=T, **EQUATIONS)
        errs.append(np.abs(tr.q[-1] - ref.q[-1]).max())
    assert errs[0] > errs[1] > errs[2]
    assert errs[2] < 1e-9


# ------------------------------------------------------------------------------------------
# transitions against an independent integration of the instant analysis
# ------------------------------------------------------------------------------------------
def _forward_reference(sm, q0, law, T, event_of):
    """Integrate the instant analysis (SceneModel.forward picks the active set at every
    call) with scipy; ``event_of(res)`` is continuous and changes sign at the transition."""
    ns = sm.n_coordinates
    q_obj, rho, _ = sm.place_object(q0)

    def res_at(t, y):
        return sm.forward(y[:ns], law(t), v=y[ns + 3:2 * ns + 3], v_obj=y[2 * ns + 3:],
                          q_obj=y[ns:ns + 3], rho=rho)

    def f(t, y):
        r = res_at(t, y)
        return np.concatenate([y[ns + 3:], r.qdd, r.a_obj])

    def ev(t, y):
        return event_of(res_at(t, y))

    ev.terminal = True
    ev.direction = -1
    y0 = np.concatenate([q0, q_obj, np.zeros(ns + 3)])
    sol = solve_ivp(f, (0, T), y0, method="DOP853", rtol=1e-11, atol=1e-13, events=ev)
    return sol.t_events[0]


@pytest.mark.parametrize("scenario", ["frictionless", "ideal_wheels"])
def test_contact_lost_at_predicted_time(models, scenario):
    """A torque ramping down to zero at t1 and beyond: the contact force crosses zero near
    t1 (velocity terms shift it slightly); the simulation separates exactly when the
    independent integration of the instant analysis does, and the contact stays open."""
    sm, _ = models(2, scenario, 10.0)
    tau0 = np.array([0.05, -0.02])
    t1 = 0.05

    def law(t):
        return tau0 * (1 - t / t1)

    traj = sm.simulate(Q2, law, 0.12, **EQUATIONS)
    ev = [e for e in traj.events if e.kind == "separation"]
    assert len(ev) == 1
    t_ref = _forward_reference(sm, Q2, law, 0.12, lambda r: r.lam[0] - r.w[0])
    assert len(t_ref) == 1
    assert abs(ev[0].t - t_ref[0]) < 1e-7
    assert abs(ev[0].t - t1) < 0.2 * t1  # the rest-based prediction, shifted by v terms
    after = traj.t > ev[0].t
    assert not traj.contact[after].any()
    assert np.all(traj.gap[after] >= -1e-12) and traj.gap[-1] > 1e-5


def test_wheel_breaks_away_at_its_friction_bound(models):
    """Torques ramped up to the breakaway scale of the rest analysis (eq. 17: the wheel
    force reaches mu m g at t1): the most loaded wheel breaks away when the independent
    integration says so; then it slides with kinetic friction -mu m g sign(u)."""
    sm, ref = models(3, "wheels", 10.0)
    L = sm.maps(Q3)["lam_from_tau"] @ TAU3
    ratio = np.where(sm.present[1:], np.abs(L[1:]) / sm.bounds[1:], 0)
    row = int(np.argmax(ratio)) + 1
    t1 = 0.1
    tau_b = TAU3 / ratio[row - 1]

    def law(t):
        return tau_b * t / t1

    traj = sm.simulate(Q3, law, 0.13, output_dt=0.002, **EQUATIONS)
    ev = [e for e in traj.events if e.kind == "breakaway"]
    assert ev and ev[0].row == row
    bound = sm.bounds[row]
    t_ref = _forward_reference(
        sm, Q3, law, 0.13, lambda r: (bound - abs(r.lam[row])) - abs(r.w[row]))
    assert abs(ev[0].t - t_ref[0]) < 1e-7
    assert abs(ev[0].t - t1) < 0.05 * t1
    sliding = (traj.t > ev[0].t) & np.isin(traj.wheel_state[:, row - 1], ("slide+", "slide-"))
    assert sliding.sum() > 5
    for i in np.flatnonzero(sliding)[1:]:
        u = row_velocities(ref, traj, i)[row]
        assert abs(traj.lam[i, row]) == pytest.approx(bound, rel=1e-12)
        assert traj.lam[i, row] * u < 0  # friction opposes the lateral velocity


def test_sliding_wheels_stick_again_and_friction_work(models):
    """A torque pulse (zero-order hold) breaks the wheels away, then is removed: each wheel
    sticks again when its lateral velocity returns to zero and stays stuck. Energy: the
    kinetic energy gained minus the exact work of the held torques is the friction work,
    negative, and equal to the simulator's friction integral."""
    sm, ref = models(3, "wheels", 10.0)
    L = sm.maps(Q3)["lam_from_tau"] @ TAU3
    scale = 1.0 / np.max(np.abs(L[2:]) / sm.bounds[2:])

    def law(t):
        return 1.5 * scale * TAU3 if t < 0.05 else np.zeros(3)

    traj = sm.simulate(Q3, law, 0.2, control_period=0.05, output_dt=0.002, **EQUATIONS)
    assert traj.summary["initial_mode"].count("slide") >= 1
    sticks = [e for e in traj.events if e.kind == "stick"]
    assert sticks
    for e in sticks:
        i = np.flatnonzero(traj.t == e.t)[0]
        assert abs(row_velocities(ref, traj, i)[e.row]) < 1e-10
        later = np.flatnonzero(traj.t > e.t + 1e-3)
        stuck = traj.wheel_state[later, e.row - 1] == "stick"
        assert stuck.all()
        for j in later[::10]:
            assert abs(row_velocities(ref, traj, j)[e.row]) < 1e-8
    assert traj.wheel_state[-1].tolist().count("stick") == 3
    # energy: work of a piecewise-constant torque is exact from the joint displacements
    k = int(np.argmin(np.abs(traj.t - 0.05)))  # the control instant is a sample
    assert traj.t[k] == pytest.approx(0.05, abs=1e-15)
    work_tau = 1.5 * scale * TAU3 @ (traj.q[k, 3:] - traj.q[0, 3:])
    ke = kinetic_energy(ref, traj.q[-1], traj.v[-1], traj.v_obj[-1])
    friction = ke - work_tau
    assert friction < -1e-4
    assert traj.work_friction[-1] == pytest.approx(friction, rel=1e-7)


def test_contact_point_leaves_the_link(models):
    """The object slides along the link while pressed against it (frictionless contact):
    the contact ends when the contact point passes the link's front end, and never closes
    again."""
    sm, _ = models(2, "frictionless", 10.0, contact_offset=0.12)
    # (link 2 lies in the object from the start: the check is off)
    traj = sm.simulate(Q2, np.zeros(2), 0.2, v_obj0=[0.3, 0.0, 0.0], f_obj=[0.0, -0.5, 0.0],
                       geometry_check="off")
    kinds = [e.kind for e in traj.events]
    assert kinds == ["off_link"]
    i = np.flatnonzero(traj.t == traj.events[0].t)
    assert traj.s[i[0]] == pytest.approx(0.15, abs=1e-10)
    assert not traj.contact[i[-1]:].any()


# ------------------------------------------------------------------------------------------
# metrics, inputs, controller
# ------------------------------------------------------------------------------------------
def test_displacement_slippage_ratio_starts_at_instant_sr(models):
    """From rest the displacements are 1/2 a t^2 to leading order, so the displacement-based
    slippage ratio tends to the paper's instantaneous sr (eq. 30) at t = 0."""
    sm, _ = models(3, "wheels", 10.0)
    sr0 = sm.forward(Q3, TAU3).sr
    traj = sm.simulate(Q3, TAU3, 2e-3, output_dt=5e-4, **EQUATIONS)
    assert np.isnan(traj.sr_displacement[0])
    assert traj.sr[0] == pytest.approx(sr0, rel=1e-12)
    assert traj.sr_displacement[1] == pytest.approx(sr0, rel=1e-3)


def test_torque_inputs_constant_time_and_feedback_agree(models):
    sm, _ = models(3, "ideal_wheels", 10.0)
    # the same integrator for all three (a constant would take the compiled segments)
    a = sm.simulate(Q3, TAU3, 0.2, output_dt=0.05, integrator="scipy", **EQUATIONS)
    b = sm.simulate(Q3, lambda t: TAU3, 0.2, output_dt=0.05, **EQUATIONS)
    seen = []

    def law(t, state):
        assert isinstance(state, State) and state.q.shape == (6,)
        seen.append(state.contact)
        return TAU3

    c = sm.simulate(Q3, law, 0.2, output_dt=0.05, **EQUATIONS)
    for other in (b, c):
        np.testing.assert_allclose(other.q, a.q, rtol=0, atol=1e-13)
    assert all(seen)


def test_zero_order_hold_calls_the_law_once_per_period(models):
    sm, _ = models(3, "frictionless", 10.0)
    calls = []

    def law(t, state):
        calls.append(t)
        return -0.5 * state.v[3:] + TAU3

    traj = sm.simulate(Q3, law, 0.1, control_period=0.02, output_dt=0.005, **EQUATIONS)
    np.testing.assert_allclose(calls, [0.0, 0.02, 0.04, 0.06, 0.08], atol=1e-12)
    for k in range(5):
        inside = (traj.t > 0.02 * k + 1e-9) & (traj.t < 0.02 * (k + 1) - 1e-9)
        assert np.ptp(traj.tau[inside], axis=0).max() == 0.0


def test_least_slip_push_controller(models):
    """The "push with least slippage" query as a feedback law: every wheel sticks, and the
    object advances along the contact normal as 1/2 a_min t^2."""
    sm, _ = models(3, "wheels", 10.0)
    from snakecg.simulate import least_slip_push_controller

    ctl = least_slip_push_controller(sm, a_min=0.02)
    T = 0.2
    traj = sm.simulate(Q3, ctl, T, control_period=0.01, output_dt=0.01, **EQUATIONS)
    assert [s for _, s, _ in ctl.history] == ["optimal"] * 20
    assert (traj.wheel_state[:, 1:] == "stick").all() and traj.contact.all()
    d = traj.q_obj[-1, 1] - traj.q_obj[0, 1]  # the normal is +y at theta = 0
    assert d == pytest.approx(0.5 * 0.02 * T**2, rel=0.02)


def test_least_slip_push_controller_keeps_the_robots_effort_limits():
    """Without tau_max the controller's torques stay in the robot's effort box (the query's
    default); a task beyond the box gets its strongest push, at the box's edge."""
    from snakecg.simulate import least_slip_push_controller

    limits = np.array([0.05, 0.08, 0.03])
    robot = snakecg.Robot(joints=3, effort_limits=limits)
    sm = snakecg.load(snakecg.Scene(robot, scenario="wheels", kappa=10.0))
    ctl = least_slip_push_controller(sm, a_min=50.0)  # far beyond what 0.08 N m can do
    tau = np.asarray(ctl(0.0, type("S", (), {"q": Q3})()))
    assert np.all(np.abs(tau) <= limits * (1 + 1e-12))
    assert np.any(np.isclose(np.abs(tau), limits, rtol=1e-9))


def test_bad_input(models):
    sm, _ = models(3, "frictionless", 10.0)
    with pytest.raises(snakecg.InputError, match=r"q0 has shape \(5,\), expected \(6,\)"):
        simulate(sm, Q3[:5], TAU3, 0.1)
    with pytest.raises(snakecg.InputError, match=r"tau has shape \(2,\)"):
        simulate(sm, Q3, TAU3[:2], 0.1)
    with pytest.raises(snakecg.InputError, match="duration must be a finite number > 0"):
        simulate(sm, Q3, TAU3, 0.0)
    with pytest.raises(snakecg.InputError, match=r"\(t\) or \(t, state\)"):
        simulate(sm, Q3, lambda a, b, c: TAU3, 0.1)
    with pytest.raises(snakecg.InputError, match="q_obj0 and rho go together"):
        simulate(sm, Q3, TAU3, 0.1, q_obj0=[0, 0, 0])
    with pytest.raises(snakecg.InputError, match="penetrates"):
        q_obj, rho, _ = sm.place_object(Q3)
        simulate(sm, Q3, TAU3, 0.1, q_obj0=q_obj - [0, 0.01, 0], rho=rho)
    with pytest.raises(snakecg.InputError, match="method must be one of DOP853"):
        simulate(sm, Q3, TAU3, 0.1, method="Euler")
    with pytest.raises(SimulationError, match="torque law returned"):
        simulate(sm, Q3, lambda t: [1.0, 2.0], 0.1)
    robot_model = snakecg.load(snakecg.Robot(joints=3))
    with pytest.raises(snakecg.InputError, match="snakecg.Scene"):
        simulate(robot_model, Q3, TAU3, 0.1)


def test_cli_json_and_errors(tmp_path, capsys):
    rc = cli.main(["simulate", "--joints", "2", "--q", "0,0,0,0.5,-0.6", "--tau", "0.05,-0.02",
                   "--duration", "0.1", "--json", "--no-figures", "--out", str(tmp_path),
                   "--geometry-check", "off"])
    out = capsys.readouterr().out
    assert rc == 0
    s = json.loads(out)
    assert s["schema"] == "snakecg.simulate/1"
    assert s["status"] == "completed (geometry not checked)"
    assert json.loads((tmp_path / "summary.json").read_text())["duration"] == 0.1
    data = np.load(tmp_path / "trajectory.npz")
    assert data["q"].shape[1] == 5 and data["t"][-1] == pytest.approx(0.1)
    rc = cli.main(["simulate", "--joints", "2", "--q", "0,0,0", "--tau", "0.05,-0.02",
                   "--no-figures", "--out", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1 and "expected (5,)" in err
    rc = cli.main(["simulate", "--joints", "2", "--q", "0,0,0,0,0", "--no-figures"])
    assert rc == 2 and "--tau" in capsys.readouterr().err


def test_figures_and_animation(models, tmp_path):
    from PIL import Image

    sm, _ = models(3, "wheels", 10.0)
    traj = sm.simulate(Q3, 2 * TAU3, 0.2, output_dt=0.005, **EQUATIONS)
    paths = save_figures(traj, tmp_path, frames=6, dpi=60)
    for name in ("displacement", "slippage", "energy", "forces"):
        with Image.open(paths[name]) as im:
            assert im.format == "PNG" and min(im.size) > 150
    with Image.open(paths["animation"]) as im:
        assert im.format == "GIF" and im.n_frames == 6


def test_max_events_stops_the_run_and_says_so(models):
    sm, _ = models(3, "wheels", 10.0)
    L = sm.maps(Q3)["lam_from_tau"] @ TAU3
    tau = 4 * TAU3 / np.max(np.abs(L[2:]) / sm.bounds[2:])
    full = sm.simulate(Q3, tau, 0.6, output_dt=0.05, geometry_check="off")
    assert len(full.events) >= 2
    assert full.summary["status"] == "completed (geometry not checked)"
    cut = sm.simulate(Q3, tau, 0.6, output_dt=0.05, max_events=1, geometry_check="off")
    assert cut.summary["status"].startswith("stopped at t = ")
    assert cut.t[-1] < 0.6 and len(cut.events) >= 1


@pytest.mark.slow
def test_long_run_with_many_transitions(models):
    """Five seconds of a hard push (wheels breaking away, sticking, sliding back; the contact
    point leaving the link): the energy balance closes, friction only dissipates, and the
    constraint residuals stay at integration-error level."""
    sm, ref = models(3, "wheels", 10.0)
    N = sm.maps(Q3)["input_metric"]
    tau = 4 * TAU3 / np.sqrt(TAU3 @ N @ TAU3)
    traj = sm.simulate(Q3, tau, 5.0, output_dt=0.01, **EQUATIONS)
    s = traj.summary
    assert s["status"] == "penetration" and traj.t[-1] == 5.0
    kinds = set(s["event_counts"])
    assert {"breakaway", "stick"} <= kinds
    # the run is long and chaotic (many friction reversals): the budget closes relative to the
    # energies involved (about 20 J of work), not absolutely
    assert abs(s["energy"]["balance_residual"]) < 1e-8 * s["energy"]["work_tau"]
    assert np.all(np.diff(traj.work_friction) <= 1e-15)
    assert s["constraint_residual"]["wheel_lateral_velocity"] < 1e-7
    assert s["constraint_residual"]["gap"] < 1e-9
    for i in range(0, traj.n_samples, 50):
        ke = kinetic_energy(ref, traj.q[i], traj.v[i], traj.v_obj[i])
        assert ke == pytest.approx(traj.kinetic_energy[i], rel=1e-9, abs=1e-15)
