"""A MuJoCo model matched to a general scene of a snake among pegs on a Coulomb ground: the
independent reference of the general scene's simulation (tests/test_scenes_stepping.py,
benchmarks/bench_simulate_scenes.py).

Written apart from snakecg's equations: only the scene's numbers are read (the robot's masses,
inertias about the COM, lengths, COM offsets, the links' radius, the ground's mu, the pegs'
centres and radii) and MuJoCo builds its own dynamics from an MJCF string.

* **The chain**: link 1 (the tail) on slide x, slide y, hinge z and slide z to the world (its
  body frame at its COM, x along the link), each next link on a hinge z at the front end of
  the link before. ``qpos = (x, y, theta, z, q1..q_n)``: snakecg's ``q`` with the height
  inserted at index 3. Nothing can tilt, so the snake stays flat on the floor.
* **The ground**: gravity -g along z; every link carries a sphere at its COM (radius the
  links' radius) that alone touches the floor plane, with ``condim 3`` (isotropic Coulomb,
  no torsion or rolling: snakecg's disc of radius ``mu m_i g`` at the COM) and friction
  ``mu``. All links share the height, so each carries its own weight (equal impedances,
  equal depths). ``noslip`` iterations remove the soft model's creep of sticking contacts.
* **Pegs**: cylinders (axis z) fixed to the world. **Links** are capsules around their
  segments; capsules touch pegs and the links that are not neighbours (MuJoCo excludes a
  body's parent), frictionless (``condim 1``: snakecg's assumption 2).
* **Contacts**: ``solref = (2 timestep, 1)`` (the stiffest MuJoCo's stability rule allows)
  and a hard impedance ``solimp = (0.99, 0.9999, 1e-6)``.
"""

from __future__ import annotations

import numpy as np

__all__ = ["pegs_mjcf", "MatchedPegs"]


def _f(*values) -> str:
    return " ".join(f"{float(v):.17g}" for v in values)


def pegs_mjcf(scene, *, timestep: float = 1e-4, noslip: int = 10) -> str:
    """The MJCF text of ``scene`` (a :class:`snakecg.scenes.GeneralScene` with pegs and one
    Coulomb ground model)."""
    robot = scene.robot
    m, length, inertia, com = (np.asarray(x, float) for x in
                               (robot.mass, robot.length, robot.inertia, robot.com))
    r = float(scene.radius)
    mu = float(scene.ground[0].mu)
    g = float(scene.gravity)
    ref = f'solref="{_f(2 * timestep, 1.0)}" solimp="0.99 0.9999 1e-6"'
    n = len(m)

    def inertial(pos, mass, izz):
        return f'<inertial pos="{_f(pos, 0, 0)}" mass="{mass:.17g}" diaginertia="{_f(izz, izz, izz)}"/>'

    def geoms(i, x0):
        return (f'<geom type="capsule" size="{r:.17g}" fromto="{_f(x0, 0, 0, x0 + length[i], 0, 0)}" '
                f'contype="2" conaffinity="2" condim="1" friction="0 0 0" mass="0" {ref}/>'
                f'<geom type="sphere" size="{r:.17g}" pos="{_f(x0 + com[i], 0, 0)}" contype="1" '
                f'conaffinity="0" condim="3" friction="{_f(mu, 0, 0)}" mass="0" {ref}/>')

    body = (f'<body name="link1" pos="0 0 {r:.17g}">'
            '<joint name="x" type="slide" axis="1 0 0"/><joint name="y" type="slide" axis="0 1 0"/>'
            '<joint name="theta" type="hinge" axis="0 0 1"/><joint name="z" type="slide" axis="0 0 1"/>'
            f'{inertial(0.0, m[0], inertia[0])}{geoms(0, -com[0])}')
    front = length[0] - com[0]
    for i in range(1, n):
        body += (f'<body name="link{i + 1}" pos="{_f(front, 0, 0)}">'
                 f'<joint name="q{i}" type="hinge" axis="0 0 1"/>'
                 f'{inertial(com[i], m[i], inertia[i])}{geoms(i, 0.0)}')
        front = length[i]
    body += "</body>" * n
    pegs = "".join(f'<geom type="cylinder" size="{_f(o.radius, 0.1)}" pos="{_f(*o.center, 0)}" '
                   f'contype="0" conaffinity="2" condim="1" friction="0 0 0" {ref}/>'
                   for o in scene.obstacles if o.shape == "peg")
    return (f'<mujoco model="snakecg-pegs"><compiler angle="radian" autolimits="true"/>'
            f'<option timestep="{timestep:.17g}" integrator="implicitfast" gravity="0 0 {-g:.17g}" '
            f'solver="Newton" iterations="50" tolerance="1e-10" cone="elliptic" '
            f'noslip_iterations="{noslip}"/>'
            f'<worldbody><geom type="plane" size="20 20 0.1" contype="0" conaffinity="1" '
            f'condim="3" friction="{_f(mu, 0, 0)}" {ref}/>{pegs}{body}</worldbody></mujoco>')


class MatchedPegs:
    """The compiled matched model: ``state()`` and ``set_state(q, v)`` in snakecg's layout,
    ``step(tau)``, ``peg_depth()`` (the deepest capsule-peg or capsule-capsule overlap now)."""

    def __init__(self, scene, *, timestep: float = 1e-4, noslip: int = 10):
        import mujoco

        self.mujoco = mujoco
        self.scene = scene
        self.model = mujoco.MjModel.from_xml_string(pegs_mjcf(scene, timestep=timestep,
                                                              noslip=noslip))
        self.data = mujoco.MjData(self.model)
        self.na = scene.robot.n_links - 1
        caps = [i for i in range(self.model.ngeom) if self.model.geom_type[i] ==
                mujoco.mjtGeom.mjGEOM_CAPSULE]
        self._caps = set(caps)

    def set_state(self, q, v=None) -> None:
        d = self.data
        d.qpos[:3], d.qpos[3], d.qpos[4:] = q[:3], 0.0, q[3:]
        v = np.zeros(len(q)) if v is None else v
        d.qvel[:3], d.qvel[3], d.qvel[4:] = v[:3], 0.0, v[3:]
        self.mujoco.mj_forward(self.model, self.data)

    def state(self):
        d = self.data
        return np.r_[d.qpos[:3], d.qpos[4:]], np.r_[d.qvel[:3], d.qvel[4:]]

    def step(self, tau, nstep: int = 1) -> None:
        """``nstep`` steps of MuJoCo's with the joint torques ``tau`` held."""
        self.data.qfrc_applied[4:] = tau
        self.mujoco.mj_step(self.model, self.data, nstep)

    def peg_depth(self) -> float:
        d = self.data
        worst = 0.0
        for c in d.contact[:d.ncon]:
            if c.geom1 in self._caps or c.geom2 in self._caps:
                worst = max(worst, -float(c.dist))
        return worst
