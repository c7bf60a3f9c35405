"""``snakecg forward``: accelerations, constraint forces and norms at one configuration."""

from __future__ import annotations

import argparse

import numpy as np

import sys

from ._common import (add_robot_args, check_vector, parse_vector, print_json, progress_reporter,
                      scene_from_args, text)

#: Version of the JSON printed by ``snakecg forward --json`` (docs/reference/cli.md).
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
    p.add_argument("--q", required=True, metavar="Q", type=text("numbers x,y,theta,q1..qn"),
                   help="configuration x,y,theta,q1..qn (m and rad; NNdeg for degrees)")
    p.add_argument("--tau", required=True, metavar="TAU", type=text("numbers tau1..tau_n"),
                   help="joint torques tau1..tau_n (N m)")
    p.add_argument("--v", metavar="V", type=text("numbers, same order as --q"),
                   help="snake velocities, same order as --q (default: rest)")
    p.add_argument("--json", action="store_true",
                   help=f"print JSON (schema {SCHEMA}, docs/reference/cli.md)")
    p.set_defaults(run=run)


def run(args) -> int:
    from .. import load
    from ._common import general_scene_from_args

    general = general_scene_from_args(args)
    if general is not None and general.__class__.__name__ == "SpatialScene":
        from ._spatial import forward_command

        return forward_command(args, general, SCHEMA)
    if general is not None:  # a general scene (snakecg.scenes)
        from ._scene import forward_command

        return forward_command(args, general, SCHEMA)
    scene = scene_from_args(args)
    na = scene.robot.joints
    what = f" = (n_joints + 3,) for a {na}-joint robot"
    # every vector checked against the robot before the model is generated or loaded
    q = check_vector("q", parse_vector("--q", args.q), na + 3, what)
    tau = check_vector("tau", parse_vector("--tau", args.tau), na,
                       f" (one torque per joint, n_a = {na})")
    v = check_vector("v", parse_vector("--v", args.v), na + 3, what) if args.v else None
    model = load(scene, progress=progress_reporter())
    res = model.forward(q, tau, v=v)
    finite = all(np.all(np.isfinite(np.asarray(x, dtype=float))) for x in
                 (res.qdd, res.a_obj, res.lam, res.w, res.norm_lambda, res.norm_a_obj,
                  res.norm_qdd, res.sr))
    if args.json:
        out = {"schema": SCHEMA, "joints": scene.robot.joints, "scenario": scene.scenario,
               "kappa": scene.kappa, "mu": scene.mu, "contact_link": scene.contact_link,
               "side": scene.side, "q": list(q), "v": None if v is None else list(v)}
        out.update(res.to_dict())
        out["contact"] = bool(res.contact)
        out["singular"] = bool(res.singular)
        out["finite"] = finite
        print_json(out)
        if not finite:
            _overflow_message()
        return 0 if finite else 1
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
    if not finite:
        _overflow_message()
        return 1
    return 0


def _overflow_message() -> None:
    sys.stderr.write("snakecg forward: failed: the result is not finite (it overflows double "
                     "precision): reduce the torques or velocities\n")
