"""General scenes against MuJoCo with matched geometry: the snake's capsule links on a planar
base (inertia about z as the robot's), pegs and a disc object as vertical capsules (MuJoCo's
analytic capsule-capsule collider; in the plane a disc), frictionless contacts (condim 1),
stiff solref and an impedance near 1, no gravity (a frictionless ground does not load the
plane). MuJoCo's contacts are soft by design: its accelerations approach the rigid answer as
the impedance approaches 1; measured here within 1e-3 relative (the impedance 0.9999)."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg import Robot
from snakecg.scenes import GeneralScene, Obstacle, SceneObject

mujoco = pytest.importorskip("mujoco")


def _mjcf(robot, radius, q, pegs, disc, disc_pose):
    L = robot.length
    opt = ('<option timestep="0.0001" gravity="0 0 0"/><default><geom condim="1" '
           'solref="0.01 1" solimp="0.9999 0.9999 0.001" margin="1e-9" contype="1" '
           'conaffinity="2"/></default>')
    links, close = "", ""
    for i in range(robot.n_links):  # straight at qpos = 0; qpos = q places them
        c = robot.com[i]
        inert = (f'<inertial pos="{c} 0 0" mass="{robot.mass[i]}" '
                 f'diaginertia="{robot.inertia[i]} {robot.inertia[i]} {robot.inertia[i]}"/>')
        if i == 0:  # the base: link 1's COM slides in x, y and turns about z
            head = (f'<body pos="{-c} 0 0"><joint type="slide" axis="1 0 0" pos="{c} 0 0"/>'
                    f'<joint type="slide" axis="0 1 0" pos="{c} 0 0"/>'
                    f'<joint type="hinge" axis="0 0 1" pos="{c} 0 0"/>')
        else:
            head = (f'<body pos="{L[i - 1]} 0 0"><joint type="hinge" axis="0 0 1"/>')
        links += (head + inert + f'<geom type="capsule" size="{radius}" '
                  f'fromto="0 0 0 {L[i]} 0 0"/>')
        close += "</body>"
    world = "".join(f'<geom type="capsule" size="{p.radius}" fromto="{p.center[0]} '
                    f'{p.center[1]} -0.05 {p.center[0]} {p.center[1]} 0.05" contype="2" '
                    f'conaffinity="1"/>' for p in pegs)
    obj = ""
    if disc is not None:
        obj = (f'<body pos="0 0 0"><joint type="slide" axis="1 0 0"/>'
               f'<joint type="slide" axis="0 1 0"/><joint type="hinge" axis="0 0 1"/>'
               f'<inertial pos="0 0 0" mass="{disc.mass}" diaginertia="{disc.plate_inertia} '
               f'{disc.plate_inertia} {disc.plate_inertia}"/><geom type="capsule" '
               f'size="{disc.radius}" fromto="0 0 -0.05 0 0 0.05" contype="2" '
               f'conaffinity="1"/></body>')
    motors = "".join(f'<motor joint="j{i}"/>' for i in range(0))
    return f"<mujoco>{opt}<worldbody>{world}{links}{close}{obj}</worldbody>{motors}</mujoco>"


def _pegs(model, q, touching, radius):
    P = model.link_poses(q)
    out = []
    for link, off, side, r in touching:
        x, y, phi = P[link - 1]
        t = np.array([np.cos(phi), np.sin(phi)])
        n = np.array([-np.sin(phi), np.cos(phi)]) * side
        c = np.array([x, y]) + (off - model.robot.com[link - 1]) * t + (r + radius) * n
        out.append(Obstacle(shape="peg", center=(float(c[0]), float(c[1])), radius=r))
    return tuple(out)


@pytest.mark.parametrize("with_disc", [False, True])
def test_matched_scene_against_mujoco(with_disc, rng):
    robot = Robot(joints=3)
    radius = 0.01
    q = np.array([0.1, -0.2, 0.3, 0.5, -0.6, 0.4])
    base = snakecg.load(robot)
    pegs = _pegs(base, q, [(1, 0.05, 1, 0.03), (3, 0.1, -1, 0.02)], radius)
    disc = (SceneObject(shape="disc", radius=0.04, mass=3.0,
                        touching={"link": 4, "offset": 0.075, "side": "left"})
            if with_disc else None)
    scene = GeneralScene(robot, radius=radius, obstacles=pegs,
                         objects=(disc,) if disc else ())
    model = snakecg.load(scene)
    disc_pose = model.object_poses(q)[0] if disc else None
    m = mujoco.MjModel.from_xml_string(_mjcf(robot, radius, q, pegs, disc, disc_pose))
    d = mujoco.MjData(m)
    worst = 0.0
    for _ in range(5):
        tau = rng.normal(size=3)
        res = model.forward(q, tau)
        assert res.status == 0
        d.qpos[:6] = q  # the same coordinates: link 1's COM, its angle, the joint angles
        if disc:
            d.qpos[6:9] = disc_pose
        d.qvel[:] = 0.0
        d.qfrc_applied[:] = 0.0
        d.qfrc_applied[3:6] = tau
        mujoco.mj_forward(m, d)
        n_held = sum(c["state"] == "held" for c in res.contacts)
        assert d.ncon == len(res.contacts) >= n_held
        ours = np.r_[res.qdd, np.ravel(res.a_obj)]
        # MuJoCo's base slides along world x, y: the same coordinates as ours
        theirs = d.qacc.copy()
        worst = max(worst, np.abs(ours - theirs).max() / np.abs(ours).max())
    print(f"largest relative difference from MuJoCo: {worst:.2e}")
    assert worst <= 1e-3, worst
