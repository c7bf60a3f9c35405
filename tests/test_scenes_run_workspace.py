"""A general scene's run on workspaces kept from run to run, its start placed in one engine
call, its record's fields made when first read, and the paper's contact check of a run made
once per tolerance (``snakecg.scenes.stepping``, ``run_record``, ``paper``).

References written apart from what they check:

* the objects' placement at a run's start: tests/scenes_rows_reference.py's ``place_objects``
  (NumPy, from the link poses) and the model's own two steps (``link_poses``, then
  ``object_poses``) bit for bit;
* a run on a workspace another run used: the same run on a new workspace (a new model), bit
  for bit, whatever ran in between (other torques, tolerances, wrenches, record spacing,
  solves from scratch); a record read after later runs: the same numbers (nothing of it lives
  in the kept buffers);
* the paper's contact check of a run: tests/overlap_reference.py's NumPy depths (every link
  against the plate, the links' crossings) at every sample of a record moved into the plate.
"""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest
from overlap_reference import link_ends, overlaps
from scenes_rows_reference import place_objects

import snakecg
from snakecg import Robot
from snakecg.scenes import GeneralScene, SceneObject, load_scene
from snakecg.scenes.paper import _checked, _plate_model
from snakecg.scenes.run_record import _COLUMNS, SceneRun
from snakecg.scenes.stepping import COLD_START_ENV, KEEP_BYTES, _Stepper

Q0 = np.deg2rad([0.0, 0.0, 0.0, 30.0, -45.0, 60.0])
TAU = np.array([0.05, 0.0, -0.02])


@pytest.fixture(scope="module")
def paper():
    scene = snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels", kappa=100.0)
    return scene, snakecg.load(scene)


def _fields(run) -> dict:
    return {k: np.array(getattr(run, k)) for k in _COLUMNS} | {
        "status": run.status, "steps": run.steps, "events": len(run.events),
        "certificate": dict(run.certificate), "cos": run.min_sliding_cosine}


def _same(a: dict, b: dict) -> None:
    assert a.keys() == b.keys()
    for k in a:
        if isinstance(a[k], np.ndarray):
            np.testing.assert_array_equal(a[k], b[k], err_msg=k)
        else:
            assert a[k] == b[k], k


def test_a_runs_start_is_the_scenes_placement(rng):
    """The objects at a run's start (one engine call from q, core_scene_place_q) are the
    model's link_poses then object_poses bit for bit, and the NumPy reference's placement
    (a box and a disc touching links, an object at its pose) to 1e-12."""
    robot = Robot(joints=3)
    objects = (
        SceneObject(shape="box", size=(0.1, 0.06), mass=2.0,
                    touching={"link": 1, "offset": 0.03, "side": "left"}),
        SceneObject(shape="disc", radius=0.04, mass=1.0,
                    touching={"link": 3, "offset": 0.11, "side": "right"}),
        SceneObject(shape="box", size=(0.05, 0.05), mass=1.0, pose=(1.0, -2.0, 0.3)),
    )
    scene = GeneralScene(robot, radius=0.01, objects=objects)
    model = load_scene(scene)
    st = _Stepper(model, 1e-5, np.zeros(9))
    for q in np.c_[rng.normal(size=(30, 2)), rng.uniform(-np.pi, np.pi, 30),
                   rng.uniform(-1.2, 1.2, (30, 3))]:
        st.place(q)
        np.testing.assert_array_equal(st.x[:6], q)
        got = st.x[6:].reshape(3, 3)
        np.testing.assert_array_equal(got, model.object_poses(q))
        np.testing.assert_allclose(got, place_objects(scene, model.link_poses(q)), rtol=0,
                                   atol=1e-12)


def test_a_kept_workspace_runs_as_a_new_one(paper, monkeypatch):
    """The plate's push on the model's kept workspace, after runs with other torques, a
    tighter tolerance, a wrench on the plate, a sparser record and solves from scratch, is the
    push on a new model's new workspace bit for bit; so is each of those runs; and the first
    record, read only after all of them, is unchanged. A long run's record buffer (over
    KEEP_BYTES) is not kept, and the next run is the same."""
    scene, sm = paper
    plate = _plate_model(sm)
    others = [dict(tau=-TAU), dict(tau=TAU, tolerance=2e-6),
              dict(tau=TAU, f_obj=np.array([[0.3, -0.1, 0.01]])),
              dict(tau=TAU, output_every=7), dict(tau=TAU, v0=np.full(6, 0.02))]
    first = plate.simulate(Q0, 0.1, tau=TAU)
    kept = plate._steppers[-1]
    got = [_fields(plate.simulate(Q0, 0.1, **kw)) for kw in others]
    monkeypatch.setenv(COLD_START_ENV, "1")
    cold = _fields(plate.simulate(Q0, 0.1, tau=TAU))
    monkeypatch.delenv(COLD_START_ENV)
    again = _fields(plate.simulate(Q0, 0.1, tau=TAU))
    assert plate._steppers[-1] is kept and len(plate._steppers) == 2  # (one per tolerance)
    fresh = load_scene(plate.scene)  # a new model: new workspaces
    want = _fields(fresh.simulate(Q0, 0.1, tau=TAU))
    _same(again, want)
    _same(_fields(first), want)  # read after the later runs
    for kw, run in zip(others, got):
        _same(run, _fields(load_scene(plate.scene).simulate(Q0, 0.1, **kw)))
    long = plate.simulate(Q0, 4.5, tau=TAU)  # 4,096 rows at a return: its buffer not kept
    assert long.status == "completed" and len(long.t) > 4096
    assert all(st.runner.rec.nbytes <= KEEP_BYTES for st in plate._steppers)
    _same(_fields(plate.simulate(Q0, 0.1, tau=TAU)), want)
    monkeypatch.setenv(COLD_START_ENV, "1")
    _same(cold, _fields(fresh.simulate(Q0, 0.1, tau=TAU)))
    assert cold["steps"] == want["steps"]
    np.testing.assert_allclose(cold["q"], want["q"], rtol=0, atol=1e-9)


def test_a_records_fields_are_made_once_and_travel(paper):
    """A finished record's fields are made when first read, each C-contiguous float64 of
    the documented shape, the same object on the next read; a copy, a deep copy and a
    pickled record give the same numbers."""
    _, sm = paper
    run = sm.simulate(Q0, TAU, 0.05, contacts="geometry")
    n = len(run.t)
    assert n == 51 and "q" not in vars(run)
    shapes = {"q": (n, 6), "v": (n, 6), "q_obj": (n, 1, 3), "v_obj": (n, 1, 3), "tau": (n, 3)}
    for k in _COLUMNS:
        a = getattr(run, k)
        assert a is getattr(run, k) and a.dtype == np.float64 and a.flags.c_contiguous
        assert a.shape == shapes.get(k, (n,))
    np.testing.assert_array_equal(run.q[0], Q0)
    np.testing.assert_array_equal(run.tau, np.tile(TAU, (n, 1)))
    np.testing.assert_allclose(np.diff(run.t), 1e-3, rtol=1e-12)
    for other in (copy.copy(run), copy.deepcopy(run), pickle.loads(pickle.dumps(run))):
        _same(_fields(other), _fields(run))
    np.testing.assert_array_equal(run.states(), np.c_[run.q, run.q_obj[:, 0]])
    assert run.summary["samples"] == n and "SceneRun(" in repr(run)


def test_the_paper_check_of_a_run_finds_its_first_overlap(paper):
    """The push's record with the plate moved into the links from a sample on: the paper's
    contact check (made once per tolerance) reports the first sample whose depth, by the
    NumPy reference's depths, exceeds the tolerance, with its bodies; at two tolerances,
    each twice, and not where the record stays outside."""
    scene, sm = paper
    for tol, shift in ((1e-5, 3e-3), (2e-6, 1e-3), (1e-5, 3e-3), (2e-6, 1e-3)):
        run = _plate_model(sm).simulate(Q0, 0.05, tau=TAU, tolerance=tol)
        assert _checked(sm, run).status == "completed"
        data = run._data
        k0 = 20
        toward = sm.link_poses(run.q[k0])[scene.contact_link - 1, :2] - run.q_obj[k0, 0, :2]
        toward /= np.linalg.norm(toward)  # the plate's centre toward the contact link's
        data[k0:, 7:9] += shift * np.linspace(0.0, 1.0, len(data) - k0)[:, None] * toward
        moved = SceneRun.start(_plate_model(sm), tol, 1e-3)
        moved.samples(data)
        moved = moved.finish("completed", 0.05, "")
        depth, bodies = overlaps(scene, moved.q, moved.q_obj[:, 0])
        first = int(np.flatnonzero(depth.max(axis=1) > tol)[0])
        assert first > k0
        out = _checked(sm, moved)
        assert out.status == "penetration"
        assert out.violation["t"] == moved.t[first]
        link = bodies[int(np.argmax(depth[first]))][0]
        assert out.violation["bodies"] == [f"link {link}", "object 1"]


def test_the_paper_checks_depths_are_numpys(paper, rng):
    """The compiled check's deepest overlap and its pair (geometry.c: segments that do not
    cross skip their ends' distances, a link beyond a side of the plate its depth) against
    the NumPy reference's depths (tests/overlap_reference.py) at random states: the plate
    near the links (apart, touching, across, inside), links folded across each other, to
    1e-15 m, and the reported pair's depth is the reported one. The first state beyond a
    tolerance (core_contact_first: the fast cos and sin, then libm's within 1e-12 of it)
    is the first whose depth exceeds it, at tolerances equal to a state's depth and an ulp
    below it too."""
    from snakecg.geometry import ContactCheck
    from snakecg.simulate.contact_check import RunCheck
    from snakecg.simulate.dynamics import N_WORK

    scene, sm = paper
    check = ContactCheck.of_scene(scene, tolerance=1e-5, radius=0.0)
    rc = RunCheck(sm, "report", 6, 2 * 9 + N_WORK, shape=check)
    n = 4000
    q = np.c_[rng.normal(0.0, 0.05, (n, 2)), rng.uniform(-np.pi, np.pi, n),
              rng.uniform(-2.8, 2.8, (n, 3))]
    ends = np.stack(link_ends(scene.robot, q), axis=2)  # (n, 4, 2, 2)
    link = rng.integers(0, 4, n)
    along = rng.uniform(-0.2, 1.2, n)[:, None]
    point = ends[np.arange(n), link, 0] + along * (ends[np.arange(n), link, 1]
                                                   - ends[np.arange(n), link, 0])
    h = scene.object_distance
    q_obj = np.c_[point + rng.normal(0.0, 1.2 * h, (n, 2)), rng.uniform(-np.pi, np.pi, n)]
    q_obj[::7, 2] = np.arctan2(*(ends[::7, 0, 1] - ends[::7, 0, 0]).T[::-1])  # flush faces
    Y = np.zeros((n, rc.ny))
    Y[:, :6], Y[:, 6:9] = q, q_obj
    depth, pair = rc.deepest(Y)
    want, _ = overlaps(scene, q, q_obj)
    np.testing.assert_allclose(depth, want.max(axis=1), rtol=0, atol=1e-15)
    hit = want.max(axis=1) > 1e-12
    np.testing.assert_allclose(want[hit, pair[hit]], depth[hit], rtol=0, atol=1e-15)  # its pair
    crossed = want[:, 4:].max(axis=1) > 1e-9
    plate = want[:, :4].max(axis=1) > 1e-9
    assert crossed.sum() >= 100 and plate.sum() >= 500 and (~hit).sum() >= 500
    k1 = int(np.flatnonzero(want.max(axis=1) > 1e-3)[0])  # tolerances at a depth: exactly
    tols = (1e-6, 1e-3, 5e-3, 1.0, depth[k1], np.nextafter(depth[k1], 0.0))
    for tol in tols:  # the first state beyond tol, in place and not
        beyond = np.flatnonzero(depth > tol)  # (depth: the reference's within 1e-15)
        k0 = int(beyond[0]) if beyond.size else None
        for states in (Y, np.asfortranarray(Y[:, :9]), Y[:, :12]):
            k, d, p = rc.first_beyond(states, tol)
            assert k == k0
            if k is not None:
                assert d == depth[k] and p == pair[k]
