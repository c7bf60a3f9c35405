"""A general scene's time step starts its solve from the last step's pieces (the warm start of
snakecg/engine/scene_step.c, scene_solve.c's ``core_scene_solve_s``). The velocities of a
step are unique, so the same run from scratch at every step is the reference: the
environment variable ``SNAKECG_SCENE_COLD_START=1`` (read when a run starts) turns the warm
start off. Each run is compared both ways over its whole trajectory (1e-9), every step's
certificate within the solve's acceptance (1e-9 of its scales) both ways, and held to
independent references:

* the pegs scene (10 joints, 10 pegs, Coulomb ground, 0.5 s with impacts and onsets; and
  with the torque clipped, where the snake jams among the pegs and the run completes): no
  penetration beyond the tolerance at any sample by NumPy distances of the capsule links,
  the pegs and the non-neighbouring links (the chain's kinematics written here); the kinetic
  energy never above the torques' work less the friction's dissipation and the impacts'
  loss (plus the gap stabilisation's contact work);
* the paper's push (contacts from geometry): the same trajectory both ways;
* a disc under Coulomb friction: its stopping distance u^2 / (2 mu g) (the closed form,
  within u h) both ways;
* a disc thrown at a wall: one inelastic impact, the same impulse both ways, and no
  penetration beyond the tolerance;
* the start taken: from the second step on, a step's solve on the pegs scene (more rows than
  coordinates: from scratch it reads its pieces after five Gauss-Seidel sweeps) needs no
  sweep at all.
"""

from __future__ import annotations


import numpy as np
import pytest

import snakecg
from snakecg.scenes import GeneralScene, Ground, Obstacle, SceneObject, load_scene
from snakecg.simulate import serpenoid_controller

from capsule_reference import deepest_overlap
from scenes_reference import pegs_row

COLD = "SNAKECG_SCENE_COLD_START"
FIELDS = ("t", "q", "v", "q_obj", "v_obj", "kinetic_energy", "work_tau",
          "friction_dissipation", "impact_loss", "min_gap", "n_contacts")


def _both(monkeypatch, simulate):
    """The run of ``simulate()`` from scratch at every step, and with the warm start."""
    monkeypatch.setenv(COLD, "1")
    cold = simulate()
    monkeypatch.setenv(COLD, "0")
    warm = simulate()
    return cold, warm


def _same(cold, warm, fields=FIELDS, atol=1e-9):
    assert cold.status == warm.status == "completed"
    assert cold.steps == warm.steps and len(cold.events) == len(warm.events)
    for k in fields:
        np.testing.assert_allclose(np.asarray(getattr(warm, k), dtype=float),
                                   np.asarray(getattr(cold, k), dtype=float), rtol=0,
                                   atol=atol, err_msg=k)
    for run in (cold, warm):  # every step's certificate within the solve's acceptance
        assert max(run.certificate.values()) <= 1e-9, run.certificate
    for a, b in zip(cold.events, warm.events):
        assert a.bodies == b.bodies and a.t == pytest.approx(b.t, abs=1e-12)
        np.testing.assert_allclose(a.impulses, b.impulses, rtol=1e-9, atol=1e-12)
        assert max(b.certificate.values()) <= 1e-8


def _gait(model, tau_max):
    return serpenoid_controller(model, amplitude=0.5, frequency=1.0, phase_lag=2 * np.pi / 5,
                                kp=10.0, kd=0.3, tau_max=tau_max)


@pytest.fixture(scope="module")
def pegs():
    scene, model, q0 = pegs_row()
    return scene, model, q0, _gait(model, None)


@pytest.mark.parametrize("tau_max", [None, 0.05])
def test_the_pegs_run_is_the_same_from_the_last_steps_pieces(pegs, monkeypatch, tau_max):
    """The serpenoid PD law, and the same with its torque clipped at 0.05 N m (the snake
    jams among the pegs: six contacts dependent with the links' sticking ground rows)."""
    scene, model, q0, _ = pegs
    gait = _gait(model, tau_max)
    cold, warm = _both(monkeypatch, lambda: model.simulate(q0, 0.5, tau=gait, dt=1e-3))
    assert warm.steps >= 500
    if tau_max is None:
        assert warm.events and warm.steps > 500  # impacts, and onsets shortened steps
    _same(cold, warm)
    if tau_max is None:  # the contacts' impulses: unique, the held rows independent here;
        # jammed, they are dependent with the sticking ground rows and the minimum-norm
        # forces leave the sets (flag 2): the forces are the basic solution, the path's own
        np.testing.assert_allclose(warm.contact_impulse, cold.contact_impulse, rtol=0,
                                   atol=1e-9)
    for run in (cold, warm):
        assert deepest_overlap(scene, run.q) <= run.tolerance
        gain = np.asarray(run.kinetic_energy) - run.kinetic_energy[0]
        budget = (np.asarray(run.work_tau) - run.friction_dissipation - run.impact_loss +
                  run.contact_work)
        assert np.all(gain <= budget + 1e-9 + 1e-9 * np.abs(budget))
        assert np.all(np.diff(run.friction_dissipation) >= -1e-12)


def test_the_papers_push_is_the_same_from_the_last_steps_pieces(monkeypatch):
    q = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])
    tau = np.array([0.05, 0.0, -0.02])
    sm = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100.0))
    cold, warm = _both(monkeypatch, lambda: sm.simulate(q, tau, 0.5, contacts="geometry"))
    assert cold.status == warm.status and cold.steps == warm.steps > 400
    for k in ("t", "q", "v"):
        np.testing.assert_allclose(getattr(warm, k), getattr(cold, k), rtol=0, atol=1e-9,
                                   err_msg=k)


def test_a_disc_stops_at_coulombs_distance_both_ways(monkeypatch):
    u, mu, g, h = 0.6, 0.3, 9.81, 1e-3
    disc = SceneObject(shape="disc", radius=0.05, mass=1.5, pose=(0.0, 0.0, 0.0), mu=mu)
    scene = GeneralScene(snakecg.Robot(joints=1), ground=Ground(model="frictionless"),
                         objects=(disc,))
    model = load_scene(scene)
    cold, warm = _both(monkeypatch, lambda: model.simulate(
        np.array([-2.0, 0.0, 0.0, 0.0]), 0.5, v_obj0=[[u, 0, 0]], dt=h))
    _same(cold, warm)
    for run in (cold, warm):
        assert run.q_obj[-1, 0, 0] == pytest.approx(u * u / (2 * mu * g), abs=u * h)
        assert np.all(run.v_obj[run.t > u / (mu * g) + 2 * h, 0, 0] == 0.0)


def test_a_disc_at_a_wall_has_the_same_impact_both_ways(monkeypatch):
    disc = SceneObject(shape="disc", radius=0.05, mass=1.0, pose=(0.0, 0.0, 0.0))
    wall = Obstacle(shape="wall", point=(0.3, 0.0), normal=(-1.0, 0.0))
    scene = GeneralScene(snakecg.Robot(joints=1), ground=Ground(model="frictionless"),
                         objects=(disc,), obstacles=(wall,))
    model = load_scene(scene)
    cold, warm = _both(monkeypatch, lambda: model.simulate(
        np.array([-2.0, 0.0, 0.0, 0.0]), 0.4, v_obj0=[[2.0, 0, 0]]))
    _same(cold, warm)
    for run in (cold, warm):
        assert len(run.events) == 1
        # the disc's momentum 1 kg x 2 m/s stopped by the wall's impulse
        assert sum(run.events[0].impulses) == pytest.approx(2.0, rel=1e-9)
        assert np.all(0.25 - run.q_obj[:, 0, 0] >= -run.tolerance)


def test_a_step_from_the_last_steps_pieces_needs_no_sweep(pegs, monkeypatch):
    from snakecg.scenes.packing import scene_size
    from snakecg.scenes.solve import INFO
    from snakecg.scenes.stepping import _Stepper

    scene, model, q0, gait = pegs
    sweeps = INFO.index("sweeps")
    got = {}
    for cold in ("1", "0"):
        monkeypatch.setenv(COLD, cold)
        st = _Stepper(model, 1e-5 * scene_size(scene), np.zeros(0))
        st.x[:13] = q0
        assert st.call(0.0) == 0
        st.tau[:] = 0.01
        counts = []
        for _ in range(5):
            assert st.call(1e-4) == 0
            counts.append(st.info[sweeps])
        assert st.out[2] > st.n  # more rows than coordinates: no held guess
        got[cold] = counts
    assert got["1"] == [5.0] * 5  # from scratch: the pieces read after five sweeps
    assert got["0"][0] == 5.0 and got["0"][1:] == [0.0] * 4
