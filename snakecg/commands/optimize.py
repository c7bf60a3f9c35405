"""``snakecg optimize``: the optimal joint torque for a task at one configuration."""

from __future__ import annotations

import argparse

import numpy as np

from .._inputs import MAX_MAGNITUDE
from ._common import (add_robot_args, check_vector, parse_vector, print_json, print_optimum,
                      real, scene_from_args, text, vector)
from ._names import limits_line, objective_name

EXAMPLES = """\
examples:
  snakecg optimize max-sr --joints 3 --q 0,0,0,30deg,-45deg,60deg --scenario wheels
  snakecg optimize max-sr --joints 3 --q 0,0,0,30deg,-45deg,60deg --scenario wheels --allow-slide --tau-max 0.2
  snakecg optimize least-slip-push --joints 3 --q 0,0,0,30deg,-45deg,60deg --scenario wheels --direction 0,1 --a-min 0.005 --tau-max 0.3 --json
  snakecg optimize strongest-push --joints 3 --q 0,0,0,30deg,-45deg,60deg --scenario ideal_wheels --tau-max 0.3

exit status: 0 optimal, 1 infeasible or failed (the result is still printed), 2 input error.
"""

#: The objectives as the command line spells them.
CLI_OBJECTIVES = ("max-sr", "least-slip-push", "strongest-push")


def register(sub) -> None:
    from ..optimize import SCHEMA

    p = sub.add_parser(
        "optimize",
        help="optimal torques: max sr, least-slip push, strongest push without sliding",
        description="The joint torque that does a task best at configuration --q (at rest): "
        "max-sr maximises the slippage ratio sr (eq. 30) over the input region; "
        "least-slip-push gives the object a requested acceleration with the least snake "
        "motion |qdd|^2 (eq. 26); strongest-push maximises the object's acceleration along a "
        "direction with no wheel sliding. The input region is the ellipsoid of eq. (31) "
        "(--radius, default 1) and/or the box |tau_j| <= tau_max_j (--tau-max). The contact "
        "is always kept. Prints the torque, the forward analysis at it, the binding limits, "
        "and, when the task cannot be done, why.",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("objective", choices=CLI_OBJECTIVES, metavar="OBJECTIVE",
                   type=objective_name,
                   help="max-sr | least-slip-push | strongest-push (or with underscores)")
    add_robot_args(p)
    p.add_argument("--q", required=True, metavar="Q", type=text("numbers x,y,theta,q1..qn"),
                   help="configuration x,y,theta,q1..qn (m and rad; NNdeg for degrees)")
    p.add_argument("--tau-max", metavar="T",
                   type=text("one positive number, one per joint, or none"),
                   help="box limits |tau_j| <= T_j (N m): one number or one per joint; "
                   "default the robot's effort limits (a URDF's <limit effort>), 'none' for "
                   "no box")
    p.add_argument("--radius", type=real(0, MAX_MAGNITUDE, lo_open=True), metavar="R",
                   help="ellipsoid tau^T B^T M_s^-1 B tau <= R^2 (eq. 31); default 1 when "
                   "there is no torque box")
    p.add_argument("--direction", metavar="D", type=text("numbers dx,dy or dx,dy,dalpha"),
                   help="push direction dx,dy (or dx,dy,dalpha), world frame; strongest-push "
                   "defaults to the contact normal")
    p.add_argument("--a-min", type=real(0, MAX_MAGNITUDE, unit="m/s^2"), metavar="A",
                   help="least-slip-push: required acceleration along --direction (m/s^2)")
    p.add_argument("--a-obj", metavar="A", type=text("numbers a_x,a_y,alpha"),
                   help="least-slip-push: full object acceleration a_x,a_y,alpha instead of "
                   "--direction/--a-min")
    p.add_argument("--allow-slide", nargs="?", const="all", metavar="LINKS",
                   type=text("'all' or link numbers such as 2,3"),
                   help="max-sr, scenario wheels: let wheels slide (all, or the listed links, "
                   "e.g. 2,3)")
    p.add_argument("--object", type=int, metavar="J",
                   help="general scene (--scene): the object (1-based) that the push task "
                   "refers to (default 1)")
    p.add_argument("--json", action="store_true",
                   help=f"print JSON (schema {SCHEMA}, docs/how-to/optimize.md)")
    p.set_defaults(run=run)


def _allow_slide(text, n_links=None):
    if text is None:
        return False
    if text.strip().lower() == "all":
        return True
    from ..errors import InputError

    tokens = text.replace(",", " ").split()
    if not tokens or not all(t.isdigit() and t.isascii() and len(t) <= 9 for t in tokens) or (
            n_links is not None and not all(1 <= int(t) <= n_links for t in tokens)):
        links = f"1..{n_links}" if n_links is not None else ">= 1"
        raise InputError(f"--allow-slide takes link numbers {links} (e.g. 2,3), 'all' or "
                         f"nothing, got {text!r:.80}")
    return [int(t) for t in tokens]


_TASKS = {"max-sr": set(), "least-slip-push": {"--direction", "--a-min", "--a-obj"},
          "strongest-push": {"--direction"}}


def _check_task(args, n_links):
    """The task options against the objective, as snakecg.optimize checks them, but before
    any model is loaded."""
    from ..errors import InputError

    given = {k for k, v in (("--direction", args.direction), ("--a-min", args.a_min),
                            ("--a-obj", args.a_obj)) if v is not None}
    extra = given - _TASKS[args.objective]
    if extra:
        takes = ", ".join(sorted(_TASKS[args.objective])) or "no task option"
        raise InputError(f"{', '.join(sorted(extra))} do(es) not apply to {args.objective} "
                         f"(it takes: {takes})")
    if args.objective == "least-slip-push":
        if args.a_obj is not None and given & {"--direction", "--a-min"}:
            raise InputError("least-slip-push takes either --a-obj or --direction and "
                             "--a-min, not both")
        if args.a_obj is None and not {"--direction", "--a-min"} <= given:
            raise InputError("least-slip-push needs a task: --direction and --a-min, or "
                             "--a-obj")
    if args.allow_slide is not None and args.objective != "max-sr":
        raise InputError("--allow-slide applies to max-sr only")


def task_options(args, na):
    """``(tau_max, direction, a_obj)`` of the command line, checked against ``na`` joints."""
    from ..errors import InputError

    tau_max = "robot"
    if args.tau_max is not None and args.tau_max.strip().lower() == "none":
        tau_max = None
    elif args.tau_max is not None:
        tm = vector("--tau-max", args.tau_max, positive=True,
                    what=f" (N m: one number or one per joint, {na} joints)")
        if len(tm) not in (1, na):
            raise InputError(f"tau_max has shape ({len(tm)},), expected one number or ({na},)"
                             f" (N m, one per joint)")
        if max(tm) > MAX_MAGNITUDE:
            raise InputError(f"--tau-max must be at most {MAX_MAGNITUDE:g} N m (the limit), "
                             f"got {max(tm):g}")
        tau_max = tm[0] if len(tm) == 1 else tm
    direction = vector("--direction", args.direction, sizes=(2, 3),
                       what=" (dx,dy or dx,dy,dalpha)")
    if direction is not None and not any(direction):
        raise InputError("--direction must be non-zero")
    a_obj = vector("--a-obj", args.a_obj, 3, what=" (a_x,a_y,alpha)")
    if a_obj is not None and max(map(abs, a_obj)) > MAX_MAGNITUDE:
        raise InputError(f"--a-obj must be at most {MAX_MAGNITUDE:g} in magnitude (the "
                         f"limit), got {args.a_obj!r:.80}")
    return tau_max, direction, a_obj


def run(args) -> int:
    from .. import load
    from ..optimize import SCHEMA

    from ..errors import InputError
    from ._common import general_scene_from_args

    general = general_scene_from_args(args)
    if general is not None and general.__class__.__name__ == "SpatialScene":  # a 3-D snake
        from ._spatial import optimize_command as spatial_optimize

        _check_task(args, general.robot.n_links)
        return spatial_optimize(args, general)
    if general is not None:  # a general scene (snakecg.scenes)
        from ._scene import optimize_command

        return optimize_command(args, general, SCHEMA, task_options, _TASKS)
    if args.object is not None and args.object != 1:
        raise InputError(f"--object {args.object}: the paper's scene has one object (1)")
    scene = scene_from_args(args)
    na = scene.robot.joints
    # every option checked against the robot and the objective before the model is loaded
    q = check_vector("q", parse_vector("--q", args.q), na + 3,
                     f" = (n_joints + 3,) for a {na}-joint robot")
    tau_max, direction, a_obj = task_options(args, na)
    _check_task(args, scene.robot.n_links)
    kwargs = dict(
        tau_max=tau_max, radius=args.radius, direction=direction, a_min=args.a_min,
        a_obj=a_obj, allow_slide=_allow_slide(args.allow_slide, scene.robot.n_links),
    )
    objective = args.objective.replace("-", "_")
    model = load(scene)
    res = model.optimize(q, objective, **kwargs)
    code = 0 if res.status == "optimal" else 1
    if args.json:
        out = {"schema": SCHEMA, "joints": scene.robot.joints, "scenario": scene.scenario,
               "kappa": scene.kappa, "mu": scene.mu, "contact_link": scene.contact_link,
               "side": scene.side, "q": list(q),
               "task": {"direction": kwargs["direction"], "a_min": args.a_min,
                        "a_obj": kwargs["a_obj"]},
               "allow_slide": kwargs["allow_slide"]}
        out.update(res.to_dict())
        print_json(out)
        return code
    np.set_printoptions(precision=6, suppress=True)
    an = res.analysis
    name = {"max_sr": "sr", "least_slip_push": "|qdd|^2",
            "strongest_push": "d . a_obj (m/s^2)"}[objective]
    between = [f"  note: {res.note}"] if res.note else []
    between.append(f"  limits: {limits_line(res.limits)}")
    c = res.certificate
    if c is not None and c.kind != "none":
        between.append(f"  certificate: {c.kind}, {'ok' if c.ok else 'failed'} (stationarity "
                       f"{c.stationarity:.1e}, feasibility {c.primal_feasibility:.1e}"
                       + (f", gap {c.duality_gap:.1e})" if c.duality_gap is not None
                          else ")"))
    print_optimum(res, objective, name, between=between)
    print(f"  a_obj  = {an.a_obj}")
    print(f"  qdd    = {an.qdd}")
    print(f"  lambda = {an.lam}  (row 0: contact, row i: wheel of link i)")
    print(f"  contact {'kept' if an.contact else 'lost'}; wheels: {' '.join(an.wheel_state)}")
    print(f"  |a_obj|^2 = {an.norm_a_obj:.6g}  |qdd|^2 = {an.norm_qdd:.6g}  sr = {an.sr:.6g}")
    return code

