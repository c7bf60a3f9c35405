"""The paper's scene at rest over time: nothing moves where nothing pushes.

Physical law: a snake at rest touching the object with exactly no contact force, under no
torque or under a torque that its wheels' friction holds, stays where it is; its kinetic
energy stays 0 and the torques do no work. The held torque is built from the dense NumPy
model of ``tests/reference.py`` (the wheel rows' forces that balance a joint torque with no
net force on the base), and that model's exact forward solve says ``qdd = 0`` for it, every
wheel sticking within its bound. Both integration paths (compiled segments, solve_ivp) run.

The contact force being exactly 0, the held contact and the separated one with a closed gap
are the same state; an event is its quantity becoming negative, so neither fires (before, the
run stopped at t = 0 after 21 events, separating and touching again).
"""

from __future__ import annotations

import numpy as np
import pytest
from reference import Reference

import snakecg

Q_BENT = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(joints, scenario):
        if (joints, scenario) not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario, kappa=100.0)
            cache[joints, scenario] = (scene, snakecg.load(scene))
        return cache[joints, scenario]

    return get


def _at_rest(traj, q0, tol):
    assert traj.summary["status"] == "completed"
    assert traj.t[-1] == pytest.approx(0.5, abs=1e-15)
    assert np.abs(traj.q - q0).max() <= tol
    assert np.abs(traj.v).max() <= tol and np.abs(traj.v_obj).max() <= tol
    assert np.abs(traj.q_obj - traj.q_obj[0]).max() <= tol
    # energy law: T(t) = T(0) + W_tau = 0 + 0
    assert np.abs(traj.kinetic_energy).max() <= tol ** 2
    assert np.abs(traj.work_tau).max() <= tol


@pytest.mark.parametrize("integrator", ["auto", "scipy"])
@pytest.mark.parametrize("scenario", ["wheels", "frictionless", "ideal_wheels"])
def test_no_torque_at_rest_stays_at_rest(models, scenario, integrator):
    scene, sm = models(3, scenario)
    ref = Reference(scene)
    exact = ref.solve(Q_BENT, np.zeros(3))
    assert np.abs(exact["lam"]).max() == 0.0 and np.abs(exact["qdd"]).max() == 0.0
    traj = sm.simulate(Q_BENT, np.zeros(3), 0.5, integrator=integrator)
    _at_rest(traj, Q_BENT, 0.0)  # exactly: every force is exactly 0
    assert traj.events == [] and traj.contact.all()
    assert np.all(traj.gap == 0.0)


def held_torque(ref, q, size):
    """A joint torque of largest entry ``size`` that the wheels hold with no contact force:
    ``B tau + A_w^T lam_w = 0`` (the wheel rows' forces cancel on the base's three
    coordinates and balance the joints'), from the dense reference's rows."""
    q_obj, rho, _ = ref.place_object(q)
    A = ref.rows(np.concatenate([q, q_obj]), rho)
    W = A[1:][ref.present[1:], :ref.ns]
    _, s, vt = np.linalg.svd(W[:, :3].T)
    lam = vt[-1]
    assert np.abs(W[:, :3].T @ lam).max() <= 1e-12  # in the null space of the base rows
    tau = -(W.T @ lam)[3:]
    return size * tau / np.abs(tau).max()


@pytest.mark.parametrize("integrator", ["auto", "scipy"])
@pytest.mark.parametrize("joints,q0", [(3, np.zeros(6)),
                                       (4, np.deg2rad([0, 0, 0, 30, -45, 60, 20]))])
def test_torque_held_by_the_wheels_moves_nothing(models, joints, q0, integrator):
    scene, sm = models(joints, "wheels")
    ref = Reference(scene)
    tau = held_torque(ref, q0, 0.01)
    exact = ref.solve(q0, tau)
    assert np.abs(exact["qdd"]).max() <= 1e-12 and np.abs(exact["a_obj"]).max() <= 1e-12
    present = ref.present[1:]
    assert all(s == "held" for s, p in zip(exact["states"][1:], present) if p)  # sticking
    assert np.all(np.abs(exact["lam"][1:]) < 0.5 * ref.bounds[1:])
    assert np.abs(exact["lam"][1:]).max() > 0.01  # the wheels do hold something
    traj = sm.simulate(q0, tau, 0.5, integrator=integrator)
    _at_rest(traj, q0, 1e-10)
    assert np.all(traj.wheel_state[:, present] == "stick")
    held = traj.lam[:, 1:][:, present]
    # (2e-9: the run's held forces drift by rounding over its 500 steps, 1.04e-9 at most
    # once the contact system is evaluated with the base at the origin)
    np.testing.assert_allclose(held, np.broadcast_to(exact["lam"][1:][present], held.shape),
                               rtol=2e-9, atol=1e-12)
    assert np.abs(traj.lam[:, 0]).max() <= 1e-10  # the contact force: 1e-9 of the wheels'
    assert np.abs(traj.gap).max() <= 1e-12


def test_casadi_backend_at_rest_and_its_placement():
    """The CasADi backend (the Python engine, no compiled library): the run places the
    object itself where the dense reference does, and at rest nothing moves."""
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100.0)
    slow = snakecg.load(scene, backend="casadi")
    traj = slow.simulate(Q_BENT, np.zeros(3), 0.5)
    assert not traj.summary["integrator"]["compiled_segments"]
    _at_rest(traj, Q_BENT, 0.0)
    assert traj.events == []
    q_obj, rho, _ = Reference(scene).place_object(Q_BENT)
    np.testing.assert_allclose(traj.q_obj[0], q_obj, atol=1e-15)
    np.testing.assert_allclose(traj.rho, rho, atol=1e-15)
