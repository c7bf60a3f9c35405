"""``snakecg optimize``: the optimal joint torque for a task at one configuration."""

from __future__ import annotations

import argparse

import numpy as np

from ._common import add_robot_args, parse_vector, print_json, scene_from_args

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
                   help="max-sr | least-slip-push | strongest-push")
    add_robot_args(p)
    p.add_argument("--q", required=True, metavar="Q",
                   help="configuration x,y,theta,q1..qn (m and rad; NNdeg for degrees; write "
                   "--q=-1,... when the first value is negative)")
    p.add_argument("--tau-max", metavar="T",
                   help="box limits |tau_j| <= T_j (N m): one number or one per joint")
    p.add_argument("--radius", type=float, metavar="R",
                   help="ellipsoid tau^T B^T M_s^-1 B tau <= R^2 (eq. 31); default 1 when "
                   "--tau-max is not given")
    p.add_argument("--direction", metavar="D",
                   help="push direction dx,dy (or dx,dy,dalpha), world frame; strongest-push "
                   "defaults to the contact normal")
    p.add_argument("--a-min", type=float, metavar="A",
                   help="least-slip-push: required acceleration along --direction (m/s^2)")
    p.add_argument("--a-obj", metavar="A",
                   help="least-slip-push: full object acceleration a_x,a_y,alpha instead of "
                   "--direction/--a-min")
    p.add_argument("--allow-slide", nargs="?", const="all", metavar="LINKS",
                   help="max-sr, scenario wheels: let wheels slide (all, or the listed links, "
                   "e.g. 2,3)")
    p.add_argument("--json", action="store_true",
                   help=f"print JSON (schema {SCHEMA}, docs/optimize.md)")
    p.set_defaults(run=run)


def _allow_slide(text):
    if text is None:
        return False
    if text.strip().lower() == "all":
        return True
    from ..errors import InputError

    try:
        vals = parse_vector("--allow-slide", text)
    except InputError:
        vals = [0.5]
    if any(v != int(v) for v in vals):
        raise InputError(f"--allow-slide takes link numbers (e.g. 2,3), 'all' or nothing, "
                         f"got {text!r}")
    return [int(v) for v in vals]


def run(args) -> int:
    from .. import load
    from ..optimize import SCHEMA

    scene = scene_from_args(args)
    q = parse_vector("--q", args.q)
    tau_max = None
    if args.tau_max is not None:
        tm = parse_vector("--tau-max", args.tau_max)
        tau_max = tm[0] if len(tm) == 1 else tm
    kwargs = dict(
        tau_max=tau_max, radius=args.radius,
        direction=parse_vector("--direction", args.direction) if args.direction else None,
        a_min=args.a_min,
        a_obj=parse_vector("--a-obj", args.a_obj) if args.a_obj else None,
        allow_slide=_allow_slide(args.allow_slide),
    )
    objective = args.objective.replace("-", "_")
    model = load(scene)
    res = model.optimize(q, objective, **kwargs)
    code = 0 if res.status == "optimal" else 1
    if args.json:
        out = {"schema": SCHEMA, "joints": scene.robot.joints, "scenario": scene.scenario,
               "kappa": scene.kappa, "mu": scene.mu, "contact_link": scene.contact_link,
               "side": scene.side, "q": list(q),
               "limits": {"tau_max": _listed(tau_max, scene.robot.joints),
                          "radius": args.radius if args.radius is not None
                          else (None if tau_max is not None else 1.0)},
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
    print(f"{args.objective}: {res.status} ({res.solver}; {res.time * 1e3:.2f} ms)")
    if res.reason:
        print(f"  reason: {res.reason}")
    c = res.certificate
    if c is not None and c.kind != "none":
        print(f"  certificate: {c.kind}, {'ok' if c.ok else 'failed'} (stationarity "
              f"{c.stationarity:.1e}, feasibility {c.primal_feasibility:.1e}"
              + (f", gap {c.duality_gap:.1e})" if c.duality_gap is not None else ")"))
    print(f"  tau    = {res.tau}  (N m)")
    print(f"  {name} = {res.objective_value:.9g}")
    if res.binding:
        print(f"  binding: {', '.join(res.binding)}")
    print(f"  a_obj  = {an.a_obj}")
    print(f"  qdd    = {an.qdd}")
    print(f"  lambda = {an.lam}  (row 0: contact, row i: wheel of link i)")
    print(f"  contact {'kept' if an.contact else 'lost'}; wheels: {' '.join(an.wheel_state)}")
    print(f"  |a_obj|^2 = {an.norm_a_obj:.6g}  |qdd|^2 = {an.norm_qdd:.6g}  sr = {an.sr:.6g}")
    return code


def _listed(tau_max, n):
    if tau_max is None:
        return None
    return [float(tau_max)] * n if np.ndim(tau_max) == 0 else [float(t) for t in tau_max]
