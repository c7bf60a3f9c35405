"""The paper's contact check of a run with contacts from geometry, done in the engine's loop
(``scene_run.c`` at every kept sample, from the links' cos and sin the step took;
``snakecg.scenes.paper``).

The paper's push never overlaps the plate beyond the tolerance, so the check is run here with
plates larger than the scene's, the scene's plate started a little away from the contact link
(the links then cross the larger plates' sides during the run, at samples from the first to
the 200th, or already at the start), against references written apart from the code checked:

* the first sample whose largest overlap exceeds the tolerance, that overlap (to 1e-15 m) and
  its pair: tests/overlap_reference.py's NumPy depths (every link a segment against the plate
  of the given half side, the links' crossings) at every sample of the run's record;
* the run itself: the same run without the check, bit for bit (the check only reads);
* a run whose check fires ends with status ``penetration`` at that sample, as the check of its
  record after the run says.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from overlap_reference import overlaps

import snakecg
from snakecg.geometry import ContactCheck
from snakecg.scenes import paper as paper_module
from snakecg.scenes import stepping
from snakecg.scenes.paper import RECORD, _checked, _plate_model
from snakecg.scenes.stepping import _simulate
from snakecg.simulate.contact_check import RunCheck
from snakecg.simulate.dynamics import N_WORK

Q0 = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])
TAU = np.array([0.05, 0.0, -0.02])
#: the check's plate: the scene's half side times these (1: none found; 30: from the start)
FACTORS = (1.0, 1.02, 1.1, 1.3, 30.0)
#: the scene's plate started this far (m) from its place touching the contact link
AWAY = 0.02


@pytest.fixture(scope="module")
def paper():
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100.0)
    sm = snakecg.load(scene)
    pm = _plate_model(sm)
    qo = pm.simulate(Q0, 0.001, tau=TAU).q_obj[0, 0]  # (placed touching the contact link)
    toward = sm.link_poses(Q0)[scene.contact_link - 1, :2] - qo[:2]
    q_obj0 = qo - np.r_[AWAY * toward / np.linalg.norm(toward), 0.0]
    return scene, sm, pm, q_obj0


def _check(scene, sm, half, tol):
    """The paper's check (segments) with a plate of half side ``half`` at ``tol``."""
    shape = ContactCheck(scene.robot, half, tolerance=tol, radius=0.0)
    return shape, RunCheck(sm, "report", 6, 2 * 9 + N_WORK, shape=shape)


def _run(pm, q_obj0, tau, every, tol, check=None):
    return _simulate(pm, Q0, 0.3, None, tau, 1e-3, q_obj0.reshape(1, 3), None, None, tol,
                     every, False, None if check is None else (lambda _: check.address))


def _reference_first(scene, half, run, tol):
    """The NumPy reference's first sample beyond ``tol`` and its depths there."""
    depth, _ = overlaps(SimpleNamespace(robot=scene.robot, object_distance=half), run.q,
                        run.q_obj[:, 0])
    beyond = np.flatnonzero(depth.max(axis=1) > tol)
    return (int(beyond[0]), depth[int(beyond[0])]) if beyond.size else (None, None)


@pytest.mark.parametrize("every", [1, 3])
def test_the_runs_check_finds_the_references_first_overlap(paper, every):
    """At every plate of FACTORS, two torques and two tolerances: the check in the run finds
    the reference's first sample beyond the tolerance, its largest overlap within 1e-15 m and
    a pair of that overlap; the record is the unchecked run's bit for bit."""
    scene, sm, pm, q_obj0 = paper
    found, later = 0, 0
    for tau in (TAU, np.array([0.3, -0.2, 0.1]), np.array([-0.3, 0.2, -0.1])):
        for tol in (1e-5, 2e-6):
            plain, none = _run(pm, q_obj0, tau, every, tol)
            assert plain.status == "completed" and none is None
            for factor in FACTORS:
                half = factor * scene.object_distance
                _, rc = _check(scene, sm, half, tol)
                run, first = _run(pm, q_obj0, tau, every, tol, rc)
                assert run.status == plain.status and run.steps == plain.steps
                for k in ("t", "q", "v", "q_obj", "v_obj", "tau"):
                    np.testing.assert_array_equal(getattr(run, k), getattr(plain, k))
                k0, depths = _reference_first(scene, half, run, tol)
                if k0 is None:
                    assert first is None
                    continue
                found += 1
                k, depth, pair = first
                assert k == k0
                np.testing.assert_allclose(depth, depths.max(), rtol=0, atol=1e-15)
                np.testing.assert_allclose(depths[pair], depth, rtol=0, atol=1e-15)
                later += k > 0  # (the step's cos and sin; the first sample: its own)
                assert k == 0 if factor == FACTORS[-1] else k > 0
    assert found == 2 * 3 * (len(FACTORS) - 1) and later == 2 * 3 * (len(FACTORS) - 2)


def test_the_check_counts_samples_across_record_buffers(paper, monkeypatch):
    """With the record's buffer a few rows long (the engine returns for every few samples),
    the first sample beyond the tolerance is still counted from the run's first."""
    scene, sm, pm, q_obj0 = paper
    half, tol = 1.1 * scene.object_distance, 1e-5
    _, rc = _check(scene, sm, half, tol)
    want, first_want = _run(pm, q_obj0, TAU, 1, tol, rc)
    monkeypatch.setattr(stepping, "RECORD_ROWS", 7)
    run, first = _run(pm, q_obj0, TAU, 1, tol, rc)
    k0, _ = _reference_first(scene, half, run, tol)
    assert k0 is not None and k0 > 7 and first[0] == k0
    assert first == first_want
    np.testing.assert_array_equal(run.q, want.q)


def test_a_run_whose_check_fires_ends_with_penetration(paper, monkeypatch):
    """contacts='geometry' with the larger plate's check: status ``penetration`` at the
    reference's first sample beyond the tolerance, the link of its deepest overlap named, the
    trajectory the unchecked run's; the same as the check of the record after the run."""
    scene, sm, pm, q_obj0 = paper
    plain = sm.simulate(Q0, TAU, 0.3, contacts="geometry", q_obj0=q_obj0)
    tol = plain.tolerance
    half = 1.1 * scene.object_distance
    got = _check(scene, sm, half, tol)
    monkeypatch.setattr(paper_module, "_run_check", lambda model, tolerance: got)
    run = sm.simulate(Q0, TAU, 0.3, contacts="geometry", q_obj0=q_obj0)
    k0, depths = _reference_first(scene, half, run, tol)
    assert k0 is not None and k0 > 0 and run.status == "penetration"
    assert run.violation["t"] == run.t[k0]
    assert run.violation["bodies"] == [f"link {int(np.argmax(depths)) + 1}", "object 1"]
    np.testing.assert_array_equal(run.q, plain.q)
    after = _checked(sm, _run(pm, q_obj0, TAU, 1, tol)[0], RECORD)
    assert (after.status, after.message, after.violation) == (run.status, run.message,
                                                              run.violation)


def test_the_default_tolerance_is_a_share_of_the_scenes_size(paper):
    """A run's default contact tolerance (read from the scene's constants packed at its load)
    is 1e-5 of the scene's size summed here: the links' lengths, the links' diameter and the
    plate's diagonal; a tolerance given is the run's."""
    scene, sm, pm, q_obj0 = paper
    general = pm.scene
    plate = general.objects[0]
    size = float(sum(general.robot.length)) + 2 * general.radius + float(np.hypot(*plate.size))
    run = pm.simulate(Q0, 0.002, tau=TAU)
    assert run.tolerance == pytest.approx(1e-5 * size, rel=1e-15, abs=0)
    assert sm.simulate(Q0, TAU, 0.002, contacts="geometry").tolerance == run.tolerance
    assert pm.simulate(Q0, 0.002, tau=TAU, tolerance=3e-6).tolerance == 3e-6
