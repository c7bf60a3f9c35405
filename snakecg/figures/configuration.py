"""Seeing a configuration: ``snakecg.plot(scene, q, tau=None, ax=None)``.

Draws, in the plane, the snake (each link from its rear end to its front end, the joints, the
links' COMs), the object (a square of side ``2 object_distance``, touched at the middle of a
face), the contact point and the contact normal (the direction in which the contact pushes
the object), and the rolling direction of every wheel. With a torque ``tau``, the forward
solve at rest adds the constraint forces (the contact force on the object, each wheel's
lateral force on its link) and the accelerations (each link COM's and the object's) as
arrows, and the title gives the active set and ``sr``.

Arrows are drawn in data units, each group scaled so that its longest arrow is 0.6 of the
mean link length; the legend states each group's scale. The artists carry ``gid`` labels
(``"link1"``..., ``"object"``, ``"contact_normal"``, ``"wheels"``, ``"force_contact"``,
``"force_wheels"``, ``"acc_links"``, ``"acc_object"``) so that they can be found again.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .axes import COLORS, _scale, frame

__all__ = ["plot", "configuration_geometry"]

#: How far from the origin (in robot lengths) a drawing may lie: farther out the float spacing
#: of the coordinates approaches the links' size (and matplotlib's ticks overflow near 1e308).
MAX_REACH = 1e6



def configuration_geometry(model, q, tau=None) -> dict:
    """The numbers the figure draws, for one configuration (and torque): link ends, COMs,
    wheel points and directions, object pose and corners, contact point and normal; with
    ``tau`` the forward result (``forward``), the wheel-force and link-acceleration vectors."""
    qa, batched = model.configurations(q)
    if batched:
        raise InputError(f"q must be one configuration of shape ({model.n_coordinates},), "
                         f"got a batch of {qa.shape[0]}")
    q1 = qa[0]
    scene, robot = model.scene, model.robot
    poses = model.link_poses(q1)
    phi = poses[:, 2]
    e = np.stack([np.cos(phi), np.sin(phi)], axis=1)
    normal_dirs = np.stack([-np.sin(phi), np.cos(phi)], axis=1)
    rear = poses[:, :2] - np.asarray(robot.com)[:, None] * e
    front = rear + np.asarray(robot.length)[:, None] * e
    q_obj, _, P = model.place_object(q1)
    k = scene.contact_link - 1
    normal = scene.side_sign * normal_dirs[k]
    half = scene.object_distance
    c, s = np.cos(q_obj[2]), np.sin(q_obj[2])
    R = np.array([[c, -s], [s, c]])
    corners = q_obj[:2] + (R @ (half * np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]]).T)).T
    wheels = list(scene.wheel_links) if scene.has_wheels else []
    off = np.asarray(scene.wheel_offset, dtype=float)
    wheel_pts = np.array([poses[i - 1, :2] + off[i - 1] * e[i - 1] for i in wheels]).reshape(-1, 2)
    out = dict(q=q1, poses=poses, rear=rear, front=front, axis=e, q_obj=q_obj,
               contact_point=P, normal=normal, corners=corners, wheel_links=wheels,
               wheel_points=wheel_pts, wheel_dirs=e[[i - 1 for i in wheels]].reshape(-1, 2),
               wheel_normals=normal_dirs[[i - 1 for i in wheels]].reshape(-1, 2))
    if tau is not None:
        res = model.forward(q1, tau)
        J = model.link_jacobians(q1)  # at rest the COM accelerations are J_i qdd
        out.update(
            forward=res,
            force_contact=res.lam[0] * normal,
            force_wheels=np.array([res.lam[i] * normal_dirs[i - 1] for i in wheels]
                                  ).reshape(-1, 2),
            acc_links=np.einsum("iak,k->ia", J[:, :2, :], res.qdd),
            acc_object=np.asarray(res.a_obj[:2]),
        )
    return out


def plot(scene, q, tau=None, ax=None, *, title: str | None = None):
    """Draw the configuration ``q`` of ``scene`` (a :class:`~snakecg.Scene`, a
    :class:`~snakecg.scenes.GeneralScene` or a loaded model of either) on ``ax`` (a new figure if None); with ``tau``, the constraint forces and the
    accelerations of the forward solve at rest. Returns the axes. See the module doc."""
    from ..kinds import is_scene_model
    from ..robot import Scene
    from ..scenes import GeneralScene

    if isinstance(scene, GeneralScene) or isinstance(getattr(scene, "scene", None),
                                                     GeneralScene):
        from ..scenes.drawing import plot_scene  # objects, obstacles, every contact

        if isinstance(scene, GeneralScene):
            from ..loading import load  # a scene given: its model

            scene = load(scene)
        return plot_scene(scene, q, tau, ax, title=title)
    if is_scene_model(scene):
        model = scene
    elif isinstance(scene, Scene):
        from ..loading import load  # a scene given: its model

        model = load(scene)
    else:
        raise InputError(f"scene must be a snakecg.Scene or its loaded model, got "
                         f"{type(scene).__name__}")
    g = configuration_geometry(model, q, tau)
    reach = float(np.abs(np.concatenate([g["corners"], g["rear"], g["front"]])).max())
    limit = MAX_REACH * float(np.sum(model.robot.length))
    if not reach <= limit:
        raise InputError(f"q places the drawing {reach:.3g} m from the origin; it must lie "
                         f"within {limit:.3g} m ({MAX_REACH:g} robot lengths) to be drawn")
    if ax is None:
        import matplotlib.pyplot as plt

        _, ax = plt.subplots(figsize=(6.4, 5.2), constrained_layout=True)
    from matplotlib.patches import Polygon

    sc = model.scene
    L0 = 0.6 * float(np.mean(model.robot.length))
    ax.add_patch(Polygon(g["corners"], closed=True, fc=COLORS["object"], ec="k", lw=1,
                         gid="object", label="object", zorder=1))
    first_other = 1 if sc.contact_link == 1 else 0
    for i in range(model.n_links):
        contact = i == sc.contact_link - 1
        label = (f"contact link ({sc.contact_link})" if contact else
                 "snake (link 1 = tail)" if i == first_other else None)
        ax.plot(*np.stack([g["rear"][i], g["front"][i]]).T, "-", lw=6, solid_capstyle="round",
                color=COLORS["contact_link"] if contact else COLORS["snake"],
                gid=f"link{i + 1}", zorder=2, label=label)
    joints = g["front"][:-1]
    ax.plot(joints[:, 0], joints[:, 1], "o", color="k", ms=4, gid="joints", zorder=3)
    ax.plot(g["poses"][:, 0], g["poses"][:, 1], "+", color="w", ms=6, mew=1.5, gid="coms",
            zorder=4)
    ax.plot(*g["contact_point"], "*", color=COLORS["normal"], ms=10, gid="contact_point",
            zorder=5)
    tips = [g["corners"], g["rear"], g["front"]]

    def arrows(points, vectors, colour, gid, label, **kw):
        pts, vec = np.asarray(points).reshape(-1, 2), np.asarray(vectors).reshape(-1, 2)
        if not len(pts):
            return
        ax.quiver(pts[:, 0], pts[:, 1], vec[:, 0], vec[:, 1], angles="xy", scale_units="xy",
                  scale=1, color=colour, gid=gid, label=label, zorder=6, width=0.006, **kw)
        tips.append(pts + vec)

    arrows(g["contact_point"], 0.5 * L0 * g["normal"], COLORS["normal"], "contact_normal",
           "contact normal")
    if len(g["wheel_points"]):
        w = 0.25 * L0 * g["wheel_dirs"]
        segs = np.concatenate([g["wheel_points"] - w, g["wheel_points"] + w], axis=1)
        for n, (x0, y0, x1, y1) in enumerate(segs):
            ax.plot([x0, x1], [y0, y1], "-", lw=3, color=COLORS["wheel"], gid="wheels",
                    solid_capstyle="butt", zorder=5, label="wheels (rolling direction)"
                    if n == 0 else None)
    if tau is not None:
        forces = [g["force_contact"], *g["force_wheels"]]
        fs, fmax = _scale(forces, L0)
        if fmax > 0:
            arrows(g["contact_point"], fs * g["force_contact"], COLORS["force"],
                   "force_contact", f"constraint forces ({fmax:.3g} N = {L0:.3g} m)")
            arrows(g["wheel_points"], fs * g["force_wheels"], COLORS["force"], "force_wheels",
                   None)
        accs = [*g["acc_links"], g["acc_object"]]
        as_, amax = _scale(accs, L0)
        if amax > 0:
            arrows(g["poses"][:, :2], as_ * g["acc_links"], COLORS["acc"], "acc_links",
                   f"accelerations ({amax:.3g} m/s$^2$ = {L0:.3g} m)")
            arrows(g["q_obj"][:2], as_ * g["acc_object"], COLORS["acc"], "acc_object", None,
                   alpha=0.8)
    frame(ax, tips, 0.08)
    if title is None:
        title = (f"{model.n_joints} joints, {sc.scenario}, contact on link {sc.contact_link}"
                 f" ({sc.side})")
        if tau is not None:
            r = g["forward"]
            title += (f"\ncontact {'kept' if r.contact else 'lost'}, wheels "
                      f"{' '.join(str(s) for s in r.wheel_state)}, sr = {float(r.sr):.4g}")
    ax.set_title(title, fontsize=10)
    ax.legend(loc="best", fontsize=8, framealpha=0.85)
    return ax
