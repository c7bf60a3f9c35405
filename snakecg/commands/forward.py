"""``snakecg forward``: accelerations, constraint forces and norms at one configuration."""

from __future__ import annotations

import numpy as np

from ._common import add_robot_args, parse_vector, print_json, scene_from_args

#: Version of the JSON printed by ``snakecg forward --json`` (docs/cli.md).
SCHEMA = "snakecg.forward/1"


def register(sub) -> None:
    p = sub.add_parser(
        "forward",
        help="forward analysis: accelerations, forces, active set, norms and sr",
        description="Solve the coupled snake + object system at rest (or with --v) for joint "
        "torques --tau at configuration --q, in the chosen ground scenario.",
        epilog="example: snakecg forward --joints 2 --q 0,0,0,-135deg,-135deg --tau 0.1,0 "
        "--scenario wheels --json",
    )
    add_robot_args(p)
    p.add_argument("--q", required=True, help="configuration x,y,theta,q1..qn (rad, or NNdeg)")
    p.add_argument("--tau", required=True, help="joint torques tau1..tau_n (N m)")
    p.add_argument("--v", help="snake velocities (default: at rest)")
    p.add_argument("--json", action="store_true", help="print JSON (schema in docs/cli.md)")
    p.set_defaults(run=run)


def run(args) -> int:
    from .. import load

    scene = scene_from_args(args)
    q = parse_vector("--q", args.q)
    tau = parse_vector("--tau", args.tau)
    v = parse_vector("--v", args.v) if args.v else None
    model = load(scene)
    res = model.forward(q, tau, v=v)
    if args.json:
        out = {"schema": SCHEMA, "joints": scene.robot.joints, "scenario": scene.scenario,
               "kappa": scene.kappa, "mu": scene.mu, "q": list(q)}
        out.update(res.to_dict())
        out["contact"] = bool(res.contact)
        out["singular"] = bool(res.singular)
        print_json(out)
        return 0
    np.set_printoptions(precision=6, suppress=True)
    print(f"scenario {scene.scenario}, kappa {scene.kappa:g}, {scene.robot.joints} joints")
    print(f"  qdd    = {res.qdd}")
    print(f"  a_obj  = {res.a_obj}")
    print(f"  lambda = {res.lam}  (row 0: contact, row i: wheel of link i)")
    print(f"  contact {'kept' if res.contact else 'lost'}; wheels: {' '.join(res.wheel_state)}")
    print(f"  |lambda|^2 = {res.norm_lambda:.6g}  |a_obj|^2 = {res.norm_a_obj:.6g}  "
          f"|qdd|^2 = {res.norm_qdd:.6g}  sr = {res.sr:.6g}")
    if res.singular:
        print("  warning: dependent constraint rows; least-norm forces")
    return 0
