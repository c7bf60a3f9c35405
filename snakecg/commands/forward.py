"""``snakecg forward``: accelerations, constraint forces and norms at one configuration."""

from __future__ import annotations

import argparse

import numpy as np

from ._common import add_robot_args, parse_vector, print_json, progress_reporter, scene_from_args

#: Version of the JSON printed by ``snakecg forward --json`` (docs/cli.md).
SCHEMA = "snakecg.forward/1"

EXAMPLES = """\
examples:
  snakecg forward --joints 2 --q 0,0,0,-135deg,-135deg --tau 0.1,0 --scenario wheels
  snakecg forward --robot examples/robot.toml --q 0,0,0,30deg,-45deg,60deg --tau 0.05,0,-0.02 --json
"""


def register(sub) -> None:
    p = sub.add_parser(
        "forward",
        help="forward analysis: accelerations, forces, active set, norms and sr",
        description="Solve the coupled snake + object system for joint torques --tau at "
        "configuration --q (at rest, or with snake velocities --v), in the chosen ground "
        "scenario: accelerations qdd and a_obj, constraint forces lambda (row 0 the contact, "
        "row i the wheel of link i), which rows hold, and the norms |lambda|^2, |a_obj|^2 "
        "(eq. 27), |qdd|^2 (eq. 26) and the slippage ratio sr (eq. 30).",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_robot_args(p)
    p.add_argument("--q", required=True, metavar="Q",
                   help="configuration x,y,theta,q1..qn (m and rad; NNdeg for degrees; write "
                   "--q=-1,... when the first value is negative)")
    p.add_argument("--tau", required=True, metavar="TAU",
                   help="joint torques tau1..tau_n (N m; --tau=-0.1,0 when the first is negative)")
    p.add_argument("--v", metavar="V", help="snake velocities, same order as --q (default: rest)")
    p.add_argument("--json", action="store_true",
                   help=f"print JSON (schema {SCHEMA}, docs/cli.md)")
    p.set_defaults(run=run)


def run(args) -> int:
    from .. import load

    scene = scene_from_args(args)
    q = parse_vector("--q", args.q)
    tau = parse_vector("--tau", args.tau)
    v = parse_vector("--v", args.v) if args.v else None
    model = load(scene, progress=progress_reporter())
    res = model.forward(q, tau, v=v)
    if args.json:
        out = {"schema": SCHEMA, "joints": scene.robot.joints, "scenario": scene.scenario,
               "kappa": scene.kappa, "mu": scene.mu, "contact_link": scene.contact_link,
               "side": scene.side, "q": list(q), "v": None if v is None else list(v)}
        out.update(res.to_dict())
        out["contact"] = bool(res.contact)
        out["singular"] = bool(res.singular)
        print_json(out)
        return 0
    np.set_printoptions(precision=6, suppress=True)
    print(f"scenario {scene.scenario}, kappa {scene.kappa:g}, {scene.robot.joints} joints, "
          f"contact on link {scene.contact_link} ({scene.side})")
    print(f"  qdd    = {res.qdd}")
    print(f"  a_obj  = {res.a_obj}")
    print(f"  lambda = {res.lam}  (row 0: contact, row i: wheel of link i)")
    print(f"  contact {'kept' if res.contact else 'lost'}; wheels: {' '.join(res.wheel_state)}")
    print(f"  |lambda|^2 = {res.norm_lambda:.6g}  |a_obj|^2 = {res.norm_a_obj:.6g}  "
          f"|qdd|^2 = {res.norm_qdd:.6g}  sr = {res.sr:.6g}")
    if res.singular:
        print("  warning: dependent constraint rows; least-norm forces")
    return 0
