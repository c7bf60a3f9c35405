"""Random pushes of the paper's scene with contacts from geometry (``contacts="geometry"``):
every run completes, and no sample is deeper than the run's tolerance by checks written apart
from the engine:

* the penetration depth of every link in the plate by the separating axis theorem
  (``overlap_reference.sat_depths``: the plate's corners from its pose, each link's segment
  from the coordinates by its own chain), and the same through
  ``scenes_geometry_reference.sat_gap`` on a few samples;
* ``overlap_reference.overlaps``: each link's deepest point in the plate and the links'
  crossings.

The study: 3 joints, kappa 10 and 100, the three scenarios, six pushes each (joint angles
within 10 degrees of the paper's, torques 0.5 to 1.5 times the paper's push plus a small
random part), 0.5 s each at the default step (about a second for the 36); the paper's push
without friction at shorter steps; the kappa-10 push of the how-to; a serpenoid gait against
the plate for 1 s (3 and 4 joints), which went 0.05 to 0.56 mm deep into it before. Before the signed
distance through overlap, 14 of the 36 stopped ``not_converged`` at their first step (two
near-identical contacts for one corner crossing a link).
"""

from __future__ import annotations

import numpy as np
import pytest
from overlap_reference import link_ends, overlaps, plate_corners, sat_depths
from scenes_geometry_reference import Shape, sat_gap

import snakecg
from snakecg.simulate import serpenoid_controller

Q0 = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])
TAU = np.array([0.05, 0.0, -0.02])
Q10 = np.array([0, 0, 0, np.deg2rad(30), np.deg2rad(-35), np.deg2rad(25)])  # the how-to's
TAU10 = np.array([0.035, 0.0, -0.014])
SCENARIOS = ("wheels", "ideal_wheels", "frictionless")


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(scenario, kappa):
        if (scenario, kappa) not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario, kappa=kappa,
                                  mu=0.1)
            cache[scenario, kappa] = (scene, snakecg.load(scene))
        return cache[scenario, kappa]

    return get


def sat_depths_by_shape(scene, q, q_obj):
    """``sat_depths`` by ``scenes_geometry_reference.sat_gap``, one sample at a time."""
    rear, front = link_ends(scene.robot, q)
    corners = plate_corners(q_obj, scene.object_distance)
    out = np.zeros(rear.shape[:2])
    for k in range(len(q)):
        plate = Shape("polygon", corners[k])
        for i in range(rear.shape[1]):
            g, _ = sat_gap(Shape("segment", [rear[k, i], front[k, i]]), plate)
            out[k, i] = max(0.0, -g)
    return out


def pushes(seed, n):
    """``n`` random pushes near the paper's: (q0, tau)."""
    rng = np.random.default_rng(seed)
    for _ in range(n):
        q = Q0.copy()
        q[3:] += np.deg2rad(rng.uniform(-10, 10, size=3))
        tau = TAU * rng.uniform(0.5, 1.5, size=3) + rng.normal(scale=0.005, size=3)
        yield q, tau


def check_run(scene, run):
    """The run completed and no sample overlaps beyond its tolerance (independent checks)."""
    assert run.status == "completed" and run.violation is None, run.summary
    tol = run.tolerance
    sat = sat_depths(scene, run.q, run.q_obj[:, 0])
    depth, _ = overlaps(scene, run.q, run.q_obj[:, 0])
    assert sat.max() <= tol and depth.max() <= tol, (sat.max(), depth.max(), tol)
    k = np.argsort(sat.max(axis=1))[-5:]  # the deepest samples, by the shapes' own SAT
    np.testing.assert_allclose(sat_depths_by_shape(scene, run.q[k], run.q_obj[k, 0]), sat[k],
                               rtol=0, atol=1e-15)
    return sat.max()


def study(models, kappas, scenarios, n, duration, dt=1e-3):
    deepest = 0.0
    for kappa in kappas:
        for s, scenario in enumerate(scenarios):
            scene, sm = models(scenario, kappa)
            for q, tau in pushes(1000 * int(kappa) + s, n):
                run = sm.simulate(q, tau, duration, contacts="geometry", dt=dt)
                deepest = max(deepest, check_run(scene, run))
    return deepest


def test_thirty_six_random_pushes_run_their_half_second_without_overlap(models):
    study(models, (10.0, 100.0), SCENARIOS, 6, duration=0.5)


def test_the_how_tos_kappa_10_push_completes_without_overlap(models):
    scene, sm = models("wheels", 10.0)
    check_run(scene, sm.simulate(Q10, TAU10, 0.5, contacts="geometry"))


@pytest.mark.parametrize("dt", [5e-4, 2.5e-4])
def test_the_push_without_friction_at_shorter_steps(models, dt):
    scene, sm = models("frictionless", 100.0)
    check_run(scene, sm.simulate(Q0, TAU, 0.5, contacts="geometry", dt=dt))


@pytest.mark.parametrize("joints, scenario", [(3, "wheels"), (3, "frictionless"),
                                              (4, "wheels")])
def test_a_serpenoid_gait_against_the_plate_stays_out_of_it(joints, scenario):
    """The serpenoid PD law from the paper's bent start: the links strike and slide along
    the plate's faces and corners for 1 s, never deeper than the tolerance."""
    scene = snakecg.Scene(snakecg.Robot(joints=joints), scenario=scenario, kappa=100.0)
    sm = snakecg.load(scene)
    q0 = np.zeros(3 + joints)
    q0[3:] = np.deg2rad([30, -45, 60, -30][:joints])
    gait = serpenoid_controller(sm, amplitude=0.5, frequency=1.0, phase_lag=2 * np.pi / 5,
                                kp=10.0, kd=0.3, tau_max=None)
    run = sm.simulate(q0, gait, 1.0, contacts="geometry")
    assert run.events  # it strikes the plate
    check_run(scene, run)
