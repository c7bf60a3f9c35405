"""A general scene's run in the engine's loop (snakecg/engine/scene_run.c) and batches of
runs (snakecg.scenes.simulate_scene_batch), against independent references:

* the serpenoid PD law the engine evaluates against Hirose's formula written here in NumPy,
  at every sample of a run (the torque held over each step from the state at its start);
* a torque table against NumPy's ``interp`` (linear) and a zero-order hold written here;
* the engine's loop against the same run with the law as a callable of the caller's own
  (the Python path: the loop returns for the torque at each step), field by field;
* a batch against the same runs one by one (bit for bit), split over threads or not;
* a batch against physical laws: Coulomb's stopping distance u^2 / (2 mu g) per run, an
  inelastic impact per disc thrown at a wall, no overlap beyond the tolerance among the pegs
  (NumPy distances of capsules and pegs at the runs' ends).
"""

from __future__ import annotations


import numpy as np
import pytest

import snakecg
from snakecg.errors import InputError
from snakecg.scenes import (GeneralScene, Ground, Obstacle, SceneObject, load_scene,
                            simulate_scene_batch)
from snakecg.simulate import Serpenoid, SerpenoidPD, TorqueTable, serpenoid_controller

from capsule_reference import point_segment
from scenes_reference import pegs_row

FIELDS = ("t", "q", "v", "q_obj", "v_obj", "tau", "min_gap", "n_contacts", "contact_impulse",
          "kinetic_energy", "work_tau", "friction_dissipation", "impact_loss", "contact_work")


@pytest.fixture(scope="module")
def pegs():
    scene, model, q0 = pegs_row()
    return scene, model, q0


def _hirose_pd(t, q, v, amplitude, frequency, lag, offset, kp, kd, tau_max):
    """tau_j = kp (A sin(w t + (j-1) lag) + offset - q_j) + kd (A w cos(w t + (j-1) lag) -
    qdot_j), clipped to +-tau_max (Hirose's serpenoid, tracked by a PD law)."""
    j = np.arange(q.shape[-1] - 3)
    w = 2 * np.pi * frequency
    ref = amplitude * np.sin(w * t[:, None] + j * lag) + offset
    rate = amplitude * w * np.cos(w * t[:, None] + j * lag)
    tau = kp * (ref - q[:, 3:]) + kd * (rate - v[:, 3:])
    return tau if tau_max is None else np.clip(tau, -tau_max, tau_max)


@pytest.mark.parametrize("tau_max", [None, 0.2])
def test_the_engines_serpenoid_pd_is_hiroses_formula(pegs, tau_max):
    scene, model, q0 = pegs
    gait = serpenoid_controller(model, amplitude=0.5, frequency=1.3, phase_lag=-2 * np.pi / 5,
                                offset=0.1, kp=10.0, kd=0.3, tau_max=tau_max)
    run = model.simulate(q0, 0.3, tau=gait)
    assert run.status == "completed" and len(run.t) == run.steps + 1
    # the torque of the step that ends at sample k, from the state at sample k - 1
    ref = _hirose_pd(run.t[:-1], run.q[:-1], run.v[:-1], 0.5, 1.3, -2 * np.pi / 5, 0.1,
                     10.0, 0.3, tau_max)
    np.testing.assert_allclose(run.tau[1:], ref, rtol=1e-12, atol=1e-12)
    if tau_max is not None:
        assert np.abs(run.tau).max() == tau_max  # the clip is reached
    assert np.abs(run.tau[0] - _hirose_pd(run.t[:1], run.q[:1], run.v[:1], 0.5, 1.3,
                                          -2 * np.pi / 5, 0.1, 10.0, 0.3, tau_max)[0]).max() \
        <= 1e-12


@pytest.mark.parametrize("interpolation", ["linear", "previous"])
def test_the_engines_torque_table_is_numpys_interpolation(pegs, interpolation):
    scene, model, q0 = pegs
    rng = np.random.default_rng(3)
    times = np.array([0.0, 0.0125, 0.05, 0.1, 0.1003, 0.2])
    torques = rng.uniform(-0.05, 0.05, (times.size, 10))
    table = TorqueTable(times + 0.01, torques, interpolation=interpolation)
    run = model.simulate(q0, 0.25, tau=table)
    assert run.status == "completed"
    t = run.t[:-1]  # each step's start
    if interpolation == "linear":
        ref = np.stack([np.interp(t, times + 0.01, torques[:, j]) for j in range(10)], axis=1)
    else:
        idx = np.clip(np.array([np.sum(times + 0.01 <= s) - 1 for s in t]), 0, None)
        ref = torques[idx]
    np.testing.assert_allclose(run.tau[1:], ref, rtol=1e-12, atol=1e-15)


def test_the_serpenoid_pd_call_is_hiroses_formula(pegs):
    """SerpenoidPD called from Python (the engine's law, core_scene_law; NumPy's copy where
    there is no compiled engine, as after pickling) against the formula written here."""
    import pickle

    from snakecg.scenes.stepping import SceneState

    scene, model, q0 = pegs
    rng = np.random.default_rng(7)
    gait = serpenoid_controller(model, amplitude=0.4, frequency=0.7, phase_lag=1.1,
                                offset=-0.2, kp=np.linspace(1, 3, 10), kd=0.2, tau_max=0.3)
    plain = pickle.loads(pickle.dumps(gait))
    assert gait._law is not None and plain._law is None
    for _ in range(20):
        t, q, v = rng.uniform(0, 3), rng.normal(size=13), rng.normal(size=13)
        ref = _hirose_pd(np.array([t]), q[None], v[None], 0.4, 0.7, 1.1, -0.2,
                         np.linspace(1, 3, 10), 0.2, 0.3)[0]
        none = np.zeros((0, 3))
        for law in (gait, plain):
            np.testing.assert_allclose(law(t, SceneState(t, q, v, none, none)), ref,
                                       rtol=1e-12, atol=1e-14)


def test_the_engines_loop_equals_the_callers_law_path(pegs):
    """The serpenoid PD law evaluated by the engine, and the same law written here in NumPy as
    a callable of the caller's own (the loop returns to Python for it at each step): the same
    run to 1e-12. The run has impacts and steps shortened by the onsets' root finding."""
    scene, model, q0 = pegs
    gait = serpenoid_controller(model, amplitude=0.5, frequency=1.0, phase_lag=2 * np.pi / 5,
                                kp=10.0, kd=0.3, tau_max=None)
    run = model.simulate(q0, 0.4, tau=gait)

    def numpy_law(t, state):
        return _hirose_pd(np.array([t]), state.q[None], state.v[None], 0.5, 1.0,
                          2 * np.pi / 5, 0.0, 10.0, 0.3, None)[0]

    ref = model.simulate(q0, 0.4, tau=numpy_law)
    assert run.status == ref.status == "completed"
    assert run.events and run.steps > 400  # impacts; onsets shortened steps
    assert run.steps == ref.steps and len(run.events) == len(ref.events)
    for k in FIELDS:
        np.testing.assert_allclose(getattr(run, k), getattr(ref, k), rtol=0, atol=1e-12,
                                   err_msg=k)
    for a, b in zip(run.events, ref.events):
        assert a.bodies == b.bodies and a.t == pytest.approx(b.t, abs=1e-12)
        np.testing.assert_allclose(a.impulses, b.impulses, rtol=1e-12, atol=1e-15)
    # output_every keeps every k-th sample and the last, the same samples
    sparse = model.simulate(q0, 0.4, tau=gait, output_every=7)
    keep = [k for k in range(len(run.t)) if k % 7 == 0] + [len(run.t) - 1]
    np.testing.assert_array_equal(sparse.t, run.t[keep])
    np.testing.assert_array_equal(sparse.q, run.q[keep])
    assert sparse.summary["energy"] == run.summary["energy"]


def test_a_run_handed_over_in_pieces_is_the_same_run(pegs, monkeypatch):
    """The engine's loop returns for a full record buffer (7 rows) and for pauses (every 5
    steps), and goes on exactly where it stopped: the same record as one long call."""
    import snakecg.scenes.stepping as stepping

    scene, model, q0 = pegs
    gait = serpenoid_controller(model, amplitude=0.5, frequency=1.0, phase_lag=2 * np.pi / 5,
                                kp=10.0, kd=0.3, tau_max=None)
    whole = model.simulate(q0, 0.2, tau=gait)
    monkeypatch.setattr(stepping, "RECORD_ROWS", 7)
    monkeypatch.setattr(stepping, "PAUSE_STEPS", 5)
    pieces = model.simulate(q0, 0.2, tau=gait)
    for k in FIELDS:
        np.testing.assert_array_equal(getattr(pieces, k), getattr(whole, k), err_msg=k)
    assert pieces.summary == whole.summary and len(whole.t) == whole.steps + 1 > 200


def test_the_loops_kept_steps_equal_steps_one_call_each(pegs):
    """The engine's loop keeps its steps' scratch from one to the next (the last step's M V,
    from its kinetic energy, in the next step's f); the same steps taken one call each
    (core_scene_step, every scratch fresh: M V summed anew) are the same run bit for bit, and
    its kinetic energy is 1/2 V^T M V of NumPy at every step's end."""
    from snakecg.scenes.run_record import ST_KE
    from snakecg.scenes.stepping import _Stepper

    scene, model, q0 = pegs
    tau = np.linspace(-0.5, 0.5, 10)
    run = model.simulate(q0, 0.06, tau=tau)
    assert run.status == "completed" and run.steps == 60  # (no step shortened)
    assert run.events  # (an impact: a step's second solve)
    st = _Stepper(model, run.tolerance, np.zeros(0))
    assert st.begin(q0, np.zeros(0), None, None) == 0
    st.tau[:] = tau
    for k in range(1, run.steps):  # (the last step's length: the duration's remainder)
        assert st.call(1e-3) == 0
        np.testing.assert_array_equal(st.x, run.q[k])
        np.testing.assert_array_equal(st.V, run.v[k])
        assert st.acc[ST_KE] == run.kinetic_energy[k]
        assert st.acc[ST_KE] == pytest.approx(0.5 * st.V @ st.M @ st.V, rel=1e-14)
    assert run.kinetic_energy[-1] > 1e-6  # (moving)


def test_a_subclassed_law_is_the_callers_own(pegs):
    """A subclass of SerpenoidPD may change the law: the engine does not evaluate it."""
    scene, model, q0 = pegs

    class Half(SerpenoidPD):
        def __call__(self, t, state):
            return 0.5 * super().__call__(t, state)

    law = Half(model, Serpenoid(10, 0.5, 1.0, 2 * np.pi / 5), kp=10.0, kd=0.3, tau_max=None)
    full = SerpenoidPD(model, Serpenoid(10, 0.5, 1.0, 2 * np.pi / 5), kp=10.0, kd=0.3,
                       tau_max=None)
    run = model.simulate(q0, 0.05, tau=law)
    ref = _hirose_pd(run.t[:-1], run.q[:-1], run.v[:-1], 0.5, 1.0, 2 * np.pi / 5, 0.0, 10.0,
                     0.3, None)
    np.testing.assert_allclose(run.tau[1:], 0.5 * ref, rtol=1e-12, atol=1e-12)
    assert not np.allclose(model.simulate(q0, 0.05, tau=full).tau[1:], run.tau[1:])


def _same_run(batch, i, run, model):
    assert batch.status[i] == run.status
    assert batch.t_end[i] == run.t[-1] and batch.steps[i] == run.steps
    assert batch.impacts[i] == len(run.events)
    np.testing.assert_array_equal(batch.q_end[i], run.q[-1])
    np.testing.assert_array_equal(batch.q_obj_end[i], run.q_obj[-1])
    np.testing.assert_array_equal(batch.object_displacement[i], run.q_obj[-1] - run.q_obj[0])
    com = model.com(run.q[[0, -1]])
    np.testing.assert_array_equal(batch.com_displacement[i], com[1] - com[0])
    assert batch.deepest_overlap[i] == max(0.0, -float(np.min(run.min_gap)))


@pytest.mark.parametrize("threads", ["1", "2"])
def test_a_batch_is_the_runs_one_by_one(pegs, monkeypatch, threads):
    monkeypatch.setenv("SNAKECG_THREADS", threads)
    scene, model, q0 = pegs
    gaits = [serpenoid_controller(model, amplitude=a, frequency=f, phase_lag=2 * np.pi / 5,
                                  kp=10.0, kd=0.3, tau_max=None)
             for a, f in ((0.3, 1.0), (0.5, 1.0), (0.7, 1.5))]
    batch = simulate_scene_batch(model, q0, 0.3, tau=gaits)
    assert len(batch) == 3 and batch.completed.all() and batch.impacts.sum() > 0
    for i, g in enumerate(gaits):
        _same_run(batch, i, model.simulate(q0, 0.3, tau=g), model)
    # many initial states, one constant torque for all
    starts = np.array([q0, q0 + np.r_[0.003, 0.0, 0.0, np.zeros(10)],
                       q0 + np.r_[0.006, 0.001, 0.0, np.zeros(10)], 0.8 * q0])  # the last overlaps
    tau = np.full(10, 0.02)
    batch = simulate_scene_batch(model, starts, 0.1, tau=tau)
    for i in range(3):
        _same_run(batch, i, model.simulate(starts[i], 0.1, tau=tau), model)
    assert batch.status[3] == "penetration" and batch.t_end[3] == 0.0
    with pytest.raises(InputError) as refused:  # one run alone is refused before any step
        model.simulate(starts[3], 0.1, tau=tau)
    assert batch.message[3] in str(refused.value)
    np.testing.assert_array_equal(batch.q_end[3], starts[3])


def test_a_batch_of_discs_stops_at_coulombs_distances():
    """Discs with ground friction mu thrown at speeds u stop after u^2 / (2 mu g) (within
    u h of it, the scheme's first order), one run each."""
    mu, g, h = 0.3, 9.81, 1e-3
    disc = SceneObject(shape="disc", radius=0.05, mass=1.5, pose=(0.0, 0.0, 0.0), mu=mu)
    scene = GeneralScene(snakecg.Robot(joints=1), ground=Ground(model="frictionless"),
                         objects=(disc,))
    model = load_scene(scene)
    u = np.array([0.2, 0.4, 0.6, 0.9])
    v_obj0 = np.zeros((4, 1, 3))
    v_obj0[:, 0, 0] = u
    batch = simulate_scene_batch(model, np.array([-2.0, 0.0, 0.0, 0.0]), 0.5, v_obj0=v_obj0,
                                 dt=h)
    assert batch.completed.all() and (batch.impacts == 0).all()
    assert np.all(np.abs(batch.object_displacement[:, 0, 0] - u * u / (2 * mu * g)) <= u * h)
    np.testing.assert_array_equal(batch.com_displacement, 0.0)  # the snake rests, far away


def test_a_batch_of_discs_at_a_wall_has_one_inelastic_impact_each():
    """A frictionless disc thrown at a wall stops on it with one inelastic impact, at the
    wall's distance less its radius: within the tolerance, or off the wall by the gap
    stabilisation's velocity (an onset located at -tol / 4 is pushed back at tol / (4 h),
    1 mm/s here, which nothing stops on a frictionless ground) times the time left."""
    disc = SceneObject(shape="disc", radius=0.05, mass=1.0, pose=(0.0, 0.0, 0.0))
    wall = Obstacle(shape="wall", point=(0.3, 0.0), normal=(-1.0, 0.0))
    scene = GeneralScene(snakecg.Robot(joints=1), ground=Ground(model="frictionless"),
                         objects=(disc,), obstacles=(wall,))
    model = load_scene(scene)
    v_obj0 = np.zeros((3, 1, 3))
    v_obj0[:, 0, 0] = [1.0, 2.0, 3.0]
    batch = simulate_scene_batch(model, np.array([-2.0, 0.0, 0.0, 0.0]), 0.4, v_obj0=v_obj0)
    assert batch.completed.all() and (batch.impacts == 1).all()
    gap = 0.25 - batch.q_obj_end[:, 0, 0]
    assert np.all(gap >= -batch.tolerance)
    assert np.all(gap <= batch.tolerance + batch.tolerance / 4 / 1e-3 * 0.4)
    np.testing.assert_array_equal(batch.object_displacement[:, 0, 0], -gap + 0.25)
    assert (batch.deepest_overlap <= batch.tolerance).all()


def test_a_batch_among_the_pegs_keeps_outside_them(pegs):
    """The runs' ends against NumPy distances of the capsule links and the pegs (the chain's
    kinematics written here), and the engine's deepest overlap within the tolerance."""
    scene, model, q0 = pegs
    gaits = [serpenoid_controller(model, amplitude=a, frequency=1.0, phase_lag=2 * np.pi / 5,
                                  kp=10.0, kd=0.3, tau_max=None) for a in (0.4, 0.6)]
    batch = simulate_scene_batch(model, q0, 0.5, tau=gaits)
    assert batch.completed.all() and (batch.deepest_overlap <= batch.tolerance).all()
    L, c, r = np.asarray(scene.robot.length), np.asarray(scene.robot.com), scene.radius
    for q in batch.q_end:
        th = q[2]
        rear = q[:2] - c[0] * np.array([np.cos(th), np.sin(th)])
        for i in range(len(L)):
            th = th + (q[2 + i] if i else 0.0)
            front = rear + L[i] * np.array([np.cos(th), np.sin(th)])
            for ob in scene.obstacles:
                gap = point_segment(np.asarray(ob.center), rear, front) - ob.radius - r
                assert gap >= -batch.tolerance
            rear = front


def test_a_batch_refuses_a_law_of_the_callers_own_and_bad_rows(pegs):
    scene, model, q0 = pegs
    with pytest.raises(InputError, match="law of its own"):
        simulate_scene_batch(model, q0, 0.1, tau=lambda t: np.zeros(10))
    with pytest.raises(InputError, match="q0"):
        simulate_scene_batch(model, np.zeros((2, 5)), 0.1)
    with pytest.raises(InputError, match="different numbers of runs"):
        simulate_scene_batch(model, np.zeros((2, 13)), 0.1, v0=np.zeros((3, 13)))
    with pytest.raises(InputError, match="output_every"):
        model.simulate(q0, 0.1, output_every=0)
