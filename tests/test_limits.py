"""A robot's joint and effort limits (snakecg.limits): read from URDF, TOML and arguments,
and the defaults of optimize, optimize_shape and sweeps.

References: Pinocchio's own URDF reader and forward kinematics (the joint limits in
snakecg's angles are the relative yaws of consecutive link frames at the URDF's limits);
the dense NumPy model of ``tests/reference.py`` (with a frictionless contact the object's
acceleration is linear in the torque, so its largest norm over a torque box is at one of the
box's vertices, which the reference evaluates one by one).
"""

from __future__ import annotations

import itertools
import json
import math
import re

import numpy as np
import pytest
from reference import Reference, rest_maps, solve_rest_batch
from test_urdf import _random_links, write_urdf

import snakecg
from snakecg.cli import main

pytest.importorskip("yourdfpy", reason="the urdf extra: pip install '.[urdf]'")

#: The issue's robot: 4 joints, every joint limited to +-2 rad (+-114.6 deg) and 2 N m.
LIMIT, EFFORT = 2.0, 2.0


def _set_joint(text, name, *, axis=None, limit=None):
    """``text`` with joint ``name``'s axis and/or <limit> element replaced."""
    m = re.search(rf'<joint name="{name}".*?</joint>', text, flags=re.S)
    joint = m.group(0)
    if axis is not None:
        joint = re.sub(r'<axis xyz="[^"]*"/>', f'<axis xyz="{axis}"/>', joint)
    if limit is not None:
        joint = re.sub(r"<limit [^>]*/>", limit, joint)
    return text[:m.start()] + joint + text[m.end():]


def issue_urdf(path, joints=4):
    """A Table 1 snake whose every joint is revolute with <limit lower=-2 upper=2 effort=2>."""
    nl = joints + 1
    path = write_urdf(path, [1.0] * nl, [0.15] * nl, [0.075] * nl, [0.002] * nl)
    text = path.read_text().replace('type="continuous"', 'type="revolute"')
    text = text.replace('<limit lower="-3" upper="3" effort="10" velocity="10"/>',
                        f'<limit lower="{-LIMIT}" upper="{LIMIT}" effort="{EFFORT}" '
                        f'velocity="3"/>')
    path.write_text(text)
    return path


def test_urdf_limits_are_read_in_snakecg_angles_as_pinocchio_moves_the_links(rng, tmp_path):
    """A bent zero configuration (joint origins yawed by delta_j), a joint whose axis is
    opposite the first, and a continuous joint: each limit in snakecg's angles is the
    relative yaw of the two links' frames (x along each link) when Pinocchio puts the URDF
    joint at that limit."""
    pin = pytest.importorskip("pinocchio", reason="Pinocchio is a test extra (PyPI 'pin')")
    joints = 3
    mass, length, com, izz = _random_links(rng, joints + 1)
    delta = np.array([0.3, 0.1, -0.2])
    path = write_urdf(tmp_path / "s.urdf", mass, length, com, izz, delta=delta)
    text = path.read_text()  # joint2 is continuous (write_urdf alternates)
    text = _set_joint(text, "joint1", limit='<limit lower="-1.0" upper="0.5" effort="2.5" '
                      'velocity="1"/>')
    text = _set_joint(text, "joint2", limit='<limit effort="3" velocity="1"/>')
    text = _set_joint(text, "joint3", axis="0 0 -1",
                      limit='<limit lower="-0.4" upper="1.2" effort="4" velocity="1"/>')
    path.write_text(text)
    robot = snakecg.Robot.from_urdf(path)

    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()

    def yaw(R):
        return math.atan2(R[1, 0], R[0, 0])

    def relative_yaw(joint, value):
        """Yaw of the joint's child frame relative to its parent's at URDF angle ``value``
        (the other joints at zero), from Pinocchio's kinematics."""
        q = pin.neutral(model)
        jid = model.getJointId(joint)
        q[model.joints[jid].idx_q] = value
        pin.forwardKinematics(model, data, q)
        parent = model.parents[jid]
        R = data.oMi[parent].rotation.T @ data.oMi[jid].rotation
        return yaw(R)

    for j, name in ((0, "joint1"), (2, "joint3")):
        jid = model.getJointId(name)
        lo, hi = model.lowerPositionLimit[model.joints[jid].idx_q], \
            model.upperPositionLimit[model.joints[jid].idx_q]
        want = sorted((relative_yaw(name, lo), relative_yaw(name, hi)))
        np.testing.assert_allclose(robot.joint_limits[j], want, rtol=0, atol=1e-12)
    assert robot.joint_limits[1] == (-math.pi, math.pi)  # continuous: turns freely
    np.testing.assert_array_equal(robot.effort_limits, model.effortLimit)  # 2.5, 3, 4


def test_urdf_limit_problems_are_refused_or_warned(rng, tmp_path):
    mass, length, com, izz = _random_links(rng, 3)
    path = write_urdf(tmp_path / "s.urdf", mass, length, com, izz)
    text = path.read_text()
    path.write_text(_set_joint(text, "joint1", limit='<limit effort="1" velocity="1"/>'))
    with pytest.raises(snakecg.InputError, match=r"revolute joint 'joint1' has no <limit lower"):
        snakecg.Robot.from_urdf(path)
    path.write_text(_set_joint(text, "joint1", limit='<limit lower="1" upper="-1" effort="1" '
                               'velocity="1"/>'))
    with pytest.raises(snakecg.InputError, match=r"joint 'joint1' has <limit lower=1 upper=-1>"):
        snakecg.Robot.from_urdf(path)
    path.write_text(_set_joint(text, "joint1", limit='<limit lower="-1" upper="1" effort="0" '
                               'velocity="1"/>'))
    with pytest.raises(snakecg.InputError, match=r"effort_limits must be positive finite "
                       r"torques \(N m\), got 0.0 \(joint 1\)"):
        snakecg.Robot.from_urdf(path)
    # joint2 (continuous) without a <limit>: no effort limits at all, said by a warning
    path.write_text(re.sub(r'(<joint name="joint2".*?)<limit [^>]*/>', r"\1", text,
                           flags=re.S))
    with pytest.warns(UserWarning, match=r"joint\(s\) 'joint2' give no <limit effort>"):
        robot = snakecg.Robot.from_urdf(path)
    assert robot.effort_limits is None and robot.joint_limits[0] == (-3.0, 3.0)


def test_limits_from_arguments_and_toml_are_validated_and_printed(tmp_path):
    r = snakecg.Robot(joints=2, joint_limits=[(-1, 1), (-2, 0.5)], effort_limits=[1, 2])
    assert r.joint_limits == ((-1.0, 1.0), (-2.0, 0.5)) and r.effort_limits == (1.0, 2.0)
    assert eval(repr(r), {"Robot": snakecg.Robot}) == r
    assert repr(snakecg.Robot(joints=3, joint_limits=(-2, 2), effort_limits=2)) == \
        "Robot(joints=3, joint_limits=(-2.0, 2.0), effort_limits=2.0)"
    with pytest.raises(snakecg.InputError, match=r"invalid robot: joint_limits must hold "
                       r"pairs lower < upper \(rad\): lower 1 >= upper 1 \(joint 2\); "
                       r"effort_limits must be positive finite torques \(N m\), got -1"):
        snakecg.Robot(joints=2, joint_limits=[(-1, 1), (1, 1)], effort_limits=-1)
    path = tmp_path / "r.toml"
    path.write_text("[robot]\njoints = 2\njoint_limits = [[-1, 1], [-0.5, 0.5]]\n"
                    "effort_limits = [0.3, 0.2]\n")
    assert snakecg.Robot.from_toml(path) == snakecg.Robot(
        joints=2, joint_limits=((-1, 1), (-0.5, 0.5)), effort_limits=(0.3, 0.2))


def test_the_issue_max_a_obj_shape_stays_within_the_urdf_limits(tmp_path):
    """The issue's case: ``optimize_shape("max_a_obj")`` on a URDF robot limited to +-2 rad
    answered -135 deg; the robot's limits are now the default joint range, and its effort
    limits the default torque box."""
    robot = snakecg.Robot.from_urdf(issue_urdf(tmp_path / "issue.urdf"))
    assert robot.joint_limits == ((-LIMIT, LIMIT),) * 4
    assert robot.effort_limits == (EFFORT,) * 4
    model = snakecg.load(snakecg.Scene(robot, scenario="wheels"))
    res = model.optimize_shape("max_a_obj")
    # the sliding states' search covers the ellipsoid, not a torque box: stick_only says so
    assert res.status in ("optimal", "stick_only"), res.reason
    assert res.status == "optimal" or "sliding wheel states are not searched" in res.reason
    qj = res.q[3:]
    assert np.all(np.abs(qj) <= LIMIT + 1e-9), np.degrees(qj)
    assert np.max(np.abs(qj)) == pytest.approx(LIMIT, abs=1e-7)  # the limit binds
    assert np.all(np.abs(res.tau) <= EFFORT * (1 + 1e-9))
    assert res.limits == {"joint_limits": [[-LIMIT, LIMIT]] * 4, "joint_limits_from": "robot",
                          "tau_max": [EFFORT] * 4, "tau_max_from": "robot", "radius": None}
    # the same query with the old defaults leaves the robot's range: the limits matter here
    old = model.optimize_shape("max_a_obj", joint_limits=snakecg.shape.JOINT_LIMITS,
                               tau_max=None)
    assert old.status == "optimal" and np.max(np.abs(old.q[3:])) > LIMIT + 0.1
    assert old.limits["joint_limits_from"] == "argument" and old.limits["radius"] == 1.0


def test_effort_box_bounds_the_best_push_as_the_reference_finds_it(tmp_path):
    """Frictionless contact: ``a_obj = a_dir lam_c`` with ``lam_c`` linear in tau, so over the
    box ``|tau_j| <= effort_j`` the largest ``||a_obj||^2`` is at a vertex. The reference
    evaluates all 16 vertices at the returned shape: the answer's torque is the best one and
    its value the reference's."""
    robot = snakecg.Robot.from_urdf(issue_urdf(tmp_path / "issue.urdf"))
    scene = snakecg.Scene(robot, scenario="frictionless")
    res = snakecg.load(scene).optimize_shape("max_a_obj")
    assert res.status == "optimal", res.reason
    assert np.all(np.abs(res.q[3:]) <= LIMIT + 1e-9)
    ref = Reference(scene)
    vertices = np.array(list(itertools.product((-EFFORT, EFFORT), repeat=4)))
    out = solve_rest_batch(ref, rest_maps(ref, res.q), vertices)
    best = int(np.argmax(np.where(out["contact"], out["norm_a_obj"], -np.inf)))
    np.testing.assert_allclose(res.tau, vertices[best], rtol=0, atol=1e-7)
    assert res.value == pytest.approx(out["norm_a_obj"][best], rel=1e-9)


def test_optimize_takes_the_effort_limits_unless_told_otherwise():
    robot = snakecg.Robot(joints=3, effort_limits=(0.05, 0.04, 0.05))
    model = snakecg.load(snakecg.Scene(robot, scenario="wheels"))
    q = np.array([0, 0, 0, 0.5, -0.7, 0.9])
    res = model.optimize(q, "max_sr")
    assert res.status == "optimal"
    assert np.all(np.abs(res.tau) <= np.array(robot.effort_limits) * (1 + 1e-9))
    assert res.limits == {"tau_max": [0.05, 0.04, 0.05], "tau_max_from": "robot",
                          "radius": None}
    given = model.optimize(q, "max_sr", tau_max=0.05)
    assert given.limits["tau_max_from"] == "argument"
    free = model.optimize(q, "max_sr", tau_max=None)
    assert free.limits == {"tau_max": None, "tau_max_from": None, "radius": 1.0}
    assert free.to_dict()["limits"] == free.limits
    plain = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels"))
    assert plain.optimize(q, "max_sr").limits == free.limits  # no effort limits: the paper's


def test_cli_reports_the_limits_and_takes_none(tmp_path, capsys):
    path = issue_urdf(tmp_path / "issue.urdf", joints=2)
    base = ["optimize", "max_sr", "--robot", str(path), "--q", "0,0,0,0.5,-0.7",
            "--scenario", "wheels"]
    assert main(base + ["--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["objective"] == "max_sr"
    assert out["limits"] == {"tau_max": [EFFORT] * 2, "tau_max_from": "robot", "radius": None}
    assert main(base + ["--tau-max", "none"]) == 0
    text = capsys.readouterr().out
    assert text.startswith("max_sr: optimal")  # the canonical spelling, as in --json
    assert "limits: no torque box; ellipsoid radius 1 (eq. 31)" in text
    assert main(["optimize-shape", "max-sr", "--robot", str(path), "--starts", "2"]) == 0
    assert "limits: joints -114.6..114.6 deg (the robot's limits); |tau_j| <= 2 N m " \
        "(the robot's limits)" in capsys.readouterr().out


def test_sweep_grid_defaults_to_the_robot_joint_limits():
    from snakecg.sweeps.plan import PAPER_STEP_DEG, joint_values
    from snakecg.sweeps.run import make_plan

    robot = snakecg.Robot(joints=2, joint_limits=[(-2.0, 2.0), (-0.5, 1.0)])
    plan = make_plan(snakecg.Scene(robot))
    step = math.radians(PAPER_STEP_DEG)
    for values, (lo, hi) in zip(plan.values, robot.joint_limits):
        assert (values[0], values[-1]) == (lo, hi)  # both limits are configurations
        gaps = np.diff(values)
        assert np.all(gaps <= step + 1e-12) and np.ptp(gaps) < 1e-12
        assert len(values) == math.ceil((hi - lo) / step) + 1
    samples = make_plan(snakecg.Scene(robot), samples=100, seed=1)
    assert samples.bounds == robot.joint_limits
    q = samples.joint_angles(0, 100)
    assert np.all(q >= [-2.0, -0.5]) and np.all(q <= [2.0, 1.0])
    # a robot without limits keeps the paper's grid, 28 values from -135 to 135 degrees
    paper = make_plan(snakecg.Scene(snakecg.Robot(joints=2)))
    assert paper.values == (tuple(joint_values(-135.0, 135.0, 10.0)),) * 2
