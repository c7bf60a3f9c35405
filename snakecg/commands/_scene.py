"""The command line on a general scene (``--scene FILE``): ``forward``, ``optimize`` and
``simulate`` (``plot`` draws either kind of scene itself)."""

from __future__ import annotations

import numpy as np

__all__ = ["forward_command", "optimize_command", "simulate_command"]


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


#: what a sample's ``dependent`` flag says about its forces (SceneResult's docstring)
_DEPENDENT = {1: "dependent constraint rows (statically indeterminate); minimum-norm forces",
              2: "dependent constraint rows (statically indeterminate); the forces are one "
                 "of a family with these accelerations, not the minimum-norm ones",
              3: "nearly dependent constraint rows; the answer holds to its KKT residuals"}


def _count(k: int, noun: str) -> str:
    return f"{k} {noun}" + ("" if k == 1 else "s")


def _shown(x) -> np.ndarray:
    """x as printed (six decimals): entries that print as zero without their sign."""
    x = np.asarray(x, dtype=float)
    return np.where(np.round(x, 6) == 0.0, 0.0, x)


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
    print(f"{_count(scene.robot.joints, 'joint')}, {_count(scene.n_objects, 'object')}, "
          f"{_count(len(scene.obstacles), 'obstacle')}, {_count(len(res.contacts), 'contact')}")
    print(f"  qdd    = {_shown(res.qdd)}")
    for o in res.objects:
        print(f"  object {o['object']}: a = {_shown(o['a'])}, |a|^2 = {o['norm_a']:.6g}")
    for c in res.contacts:
        fric = (f", friction {c['friction']:.6g} N ({c['friction_state']}, mu {c['mu']:.3g})"
                if "friction" in c else "")
        print(f"  contact {c['bodies'][0]} - {c['bodies'][1]}: force {c['force']:.6g} N, "
              f"{c['state']}{fric}")
    for g in res.ground:
        body = f"link {g['link']}" if "link" in g else f"object {g['object']}"
        print(f"  ground under {body} ({g['model']}): force {_shown(g['force'])} N, "
              f"{g['state']}")
    print(f"  |lambda|^2 = {res.norm_lambda:.6g}  |a_obj|^2 = {res.norm_a_obj:.6g}  "
          f"|qdd|^2 = {res.norm_qdd:.6g}  sr = {res.sr:.6g}")
    cert = res.certificate
    print(f"  KKT residuals: primal {cert['primal']:.2g}, dual {cert['dual']:.2g}, "
          f"complementarity {cert['complementarity']:.2g}")
    if res.uniqueness is not None:
        print(f"  Coulomb friction at the contacts: {res.uniqueness} ({res.solutions} solutions "
              "found by enumeration; 0: not enumerated, negative: some piece singular)")
    if res.dependent and res.status == 0:
        print("  warning: " + _DEPENDENT[res.dependent])
    if res.status != 0:
        import sys

        sys.stderr.write(f"snakecg forward: failed: {res.reason[0]}\n")
        return 1
    return 0


#: the paper-scene options of ``snakecg simulate`` that a general scene's run does not take
_NOT_FOR_SCENES = (("--v-obj", "v_obj"), ("--a-min", "a_min"), ("--control-period",
                   "control_period"), ("--output-dt", "output_dt"))


def simulate_command(args, scene, gait: dict, paper=None) -> int:
    """``snakecg simulate --scene FILE``: the general scene over time (velocity-level time
    stepping, :func:`snakecg.scenes.stepping.simulate_scene`); writes ``summary.json`` and
    ``trajectory.npz`` to ``--out``; ``--json`` prints the summary. ``paper``: the paper's
    scene of ``--contacts geometry`` (``scene`` its general one), run by its model's
    ``simulate(..., contacts="geometry")``."""
    import json
    import sys

    from .. import load
    from .._files import write_text
    from ..errors import InputError, SnakecgError
    from ..simulate import serpenoid_controller
    from ._common import check_vector, out_dir, parse_vector, print_json, progress_reporter
    from ._common import strict_json

    given = [opt for opt, key in _NOT_FOR_SCENES if getattr(args, key, None) is not None]
    if args.controller == "least-slip-push":
        given.append("--controller least-slip-push")
    if given:
        raise InputError(f"--scene: {', '.join(given)} applies to the paper's scene only")
    q, tau = _vectors(args, scene)
    na = scene.robot.joints
    v = (check_vector("v0", parse_vector("--v", args.v), na + 3,
                      f" = (n_joints + 3,) for a {na}-joint robot") if args.v else None)
    if args.controller and tau is not None:
        raise InputError("give either --tau or --controller, not both")
    if not args.controller and tau is None:
        raise InputError("give the joint torques --tau (or --controller serpenoid)")
    out = out_dir("--out", args.out)
    model = load(scene, progress=progress_reporter())
    if args.controller == "serpenoid":
        tau = serpenoid_controller(model, **gait,
                                   tau_max="robot" if args.tau_max is None else args.tau_max)
    if paper is None:
        run = model.simulate(q, args.duration, v0=v, tau=tau,
                             dt=1e-3 if args.dt is None else args.dt, progress=None)
    else:
        run = load(paper).simulate(q, tau, args.duration, v0=v, contacts="geometry",
                                   dt=args.dt)
    s = strict_json(run.summary)
    s["scene"] = (str(args.scene) if paper is None
                  else "the paper's scene, contacts from geometry")
    try:
        out.mkdir(parents=True, exist_ok=True)
        write_text(out / "summary.json", json.dumps(s, indent=2, allow_nan=False) + "\n")
        arrays = {k: getattr(run, k) for k in ("t", "q", "v", "q_obj", "v_obj", "tau",
                                               "min_gap", "kinetic_energy", "work_tau",
                                               "friction_dissipation", "impact_loss")}
        tmp = out / ".trajectory.npz.part"
        with open(tmp, "wb") as fh:
            np.savez(fh, **arrays)
        tmp.replace(out / "trajectory.npz")
    except OSError as exc:
        raise SnakecgError(f"cannot write to --out {str(out)!r}: {exc}") from None
    files = {"trajectory": str(out / "trajectory.npz"), "summary": str(out / "summary.json")}
    if args.json:
        print_json({**s, "files": files})
    else:
        e = s["energy"]
        print(f"{na} joints, {scene.n_objects} objects, {len(scene.obstacles)} obstacles, "
              f"{s['duration']:g} s in {s['steps']} steps: {s['status']}")
        print(f"  impacts {s['impacts']}, smallest gap {s['min_gap']} m (tolerance "
              f"{s['tolerance']:.3g} m)")
        print(f"  energy (J): kinetic {e['kinetic_start']:.4g} -> {e['kinetic_end']:.4g}, "
              f"torques {e['work_tau']:.4g}, friction {e['friction_dissipation']:.4g}, "
              f"impacts {e['impact_loss']:.4g}")
        c = s["certificate"]
        print(f"  KKT residuals (largest over the steps): primal {c['primal']:.2g}, dual "
              f"{c['dual']:.2g}, complementarity {c['complementarity']:.2g}")
    if s["status"] != "completed":
        sys.stderr.write(f"snakecg simulate: {s['status']}: {s['message']}\n")
        return 1
    return 0


def optimize_command(args, scene, schema: str, task_options, tasks) -> int:
    """``snakecg optimize --scene FILE``: the task's options checked against the scene before
    the model is loaded (``task_options``: the command's parsing of --tau-max, --direction,
    --a-obj; ``tasks``: the options each objective takes), then
    :func:`snakecg.scenes.optimize.optimize`."""
    from .. import load
    from ..errors import InputError
    from ._common import print_json, print_optimum

    q, _ = _vectors(args, scene)
    tau_max, direction, a_obj = task_options(args, scene.robot.joints)
    given = {k for k, v in (("--direction", args.direction), ("--a-min", args.a_min),
                            ("--a-obj", args.a_obj)) if v is not None}
    extra = given - tasks[args.objective]
    if extra:
        raise InputError(f"{', '.join(sorted(extra))} do(es) not apply to {args.objective} "
                         f"(it takes: {', '.join(sorted(tasks[args.objective])) or 'none'})")
    if args.objective == "strongest-push" and direction is None:
        raise InputError("strongest-push on a general scene needs --direction dx,dy")
    if args.objective == "least-slip-push" and a_obj is None and not {
            "--direction", "--a-min"} <= given:
        raise InputError("least-slip-push needs a task: --direction and --a-min, or --a-obj")
    if scene.n_objects == 0:
        raise InputError(f"--scene {args.scene}: {args.objective} needs an object in the "
                         f"scene; it has none")
    obj = 1 if args.object is None else args.object
    if not 1 <= obj <= scene.n_objects:
        raise InputError(f"--object must be an object number 1..{scene.n_objects}, got {obj}")
    slide = None
    if args.allow_slide is not None:
        if args.allow_slide.strip().lower() != "all":
            raise InputError("--allow-slide on a general scene takes no link list: every "
                             "link's set may slide (give it alone, or 'all')")
        slide = True
    objective = args.objective.replace("-", "_")
    model = load(scene)
    res = model.optimize(q, objective, object=obj, tau_max=tau_max, radius=args.radius,
                         direction=direction, a_min=args.a_min, a_obj=a_obj,
                         allow_slide=slide)
    code = 0 if res.status == "optimal" else 1
    if args.json:
        out = {"schema": schema, "joints": scene.robot.joints, "scene": str(args.scene),
               "q": list(q), "task": {"direction": direction, "a_min": args.a_min,
                                      "a_obj": a_obj}}
        out.update(res.to_dict())
        print_json(out)
        return code
    np.set_printoptions(precision=6, suppress=True)
    name = {"max_sr": "sr", "least_slip_push": "|qdd|^2",
            "strongest_push": f"d . a_obj of object {obj} (m/s^2)"}[objective]
    print_optimum(res, objective, name, timed=False)
    an = res.analysis
    for o in an.objects:
        print(f"  object {o['object']}: a = {_shown(o['a'])}")
    print(f"  |a_obj|^2 = {an.norm_a_obj:.6g}  |qdd|^2 = {an.norm_qdd:.6g}  sr = {an.sr:.6g}")
    return code
