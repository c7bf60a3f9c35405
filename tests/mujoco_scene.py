"""A MuJoCo model matched to a snakecg scene: the independent reference of the simulation
(tests/test_simulate_mujoco.py, benchmarks/bench_simulate_mujoco.py,
docs/explanation/simulation-vs-mujoco.md).

Written apart from snakecg's equations: only the scene's numbers are read (masses, inertias
about the COM, lengths, COM offsets of the :class:`~snakecg.Robot`; the object's mass,
inertia and half side of the :class:`~snakecg.Scene`), and MuJoCo builds its own dynamics
from an MJCF string.

* **Planar by construction.** The snake is a chain of bodies: link 1 (the tail) on three
  joints to the world (slide x, slide y, hinge z, its body frame at the link's COM, x along
  the link), each next link on a hinge z at the front end of the link before. The object is
  one body on slide x, slide y, hinge z at its COM. No body has any other degree of freedom,
  so the motion stays in the plane z = 0 whatever the forces; gravity is off (nothing
  carries weight: the ground is frictionless, so it is simply absent). MuJoCo's ``qpos``
  and ``qvel`` are then snakecg's ``q, v`` (snake) followed by ``q_obj, v_obj`` (object)
  exactly: the same coordinates, no conversion.
* **Links** are capsules of radius ``link_radius`` around the segment from the rear to the
  front joint; snakecg's links are lines, so the object is shrunk by that radius (below), and
  the capsule's surface touches it where the line would touch the real object.
* **The object**, ``object_geometry=``

  - ``"box"`` (default): the scene's square plate (side ``2 object_distance``), a box of
    half side ``object_distance - link_radius`` in the plane (and 0.05 m half height), that
    every link may touch: the physical object;
  - ``"point"``: today's contact model of snakecg, a point fixed in the object (``rho``,
    the scene's contact point) against the contact link alone: a sphere of radius
    ``link_radius`` at ``rho`` moved ``2 link_radius`` into the object, so that sphere and
    capsule touch where the point touches the line (to ``2 link_radius (1 - cos theta)``,
    ``theta`` the angle between the link and the face).

  Links never touch each other (snakecg does not model it; the runs compared avoid it).
* **Contacts** are frictionless (``condim 1``: the normal force only; elliptic cones and
  ``noslip`` iterations act on friction dimensions alone, so they play no part here),
  ``margin 0``, with the stiffest reference MuJoCo's stability rule allows
  (``solref = (2 timestep, dampratio)``, the time constant at its floor ``2 timestep``) and a
  hard impedance (``solimp = (dmin, dmax, width)``, default ``(0.99, 0.9999, 1e-6)``).
  A held contact then sits inside by about ``(1 - d)/d * a_0 * (2 timestep)^2`` (MuJoCo's
  soft constraint at rest, ``a_0`` the gap's acceleration without the contact, ``d`` the
  impedance): it falls as the step squared (measured on the W push of the tests: 2e-8 m at
  1e-4 s, 2e-9 at 3e-5 s, 2e-10 at 1e-5 s, growing through the push with the snake's
  speed); through an impact it peaks at the order of the closing speed times ``2 timestep``.
* **Joint torques** enter as generalized forces on the hinge coordinates
  (``qfrc_applied``), as snakecg's ``B tau``.

The solver is Newton at tolerance 1e-12; the integrator ``implicitfast`` (default),
``Euler`` or ``RK4``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["MatchedScene", "matched_mjcf", "matched_scene"]

DEFAULT_SOLIMP = (0.99, 0.9999, 1e-6)


def _f(*values) -> str:
    return " ".join(f"{float(v):.17g}" for v in values)


def matched_mjcf(scene, *, timestep: float = 1e-5, integrator: str = "implicitfast",
                 link_radius: float = 1e-3, object_geometry: str = "box",
                 rho=None, dampratio: float = 1.0, solimp=DEFAULT_SOLIMP,
                 iterations: int = 100, tolerance: float = 1e-12) -> str:
    """The MJCF text of ``scene`` (a :class:`snakecg.Scene`), see the module's doc.
    ``rho`` (``"point"`` only): the contact point in the object's frame (default: the
    middle of the face towards the snake, ``(0, -side_sign object_distance)``)."""
    if object_geometry not in ("box", "point"):
        raise ValueError(f"object_geometry must be 'box' or 'point', got {object_geometry!r}")
    robot = scene.robot
    m, length, inertia, com = (np.asarray(x, float) for x in
                               (robot.mass, robot.length, robot.inertia, robot.com))
    h = float(scene.object_distance)
    r = float(link_radius)
    if not 0 < r < h / 10:
        raise ValueError(f"link_radius must be in (0, object_distance / 10), got {r}")
    solref = _f(2.0 * timestep, dampratio)
    contact = (f'condim="1" margin="0" gap="0" solref="{solref}" '
               f'solimp="{_f(*solimp)}" friction="0 0 0"')

    def inertial(pos, mass, i_zz):  # the x, y inertias only need to be valid (no such dof)
        return (f'<inertial pos="{_f(pos, 0, 0)}" mass="{mass:.17g}" '
                f'diaginertia="{_f(i_zz, i_zz, i_zz)}"/>')

    k = scene.contact_link - 1
    point = object_geometry == "point"

    def link_geom(i, x0):  # capsule along the link, x0 = rear end in the body frame
        collide = (not point) or i == k
        flags = 'contype="1" conaffinity="0"' if collide else 'contype="0" conaffinity="0"'
        return (f'<geom name="link{i + 1}" type="capsule" size="{r:.17g}" '
                f'fromto="{_f(x0, 0, 0, x0 + length[i], 0, 0)}" {flags} {contact}/>')

    n = len(m)
    body = (f'<body name="link1" pos="0 0 0">'
            f'<joint name="x" type="slide" axis="1 0 0"/>'
            f'<joint name="y" type="slide" axis="0 1 0"/>'
            f'<joint name="theta" type="hinge" axis="0 0 1"/>'
            f'{inertial(0.0, m[0], inertia[0])}{link_geom(0, -com[0])}')
    front = length[0] - com[0]  # link 1's front joint in its body frame (at the COM)
    for i in range(1, n):
        body += (f'<body name="link{i + 1}" pos="{_f(front, 0, 0)}">'
                 f'<joint name="q{i}" type="hinge" axis="0 0 1"/>'
                 f'{inertial(com[i], m[i], inertia[i])}{link_geom(i, 0.0)}')
        front = length[i]
    body += "</body>" * n
    if point:
        if rho is None:
            rho = (0.0, -scene.side_sign * h)
        rho = np.asarray(rho, float)
        inward = -rho / np.linalg.norm(rho)  # towards the object's COM (a face's middle)
        centre = rho + 2.0 * r * inward
        obj_geom = (f'<geom name="object" type="sphere" size="{r:.17g}" '
                    f'pos="{_f(centre[0], centre[1], 0)}" contype="0" conaffinity="1" '
                    f'{contact}/>')
    else:
        obj_geom = (f'<geom name="object" type="box" size="{_f(h - r, h - r, 0.05)}" '
                    f'contype="0" conaffinity="1" {contact}/>')
    obj = (f'<body name="object" pos="0 0 0">'
           f'<joint name="x_o" type="slide" axis="1 0 0"/>'
           f'<joint name="y_o" type="slide" axis="0 1 0"/>'
           f'<joint name="psi" type="hinge" axis="0 0 1"/>'
           f'{inertial(0.0, scene.object_mass, scene.object_inertia)}{obj_geom}</body>')
    return (f'<mujoco model="snakecg-matched"><compiler angle="radian" autolimits="true"/>'
            f'<option timestep="{timestep:.17g}" integrator="{integrator}" gravity="0 0 0" '
            f'solver="Newton" iterations="{iterations}" tolerance="{tolerance:.3g}" '
            f'cone="elliptic"/>'
            f'<worldbody>{body}{obj}</worldbody></mujoco>')


@dataclass
class MatchedScene:
    """A compiled matched model and its data, with snakecg's state layout."""

    mujoco: object
    model: object
    data: object
    ns: int
    masses: np.ndarray  # the snake's link masses (for its COM)

    def set_state(self, q, v=None, q_obj=None, v_obj=None) -> None:
        d, ns = self.data, self.ns
        d.qpos[:ns] = q
        d.qvel[:ns] = 0.0 if v is None else v
        d.qpos[ns:] = 0.0 if q_obj is None else q_obj
        d.qvel[ns:] = 0.0 if v_obj is None else v_obj
        d.time = 0.0
        self.mujoco.mj_forward(self.model, self.data)

    @property
    def q(self) -> np.ndarray:
        return self.data.qpos[:self.ns].copy()

    @property
    def v(self) -> np.ndarray:
        return self.data.qvel[:self.ns].copy()

    @property
    def q_obj(self) -> np.ndarray:
        return self.data.qpos[self.ns:].copy()

    @property
    def v_obj(self) -> np.ndarray:
        return self.data.qvel[self.ns:].copy()

    def com(self) -> np.ndarray:
        """The snake's COM (x, y), from MuJoCo's body COM positions."""
        P = self.data.xipos[1:1 + len(self.masses), :2]
        return self.masses @ P / self.masses.sum()

    def penetration(self) -> float:
        """The deepest contact now (m, >= 0): MuJoCo's contact distances."""
        n = self.data.ncon
        return float(max(0.0, -self.data.contact.dist[:n].min())) if n else 0.0

    def contact_force(self) -> float:
        """The sum of the normal forces of the active contacts now (N)."""
        total, f = 0.0, np.zeros(6)
        for i in range(self.data.ncon):
            self.mujoco.mj_contactForce(self.model, self.data, i, f)
            total += f[0]
        return total

    def run(self, tau, duration: float, times=None, *, control_period=None):
        """Step to ``duration`` with joint torques ``tau``: a constant ``(n_a,)`` or a law
        ``tau(t, q, v)`` (called every ``control_period`` seconds, default every step, its
        value held in between). Returns the samples at ``times`` (each rounded to a whole
        number of steps, default: every step): a dict of ``t``, ``q``, ``v``, ``q_obj``,
        ``v_obj``, ``com`` and the largest penetration over every step, ``max_depth``."""
        mj, m, d, ns = self.mujoco, self.model, self.data, self.ns
        dt = m.opt.timestep
        n_steps = round(duration / dt)
        law = callable(tau)
        if not law:
            d.qfrc_applied[3:ns] = np.asarray(tau, float)
        every = 1 if control_period is None else max(1, round(control_period / dt))
        if times is None:
            marks = np.arange(n_steps + 1)
        else:
            marks = np.unique(np.round(np.asarray(times, float) / dt).astype(int))
        want = np.zeros(n_steps + 1, dtype=bool)
        want[marks[(marks >= 0) & (marks <= n_steps)]] = True
        out = {k: [] for k in ("t", "q", "v", "q_obj", "v_obj", "com")}
        depth = self.penetration()

        def record(step):
            out["t"].append(step * dt)
            out["q"].append(self.q)
            out["v"].append(self.v)
            out["q_obj"].append(self.q_obj)
            out["v_obj"].append(self.v_obj)
            out["com"].append(self.com())

        if want[0]:
            record(0)
        for step in range(n_steps):
            if law and step % every == 0:
                d.qfrc_applied[3:ns] = tau(step * dt, self.q, self.v)
            mj.mj_step(m, d)
            depth = max(depth, self.penetration())
            if want[step + 1]:
                record(step + 1)
        res = {k: np.array(val) for k, val in out.items()}
        res["max_depth"] = depth
        return res


def matched_scene(scene, **options) -> MatchedScene:
    """:func:`matched_mjcf` compiled: a :class:`MatchedScene` (needs ``mujoco``)."""
    import mujoco

    model = mujoco.MjModel.from_xml_string(matched_mjcf(scene, **options))
    data = mujoco.MjData(model)
    ns = scene.robot.joints + 3
    return MatchedScene(mujoco, model, data, ns, np.asarray(scene.robot.mass, float))

