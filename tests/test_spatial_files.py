"""Spatial robots from URDF and MJCF files: what is read, what is refused, and the planar
embedding (a chain of yaw joints is the planar model)."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg.spatial.files import rpy_of

from test_spatial_references import mujoco_chain, random_robot, rel

mujoco = pytest.importorskip("mujoco", reason="MuJoCo is a test extra: pip install '.[test]'")
pytest.importorskip("yourdfpy", reason="yourdfpy is a test extra: pip install '.[test]'")


def _urdf(robot, path, *, extra=""):
    f = lambda x: " ".join(repr(float(v)) for v in x)  # noqa: E731
    text = ['<robot name="s">']
    for i in range(robot.n_links):
        I = robot.inertia[i]
        text.append(
            f'<link name="l{i + 1}"><inertial><origin xyz="{f(robot.com[i])}" rpy="0 0 0"/>'
            f'<mass value="{robot.mass[i]!r}"/><inertia ixx="{I[0]!r}" iyy="{I[1]!r}" '
            f'izz="{I[2]!r}" ixy="{I[3]!r}" ixz="{I[4]!r}" iyz="{I[5]!r}"/></inertial></link>')
    for j in range(robot.joints):
        text.append(
            f'<joint name="j{j + 1}" type="revolute"><parent link="l{j + 1}"/>'
            f'<child link="l{j + 2}"/><origin xyz="{f(robot.joint_xyz[j])}" '
            f'rpy="{f(robot.joint_rpy[j])}"/><axis xyz="{f(robot.joint_axis[j])}"/>'
            f'<limit lower="-1.5" upper="{1.0 + j!r}" effort="{2.0 + j!r}" velocity="1"/>'
            '</joint>')
    text.append(extra + "</robot>")
    path.write_text("\n".join(text))
    return path


def test_urdf_round_trip_and_mass_matrix(rng, tmp_path):
    """A random spatial chain written as URDF reads back with the same parameters and the
    same mass matrix; limits are kept."""
    robot = random_robot(rng, 4)
    path = _urdf(robot, tmp_path / "s.urdf")
    read = snakecg.Robot.from_urdf(path)
    assert isinstance(read, snakecg.SpatialRobot)
    assert read == snakecg.SpatialRobot.from_urdf(path)
    assert read.joint_limits == tuple((-1.5, 1.0 + j) for j in range(robot.joints))
    assert read.effort_limits == tuple(2.0 + j for j in range(robot.joints))
    q = np.r_[0.1, 0.2, 0.3, 0, 0, 0, 1, rng.uniform(-1, 1, robot.joints)]
    assert rel(snakecg.load(read).mass_matrix(q), snakecg.load(robot).mass_matrix(q)) <= 1e-12


def test_mjcf_reads_mujocos_model(rng, tmp_path):
    """An MJCF chain (free root, hinges, joint positions off the body origins) gives the mass
    matrix MuJoCo computes for it."""
    robot = random_robot(rng, 5)
    _, mm = mujoco_chain(robot)
    path = tmp_path / "s.xml"
    mujoco.mj_saveLastXML(str(path), mm)
    text = path.read_text()
    # move every hinge off its body origin: the reader re-expresses the link frames
    path.write_text(text.replace('type="hinge"', 'type="hinge" pos="0.03 -0.02 0.01"', 1)
                    if 'type="hinge"' in text else
                    text.replace('<joint name="j1"', '<joint name="j1" pos="0.03 -0.02 0.01"'))
    mm = mujoco.MjModel.from_xml_path(str(path))
    md = mujoco.MjData(mm)
    read = snakecg.SpatialRobot.from_mjcf(path)
    assert read.joint_names == tuple(f"j{j + 1}" for j in range(robot.joints))
    q = np.r_[0.1, 0.2, 0.3, 0, 0, 0, 1, rng.uniform(-1, 1, robot.joints)]
    md.qpos[:] = np.r_[q[:3], 1, 0, 0, 0, q[7:]]
    mujoco.mj_forward(mm, md)
    M = np.zeros((read.nv, read.nv))
    try:
        mujoco.mj_fullM(mm, md, M)
    except TypeError:
        mujoco.mj_fullM(mm, M, md.qM)
    assert rel(snakecg.load(read).mass_matrix(q), M) <= 1e-12


@pytest.mark.parametrize("body, message", [
    ('<body name="x" pos="1 0 0"><joint name="s" type="slide"/>'
     '<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body>', "joint 's' .* slide"),
    ('<body name="x" pos="1 0 0"><joint name="b" type="ball"/>'
     '<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body>', "joint 'b' .* ball"),
    ('<body name="x" pos="1 0 0"><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>'
     '</body>', "body 'x' has 0 joints"),
])
def test_mjcf_refuses_other_joints_naming_them(tmp_path, body, message):
    xml = ('<mujoco><worldbody><body name="a"><freejoint/><inertial pos="0 0 0" mass="1" '
           'diaginertia="1 1 1"/><body name="b" pos="1 0 0"><joint name="h" type="hinge"/>'
           f'<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>{body}</body></body>'
           '</worldbody></mujoco>')
    (tmp_path / "x.xml").write_text(xml)
    with pytest.raises(snakecg.InputError, match=message):
        snakecg.Robot.from_mjcf(tmp_path / "x.xml")


def test_mjcf_refuses_a_branch(tmp_path):
    inertial = '<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>'
    xml = (f'<mujoco><worldbody><body name="a"><freejoint/>{inertial}'
           f'<body name="b" pos="1 0 0"><joint name="h1"/>{inertial}</body>'
           f'<body name="c" pos="-1 0 0"><joint name="h2"/>{inertial}</body>'
           '</body></worldbody></mujoco>')
    (tmp_path / "x.xml").write_text(xml)
    with pytest.raises(snakecg.InputError, match=r"branches at body 'a'"):
        snakecg.SpatialRobot.from_mjcf(tmp_path / "x.xml")


def test_planar_mjcf_gives_the_planar_robot(tmp_path):
    """Hinges about z with links along x and centred COMs: the paper's planar Robot."""
    inertial = '<inertial pos="0.075 0 0" mass="1" fullinertia="0.0002 0.002 0.002 0 0 0"/>'
    xml = (f'<mujoco><worldbody><body name="a"><freejoint/>{inertial}'
           f'<body name="b" pos="0.15 0 0"><joint name="h1" axis="0 0 1"/>{inertial}'
           f'<body name="c" pos="0.15 0 0"><joint name="h2" axis="0 0 1"/>{inertial}'
           '</body></body></body></worldbody></mujoco>')
    (tmp_path / "x.xml").write_text(xml)
    robot = snakecg.Robot.from_mjcf(tmp_path / "x.xml")
    assert isinstance(robot, snakecg.Robot)
    assert robot.length == pytest.approx((0.15,) * 3) and robot.inertia == pytest.approx(
        (0.002,) * 3) and robot.com == pytest.approx((0.075,) * 3)


def test_rpy_round_trip(rng):
    from snakecg.spatial.files import _rpy_matrix

    for _ in range(20):
        R = _rpy_matrix(*rng.uniform(-3, 3, 3))
        assert np.allclose(_rpy_matrix(*rpy_of(R)), R, atol=1e-14)
    assert np.allclose(_rpy_matrix(*rpy_of(_rpy_matrix(0.3, np.pi / 2, 0.2))),
                       _rpy_matrix(0.3, np.pi / 2, 0.2), atol=1e-14)


def _embedding(planar: snakecg.Robot) -> snakecg.SpatialRobot:
    """The planar snake as a spatial chain of yaw joints: the base frame at link 1's COM,
    link j+1's frame at joint j, x along the links, z up."""
    l, c = np.array(planar.length), np.array(planar.com)
    nl = planar.n_links
    xyz = [(l[0] - c[0], 0, 0)] + [(l[j], 0, 0) for j in range(1, nl - 1)]
    com = [(0, 0, 0)] + [(c[i], 0, 0) for i in range(1, nl)]
    return snakecg.SpatialRobot(joints=planar.joints, mass=planar.mass, com=com,
                                inertia=[(0.3 * I, 0.7 * I, I, 0, 0, 0) for I in planar.inertia],
                                joint_xyz=xyz, joint_axis=(0, 0, 1))


@pytest.mark.parametrize("joints", (1, 3))
def test_planar_embedding_gives_the_planar_model(rng, joints):
    """A chain of yaw joints in 3-D gives the planar model's M, link Jacobians, h and bias
    accelerations, mapped through the embedding v = E(q) v_s (to 1e-12): the base twist in
    the base frame is (R(theta)^T (xdot, ydot), 0; 0, 0, thetadot)."""
    planar = snakecg.Robot(joints=joints, mass=rng.uniform(0.5, 2, joints + 1),
                           length=rng.uniform(0.1, 0.3, joints + 1),
                           inertia=rng.uniform(1e-3, 5e-3, joints + 1))
    pm, sm = snakecg.load(planar), snakecg.load(_embedding(planar))
    qs = rng.uniform(-2, 2, planar.n_coordinates)
    vs = rng.normal(size=planar.n_coordinates)
    x, y, th = qs[:3]
    q = np.r_[x, y, 0, 0, 0, np.sin(th / 2), np.cos(th / 2), qs[3:]]
    ns, nv = planar.n_coordinates, sm.nv
    E = np.zeros((nv, ns))
    R2 = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
    E[:2, :2] = R2.T
    E[5, 2] = 1
    E[6:, 3:] = np.eye(joints)
    Edot = np.zeros((nv, ns))
    Edot[:2, :2] = (np.array([[-np.sin(th), -np.cos(th)], [np.cos(th), -np.sin(th)]]) * vs[2]).T
    v = E @ vs
    M = sm.mass_matrix(q)
    assert rel(E.T @ M @ E, pm.mass_matrix(qs)) <= 1e-12
    h = sm.bias_forces(q, v)  # gravity along -z does no work in the plane
    assert rel(E.T @ (M @ Edot @ vs + h), pm.bias_forces(qs, vs)) <= 1e-12
    Jp = pm.link_jacobians(qs)
    for i in range(planar.n_links):
        com = sm.robot.com[i]
        Jc = sm.point_jacobian(q, i + 1, com) @ E
        Jw = sm.link_jacobians(q)[i, 5] @ E
        assert rel(np.vstack([Jc[:2], Jw]), Jp[i]) <= 1e-12
        bias = (sm.point_bias_acceleration(q, v, i + 1, com)
                + sm.point_jacobian(q, i + 1, com) @ Edot @ vs)
        planar_bias = pm._named("link_bias_accelerations", 1, q=qs, v=vs,
                                K=pm.parameters)["bias"][0][:2, i]
        assert np.abs(bias[:2] - planar_bias).max() <= 1e-12 * max(1, np.abs(planar_bias).max())


_LINK = ('<link name="{}"><inertial><origin xyz="0.075 0 0"/><mass value="1"/><inertia '
         'ixx="0.0002" iyy="0.002" izz="0.002" ixy="0" ixz="0" iyz="0"/></inertial></link>')


def _joint(name, parent, child, kind="revolute"):
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
            '<origin xyz="0.15 0 0"/><axis xyz="0 1 0"/>'
            '<limit lower="-1" upper="1" effort="2" velocity="1"/></joint>')


@pytest.mark.parametrize("joints, message", [
    ([("j1", "a", "b"), ("j2", "a", "c")], r"branches at link 'a' \(joints 'j1', 'j2'\)"),
    ([("j1", "a", "b"), ("j2", "b", "c", "prismatic")], r"joint 'j2' is prismatic"),
    ([("j1", "a", "b"), ("j2", "b", "c", "floating")], r"joint 'j2' is floating"),
    ([("j1", "a", "b"), ("j2", "b", "c", "planar")], r"joint 'j2' is planar"),
    ([("j1", "a", "b"), ("j2", "b", "c", "fixed")], r"fixed joint 'j2' attaches link 'c'"),
    ([("j1", "a", "b"), ("j2", "b", "c"), ("j3", "a", "c")], r"'j3'"),
])
@pytest.mark.parametrize("reader", ["Robot", "SpatialRobot"])
def test_urdf_refusals_name_the_element(tmp_path, joints, message, reader):
    """A 3-D chain (pitch joints) with a branch, a loop or a joint that is not revolute is
    refused by both readers, naming the joint or link."""
    text = "".join(_LINK.format(n) for n in "abc") + "".join(_joint(*j) for j in joints)
    path = tmp_path / "x.urdf"
    path.write_text(f'<robot name="s">{text}</robot>')
    with pytest.raises(snakecg.InputError, match=message):
        getattr(snakecg, reader).from_urdf(path)


_INERTIAL = '<inertial pos="0.075 0 0" mass="1" fullinertia="0.0002 0.002 0.002 0 0 0"/>'


def _mjcf(tmp_path, hinges, after=""):
    """A chain of bodies 0.15 m apart under a free root; ``hinges`` the joints' attributes."""
    body, closing = f'<body name="b0"><freejoint name="root"/>{_INERTIAL}', "</body>"
    for k, attrs in enumerate(hinges, start=1):
        body += f'<body name="b{k}" {attrs[1]}><joint name="h{k}" {attrs[0]}/>{_INERTIAL}'
        closing += "</body>"
    path = tmp_path / "x.xml"
    path.write_text(f'<mujoco><compiler angle="radian"/><worldbody>{body}{closing}</worldbody>'
                    f'{after}</mujoco>')
    return path


@pytest.mark.parametrize("after, message", [
    ('<equality><connect name="close" body1="b0" body2="b2" anchor="0 0 0"/></equality>',
     r"equality 'close' \(connect: bodies 'b0' and 'b2'\) closes a loop"),
    ('<equality><weld body1="b1" body2="b2"/></equality>',
     r"equality constraint 1 \(unnamed\) \(weld: bodies 'b1' and 'b2'\) closes a loop"),
    ('<equality><joint name="couple" joint1="h1" joint2="h2"/></equality>',
     r"equality 'couple' \(joint: joints 'h1' and 'h2'\)"),
])
def test_mjcf_refuses_a_loop_naming_the_equality(tmp_path, after, message):
    path = _mjcf(tmp_path, [('axis="0 1 0"', 'pos="0.15 0 0"')] * 2, after)
    with pytest.raises(snakecg.InputError, match=message):
        snakecg.Robot.from_mjcf(path)


def test_mjcf_limits_are_mujocos_on_both_forms(tmp_path):
    """Position limits are MuJoCo's compiled ranges (degrees turned to radians by MuJoCo);
    effort limits a hinge's actuatorfrcrange, else gear times a motor's forcerange or
    ctrlrange, infinite (spatial) or absent (planar) where nothing bounds the joint; the
    planar Robot (yaw hinges) keeps them as the spatial one (a pitch hinge) does."""
    motors = ('<actuator><motor joint="h2" gear="3" ctrlrange="-0.5 0.25" ctrllimited="true"/>'
              '<motor joint="h3" gear="-2" forcerange="-1.5 1" forcelimited="true"/>'
              '</actuator>')
    spec = [('axis="0 0 1" range="-0.5 0.7" actuatorfrcrange="-4 2.5"', 'pos="0.15 0 0"'),
            ('axis="0 0 1" range="-1 1"', 'pos="0.15 0 0"'), ('axis="0 0 1"', 'pos="0.15 0 0"')]
    planar = snakecg.Robot.from_mjcf(_mjcf(tmp_path, spec, motors))
    assert isinstance(planar, snakecg.Robot)
    mm = mujoco.MjModel.from_xml_path(str(tmp_path / "x.xml"))
    assert planar.joint_limits == (tuple(mm.jnt_range[1]), tuple(mm.jnt_range[2]),
                                   (-np.pi, np.pi))
    assert planar.effort_limits == pytest.approx((4.0, 1.5, 3.0), rel=1e-15)
    spec[2] = ('axis="0 1 0"', 'pos="0.15 0 0"')  # a pitch hinge: the spatial form
    spatial = snakecg.Robot.from_mjcf(_mjcf(tmp_path, spec, motors))
    assert isinstance(spatial, snakecg.SpatialRobot)
    assert spatial.joint_limits[:2] == planar.joint_limits[:2]
    assert spatial.joint_limits[2] == (-np.inf, np.inf)
    assert spatial.effort_limits == pytest.approx((4.0, 1.5, 3.0), rel=1e-15)
    spec[2] = ('axis="0 0 1"', 'pos="0.15 0 0"')
    free = snakecg.Robot.from_mjcf(_mjcf(tmp_path, spec))  # no motors: h2 and h3 unbounded
    assert free.effort_limits is None
    assert snakecg.SpatialRobot.from_mjcf(tmp_path / "x.xml").effort_limits == (4.0, np.inf,
                                                                                np.inf)


@pytest.mark.parametrize("spec, why", [
    ([('axis="0 0 1"', 'pos="0.15 0 0"'), ('axis="0 0 -1"', 'pos="0.15 0 0"')],
     "an axis turned over"),
    ([('axis="0 0 1"', 'pos="0.15 0 0"'), ('axis="0 0 1"', 'pos="0.15 0 0" euler="0 0 0.4"')],
     "bent at zero"),
])
def test_planar_mjcf_whose_angles_differ_is_spatial_and_exact(tmp_path, rng, spec, why):
    """Yaw hinges whose planar angles would not be the file's (an axis pointing down, a
    chain bent in its zero configuration) are read in the spatial form, whose mass matrix
    is MuJoCo's (1e-12)."""
    path = _mjcf(tmp_path, spec)
    robot = snakecg.Robot.from_mjcf(path)
    assert isinstance(robot, snakecg.SpatialRobot), why
    mm = mujoco.MjModel.from_xml_path(str(path))
    md = mujoco.MjData(mm)
    q = np.r_[0.1, 0.2, 0.3, 0, 0, 0, 1, rng.uniform(-1, 1, robot.joints)]
    md.qpos[:] = np.r_[q[:3], 1, 0, 0, 0, q[7:]]
    mujoco.mj_forward(mm, md)
    M = np.zeros((robot.nv, robot.nv))
    try:
        mujoco.mj_fullM(mm, md, M)
    except TypeError:
        mujoco.mj_fullM(mm, M, md.qM)
    assert rel(snakecg.load(robot).mass_matrix(q), M) <= 1e-12


def test_mjcf_armature_is_left_out_with_a_warning(tmp_path):
    path = _mjcf(tmp_path, [('axis="0 1 0" armature="0.01"', 'pos="0.15 0 0"')])
    with pytest.warns(UserWarning, match=r"armature of joint\(s\) 'h1'"):
        snakecg.Robot.from_mjcf(path)
