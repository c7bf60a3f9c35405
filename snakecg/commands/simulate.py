"""``snakecg simulate``: pushing over time, with contact and wheel transitions as events."""

from __future__ import annotations

import argparse
import json
import sys

import numpy as np

from .._inputs import MAX_MAGNITUDE
from ..errors import InputError, SnakecgError
from ..simulate.inputs import (DURATION_MAX, DURATION_MIN, MAX_FRAMES, MAX_OUTPUT_SAMPLES,
                               MAX_PERIODS, METHODS, RTOL_MIN,
                               STABILIZATION_MAX, check_count)
from ._common import (add_robot_args, check_vector, count, out_dir, parse_vector, print_json,
                      progress_reporter, real, scene_from_args, strict_json, text)
from ._names import objective_name

EXAMPLES = """\
examples:
  snakecg simulate --joints 3 --q 0,0,0,30deg,-35deg,25deg --tau 0.035,0,-0.014 --duration 0.5
  snakecg simulate --joints 3 --scenario wheels --kappa 10 --q 0,0,0,30deg,-35deg,25deg \\
      --controller least-slip-push --a-min 0.02 --control-period 0.01 --out run1
  snakecg simulate --joints 2 --q 0,0,0,30deg,-35deg --tau 0.05,-0.02 --json --no-figures
  snakecg simulate --joints 3 --scenario ideal_wheels --q 0,0,0,0,0,0 --controller serpenoid \
      --amplitude 25deg --frequency 1 --phase-lag=-60deg --kp 3 --kd 0.2 --duration 2
"""


def register(sub) -> None:
    p = sub.add_parser(
        "simulate",
        help="integrate the snake + object over time (contact loss, impacts, wheel slip)",
        description="Integrate the coupled snake + object dynamics from configuration --q "
        "(and velocities --v, --v-obj) for --duration seconds with constant joint torques "
        "--tau, or with the least-slippage push query as a feedback law (--controller). "
        "Contact separation, impacts and wheels breaking away or sticking again are events. "
        "Writes the trajectory (trajectory.npz), the summary (summary.json), figures (PNG) and "
        "an animation (GIF) to --out; --json prints the summary (docs/how-to/simulate.md).",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_robot_args(p)
    p.add_argument("--q", required=True, metavar="Q", type=text("numbers x,y,theta,q1..qn"),
                   help="initial configuration x,y,theta,q1..qn (m and rad; NNdeg for degrees)")
    p.add_argument("--tau", metavar="TAU", type=text("numbers tau1..tau_n"),
                   help="constant joint torques tau1..tau_n (N m); or use --controller")
    p.add_argument("--v", metavar="V", type=text("numbers, same order as --q"),
                   help="initial snake velocities (default: rest)")
    p.add_argument("--v-obj", metavar="VO", type=text("numbers vx,vy,omega"),
                   help="initial object twist vx,vy,omega (default 0)")
    p.add_argument("--duration", type=real(DURATION_MIN, DURATION_MAX, unit="s"), default=0.5,
                   help=f"seconds, {DURATION_MIN:g} to {DURATION_MAX:g} (default 0.5)")
    p.add_argument("--controller", choices=("least-slip-push", "serpenoid"),
                   type=objective_name,
                   help="feedback law instead of --tau: the least-slippage push query "
                   "(snakecg optimize) answered every --control-period, or a PD law that "
                   "tracks Hirose's serpenoid curve (lateral undulation: --amplitude, "
                   "--frequency, --phase-lag, --offset, gains --kp and --kd)")
    p.add_argument("--a-min", type=real(0, MAX_MAGNITUDE, unit="m/s^2"),
                   help="controller task: object acceleration along the contact normal (m/s^2)")
    p.add_argument("--tau-max", type=real(0, MAX_MAGNITUDE, lo_open=True, unit="N m"),
                   help="controller: torque limit |tau_j| (N m; default the robot's effort "
                   "limits)")
    p.add_argument("--amplitude", type=text("an angle (rad, or NNdeg)"),
                   help="serpenoid: amplitude of the joint angles (rad; NNdeg for degrees)")
    p.add_argument("--frequency", type=real(0, 1e6, unit="Hz"),
                   help="serpenoid: frequency of the wave (Hz)")
    p.add_argument("--phase-lag", type=text("an angle (rad, or NNdeg)"),
                   help="serpenoid: phase between neighbouring joints (rad; negative: the wave "
                   "runs from the tail to the head)")
    p.add_argument("--offset", type=text("an angle (rad, or NNdeg)"),
                   help="serpenoid: constant bend added to every joint (rad; default 0)")
    p.add_argument("--kp", type=real(0, MAX_MAGNITUDE, unit="N m/rad"),
                   help="serpenoid: proportional gain (N m/rad)")
    p.add_argument("--kd", type=real(0, MAX_MAGNITUDE, unit="N m s/rad"),
                   help="serpenoid: derivative gain (N m s/rad)")
    p.add_argument("--control-period", type=real(0, lo_open=True, unit="s"),
                   help="zero-order hold of the controller (s, default 0.01)")
    p.add_argument("--method", default="DOP853", choices=METHODS,
                   help="scipy solve_ivp method (default DOP853)")
    p.add_argument("--integrator", default="auto", choices=("auto", "compiled", "scipy"),
                   help="auto (default): DOP853 segments in compiled code when the torque is "
                   "held over each segment, solve_ivp otherwise; compiled or scipy to insist")
    p.add_argument("--rtol", type=real(RTOL_MIN, 1.0), default=1e-9,
                   help=f"relative tolerance, {RTOL_MIN:.3g} to 1 (default 1e-9)")
    p.add_argument("--atol", type=real(0, lo_open=True), default=1e-11,
                   help="absolute tolerance (default 1e-11)")
    p.add_argument("--stabilization", type=real(0, STABILIZATION_MAX, unit="1/s"), default=10.0,
                   help=f"Baumgarte rate of the held rows, 1/s, at most {STABILIZATION_MAX:g} "
                   "(default 10; 0: off)")
    p.add_argument("--geometry-check", default="stop", choices=("stop", "report", "off"),
                   help="when a link enters the object or two links cross (beyond 1e-6 of "
                   "the longest link): stop there (default, status penetration or "
                   "self_contact), report it and integrate on, or check nothing")
    p.add_argument("--contacts", default="paper", choices=("paper", "geometry"),
                   help="paper (default): the paper's one point contact, integrated between "
                   "events; geometry: the object as its square plate and every contact from "
                   "the geometry, velocity-level time stepping (--dt), as a general scene "
                   "(docs/how-to/simulate.md)")
    p.add_argument("--output-dt", type=real(0, lo_open=True, unit="s"),
                   help="output sample spacing (default duration/400; at most "
                   f"{MAX_OUTPUT_SAMPLES:g} samples)")
    p.add_argument("--out", default="snakecg-output/simulate", metavar="DIR",
                   type=text("an output folder"),
                   help="output folder (default snakecg-output/simulate)")
    p.add_argument("--no-figures", action="store_true", help="write no PNG and no GIF")
    p.add_argument("--no-animation", action="store_true", help="write the PNGs but no GIF")
    p.add_argument("--frames", type=count(2, MAX_FRAMES, why=" (the limit: frames are held in "
                                           "memory until the GIF is written)"), default=100,
                   help=f"animation frames, 2 to {MAX_FRAMES} (default 100)")
    p.add_argument("--dt", type=real(1e-7, 1.0, lo_open=False, unit="s"),
                   help="--scene: the time step (s, default 0.001; shortened where a contact "
                   "begins)")
    p.add_argument("--json", action="store_true",
                   help="print the summary as JSON (schema snakecg.simulate/1)")
    p.set_defaults(run=run)


def _check_counts(args) -> None:
    """Output samples and controller periods within their limits (before any work)."""
    output_dt = args.output_dt if args.output_dt is not None else args.duration / 400
    check_count("--output-dt", args.duration, output_dt, MAX_OUTPUT_SAMPLES, "output samples")
    if args.controller:
        check_count("--control-period", args.duration, args.control_period or 0.01,
                    MAX_PERIODS, "controller periods (one torque query each)")


def run(args) -> int:
    from .. import load
    from .._files import write_text
    from ..figures.simulation import save_figures
    from ..simulate import least_slip_push_controller, serpenoid_controller, simulate

    from ._common import general_scene_from_args

    general = general_scene_from_args(args)
    if general is not None and general.__class__.__name__ == "SpatialScene":
        raise InputError(f"--scene {args.scene}: a 3-D snake's scene is not simulated "
                         f"(forward, optimize and plot take it)")
    if general is not None:  # a general scene: time stepping (snakecg.scenes.stepping)
        from ._scene import simulate_command

        if args.contacts != "paper":
            raise InputError("--contacts applies to the paper's scene; a general scene's "
                             "contacts always come from its geometry")

        return simulate_command(args, general, _gait_options(args))
    if args.contacts == "geometry":  # the paper's scene stepped as a general one
        from ..scenes.paper import plate_scene
        from ._scene import simulate_command

        paper = scene_from_args(args)
        return simulate_command(args, plate_scene(paper), _gait_options(args), paper=paper)
    if args.dt is not None:
        raise InputError("--dt applies to a general scene (--scene FILE) or --contacts "
                         "geometry only; the paper's model is integrated with error control "
                         "(--rtol, --atol)")
    # every option checked against the robot and each other before the model is loaded
    scene = scene_from_args(args)
    na = scene.robot.joints
    what = f" = (n_joints + 3,) for a {na}-joint robot"
    q = check_vector("q0", parse_vector("--q", args.q), na + 3, what)
    v = check_vector("v0", parse_vector("--v", args.v), na + 3, what) if args.v else None
    v_obj = check_vector("v_obj0", parse_vector("--v-obj", args.v_obj), 3) \
        if args.v_obj else None
    gait = _gait_options(args)
    if args.controller:
        if args.tau:
            raise InputError("give either --tau or --controller, not both")
        if args.controller == "least-slip-push" and args.a_min is None:
            raise InputError("--controller least-slip-push needs --a-min (m/s^2 along the "
                             "contact normal)")
        if args.controller == "serpenoid" and args.a_min is not None:
            raise InputError("--a-min applies to --controller least-slip-push only")
        tau = None
    else:
        if not args.tau:
            raise InputError("give the joint torques --tau (or --controller least-slip-push "
                             "or serpenoid)")
        for opt, val, which in (("--a-min", args.a_min, " least-slip-push"),
                                ("--tau-max", args.tau_max, ""),
                                ("--control-period", args.control_period, "")):
            if val is not None:
                raise InputError(f"{opt} applies to --controller{which} only")
        tau = check_vector("tau", parse_vector("--tau", args.tau), na,
                           f" (one torque per joint, n_a = {na})")
    _check_counts(args)
    out = out_dir("--out", args.out)
    model = load(scene, progress=progress_reporter())
    control_period = args.control_period
    if args.controller == "least-slip-push":
        tau = least_slip_push_controller(model, a_min=args.a_min, tau_max=args.tau_max)
        if control_period is None:
            control_period = 0.01
    elif args.controller == "serpenoid":
        tau = serpenoid_controller(model, **gait,
                                   tau_max="robot" if args.tau_max is None else args.tau_max)
        if control_period is None:
            control_period = 0.002
    traj = simulate(model, q, tau, args.duration, v0=v, v_obj0=v_obj,
                    control_period=control_period, method=args.method, rtol=args.rtol,
                    atol=args.atol, stabilization=args.stabilization,
                    output_dt=args.output_dt, integrator=args.integrator,
                    geometry_check=args.geometry_check)
    try:
        out.mkdir(parents=True, exist_ok=True)
        # every file under a unique temporary name, then renamed: two runs into one folder
        # both succeed (the later one's files win), a reader never sees half a file
        traj.save(out / "trajectory.npz")
        write_text(out / "summary.json", json.dumps(strict_json(traj.summary), indent=2,
                                                    allow_nan=False) + "\n")
        files = {"trajectory": str(out / "trajectory.npz"), "summary": str(out / "summary.json")}
        if not args.no_figures:
            files.update(save_figures(traj, out, animation=not args.no_animation,
                                      frames=args.frames))
    except OSError as exc:  # not the input's fault (disk full, permissions): exit status 1
        raise SnakecgError(f"cannot write to --out {str(out)!r}: {exc}") from None
    s = traj.summary
    if args.json:
        print_json({**s, "files": files})
    else:
        _print_text(s, files)
    if s["violation"] is not None:  # not physical from there on: the run stopped (or went on)
        sys.stderr.write(f"snakecg simulate: {s['status']}: {s['violation']['description']}\n")
        return 1
    if not s["status"].startswith("completed"):
        sys.stderr.write(f"snakecg simulate: failed: {s['status']}\n")
        return 1
    return 0


_GAIT = {"--amplitude": "amplitude", "--frequency": "frequency", "--phase-lag": "phase_lag",
         "--offset": "offset", "--kp": "kp", "--kd": "kd"}


def _gait_options(args) -> dict:
    """The serpenoid's options (angles in rad or NNdeg), all given with --controller
    serpenoid and none without it."""
    given = {opt: getattr(args, key) for opt, key in _GAIT.items()
             if getattr(args, key) is not None}
    if args.controller != "serpenoid":
        if given:
            raise InputError(f"{next(iter(given))} applies to --controller serpenoid only")
        return {}
    missing = [opt for opt in _GAIT if opt != "--offset" and opt not in given]
    if missing:
        raise InputError(f"--controller serpenoid needs {', '.join(missing)}")
    gait = {}
    for opt, value in given.items():
        if opt in ("--amplitude", "--phase-lag", "--offset"):
            value = float(check_vector(opt, parse_vector(opt, value), 1, " (one angle)")[0])
        gait[_GAIT[opt]] = value
    return gait


def _print_text(s: dict, files: dict) -> None:
    np.set_printoptions(precision=6, suppress=True)
    print(f"{s['joints']} joints, {s['scenario']}, kappa {s['kappa']:g}, {s['duration']:g} s, "
          f"torque {s['torque']}: {s['status']}")
    v = s["violation"]
    if v is not None:
        after = ("the run stopped there" if s["contact_check"]["mode"] == "stop"
                 else "reported; the run went on without the check")
        print(f"  {v['kind']}: {v['description']}; {after}")
    print(f"  start: {s['initial_mode']}")
    for e in s["events"]:
        extra = ""
        if "energy_loss" in e:
            extra = f" (energy lost {e['energy_loss']:.3g} J)"
        print(f"  t = {e['t']:.6f} s  {e['kind']:<10} row {e['row']}{extra} -> {e['after']}")
    print(f"  end:   {s['final_mode']}")
    do, dc = s["object_displacement"], s["snake_com_displacement"]
    print(f"  object moved {do['distance'] * 1e3:.4g} mm (x {do['x'] * 1e3:.4g}, "
          f"y {do['y'] * 1e3:.4g} mm, psi {np.degrees(do['psi']):.3g} deg); snake COM "
          f"{dc['distance'] * 1e3:.4g} mm")
    srd = s["sr_displacement_final"]
    print(f"  sr: initial {s['sr_initial']:.4g}, time mean {s['sr_mean']:.4g}, "
          f"from displacements {'n/a' if srd is None else format(srd, '.4g')}")
    e = s["energy"]
    print(f"  energy (J): kinetic {e['kinetic_initial']:.4g} -> {e['kinetic_final']:.4g}, "
          f"torques {e['work_tau']:.4g}, friction {e['work_friction']:.4g}, impacts "
          f"-{e['impact_loss']:.4g}, balance residual {e['balance_residual']:.2g}")
    r = s["constraint_residual"]
    print(f"  constraint residual: gap {r['gap']:.2g} m, gap rate {r['gap_rate']:.2g} m/s, "
          f"wheel lateral velocity {r['wheel_lateral_velocity']:.2g} m/s")
    i = s["integrator"]
    print(f"  integrator {i['method']}"
          f"{' (compiled segments)' if i.get('compiled_segments') else ''}: "
          f"{i['rhs_evaluations']} evaluations, "
          f"{i['segments']} segments, {i['wall_time_s']:.3g} s")
    for k, path in files.items():
        print(f"  wrote {path}")
