"""Robots from URDF (snakecg.Robot.from_urdf, --robot FILE.urdf).

Reference: Pinocchio's own URDF reader, ``pin.buildModelFromUrdf``, with a planar root made
of prismatic X, prismatic Y and revolute Z joints. The URDFs written here put link 1's frame
at the tail's tip, so Pinocchio's root coordinates are those of the tip, not of link 1's COM
(snakecg's), and the zero configuration is bent by joint offsets ``delta_j``; the test maps
snakecg's coordinates to Pinocchio's, ``x_p = x - c_1 cos(theta)``, ``y_p = y - c_1
sin(theta)``, ``q_p = q - delta``, and compares ``M = T^T M_p T`` with ``T = dq_p/dq``.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

import snakecg
from snakecg.cli import main

pytest.importorskip("yourdfpy", reason="the urdf extra: pip install '.[urdf]'")


def _f(x) -> str:
    return repr(float(x))


def _rpy_matrix(r, p, y):
    cr, sr, cp, sp, cy, sy = np.cos(r), np.sin(r), np.cos(p), np.sin(p), np.cos(y), np.sin(y)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def write_urdf(path, mass, length, com, izz, *, delta=None, inertial_rpy=None, tips=(1, 1),
               axis="0 0 1", extra_joints="", name="snake"):
    """A planar snake: link k's frame at its rear end, x along the link; joint k at
    (l_k, 0, 0) of link k, yawed by delta_k; ``tips``: tip frames at the tail and head.
    ``inertial_rpy``: per link, the inertial frame's orientation; the tensor is given in that
    frame so that the inertia about the world z axis is ``izz`` (tests the rotation)."""
    nl = len(mass)
    delta = np.zeros(nl - 1) if delta is None else delta
    rpy = np.zeros((nl, 3)) if inertial_rpy is None else inertial_rpy
    out = [f'<robot name="{name}">']
    for k in range(nl):
        R = _rpy_matrix(*rpy[k])
        # a tensor with izz about z in the link frame, expressed in the inertial frame
        Iw = np.diag([0.3 * izz[k] + 1e-4, 0.7 * izz[k] + 1e-4, izz[k]])
        Iw[0, 1] = Iw[1, 0] = 0.1 * izz[k]
        Ii = R.T @ Iw @ R
        out.append(
            f'<link name="link{k + 1}"><inertial><origin xyz="{_f(com[k])} 0 0" '
            f'rpy="{_f(rpy[k][0])} {_f(rpy[k][1])} {_f(rpy[k][2])}"/>'
            f'<mass value="{_f(mass[k])}"/>'
            f'<inertia ixx="{_f(Ii[0, 0])}" ixy="{_f(Ii[0, 1])}" ixz="{_f(Ii[0, 2])}" '
            f'iyy="{_f(Ii[1, 1])}" iyz="{_f(Ii[1, 2])}" izz="{_f(Ii[2, 2])}"/></inertial></link>')
    for k in range(nl - 1):
        out.append(
            f'<joint name="joint{k + 1}" type="{"continuous" if k % 2 else "revolute"}">'
            f'<parent link="link{k + 1}"/><child link="link{k + 2}"/>'
            f'<origin xyz="{_f(length[k])} 0 0" rpy="0 0 {_f(delta[k])}"/>'
            f'<axis xyz="{axis}"/>'
            '<limit lower="-3" upper="3" effort="10" velocity="10"/></joint>')
    if tips[0]:
        out.append('<link name="tail_tip"/><joint name="tail_tip_joint" type="fixed">'
                   '<parent link="link1"/><child link="tail_tip"/>'
                   '<origin xyz="0 0 0"/></joint>')
    if tips[1]:
        out.append(f'<link name="head_tip"/><joint name="head_tip_joint" type="fixed">'
                   f'<parent link="link{nl}"/><child link="head_tip"/>'
                   f'<origin xyz="{_f(length[-1])} 0 0"/></joint>')
    out.append(extra_joints)
    out.append("</robot>")
    path.write_text("\n".join(out))
    return path


def _random_links(rng, nl):
    mass = rng.uniform(0.2, 3.0, nl)
    length = rng.uniform(0.05, 0.4, nl)
    com = length * rng.uniform(0.1, 0.9, nl)
    izz = rng.uniform(1e-4, 1e-2, nl)
    return mass, length, com, izz


@pytest.mark.parametrize("joints", [1, 3, 5])
def test_urdf_robot_mass_matrix_matches_pinocchio(joints, rng, tmp_path):
    pin = pytest.importorskip("pinocchio", reason="Pinocchio is a test extra (PyPI 'pin')")
    nl = joints + 1
    mass, length, com, izz = _random_links(rng, nl)
    delta = rng.uniform(-0.5, 0.5, joints)
    rpy = rng.uniform(-0.4, 0.4, (nl, 3))
    path = write_urdf(tmp_path / "snake.urdf", mass, length, com, izz, delta=delta,
                      inertial_rpy=rpy)
    robot = snakecg.Robot.from_urdf(path)
    assert robot.joints == joints and robot.name == "snake"
    np.testing.assert_allclose(robot.mass, mass, rtol=1e-15)
    np.testing.assert_allclose(robot.length, length, rtol=1e-12)
    np.testing.assert_allclose(robot.com, com, rtol=1e-12)
    np.testing.assert_allclose(robot.inertia, izz, rtol=1e-10)
    root = pin.JointModelComposite(3)
    for jm in (pin.JointModelPX(), pin.JointModelPY(), pin.JointModelRZ()):
        root.addJoint(jm)
    pmodel = pin.buildModelFromUrdf(str(path), root)
    pmodel.gravity = pin.Motion.Zero()
    data = pmodel.createData()
    assert pmodel.nv == robot.n_coordinates  # continuous joints: nq 2 (cos, sin), nv 1
    model = snakecg.load(robot)
    for _ in range(4):
        q = rng.uniform(-np.pi, np.pi, robot.n_coordinates)
        q[:2] = rng.uniform(-1, 1, 2)
        th = q[2]
        qp = np.zeros(pmodel.nq)
        qp[:3] = q[0] - com[0] * np.cos(th), q[1] - com[0] * np.sin(th), th
        for j in range(joints):
            jm = pmodel.joints[pmodel.getJointId(f"joint{j + 1}")]
            angle = q[3 + j] - delta[j]
            if jm.nq == 1:
                qp[jm.idx_q] = angle
            else:
                qp[jm.idx_q:jm.idx_q + 2] = np.cos(angle), np.sin(angle)
        T = np.eye(robot.n_coordinates)
        T[0, 2], T[1, 2] = com[0] * np.sin(th), -com[0] * np.cos(th)
        Mp = pin.crba(pmodel, data, qp).copy()
        Mp = np.triu(Mp) + np.triu(Mp, 1).T
        want = T.T @ Mp @ T
        np.testing.assert_allclose(model.mass_matrix(q), want, rtol=0,
                                   atol=1e-12 * np.abs(want).max())


def test_end_links_without_tips_have_their_com_in_the_middle(rng, tmp_path):
    mass, length, com, izz = _random_links(rng, 3)
    com[[0, -1]] = length[[0, -1]] / 2
    a = snakecg.Robot.from_urdf(write_urdf(tmp_path / "a.urdf", mass, length, com, izz))
    b = snakecg.Robot.from_urdf(write_urdf(tmp_path / "b.urdf", mass, length, com, izz,
                                           tips=(0, 0)))
    np.testing.assert_allclose(b.length, a.length, rtol=1e-12)
    np.testing.assert_allclose(b.com, a.com, rtol=1e-12)


def test_a_chain_in_another_plane_reads_the_same(rng, tmp_path):
    """Axes along y (the links in the xz plane): the same lengths and COMs, and the inertia
    about y."""
    mass, length, com, izz = _random_links(rng, 3)
    a = snakecg.Robot.from_urdf(write_urdf(tmp_path / "a.urdf", mass, length, com, izz))
    b_path = write_urdf(tmp_path / "b.urdf", mass, length, com, izz, axis="0 1 0")
    b = snakecg.Robot.from_urdf(b_path)
    np.testing.assert_allclose(b.length, a.length, rtol=1e-12)
    np.testing.assert_allclose(b.com, a.com, rtol=1e-12)
    # about y, the diag(0.3 izz, 0.7 izz, izz) tensor of write_urdf gives 0.7 izz + 1e-4
    np.testing.assert_allclose(b.inertia, 0.7 * izz + 1e-4, rtol=1e-10)


BAD = {
    "branch": ('<link name="fin"><inertial><mass value="1"/><inertia ixx="1" ixy="0" ixz="0"'
               ' iyy="1" iyz="0" izz="1"/></inertial></link><joint name="fin_joint" '
               'type="revolute"><parent link="link2"/><child link="fin"/><axis xyz="0 0 1"/>'
               '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>',
               r"branches at link 'link2' \(joints 'joint2', 'fin_joint'\)"),
    "prismatic": ('<link name="slider"><inertial><mass value="1"/><inertia ixx="1" ixy="0" '
                  'ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link><joint name="slide" '
                  'type="prismatic"><parent link="link3"/><child link="slider"/>'
                  '<axis xyz="1 0 0"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'
                  '</joint>', r"joint 'slide' is prismatic"),
    "fixed_mass": (('<link name="camera"><inertial><mass value="0.2"/><inertia ixx="1" '
                    'ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link><joint '
                    'name="cam_mount" type="fixed"><parent link="link1"/><child '
                    'link="camera"/></joint>'),
                   r"fixed joint 'cam_mount' attaches link 'camera', which has mass"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_other_structures_are_refused_naming_the_element(case, rng, tmp_path):
    extra, message = BAD[case]
    mass, length, com, izz = _random_links(rng, 3)
    path = write_urdf(tmp_path / "x.urdf", mass, length, com, izz, tips=(0, 1),
                      extra_joints=extra)
    with pytest.raises(snakecg.InputError, match=message):
        snakecg.Robot.from_urdf(path)


def test_non_parallel_axes_and_off_axis_com_are_refused(rng, tmp_path):
    """The planar reader refuses them; ``Robot.from_urdf`` reads them as a spatial chain."""
    from snakecg.urdf import robot_from_urdf

    mass, length, com, izz = _random_links(rng, 3)
    path = write_urdf(tmp_path / "x.urdf", mass, length, com, izz)
    text = path.read_text()
    tilted = text.replace(f'<origin xyz="{_f(length[1])} 0 0" rpy="0 0 0.0"/>',
                          f'<origin xyz="{_f(length[1])} 0 0" rpy="0.2 0 0.0"/>')
    assert tilted != text
    path.write_text(tilted)
    with pytest.raises(snakecg.InputError, match=r"axis of joint 'joint2' is 11.5 deg off"):
        robot_from_urdf(path, robot_type=snakecg.Robot)
    assert isinstance(snakecg.Robot.from_urdf(path), snakecg.SpatialRobot)
    off = text.replace(f'<origin xyz="{_f(com[1])} 0 0"',
                       f'<origin xyz="{_f(com[1])} 0.01 0"')
    path.write_text(off)
    with pytest.raises(snakecg.InputError, match=r"COM of link 'link2' lies 0.01 m off"):
        robot_from_urdf(path, robot_type=snakecg.Robot)
    assert snakecg.Robot.from_urdf(path).com[1] == pytest.approx((com[1], 0.01, 0.0))
    # within the tolerance it is read (and the offset along the axis n is irrelevant)
    path.write_text(text.replace(f'<origin xyz="{_f(com[1])} 0 0"',
                                 f'<origin xyz="{_f(com[1])} 1e-9 0.02"'))
    assert snakecg.Robot.from_urdf(path).com[1] == pytest.approx(com[1], rel=1e-12)


def test_missing_and_malformed_files(tmp_path):
    with pytest.raises(snakecg.InputError, match="does not exist"):
        snakecg.Robot.from_urdf(tmp_path / "nope.urdf")
    bad = tmp_path / "bad.urdf"
    bad.write_text("<robot name='x'><link name='a'></robot")
    with pytest.raises(snakecg.InputError, match="cannot be read"):
        snakecg.Robot.from_urdf(bad)


def test_cli_takes_a_urdf_robot(rng, tmp_path, capsys):
    mass, length, com, izz = _random_links(rng, 3)
    path = write_urdf(tmp_path / "s.urdf", mass, length, com, izz)
    assert main(["forward", "--robot", str(path), "--q", "0,0,0,0.3,-0.2",
                 "--tau", "0.01,0", "--scenario", "wheels", "--json"]) == 0
    import json

    out = json.loads(capsys.readouterr().out)
    robot = snakecg.Robot.from_urdf(path)
    want = snakecg.load(snakecg.Scene(robot, scenario="wheels")).forward(
        [0, 0, 0, 0.3, -0.2], [0.01, 0])
    np.testing.assert_allclose(out["qdd"], want.qdd, rtol=1e-12)
    path.write_text(path.read_text().replace('type="continuous"', 'type="prismatic"'))
    assert main(["forward", "--robot", str(path), "--q", "0,0,0,0.3,-0.2",
                 "--tau", "0.01,0"]) == 2
    err = capsys.readouterr().err
    assert "joint 'joint2' is prismatic" in err and len(err.strip().splitlines()) == 1


def test_the_example_urdf_is_the_example_toml_robot():
    from pathlib import Path

    root = Path(__file__).resolve().parents[1] / "examples"
    a = snakecg.Robot.from_urdf(root / "snake3.urdf")
    b = snakecg.Robot.from_toml(root / "robot.toml")
    assert a == b and a.name == b.name  # Table 1, exactly (the lengths rounded from 1e-17)


def _example_body() -> str:
    from pathlib import Path

    text = (Path(__file__).resolve().parents[1] / "examples" / "snake3.urdf").read_text()
    return text[text.index("<robot"):]


def test_dtds_and_entities_are_refused(tmp_path, capsys):
    """An external entity would make the file read as another robot (yourdfpy's recovering
    parser dropped the link that used it: 3 joints came back as 2); any DTD is refused, the
    entity never resolved, billion laughs included; CLI: one line, exit 2."""
    secret = tmp_path / "secret.txt"
    secret.write_text("link9")
    body = _example_body()
    cases = {
        "external": f'<!DOCTYPE robot [<!ENTITY x SYSTEM "file://{secret}">]>\n'
                    + body.replace('name="link2"', 'name="&x;"'),
        "internal": '<!DOCTYPE robot [<!ENTITY m "2.0">]>\n'
                    + body.replace('<mass value="1.0"/>', '<mass value="&m;"/>', 1),
        "doctype only": '<?xml version="1.0"?>\n<!DOCTYPE robot SYSTEM "robot.dtd">\n' + body,
        "billion laughs": '<!DOCTYPE r [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;'
                          '&a;&a;&a;&a;&a;"><!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">]>\n'
                          + body.replace('name="link1"', 'name="&c;"'),
    }
    for name, text in cases.items():
        path = tmp_path / f"{name.replace(' ', '_')}.urdf"
        path.write_text(text)
        with pytest.raises(snakecg.InputError, match="declares a DTD or entities"):
            snakecg.Robot.from_urdf(path)
        code = main(["forward", "--robot", str(path), "--q", "0,0,0,0,0,0", "--tau", "0,0,0"])
        err = capsys.readouterr().err
        assert code == 2 and len(err.splitlines()) == 1 and "DTD" in err, (name, err)
        assert "Traceback" not in err
    # an entity used without a declaration is not well-formed
    path = tmp_path / "undeclared.urdf"
    path.write_text(body.replace('name="link2"', 'name="&x;"'))
    with pytest.raises(snakecg.InputError, match="not well-formed XML.*'x' not defined"):
        snakecg.Robot.from_urdf(path)


def test_bad_arguments_axes_and_names(tmp_path):
    """from_urdf's arguments, a two-number axis and duplicate names: one clear InputError."""
    from pathlib import Path

    example = Path(__file__).resolve().parents[1] / "examples" / "snake3.urdf"
    for bad in (None, 3, b"robot.urdf", ["a"]):
        with pytest.raises(snakecg.InputError, match="path must be the path of a robot"):
            snakecg.Robot.from_urdf(bad)
    for tol, words in ((float("nan"), "finite"), (-1e-6, ">= 0"), (float("inf"), "finite"),
                       ("1e-6", "real number")):
        with pytest.raises(snakecg.InputError, match=f"tol must be.*{words}"):
            snakecg.Robot.from_urdf(example, tol=tol)
    body = _example_body()
    for axis in ("0 1", "0 0 1 0", "0 nan 1", "0 0 inf"):
        path = tmp_path / "axis.urdf"
        path.write_text(body.replace('<axis xyz="0 0 1"/>', f'<axis xyz="{axis}"/>', 1))
        with pytest.raises(snakecg.InputError,
                           match=f"joint 'joint1' has axis '{axis}'; expected three finite"):
            snakecg.Robot.from_urdf(path)
    path = tmp_path / "dup.urdf"
    path.write_text(body.replace('<link name="link3">', '<link name="link2">'))
    with pytest.raises(snakecg.InputError, match="link names must be unique; repeated: 'link2'"):
        snakecg.Robot.from_urdf(path)
    path.write_text(body.replace('name="joint2"', 'name="joint1"'))
    with pytest.raises(snakecg.InputError, match="joint names must be unique; repeated: 'joint1'"):
        snakecg.Robot.from_urdf(path)
    for device in ("/dev/zero", "/dev/null"):
        with pytest.raises(snakecg.InputError, match="is a device"):
            snakecg.Robot.from_urdf(device)


def test_values_come_back_as_the_file_writes_them(tmp_path):
    """A bent zero configuration puts the COMs through rotations: rounding to 15 digits left
    ``0.0999999999999999`` in the robot and its repr; the file's decimals come back."""
    com = [0.06, 0.05, 0.075, 0.1]
    path = write_urdf(tmp_path / "bent.urdf", [1.0] * 4, [0.15, 0.12, 0.15, 0.2], com,
                      [0.002] * 4, delta=np.array([0.09, 0.32, -0.77]))
    robot = snakecg.Robot.from_urdf(path)
    assert robot.com == tuple(com) and robot.length == (0.15, 0.12, 0.15, 0.2)
    assert "com=(0.06, 0.05, 0.075, 0.1)" in repr(robot)
    # limits shifted by the bend: joint 1 of write_urdf is revolute with lower -3, upper 3
    assert robot.joint_limits[0] == (-2.91, 3.09)


def test_a_missing_urdf_extra_names_the_install_for_this_installation(monkeypatch, tmp_path):
    """The advice follows pip's record of the installation (direct_url.json, PEP 610)."""
    import builtins
    import importlib.metadata as md

    from snakecg.extras import install_hint

    class Dist:
        def __init__(self, direct):
            self.direct = direct

        def read_text(self, name):
            return None if self.direct is None else json.dumps(self.direct)

    cases = [
        (None, "pip install 'snakecg[urdf]'"),
        ({"url": "file:///home/me/snakecg", "dir_info": {"editable": True}},
         "pip install -e '/home/me/snakecg[urdf]'"),
        ({"url": "file:///home/me/snakecg", "dir_info": {}},
         "pip install '/home/me/snakecg[urdf]'"),
        ({"url": "https://github.com/x/snakecg", "vcs_info": {"vcs": "git"}},
         "pip install 'snakecg[urdf] @ git+https://github.com/x/snakecg'"),
    ]
    for direct, want in cases:
        monkeypatch.setattr(md, "distribution", lambda name, d=direct: Dist(d))
        assert install_hint("urdf") == want

    def missing(name):
        raise md.PackageNotFoundError(name)

    monkeypatch.setattr(md, "distribution", missing)
    assert install_hint("urdf") == "pip install yourdfpy"
    # and the error a user sees without yourdfpy
    real_import = builtins.__import__

    def no_yourdfpy(name, *args, **kwargs):
        if name == "yourdfpy":
            raise ImportError(name)
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_yourdfpy)
    with pytest.raises(snakecg.InputError, match=r"needs the yourdfpy package \(the urdf "
                       r"extra\): pip install yourdfpy$"):
        snakecg.Robot.from_urdf(tmp_path / "any.urdf")
