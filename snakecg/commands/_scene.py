"""The command line on a general scene (``--scene FILE``): ``forward`` and ``plot``."""

from __future__ import annotations

import numpy as np

__all__ = ["forward_command"]


def _vectors(args, scene):
    from ._common import check_vector, parse_vector

    na = scene.robot.joints
    what = f" = (n_joints + 3,) for a {na}-joint robot"
    q = check_vector("q", parse_vector("--q", args.q), na + 3, what)
    tau = None
    if getattr(args, "tau", None):
        tau = check_vector("tau", parse_vector("--tau", args.tau), na,
                           f" (one torque per joint, n_a = {na})")
    return q, tau


def forward_command(args, scene, schema: str) -> int:
    from .. import load
    from ..errors import InputError
    from ._common import print_json, progress_reporter

    q, tau = _vectors(args, scene)
    if args.v:
        raise InputError("--v: a general scene is solved at rest; drop --v")
    model = load(scene, progress=progress_reporter())
    res = model.forward(q, tau)
    if args.json:
        out = {"schema": schema, "joints": scene.robot.joints, "scene": str(args.scene),
               "q": list(q), "v": None}
        out.update(res.to_dict())
        out["finite"] = bool(res.status == 0)
        print_json(out)
        return 0 if res.status == 0 else 1
    np.set_printoptions(precision=6, suppress=True)
    print(f"{scene.robot.joints} joints, {scene.n_objects} objects, {len(scene.obstacles)} "
          f"obstacles, {len(res.contacts)} contacts")
    print(f"  qdd    = {res.qdd}")
    for o in res.objects:
        print(f"  object {o['object']}: a = {np.asarray(o['a'])}, |a|^2 = {o['norm_a']:.6g}")
    for c in res.contacts:
        print(f"  contact {c['bodies'][0]} - {c['bodies'][1]}: force {c['force']:.6g} N, "
              f"{c['state']}")
    for g in res.ground:
        print(f"  ground {g}")
    print(f"  |lambda|^2 = {res.norm_lambda:.6g}  |a_obj|^2 = {res.norm_a_obj:.6g}  "
          f"|qdd|^2 = {res.norm_qdd:.6g}  sr = {res.sr:.6g}")
    cert = res.certificate
    print(f"  KKT residuals: primal {cert['primal']:.2g}, dual {cert['dual']:.2g}, "
          f"complementarity {cert['complementarity']:.2g}")
    if res.dependent:
        print("  warning: dependent constraint rows (statically indeterminate); minimum-norm "
              "forces")
    if res.status != 0:
        import sys

        sys.stderr.write(f"snakecg forward: failed: {res.reason[0]}\n")
        return 1
    return 0
