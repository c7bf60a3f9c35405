"""The generated model against Pinocchio (test extra ``pin``), random links and states.

The snake as a Pinocchio tree: a planar floating root made of prismatic X, prismatic Y and
revolute Z joints (massless except the last, which carries link 1 with its COM on the joint
axis), then one revolute Z joint per snake joint. ``JointModelPlanar`` is not used because its
velocity is expressed in the moving frame; the PX-PY-RZ chain has exactly snakecg's
coordinates and velocities ``(x, y, theta, q1..qn)``, so ``M``, ``h`` and the Jacobians compare
entry by entry.
"""

from __future__ import annotations

import numpy as np
import pytest

import snakecg

pin = pytest.importorskip(
    "pinocchio", reason="Pinocchio is a test extra: pip install '.[test]' (PyPI package 'pin')"
)

JOINTS = (1, 2, 4, 7)


def pinocchio_snake(robot: snakecg.Robot):
    """``(model, com_frame_ids)``: the snake in Pinocchio, one OP frame at each link COM."""
    m, l, inertia, c = (np.asarray(a) for a in (robot.mass, robot.length, robot.inertia,
                                                 robot.com))
    model = pin.Model()
    model.gravity = pin.Motion.Zero()
    parent = 0
    for name, joint in (("x", pin.JointModelPX()), ("y", pin.JointModelPY()),
                        ("theta", pin.JointModelRZ())):
        parent = model.addJoint(parent, joint, pin.SE3.Identity(), name)
    link_joints = [parent]  # link 1's frame: origin at its COM, x along the link
    for i in range(1, robot.n_links):
        # joint i at the front end of link i: (l_1 - c_1) from link 1's COM, then l_i from
        # the rear end of link i (the previous joint)
        offset = l[0] - c[0] if i == 1 else l[i - 1]
        parent = model.addJoint(parent, pin.JointModelRZ(),
                                pin.SE3(np.eye(3), np.array([offset, 0.0, 0.0])), f"q{i}")
        link_joints.append(parent)
    frames = []
    for i, jid in enumerate(link_joints):
        com = np.array([0.0 if i == 0 else c[i], 0.0, 0.0])
        # planar inertia about z is I_i; x and y rotational inertia never enter planar motion
        model.appendBodyToJoint(jid, pin.Inertia(m[i], com, np.diag([inertia[i]] * 3)),
                                pin.SE3.Identity())
        frames.append(model.addFrame(pin.Frame(f"com{i + 1}", jid, pin.SE3(np.eye(3), com),
                                               pin.FrameType.OP_FRAME)))
    return model, frames


def _random_states(rng, robot, n):
    q = rng.uniform(-np.pi, np.pi, (n, robot.n_coordinates))
    q[:, :2] = rng.uniform(-2, 2, (n, 2))
    return q, rng.normal(size=(n, robot.n_coordinates))


@pytest.mark.parametrize("joints", JOINTS)
def test_mass_matrix_bias_and_jacobians_match_pinocchio(joints, rng, random_robot):
    for _ in range(2):
        robot = random_robot(joints)
        model = snakecg.load(robot)
        pmodel, frames = pinocchio_snake(robot)
        data = pmodel.createData()
        assert pmodel.nq == pmodel.nv == robot.n_coordinates
        Q, V = _random_states(rng, robot, 5)
        M_all = model.mass_matrix(Q)
        H_all = model.bias_forces(Q, V)
        J_all = model.link_jacobians(Q)
        for q, v, M, h, J in zip(Q, V, M_all, H_all, J_all):
            Mp = pin.crba(pmodel, data, q).copy()
            Mp = np.triu(Mp) + np.triu(Mp, 1).T  # crba may fill the upper triangle only
            scale = np.abs(Mp).max()
            np.testing.assert_allclose(M, Mp, rtol=0, atol=1e-13 * scale)
            # h = rnea(q, v, 0) with zero gravity: Coriolis and centripetal terms
            hp = pin.rnea(pmodel, data, q, v, np.zeros_like(v))
            np.testing.assert_allclose(h, hp, rtol=0, atol=1e-12 * scale * (1 + v @ v))
            pin.computeJointJacobians(pmodel, data, q)
            pin.updateFramePlacements(pmodel, data)
            for i, fid in enumerate(frames):
                J6 = pin.getFrameJacobian(pmodel, data, fid, pin.LOCAL_WORLD_ALIGNED)
                # (v_x, v_y, omega_z) rows; the others vanish in planar motion
                np.testing.assert_allclose(J[i], J6[[0, 1, 5]], rtol=0, atol=1e-13 * (
                    1 + np.abs(J6).max()), err_msg=f"J of link {i + 1}")
                assert np.abs(J6[[2, 3, 4]]).max() == 0.0
                pose, mine = data.oMf[fid], model.link_poses(q)[i]
                np.testing.assert_allclose(mine[:2], pose.translation[:2], rtol=0,
                                           atol=1e-13 * (1 + np.abs(q[:2]).max()))
                angle = np.arctan2(pose.rotation[1, 0], pose.rotation[0, 0])
                assert np.angle(np.exp(1j * (mine[2] - angle))) == pytest.approx(0, abs=1e-13)
