"""Gaits: the serpenoid curve against its formula and finite differences, the PD law and the
torque table against hand-computed values, and runs of a serpenoid gait against physical
laws (a snake on frictionless ground cannot move its centre of mass; on wheels it crawls)."""

import math

import numpy as np
import pytest

import snakecg
from snakecg.simulate import Serpenoid, TorqueTable, serpenoid_controller, simulate


def test_serpenoid_matches_hirose_and_its_derivatives():
    c = Serpenoid(4, amplitude=0.5, frequency=0.8, phase_lag=-1.1, offset=0.05)
    t = 0.37
    want = [0.5 * math.sin(2 * math.pi * 0.8 * t + j * -1.1) + 0.05 for j in range(4)]
    assert c.angles(t) == pytest.approx(want, abs=1e-15)
    h = 1e-5
    assert c.rates(t) == pytest.approx((c.angles(t + h) - c.angles(t - h)) / (2 * h), abs=1e-9)
    assert c.accelerations(t) == pytest.approx((c.rates(t + h) - c.rates(t - h)) / (2 * h),
                                               abs=1e-8)


def test_torque_table_interpolates_and_holds():
    table = TorqueTable([0.0, 1.0, 3.0], [[0.0, 1.0], [2.0, -1.0], [4.0, 0.0]])
    assert table(0.5) == pytest.approx([1.0, 0.0])
    assert table(2.0) == pytest.approx([3.0, -0.5])
    assert table(-1.0) == pytest.approx([0.0, 1.0]) and table(9.0) == pytest.approx([4.0, 0.0])
    held = TorqueTable([0.0, 1.0, 3.0], [[0.0, 1.0], [2.0, -1.0], [4.0, 0.0]],
                       interpolation="previous")
    assert held(0.999) == pytest.approx([0.0, 1.0]) and held(1.0) == pytest.approx([2.0, -1.0])


def test_bad_gait_arguments_are_named():
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="frictionless"))
    with pytest.raises(snakecg.InputError, match="times must be finite, strictly increasing"):
        TorqueTable([0.0, 0.0], [[1.0], [2.0]])
    with pytest.raises(snakecg.InputError, match=r"torques must be .* shape \(2, n_a\)"):
        TorqueTable([0.0, 1.0], [1.0, 2.0])
    with pytest.raises(snakecg.InputError, match="frequency must be a number from 0 to 1e"):
        Serpenoid(3, 0.3, -1.0, 0.5)
    with pytest.raises(snakecg.InputError, match=r"kp must be .*; kd must be"):
        serpenoid_controller(model, amplitude=0.3, frequency=1.0, phase_lag=0.5,
                             kp=[1.0, 2.0], kd=-1.0)


def test_pd_law_against_its_formula_and_box():
    robot = snakecg.Robot(joints=3, effort_limits=[0.2, 0.2, 0.05])
    model = snakecg.load(snakecg.Scene(robot, scenario="frictionless"))
    law = serpenoid_controller(model, amplitude=0.4, frequency=1.0, phase_lag=0.9, kp=2.0,
                               kd=0.1)
    state = type("S", (), {"q": np.array([0, 0, 0, 0.1, -0.2, 0.3]),
                           "v": np.array([0, 0, 0, 0.5, 0.0, -0.5])})()
    t = 0.1
    ref = [0.4 * math.sin(2 * math.pi * t + 0.9 * j) for j in range(3)]
    dref = [0.4 * 2 * math.pi * math.cos(2 * math.pi * t + 0.9 * j) for j in range(3)]
    raw = [2.0 * (ref[j] - state.q[3 + j]) + 0.1 * (dref[j] - state.v[3 + j]) for j in range(3)]
    want = np.clip(raw, [-0.2, -0.2, -0.05], [0.2, 0.2, 0.05])
    assert law(t, state) == pytest.approx(want, abs=1e-15)
    assert abs(raw[2]) > 0.05  # the box acts on this state


def _com(model, q):
    poses = model.link_poses(q)
    m = np.asarray(model.robot.mass, float) * np.ones(poses.shape[-2])
    return (m[:, None] * poses[..., :2]).sum(-2) / m.sum()


@pytest.mark.parametrize("scenario", ["frictionless", "ideal_wheels"])
def test_serpenoid_gait_obeys_momentum(scenario):
    """Far from the object, a snake on frictionless ground has no external horizontal force:
    its centre of mass stays where it was while the joints swing. On ideal wheels the same
    gait moves it (the wheels' lateral forces push it)."""
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario=scenario, kappa=10.0))
    q0 = np.array([0.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    q_obj, rho, _ = model.place_object(q0)
    law = serpenoid_controller(model, amplitude=0.4, frequency=1.0, phase_lag=-1.0, kp=3.0,
                               kd=0.2)
    traj = simulate(model, q0, law, 2.0, q_obj0=q_obj + [0.0, 10.0, 0.0], rho=rho,
                    control_period=0.002)
    assert traj.summary["status"] == "completed"
    com = _com(model, traj.q)
    drift = np.linalg.norm(com - com[0], axis=-1).max()
    swing = np.ptp(traj.q[:, 3:], axis=0).min()
    assert swing > 0.3  # the gait does swing every joint
    if scenario == "frictionless":
        assert drift < 1e-8
    else:
        assert drift > 0.02


def test_batch_of_runs_equals_single_runs_and_sorts_out_gaits():
    """A batch of runs equals the single calls bit for bit (in this process and in worker
    processes), one row per run; and mirror symmetry: from the straight shape at rest on the
    x axis, the gait of amplitude -A is the mirror image (y -> -y) of the gait of amplitude A,
    so the centre of mass moves by the same x and the opposite y."""
    from snakecg.simulate import simulate_batch

    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="ideal_wheels",
                                       kappa=10.0))
    q0 = np.zeros(6)
    q_obj, rho, _ = model.place_object(q0)
    far = q_obj + [0.0, 10.0, 0.0]
    laws = [serpenoid_controller(model, amplitude=a, frequency=1.0, phase_lag=-1.0, kp=3.0,
                                 kd=0.2) for a in (0.4, -0.4)]
    opts = dict(q_obj0=far, rho=rho, control_period=0.005)
    single = [simulate(model, q0, law, 1.0, **opts) for law in laws]
    for processes in (1, 2):
        batch = simulate_batch(model, q0, laws, 1.0, processes=processes, progress=False,
                               **opts)
        assert len(batch) == 2 and batch.completed.all()
        for i, traj in enumerate(single):
            assert np.array_equal(batch.q_end[i], traj.q[-1])
            assert np.array_equal(batch.q_obj_end[i], traj.q_obj[-1])
    d = batch.com_displacement
    assert abs(d[0, 0]) > 0.05 and abs(d[0, 1]) > 1e-3
    assert d[1] == pytest.approx([d[0, 0], -d[0, 1]], rel=1e-9, abs=1e-12)
    with pytest.raises(snakecg.InputError, match="q0 has 3 rows, other arguments 2"):
        simulate_batch(model, np.zeros((3, 6)), laws, 1.0, **opts)


def test_cli_serpenoid(tmp_path, capsys):
    """``snakecg simulate --controller serpenoid`` runs the gait (the summary's COM moved as
    the library's run says) and names what is missing or misplaced (exit 2, one line)."""
    import json

    from snakecg import cli

    argv = ["simulate", "--joints", "3", "--scenario", "ideal_wheels", "--q", "0,0,0,0,0,0",
            "--controller", "serpenoid", "--amplitude", "0.4", "--frequency", "1",
            "--phase-lag=-1", "--kp", "3", "--kd", "0.2", "--duration", "1", "--json",
            "--no-figures", "--out", str(tmp_path / "run"), "--geometry-check", "off"]
    assert cli.main(argv) == 0
    out = json.loads(capsys.readouterr().out)
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="ideal_wheels"))
    law = serpenoid_controller(model, amplitude=0.4, frequency=1.0, phase_lag=-1.0, kp=3.0,
                               kd=0.2)
    traj = simulate(model, np.zeros(6), law, 1.0, control_period=0.002, geometry_check="off")
    assert out["snake_com_displacement"]["x"] == pytest.approx(
        traj.summary["snake_com_displacement"]["x"], rel=1e-12)
    assert cli.main(argv[:9] + ["--frequency", "1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "needs --amplitude, --phase-lag, --kp, --kd" in err
    assert cli.main(argv[:7] + ["--tau", "0,0,0", "--kp", "3"]) == 2
    assert "--kp applies to --controller serpenoid only" in capsys.readouterr().err
