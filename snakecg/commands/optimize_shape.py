"""``snakecg optimize-shape``: the best shape (joint angles) and torque for a task."""

from __future__ import annotations

import argparse
import os
import tempfile
from pathlib import Path

import numpy as np

from ..errors import InputError
from ._common import add_robot_args, parse_vector, print_json, scene_from_args
from ._names import limits_line, objective_name

EXAMPLES = """\
examples:
  snakecg optimize-shape max-sr --joints 3 --scenario wheels
  snakecg optimize-shape max-a-obj --joints 3 --scenario ideal_wheels --json
  snakecg optimize-shape strongest-push --joints 3 --scenario wheels --figure best.png
  snakecg optimize-shape max-sr --joints 3 --scenario frictionless --ignore-geometry --starts 16

exit status: 0 optimal, 1 any other status (stick_only: sliding pieces not searched;
infeasible; failed; the result is still printed), 2 input error.
"""

CLI_OBJECTIVES = ("max-sr", "strongest-push", "least-slip-push", "max-a-obj")
FIGURE_SUFFIXES = (".png", ".svg", ".pdf")


def register(sub) -> None:
    from ..shape import SCHEMA

    p = sub.add_parser(
        "optimize-shape",
        help="optimal shapes: the joint angles and torque that do a task best",
        description="The shape (joint angles, pose fixed) and joint torque that maximise sr "
        "(max-sr), ||a_obj||^2 (max-a-obj) or the push along a direction (strongest-push), "
        "or give a required push with the least snake motion (least-slip-push), at rest, "
        "with the contact kept and every wheel within its friction bound. Joint limits "
        "always apply; non-adjacent links keep --clearance apart and no link enters the "
        "object unless --ignore-geometry. IPOPT on the generated model, multi-started from "
        "the best points of a coarse grid.",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("objective", choices=CLI_OBJECTIVES, metavar="OBJECTIVE",
                   type=objective_name,
                   help="max-sr | strongest-push | least-slip-push | max-a-obj (or with "
                   "underscores)")
    add_robot_args(p)
    p.add_argument("--starts", type=int, default=8, metavar="K",
                   help="IPOPT runs from the best distinct grid points (default 8)")
    p.add_argument("--seed", type=int, default=0,
                   help="seed of the Sobol sample used instead of the grid beyond 8 joints")
    p.add_argument("--joint-limits", metavar="LO,HI",
                   help="joint range, e.g. -135deg,135deg (radians without 'deg'); default "
                   "the robot's joint limits (a URDF's <limit lower upper>), or -135deg,135deg "
                   "for a robot without them")
    p.add_argument("--q0", metavar="Q",
                   help="start from this configuration x,y,theta,q1..qn instead of the grid "
                   "(write --q0=-1,... when the first value is negative)")
    p.add_argument("--ignore-geometry", action="store_true",
                   help="allow self-intersecting shapes and links inside the object (the "
                   "paper's grid keeps every shape)")
    p.add_argument("--clearance", type=float, metavar="M",
                   help="least distance between non-adjacent links, m (default 0.01)")
    p.add_argument("--tau-max", metavar="T",
                   help="box limits |tau_j| <= T_j (N m): one number or one per joint; "
                   "default the robot's effort limits (a URDF's <limit effort>), 'none' for "
                   "no box")
    p.add_argument("--radius", type=float, metavar="R",
                   help="ellipsoid tau^T B^T M_s^-1 B tau <= R^2 (eq. 31); default 1 when "
                   "there is no torque box")
    p.add_argument("--direction", metavar="D",
                   help="push direction dx,dy (or dx,dy,dalpha), world frame")
    p.add_argument("--a-min", type=float, metavar="A",
                   help="least-slip-push: required acceleration along --direction (m/s^2)")
    p.add_argument("--a-obj", metavar="A",
                   help="least-slip-push: full object acceleration a_x,a_y,alpha")
    p.add_argument("--figure", metavar="FILE",
                   help=f"draw the best shape and the object ({', '.join(FIGURE_SUFFIXES)})")
    p.add_argument("--json", action="store_true",
                   help=f"print JSON (schema {SCHEMA}, docs/how-to/shapes.md)")
    p.set_defaults(run=run)


def _task(args, n):
    task = {}
    if args.tau_max is not None and args.tau_max.strip().lower() == "none":
        task["tau_max"] = None
    elif args.tau_max is not None:
        tm = parse_vector("--tau-max", args.tau_max)
        task["tau_max"] = tm[0] if len(tm) == 1 else tm
    if args.radius is not None:
        task["radius"] = args.radius
    if args.direction is not None:
        task["direction"] = parse_vector("--direction", args.direction)
    if args.a_min is not None:
        task["a_min"] = args.a_min
    if args.a_obj is not None:
        task["a_obj"] = parse_vector("--a-obj", args.a_obj)
    return task


def run(args) -> int:
    from .. import load
    from ..shape import SCHEMA

    scene = scene_from_args(args)
    n = scene.robot.joints
    task = _task(args, n)
    limits = "robot"
    if args.joint_limits is not None:
        lim = parse_vector("--joint-limits", args.joint_limits)
        if len(lim) != 2:
            raise InputError(f"--joint-limits takes two numbers LO,HI (e.g. -135deg,135deg), "
                             f"got {args.joint_limits!r}")
        limits = tuple(lim)
    q0 = parse_vector("--q0", args.q0) if args.q0 is not None else None
    if args.figure is not None and Path(args.figure).suffix.lower() not in FIGURE_SUFFIXES:
        raise InputError(f"--figure must end in {', '.join(FIGURE_SUFFIXES)}, got "
                         f"{args.figure!r}")
    if args.figure is not None and not Path(args.figure).resolve().parent.is_dir():
        raise InputError(f"--figure: the folder of {args.figure!r} does not exist")
    kwargs = dict(q0=q0, starts=args.starts, seed=args.seed, joint_limits=limits,
                  feasible=not args.ignore_geometry, **task)
    if args.clearance is not None:
        kwargs["clearance"] = args.clearance
    objective = args.objective.replace("-", "_")
    model = load(scene)
    res = model.optimize_shape(objective, **kwargs)
    code = 0 if res.status == "optimal" else 1
    if args.figure is not None:
        _figure(model, res, args.figure)
    if args.json:
        out = {"schema": SCHEMA, "joints": n, "scenario": scene.scenario,
               "kappa": scene.kappa, "mu": scene.mu, "contact_link": scene.contact_link,
               "side": scene.side, "feasible": not args.ignore_geometry,
               "task": {k: (None if v is None else np.asarray(v).tolist())
                        for k, v in task.items()}}
        out.update(res.to_dict())
        print_json(out)
        return code
    np.set_printoptions(precision=6, suppress=True)
    name = {"max_sr": "sr", "least_slip_push": "|qdd|^2", "max_a_obj": "|a_obj|^2",
            "strongest_push": "d . a_obj (m/s^2)"}[objective]
    print(f"{objective}: {res.status} (IPOPT, {len(res.starts)} starts; "
          f"{res.time:.2f} s)")
    if res.reason:
        print(f"  reason: {res.reason}")
    print(f"  limits: {limits_line(res.limits)}")
    print(f"  q      = {_deg(res.q[3:])} deg  (joints; pose {res.q[:3]})")
    print(f"  tau    = {res.tau}  (N m)")
    print(f"  {name} = {res.value:.9g}")
    if res.grid_best is not None and res.grid_best_value is not None:
        print(f"  best grid point: {name} = {res.grid_best_value:.9g} at "
              f"{_deg(res.grid_best[3:])} deg")
    c = res.certificate
    print(f"  KKT: stationarity {c['stationarity']:.2g}, primal "
          f"{c['primal_infeasibility']:.2g}, complementarity {c['complementarity']:.2g}")
    if c.get("active"):
        print(f"  active: {', '.join(c['active'])}")
    an = res.analysis
    print(f"  contact {'kept' if an.contact else 'lost'}; wheels: {' '.join(an.wheel_state)}")
    print(f"  |a_obj|^2 = {an.norm_a_obj:.6g}  |qdd|^2 = {an.norm_qdd:.6g}  sr = {an.sr:.6g}")
    if args.figure is not None:
        print(f"  figure: {args.figure}")
    return code


def _deg(q):
    return "(" + ", ".join(f"{d:.3f}" for d in np.rad2deg(q)) + ")"


def _figure(model, res, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..reproduce import draw_robot

    fig, ax = plt.subplots(figsize=(4.5, 4.5), constrained_layout=True)
    draw_robot(ax, model, res.q, title=f"{res.objective} = {res.value:.6g} ({res.status})\n"
               f"q = {_deg(res.q[3:])} deg")
    path = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.stem}-", suffix=path.suffix,
                               dir=path.parent if str(path.parent) else ".")
    os.close(fd)
    try:
        fig.savefig(tmp, dpi=150)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    finally:
        plt.close(fig)
