"""A step whose gap stabilisation would need a jam's velocities holds its overlaps instead.

A run's step pushes an overlap within the tolerance back out at gap / h. Where the contact's
row is nearly dependent on others (a peg pressing a link next to its ideal wheel's line), that
asks for velocities far beyond the push itself: kinetic energy from nothing, or, where the rows
are dependent, no velocity at all (the step's solve does not converge). Such a step holds its
overlaps (offsets 0) and the run counts it (``held_steps``). The references are Clarabel on
the step's problem (NumPy's inertia, the engine's rows) and the step's energy balance.
"""

import numpy as np
import pytest

import snakecg
from scenes_reference import clarabel_accelerations, gauss_objective, inertia_and_force
from scenes_reference import peg_obstacles, problem_of
from snakecg.scenes import GeneralScene, Ground, simulate_scene_batch
from snakecg.scenes.description import Obstacle

Q = np.array([0.0, 0.0, 0.0, 0.3, -0.2, 0.25])
TAU = np.array([0.05, -0.03, 0.02])
H = 1e-3


def _pressed_beside_the_wheel(lever):
    """The paper's 3-joint snake on ideal wheels, a peg of radius 2 cm pressing link 2's left
    side ``lever`` metres ahead of its wheel (at its COM), overlapping by half the run's
    tolerance; the model and that tolerance."""
    robot = snakecg.Robot(joints=3)
    ground = Ground(model="ideal_wheels")
    free = snakecg.load(GeneralScene(robot, ground=ground))
    phi = free.link_poses(Q)[1][2]
    normal = np.array([-np.sin(phi), np.cos(phi)])  # (link 2's left)
    touching = peg_obstacles(free, [(2, robot.com[1] + lever, "left", 0.02)], Q)[0]
    tol = snakecg.load(GeneralScene(robot, ground=ground, obstacles=(touching,))).simulate(
        Q, H, dt=H).tolerance
    peg = Obstacle(shape="peg", center=tuple(np.array(touching.center) - 0.5 * tol * normal),
                   radius=0.02)
    return snakecg.load(GeneralScene(robot, ground=ground, obstacles=(peg,))), tol


def _step_problems(model, tol):
    """The first step's problem from rest, held (the contact's offset 0) and pushed out (gap /
    h): NumPy's inertia and torques, the engine's rows at Q; and the energy of pushing the
    overlap out alone, 1/2 (g / h)^2 / (a M^-1 a^T)."""
    from snakecg.scenes.stepping import _Stepper

    st = _Stepper(model, tol, np.zeros(0))
    st.begin(Q, np.zeros(0), None, None)
    nc, m, nb = int(st.out[1]), int(st.out[2]), int(st.out[3])
    assert nc == 1 and list(st.kind[:nb]) == [1, 0, 0, 0, 0]  # (the contact, 4 ideal wheels)
    gap = st.out[10 + 3 * st.no + 10]
    assert gap == pytest.approx(-0.5 * tol, rel=1e-6)
    M, f = inertia_and_force(model, Q, TAU)
    A, kind, start, par = (st.A[:m].copy(), st.kind[:nb].copy(), st.start[:nb].copy(),
                           st.par[:nb].copy())
    held = problem_of(M, H * f, A, kind, start, par, c=np.zeros(m))
    c = np.zeros(m)
    c[start[0]] = gap / H
    pushed = problem_of(M, H * f, A, kind, start, par, c=c)
    a = A[start[0]]
    alone = 0.5 * (gap / H) ** 2 / (a @ pushed["Minv"] @ a)
    return held, pushed, alone


def _excess(p, V):
    """The kinetic energy of V above the free motion's (V* = h M^-1 B tau from rest)."""
    return 0.5 * V @ p["M"] @ V - 0.5 * p["a_free"] @ p["M"] @ p["a_free"]


def test_a_peg_pressing_beside_an_ideal_wheel_is_held_not_pushed_out():
    """A tenth of a millimetre ahead of the wheel, pushing 3.2 micrometres out in one step
    would spin the snake at tens of rad/s, more than 10^5 times the energy of that push alone
    (Clarabel on the pushed out problem; the jam's threshold is 10^4). The step holds the
    overlap: it is Clarabel's answer of the held problem, the stabilisation does no work and
    the kinetic energy gained is at most the torques' work."""
    model, tol = _pressed_beside_the_wheel(1e-4)
    held, pushed, alone = _step_problems(model, tol)
    V_push, status = clarabel_accelerations(pushed, tol=1e-12)
    assert status == "optimal"
    assert _excess(pushed, V_push) > 1e5 * alone  # (the jam: far beyond the push alone)
    assert np.abs(V_push[3:]).max() > 10.0

    run = model.simulate(Q, H, dt=H, tau=TAU)
    assert run.status == "completed", run.message
    assert run.held_steps == 1 and run.steps == 1
    V = np.asarray(run.v[-1])
    ref, status = clarabel_accelerations(held, tol=1e-12)
    assert status == "optimal"
    scale = np.abs(ref).max()
    assert 0 < scale < 1e-3
    # Clarabel stops 4e-5 short on the nearly dependent pair; the step is the unique
    # minimiser: no higher objective, and within that distance
    assert np.abs(V - ref).max() <= 1e-4 * scale
    assert gauss_objective(held, V) <= gauss_objective(held, ref) * (1 + 1e-12)
    w = held["A"] @ V
    assert w[0] >= -1e-9 * scale and np.abs(w[1:]).max() <= 1e-9 * scale  # (held, wheels)
    assert abs(run.contact_work[-1]) <= 1e-6 * run.work_tau[-1]  # (rounding of A V+ = 0)
    assert run.kinetic_energy[-1] <= run.work_tau[-1] * (1 + 1e-9)
    batch = simulate_scene_batch(model, np.stack([Q, Q]), H, dt=H, tau=TAU)  # (counted too)
    assert list(batch.held_steps) == [1, 1] and list(batch.status) == ["completed"] * 2
    np.testing.assert_array_equal(batch.q_end[0], run.q[-1])


def test_a_peg_a_millimetre_from_the_wheel_is_pushed_out():
    """Ten times farther from the wheel the push costs about 5,600 times its energy alone:
    below the jam's 10^4, so the overlap is pushed out at gap / h, as Clarabel's pushed out
    problem. The kinetic energy it gives beyond the torques' work (Clarabel's velocities,
    NumPy's inertia) is the stabilisation's work, which the run reports and its message
    names."""
    model, tol = _pressed_beside_the_wheel(1e-3)
    _, pushed, alone = _step_problems(model, tol)
    ref, status = clarabel_accelerations(pushed, tol=1e-12)
    assert status == "optimal"
    assert 1e3 * alone < _excess(pushed, ref) < 1e4 * alone
    run = model.simulate(Q, H, dt=H, tau=TAU)
    assert run.status == "completed" and run.held_steps == 0
    V = np.asarray(run.v[-1])
    assert np.abs(V - ref).max() <= 1e-6 * np.abs(ref).max()
    from_nothing = 0.5 * ref @ pushed["M"] @ ref - H * TAU @ ref[3:]
    assert from_nothing > 10 * abs(run.work_tau[-1])
    assert run.contact_work[-1] >= from_nothing * (1 - 1e-6)
    assert "gap stabilisation did" in run.message
