"""The spatial model against Pinocchio and MuJoCo, random axes, placements and links.

Both references are built here from the same raw numbers (masses, COMs, inertias, joint
origins ``xyz``/``rpy`` and axes), independently of snakecg: Pinocchio as a free-flyer root
with ``JointModelRevoluteUnaligned`` joints, MuJoCo from an MJCF string with a free joint and
hinges. Pinocchio shares snakecg's coordinates (``q`` with the quaternion scalar last, the
base twist in the base frame); MuJoCo's free joint takes the quaternion scalar first and the
linear velocity in world axes, so its matrices are mapped by ``v_mj = T v`` with
``T = diag(R_b, 1, 1)``: ``M = T^T M_mj T``, ``J = J_mj T``, ``h = T^T (M_mj Tdot v + h_mj)``.
"""

from __future__ import annotations

import numpy as np
import pytest

import snakecg

pin = pytest.importorskip("pinocchio", reason="Pinocchio is a test extra: pip install '.[test]'")

#: Link counts of the default run (the checked-in models and one generated into the cache);
#: the long chains are in the slow run.
LINKS = (2, 3, 4, 9)
LINKS_SLOW = (16, 32)
TOL = 1e-12


def rel(a, b) -> float:
    a, b = np.asarray(a), np.asarray(b)
    return float(np.abs(a - b).max() / max(np.abs(b).max(), 1e-300))


def random_inertia(rng):
    """Six entries of a random physical inertia about a COM (principal moments obeying the
    triangle inequality, random principal axes)."""
    a, b = rng.uniform(0.2, 1.0, 2)
    moments = np.array([a, b, rng.uniform(abs(a - b) + 0.05, a + b - 0.05)]) * \
        10 ** rng.uniform(-3, -1)
    Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    I = Q @ np.diag(moments) @ Q.T
    return [I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]]


def random_robot(rng, n_links) -> snakecg.SpatialRobot:
    na = n_links - 1
    return snakecg.SpatialRobot(
        joints=na, mass=rng.uniform(0.2, 3.0, n_links), com=rng.normal(0, 0.1, (n_links, 3)),
        inertia=[random_inertia(rng) for _ in range(n_links)],
        joint_xyz=rng.normal(0, 0.2, (na, 3)), joint_rpy=rng.uniform(-np.pi, np.pi, (na, 3)),
        joint_axis=rng.normal(size=(na, 3)), gravity=rng.normal(0, 5, 3))


def _matrix(six):
    xx, yy, zz, xy, xz, yz = six
    return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])


def _rpy(r, p, y):
    cr, sr, cp, sp_, cy, sy = np.cos(r), np.sin(r), np.cos(p), np.sin(p), np.cos(y), np.sin(y)
    Rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    Ry = np.array([[cp, 0, sp_], [0, 1, 0], [-sp_, 0, cp]])
    Rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return Rz @ Ry @ Rx


def pinocchio_chain(robot):
    model = pin.Model()
    model.gravity.linear = np.array(robot.gravity)
    jid = model.addJoint(0, pin.JointModelFreeFlyer(), pin.SE3.Identity(), "base")
    model.appendBodyToJoint(jid, pin.Inertia(robot.mass[0], np.array(robot.com[0]),
                                             _matrix(robot.inertia[0])), pin.SE3.Identity())
    for j in range(robot.joints):
        a = np.array(robot.joint_axis[j])
        jid = model.addJoint(jid, pin.JointModelRevoluteUnaligned(a / np.linalg.norm(a)),
                             pin.SE3(_rpy(*robot.joint_rpy[j]), np.array(robot.joint_xyz[j])),
                             f"j{j + 1}")
        model.appendBodyToJoint(jid, pin.Inertia(robot.mass[j + 1], np.array(robot.com[j + 1]),
                                                 _matrix(robot.inertia[j + 1])),
                                pin.SE3.Identity())
    return model


def mujoco_chain(robot):
    mujoco = pytest.importorskip("mujoco", reason="MuJoCo is a test extra: pip install '.[test]'")

    def quat(R):  # w x y z of a rotation matrix (Shepperd's method via pinocchio-free numpy)
        w = np.sqrt(max(0.0, 1 + np.trace(R))) / 2
        if w > 1e-3:
            return [w, (R[2, 1] - R[1, 2]) / (4 * w), (R[0, 2] - R[2, 0]) / (4 * w),
                    (R[1, 0] - R[0, 1]) / (4 * w)]
        k = int(np.argmax(np.diag(R)))
        i, j2, l_ = k, (k + 1) % 3, (k + 2) % 3
        s = np.sqrt(max(0.0, 1 + R[i, i] - R[j2, j2] - R[l_, l_])) * 2
        v = [0.0, 0.0, 0.0]
        v[i] = s / 4
        v[j2] = (R[j2, i] + R[i, j2]) / s
        v[l_] = (R[l_, i] + R[i, l_]) / s
        return [(R[l_, j2] - R[j2, l_]) / s] + v

    f = lambda x: " ".join(repr(float(v)) for v in x)  # noqa: E731

    def inertial(i):
        return (f'<inertial pos="{f(robot.com[i])}" mass="{robot.mass[i]!r}" '
                f'fullinertia="{f(robot.inertia[i])}"/>')

    body = f'<body name="b1">{inertial(0)}<freejoint name="root"/>'
    closing = "</body>"
    for j in range(robot.joints):
        body += (f'<body name="b{j + 2}" pos="{f(robot.joint_xyz[j])}" '
                 f'quat="{f(quat(_rpy(*robot.joint_rpy[j])))}">{inertial(j + 1)}'
                 f'<joint name="j{j + 1}" type="hinge" axis="{f(robot.joint_axis[j])}"/>')
        closing += "</body>"
    xml = (f'<mujoco><compiler angle="radian"/><option gravity="{f(robot.gravity)}"/>'
           f'<worldbody>{body}{closing}</worldbody></mujoco>')
    return mujoco, mujoco.MjModel.from_xml_string(xml)


def _states(rng, robot, model, n):
    qs = [pin.randomConfiguration(model, -2 * np.ones(model.nq), 2 * np.ones(model.nq))
          for _ in range(n)]
    return np.array(qs), rng.normal(size=(n, model.nv))


def _check_against_pinocchio(rng, n_links):
    robot = random_robot(rng, n_links)
    sm = snakecg.load(robot)
    model = pinocchio_chain(robot)
    data = model.createData()
    q, v = _states(rng, robot, model, 4)
    M, h = sm.mass_matrix(q), sm.bias_forces(q, v)
    J, bias = sm.link_jacobians(q), sm.link_bias_accelerations(q, v)
    T = sm.link_poses(q)
    for k in range(len(q)):
        Mp = pin.crba(model, data, q[k])
        Mp = np.triu(Mp) + np.triu(Mp, 1).T
        assert rel(M[k], Mp) <= TOL
        assert rel(h[k], pin.rnea(model, data, q[k], v[k], np.zeros(model.nv))) <= TOL
        pin.forwardKinematics(model, data, q[k], v[k], np.zeros(model.nv))
        pin.computeJointJacobians(model, data, q[k])
        for i in range(n_links):
            Jp = pin.getJointJacobian(model, data, i + 1, pin.LOCAL_WORLD_ALIGNED)
            assert rel(J[k, i], Jp) <= TOL
            acc = pin.getClassicalAcceleration(model, data, i + 1, pin.LOCAL_WORLD_ALIGNED)
            assert rel(bias[k, i], np.r_[acc.linear, acc.angular]) <= TOL
            assert rel(T[k, i], data.oMi[i + 1].homogeneous) <= TOL
    # a point of the last link: Jacobian and classical acceleration of an operational frame
    r = rng.normal(0, 0.2, 3)
    fid = model.addFrame(pin.Frame("p", n_links, 0, pin.SE3(np.eye(3), r),
                                   pin.FrameType.OP_FRAME))
    data = model.createData()
    Jpt = sm.point_jacobian(q, n_links, r)
    bpt = sm.point_bias_acceleration(q, v, n_links, r)
    for k in range(len(q)):
        pin.forwardKinematics(model, data, q[k], v[k], np.zeros(model.nv))
        pin.computeJointJacobians(model, data, q[k])
        pin.updateFramePlacements(model, data)
        assert rel(Jpt[k], pin.getFrameJacobian(model, data, fid,
                                                pin.LOCAL_WORLD_ALIGNED)[:3]) <= TOL
        acc = pin.getFrameClassicalAcceleration(model, data, fid, pin.LOCAL_WORLD_ALIGNED)
        assert rel(bpt[k], acc.linear) <= TOL


def _check_against_mujoco(rng, n_links):
    robot = random_robot(rng, n_links)
    mujoco, mm = mujoco_chain(robot)
    md = mujoco.MjData(mm)
    sm = snakecg.load(robot)
    model = pinocchio_chain(robot)  # only for random configurations on the right manifold
    q, v = _states(rng, robot, model, 3)
    M, h, J = sm.mass_matrix(q), sm.bias_forces(q, v), sm.link_jacobians(q)
    bias = sm.link_bias_accelerations(q, v)
    nv = robot.nv
    for k in range(len(q)):
        quat = q[k, 3:7]
        R = pin.Quaternion(quat[3], *quat[:3]).toRotationMatrix()
        T = np.eye(nv)
        T[:3, :3] = R
        md.qpos[:] = np.r_[q[k, :3], quat[3], quat[:3], q[k, 7:]]
        md.qvel[:] = T @ v[k]
        mujoco.mj_forward(mm, md)
        Mmj = np.zeros((nv, nv))
        try:
            mujoco.mj_fullM(mm, md, Mmj)  # MuJoCo 4: (model, data, dst)
        except TypeError:
            mujoco.mj_fullM(mm, Mmj, md.qM)  # MuJoCo 3: (model, dst, qM)
        assert rel(M[k], T.T @ Mmj @ T) <= TOL
        Tdot_v = np.zeros(nv)
        Tdot_v[:3] = R @ np.cross(v[k, 3:6], v[k, :3])
        assert rel(h[k], T.T @ (Mmj @ Tdot_v + md.qfrc_bias)) <= TOL
        for i in range(n_links):
            jacp, jacr = np.zeros((3, nv)), np.zeros((3, nv))
            mujoco.mj_jac(mm, md, jacp, jacr, md.xpos[i + 1], i + 1)
            assert rel(J[k, i], np.vstack([jacp, jacr]) @ T) <= TOL
            # Jdot v of the same rows: d/dt (J_mj T) v = Jdot_mj v_mj + J_mj Tdot v
            dp, dr = np.zeros((3, nv)), np.zeros((3, nv))
            mujoco.mj_jacDot(mm, md, dp, dr, md.xpos[i + 1], i + 1)
            expected = np.vstack([dp, dr]) @ md.qvel + np.vstack([jacp, jacr]) @ Tdot_v
            assert rel(bias[k, i], expected) <= TOL, i


@pytest.mark.parametrize("n_links", LINKS)
def test_against_pinocchio(rng, n_links):
    """M (crba), h (rnea), link Jacobians and classical accelerations, poses and a point's
    Jacobian and acceleration, to 1e-12 relative."""
    _check_against_pinocchio(rng, n_links)


@pytest.mark.parametrize("n_links", LINKS)
def test_against_mujoco(rng, n_links):
    """M (mj_fullM), h (qfrc_bias), link Jacobians (mj_jac) and their Jdot v (mj_jacDot) to
    1e-12 relative."""
    _check_against_mujoco(rng, n_links)


@pytest.mark.slow
@pytest.mark.parametrize("n_links", LINKS_SLOW)
def test_long_chains_against_pinocchio_and_mujoco(rng, n_links):
    _check_against_pinocchio(rng, n_links)
    _check_against_mujoco(rng, n_links)


def test_full_blocks_against_pinocchio(rng):
    """Batches of two full blocks of 16 and a partial one (the block drivers' transposing
    scatter and its one-by-one tail): every sample's M and h equal Pinocchio's crba and rnea
    (1e-12)."""
    robot = random_robot(rng, 5)
    sm = snakecg.load(robot)
    model = pinocchio_chain(robot)
    data = model.createData()
    q, v = _states(rng, robot, model, 37)
    M, h = sm.mass_matrix(q), sm.bias_forces(q, v)
    for k in range(len(q)):
        Mp = pin.crba(model, data, q[k])
        assert rel(M[k], np.triu(Mp) + np.triu(Mp, 1).T) <= TOL, k
        assert rel(h[k], pin.rnea(model, data, q[k], v[k], np.zeros(model.nv))) <= TOL, k
