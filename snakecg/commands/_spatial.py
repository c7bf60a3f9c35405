"""The command line on a spatial scene file (``--scene FILE`` whose ``[robot]`` is spatial):
``forward``, ``optimize`` and ``plot``; what does not apply is refused in one line.

``--q`` takes the spatial configuration ``x,y,z,qx,qy,qz,qw,q1..qn`` (``n_a + 7`` numbers),
or, for a snake lying flat, ``x,y,yaw,q1..qn`` (``n_a + 3``: the base frame at ``(x, y, 0)``
turned by ``yaw`` about the vertical).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from ..spatial.scene import SpatialScene

__all__ = ["configuration", "forward_command", "optimize_command", "plot_command"]


def configuration(text: str, scene: SpatialScene) -> np.ndarray:
    """``--q`` of a spatial scene: ``n_a + 7`` numbers, or ``x,y,yaw,q1..qn`` lying flat."""
    from ._common import parse_vector

    q = parse_vector("--q", text)
    na = scene.robot.joints
    if len(q) == na + 3:
        x, y, yaw = q[:3]
        q = [x, y, 0.0, 0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2), *q[3:]]
    if len(q) != na + 7 or not all(math.isfinite(v) for v in q):
        raise InputError(f"q has {len(q)} numbers, expected {na + 7} = x,y,z,qx,qy,qz,qw,"
                         f"q1..q{na} or {na + 3} = x,y,yaw,q1..q{na} (lying flat) for a "
                         f"{na}-joint spatial robot")
    n = math.sqrt(sum(v * v for v in q[3:7]))
    if abs(n - 1.0) > 1e-9:
        raise InputError(f"q's quaternion qx,qy,qz,qw must have unit norm, got norm {n:.12g}")
    return np.array(q, dtype=float)


def _torques(text, scene):
    from ._common import check_vector, parse_vector

    na = scene.robot.joints
    return check_vector("tau", parse_vector("--tau", text), na,
                        f" (one torque per joint, n_a = {na})")


def _header(scene, path) -> dict:
    return {"scene": str(path), "kind": "spatial", "joints": scene.robot.joints,
            "scenario": scene.scenario, "kappa": scene.kappa, "mu": scene.mu,
            "contact_link": scene.contact_link, "side": scene.side}


def forward_command(args, scene: SpatialScene, schema: str) -> int:
    """``snakecg forward --scene FILE``: one sample of the spatial forward analysis."""
    from .. import load
    from ._common import check_vector, parse_vector, print_json, progress_reporter

    q = configuration(args.q, scene)
    tau = _torques(args.tau, scene)
    nv = scene.robot.nv
    v = None
    if args.v:
        v = check_vector("v", parse_vector("--v", args.v), nv,
                         " = (joints + 6,): the base twist in the base frame, then the joint "
                         "rates")
    model = load(scene, progress=progress_reporter())
    res = model.forward(q, tau, v=v)
    if args.json:
        out = {"schema": schema, **_header(scene, args.scene), "q": q.tolist(),
               "v": None if v is None else list(v)}
        out.update(res.to_dict())
        out["contact"] = bool(res.contact)
        out["singular"] = bool(res.singular)
        out["reason"] = res.reason
        print_json(out)
        return 1 if res.singular else 0
    np.set_printoptions(precision=6, suppress=True)
    print(f"spatial scene, scenario {scene.scenario}, kappa {scene.kappa:g}, "
          f"{scene.robot.joints} joints, contact on link {scene.contact_link} ({scene.side})")
    if res.singular:
        import sys

        sys.stderr.write(f"snakecg forward: failed: {res.reason}\n")
        return 1
    nl = scene.robot.n_links
    print(f"  qdd    = {res.qdd}  (base twist rate in the base frame, then the joints)")
    print(f"  a_obj  = {res.a_obj}")
    print(f"  lambda = {res.lam[:nl + 1]}  (row 0: contact, row i: wheel of link i)")
    print(f"  normal = {res.normal}  (N, the ground on each link)")
    print(f"  pitch  = {res.pitch_moment}  (N m, the ground's moment on each link)")
    print(f"  contact {'kept' if res.contact else 'lost'}; wheels: {' '.join(res.wheel_state)}")
    print(f"  |lambda|^2 = {res.norm_lambda:.6g}  |a_obj|^2 = {res.norm_a_obj:.6g}  "
          f"|qdd|^2 = {res.norm_qdd:.6g}  sr = {res.sr:.6g}")
    return 0


def optimize_command(args, scene: SpatialScene) -> int:
    """``snakecg optimize OBJECTIVE --scene FILE``."""
    from .. import load
    from .._inputs import MAX_MAGNITUDE
    from ._common import print_json, print_optimum, vector
    from ..optimize import SCHEMA

    q = configuration(args.q, scene)
    na = scene.robot.joints
    for flag, given in (("--a-obj", args.a_obj), ("--allow-slide", args.allow_slide)):
        if given is not None:
            raise InputError(f"{flag} does not apply to a spatial scene (the contact pushes "
                             f"along its normal and every wheel stays within its bound)")
    tau_max = "robot"
    if args.tau_max is not None and args.tau_max.strip().lower() == "none":
        tau_max = None
    elif args.tau_max is not None:
        tm = vector("--tau-max", args.tau_max, positive=True,
                    what=f" (N m: one number or one per joint, {na} joints)")
        if len(tm) not in (1, na) or max(tm) > MAX_MAGNITUDE:
            raise InputError(f"--tau-max takes one number or {na} (N m, one per joint), at "
                             f"most {MAX_MAGNITUDE:g}; got {args.tau_max!r:.80}")
        tau_max = tm[0] if len(tm) == 1 else tm
    direction = vector("--direction", args.direction, sizes=(2, 3),
                       what=" (dx,dy or dx,dy,dalpha)")
    objective = args.objective.replace("-", "_")
    model = load(scene)
    res = model.optimize(q, objective, tau_max=tau_max, radius=args.radius,
                         direction=direction, a_min=args.a_min)
    code = 0 if res.status == "optimal" else 1
    if args.json:
        out = {"schema": SCHEMA, **_header(scene, args.scene), "q": q.tolist(),
               "task": {"direction": direction, "a_min": args.a_min, "a_obj": None}}
        out.update(res.to_dict())
        print_json(out)
        return code
    np.set_printoptions(precision=6, suppress=True)
    an = res.analysis
    name = {"max_sr": "sr", "least_slip_push": "|qdd|^2",
            "strongest_push": "d . a_obj (m/s^2)"}[objective]
    print_optimum(res, objective, name)
    if an.singular:  # nothing answered at this configuration: the reason says why
        return code
    print(f"  a_obj  = {an.a_obj}")
    print(f"  normal = {an.normal}  (N)")
    print(f"  contact {'kept' if an.contact else 'lost'}; wheels: {' '.join(an.wheel_state)}")
    print(f"  |a_obj|^2 = {an.norm_a_obj:.6g}  |qdd|^2 = {an.norm_qdd:.6g}  sr = {an.sr:.6g}")
    return code


def draw(model, q, tau=None, *, ax):
    """A 3-D view of the snake (its links as segments from joint to joint), the object
    (a square plate at its placement), the contact point and, with ``tau``, the ground's
    normal forces and the contact force as arrows (scaled to the largest)."""
    scene = model.scene
    robot = scene.robot
    T = model.robot_model.link_poses(q)
    ends = []
    for i in range(robot.n_links):
        length = np.linalg.norm(robot.joint_xyz[min(i, robot.joints - 1)])
        ends.append((T[i, :3, 3], T[i, :3, 3] + length * T[i, :3, 0]))
    for i, (a, b) in enumerate(ends):
        ax.plot(*np.c_[a, b], lw=4, color="tab:green" if i + 1 != scene.contact_link
                else "tab:olive", solid_capstyle="round")
    k = scene.contact_link - 1
    e = T[k, :2, 0] / np.linalg.norm(T[k, :2, 0])
    n = scene.side_sign * np.array([-e[1], e[0]])
    P = T[k, :2, 3] + scene.contact_offset * e
    c = P + scene.object_distance * n
    h = scene.object_distance
    corners = np.array([c + h * (sx * e + sy * n) for sx, sy in
                        ((-1, -1), (1, -1), (1, 1), (-1, 1), (-1, -1))])
    ax.plot(corners[:, 0], corners[:, 1], np.zeros(5), color="tab:blue")
    ax.scatter([P[0]], [P[1]], [0.0], color="tab:red", s=12)
    title = f"{robot.joints}-joint spatial snake, scenario {scene.scenario}"
    drawn = {"links": robot.n_links}
    if tau is not None:
        r = model.forward(q, tau)
        com = np.asarray(robot.com)
        pts = np.einsum("kij,kj->ki", T[:, :3, :3], com) + T[:, :3, 3]
        forces = np.r_[np.abs(r.normal), abs(float(r.lam[0]))]
        scale = 0.1 / max(forces.max(), 1e-300)
        ax.quiver(pts[:, 0], pts[:, 1], pts[:, 2], 0 * pts[:, 0], 0 * pts[:, 1],
                  scale * r.normal, color="tab:gray", label="ground normal forces")
        f = scale * float(r.lam[0]) * n
        ax.quiver([P[0]], [P[1]], [0.0], [f[0]], [f[1]], [0.0], color="tab:red",
                  label="contact force")
        title += f", sr = {r.sr:.4g}"
        drawn.update({"sr": r.sr, "normal": r.normal.tolist(), "contact_force": float(r.lam[0])})
    pts = np.vstack([np.array(ends).reshape(-1, 3), np.c_[corners, np.zeros(5)]])
    mid, span = pts.mean(axis=0), max(np.ptp(pts, axis=0).max(), 0.1) / 2
    ax.set_xlim(mid[0] - span, mid[0] + span)
    ax.set_ylim(mid[1] - span, mid[1] + span)
    ax.set_zlim(-span / 4, 3 * span / 4)
    ax.set_box_aspect((2, 2, 1))  # equal scales on the three axes
    ax.view_init(elev=35, azim=-65)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    ax.set_title(title)
    return drawn


def plot_command(args, scene: SpatialScene, out, fmt: str, schema: str) -> int:
    """``snakecg plot --scene FILE``: the 3-D view, written atomically (``schema``: the
    plot command's JSON schema)."""
    from matplotlib.figure import Figure

    from .. import load
    from .._files import save_figure
    from ._common import print_json, progress_reporter

    q = configuration(args.q, scene)
    tau = _torques(args.tau, scene) if args.tau else None
    model = load(scene, progress=progress_reporter())
    fig = Figure(figsize=(6.4, 5.2), constrained_layout=True)
    ax = fig.add_subplot(projection="3d")
    draw(model, q, tau, ax=ax)
    save_figure(fig, out, fmt, args.dpi)
    if args.json:
        print_json({"schema": schema, "file": str(out), "format": fmt,
                    **_header(scene, args.scene), "q": q.tolist(),
                    "tau": None if tau is None else list(tau), "title": ax.get_title()})
        return 0
    print(f"wrote {out}")
    return 0
