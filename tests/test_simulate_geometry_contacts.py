"""The paper's scene simulated with contacts from geometry (``contacts="geometry"``).

The paper's push (3 joints, kappa 100, q0 = (0, 0, 0, 30, -45, 60) deg, tau = (0.05, 0,
-0.02) N m) stops with ``penetration`` within the first millisecond in the paper's model (its
contact link lies flush on the plate and turns about the one contact point). With the contacts
from geometry it runs its 0.5 s to the end, and the tests check it against references written
apart from the package:

* no overlap beyond the tolerance (1e-6 of the longest link) at any sample: the independent
  NumPy segment/plate depths of ``overlap_reference.py`` (the plate of side
  ``2 object_distance`` at the run's object pose, every link, and the links' crossings);
* no link deeper in the plate than the tolerance by the separating axis theorem either (the
  penetration depth, ``overlap_reference.sat_depths``);
* the energy law: the kinetic energy (the dense reference's mass matrix at every sample)
  never exceeds the torques' work, exactly ``tau . (q_joints(t) - q_joints(0))`` for a
  constant torque, but by the scheme's first-order error (below 1 % of the work at dt = 1 ms,
  and shrinking with dt; with the wheels' friction below 0.1 % at 1 ms and none at 0.5 ms);
* the object is pushed along the contact normal.
"""

from __future__ import annotations

import numpy as np
import pytest
from overlap_reference import overlaps, sat_depths
from reference import Reference

import snakecg
from snakecg.errors import InputError

Q0 = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])
TAU = np.array([0.05, 0.0, -0.02])


@pytest.fixture(scope="module")
def models():
    cache = {}

    def get(scenario):
        if scenario not in cache:
            scene = snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario, kappa=100.0)
            cache[scenario] = (scene, snakecg.load(scene), Reference(scene))
        return cache[scenario]

    return get


def _energy(ref, run):
    """The kinetic energy at every sample, from the dense reference, and the torques' work."""
    I_obj = np.diag([ref.m_obj, ref.m_obj, ref.I_obj_rot])
    ke = np.array([0.5 * v @ ref.mass_matrix(q) @ v + 0.5 * vo @ I_obj @ vo
                   for q, v, vo in zip(run.q, run.v, run.v_obj[:, 0])])
    work = (run.q[:, 3:] - run.q[0, 3:]) @ TAU
    return ke, work


@pytest.mark.parametrize("scenario", ["wheels", "ideal_wheels", "frictionless"])
def test_paper_push_runs_to_its_end_without_overlap(models, scenario):
    scene, sm, ref = models(scenario)
    paper = sm.simulate(Q0, TAU, 0.5)
    assert paper.summary["status"] == "penetration" and paper.t[-1] < 2e-3  # the finding
    run = sm.simulate(Q0, TAU, 0.5, contacts="geometry")
    assert run.status == "completed" and run.violation is None
    # every step of dt = 1 ms, but where the root finding shortened one at a contact's onset
    assert run.t[-1] == pytest.approx(0.5, abs=1e-12) and len(run.t) >= 501
    assert run.t[0] == 0.0 and 0 < np.diff(run.t).min() and np.diff(run.t).max() < 1e-3 + 1e-12
    tol = run.tolerance  # the time stepping's: 1e-5 of the scene's size
    assert 1e-7 < tol < 1e-5
    depth, bodies = overlaps(scene, run.q, run.q_obj[:, 0])
    worst = np.unravel_index(np.argmax(depth), depth.shape)
    assert depth.max() <= tol, (run.t[worst[0]], bodies[worst[1]], depth.max())
    assert sat_depths(scene, run.q, run.q_obj[:, 0]).max() <= tol
    # the same start as the paper's model: its placement of the object
    q_obj0, _, _ = ref.place_object(Q0)
    np.testing.assert_allclose(run.q_obj[0, 0], q_obj0, atol=1e-15)
    # pushed along the contact normal (link 1's left normal at the start)
    n0 = np.array([-np.sin(Q0[2]), np.cos(Q0[2])])
    assert (run.q_obj[-1, 0, :2] - run.q_obj[0, 0, :2]) @ n0 > 2e-4  # 0.5 mm (kappa 100)
    ke, work = _energy(ref, run)
    np.testing.assert_allclose(run.kinetic_energy, ke, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(run.work_tau, work, rtol=1e-9, atol=1e-15)
    assert work[-1] > 0.05  # the push does work
    if scenario == "wheels":
        assert np.all(ke <= work + 1e-3 * work[-1])
        assert run.friction_dissipation[-1] > 0
        fine = sm.simulate(Q0, TAU, 0.5, contacts="geometry", dt=5e-4)
        ke, work = _energy(ref, fine)
        assert fine.status == "completed" and np.all(ke <= work + 1e-12)
    else:
        assert np.all(ke <= work + 1e-2 * work[-1])


def test_energy_excess_is_the_schemes_first_order_error(models):
    """Without friction the kinetic energy may exceed the work by the scheme's error only: it
    falls with the step, by about 4 from dt = 1 ms to 0.25 ms (first order)."""
    scene, sm, ref = models("ideal_wheels")
    excess = []
    for dt in (1e-3, 2.5e-4):
        run = sm.simulate(Q0, TAU, 0.5, contacts="geometry", dt=dt)
        assert run.status == "completed"
        ke, work = _energy(ref, run)
        excess.append(float(np.max(ke - work)))
    assert excess[0] > 0 and 0 <= excess[1] < excess[0] / 3


def test_a_tighter_tolerance_is_kept_at_every_sample(models):
    """With the paper's tolerance (1e-6 of the longest link) the push stays within it, with
    wheels and without friction (where the plate's corner turns across the link: its depth
    is seen and held), by both independent checks."""
    tol = 1e-6 * 0.15
    for scenario in ("wheels", "frictionless"):
        scene, sm, ref = models(scenario)
        run = sm.simulate(Q0, TAU, 0.5, contacts="geometry", tolerance=tol)
        assert run.status == "completed" and run.t[-1] == pytest.approx(0.5, abs=1e-12)
        depth, _ = overlaps(scene, run.q, run.q_obj[:, 0])
        assert depth.max() <= tol
        assert sat_depths(scene, run.q, run.q_obj[:, 0]).max() <= tol


def test_at_rest_nothing_moves(models):
    scene, sm, ref = models("wheels")
    run = sm.simulate(Q0, np.zeros(3), 0.1, contacts="geometry")
    assert run.status == "completed"
    assert np.abs(run.q - Q0).max() == 0.0 and np.abs(run.kinetic_energy).max() == 0.0


def test_options_belong_to_their_model(models):
    scene, sm, ref = models("wheels")
    with pytest.raises(InputError, match="contacts must be 'paper' or 'geometry'"):
        sm.simulate(Q0, TAU, 0.1, contacts="plate")
    with pytest.raises(InputError, match="rtol is an option of contacts='paper'"):
        sm.simulate(Q0, TAU, 0.1, contacts="geometry", rtol=1e-6)
    with pytest.raises(InputError, match="dt is an option of contacts='geometry'"):
        sm.simulate(Q0, TAU, 0.1, dt=1e-3)
    with pytest.raises(InputError, match="q_obj0 must be 3 numbers"):
        sm.simulate(Q0, TAU, 0.1, contacts="geometry", q_obj0=[0.0, 0.05])


def test_cli_contacts_geometry(models, tmp_path, capsys):
    import json

    from snakecg import cli

    args = ["simulate", "--joints", "3", "--scenario", "wheels", "--kappa", "100", "--q",
            "0,0,0,30deg,-45deg,60deg", "--tau", "0.05,0,-0.02", "--duration", "0.5",
            "--out", str(tmp_path)]
    rc = cli.main([*args, "--contacts", "geometry", "--json"])
    s = json.loads(capsys.readouterr().out)
    assert rc == 0 and s["status"] == "completed" and s["duration"] == pytest.approx(0.5)
    scene, sm, ref = models("wheels")
    saved = np.load(tmp_path / "trajectory.npz")
    depth, _ = overlaps(scene, saved["q"], saved["q_obj"][:, 0])
    assert len(saved["t"]) == 501 and depth.max() <= s["tolerance"]
    rc = cli.main([*args, "--dt", "1e-3"])
    assert rc == 2 and "--dt applies to" in capsys.readouterr().err
