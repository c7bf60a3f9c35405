"""``snakecg sweep``: per-configuration extremes over a grid or samples on Dask, into Zarr;
``--summary`` and ``--figure`` reduce a store chunk by chunk."""

from __future__ import annotations

import argparse
import math
import sys

from ..errors import InputError
from ._common import add_robot_args, print_json, real, scene_from_args, text, vector
from ._names import limits_line

#: Version of the JSON printed by ``snakecg sweep --json`` (docs/how-to/sweep.md).
SCHEMA = "snakecg.sweep/1"

EXAMPLES = """\
examples:
  snakecg sweep --joints 3 --scenario wheels --range 135 --step 10 --out wheels3.zarr
  snakecg sweep --joints 4 --scenario frictionless --samples 100000 --seed 1 --out s4.zarr --workers 2
  snakecg sweep --joints 3 --range=-90:90,-45:45,0:90 --step 5,5,10 --out part.zarr --scheduler tcp://scheduler-host:8786
  snakecg sweep --joints 3 --range 60 --step 20 --simulate 0.5 --tau 0.035,0,-0.014 --out push3.zarr
  snakecg sweep --summary wheels3.zarr --json
  snakecg sweep --summary wheels3.zarr --feasible-only
  snakecg sweep --figure wheels3.zarr --every-shape
  snakecg sweep --figure wheels3.zarr --out wheels3-polar.svg
"""


def register(sub) -> None:
    from ..sweeps.run import LIMIT

    p = sub.add_parser(
        "sweep",
        help="extremes of every configuration of a grid or of samples, on Dask, into Zarr",
        description="Evaluate the best and worst |a_obj|^2, |qdd|^2, |lambda|^2 and sr over "
        "the input ellipsoid (eq. 31) with the torques attaining them, and the COM's polar "
        "coordinates, for every configuration of a joint grid (--range/--step) or of seeded "
        "random samples (--samples/--seed), chunk by chunk on Dask (a local cluster of "
        "--workers processes, or a running one at --scheduler) into the Zarr store --out. "
        "Rerun the same command after an interruption: only the missing chunks are computed. "
        "--summary and --figure read a store chunk by chunk. Needs the sweep extra "
        "(pip install 'snakecg[sweep]'). Reference: docs/how-to/sweep.md.",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_robot_args(p)
    g = p.add_argument_group("configurations (default: the robot's joint limits every 10 deg "
                             "or a little less, both included; without limits the paper's "
                             "grid, -135..135 deg every 10)")
    g.add_argument("--range", metavar="DEG",
                   help="joint range in degrees: R (for -R:R), LO:HI, or one per joint "
                   "separated by commas (write --range=-90:90 when it starts with '-'); "
                   "the sampling box with --samples")
    g.add_argument("--step", metavar="DEG",
                   help="grid step in degrees, one for every joint or one per joint (default 10)")
    g.add_argument("--samples", type=int, metavar="N",
                   help="N random configurations, uniform in --range, instead of a grid")
    g.add_argument("--seed", type=int, metavar="S", help="seed of --samples (required with it)")
    f = p.add_argument_group("feasible shapes (default: every shape, as the paper's grid)")
    fx = f.add_mutually_exclusive_group()
    fx.add_argument("--feasible-only", action="store_true",
                   help="leave out the shapes that are not physically possible (non-adjacent "
                   "links closer than --clearance, or a link inside the object): with a sweep, "
                   "the default of its --summary and --figure (every shape is still computed "
                   "and stored); with --summary or --figure, for that reduction")
    fx.add_argument("--every-shape", action="store_true",
                    help="with --summary or --figure: every shape, also of a store made with "
                    "--feasible-only")
    f.add_argument("--clearance", type=real(0, unit="m", name="distance"), metavar="M",
                   help="with --feasible-only when sweeping: least distance between "
                   "non-adjacent links of a feasible shape, in metres (default 0.01, as "
                   "snakecg reproduce --feasible-only)")
    s = p.add_argument_group("a simulated push from every configuration (optional)")
    s.add_argument("--simulate", type=real(0, 60, lo_open=True, unit="s", name="duration"),
                   metavar="SECONDS",
                   help="also simulate a push of this many seconds from rest from every "
                        "configuration, with the constant torques --tau, and store how it "
                        "ended, the object's and the COM's displacements and the mean sr")
    s.add_argument("--tau", metavar="TAU", type=text("numbers tau1..tau_n"),
                   help="the constant joint torques tau1..tau_n (N m) of --simulate")
    r = p.add_argument_group("where and how")
    r.add_argument("--out", metavar="STORE",
                   help="Zarr store to write (a folder, e.g. sweep.zarr); resumed if it exists; "
                   "with --figure, the image file (default STORE-polar.png)")
    w = r.add_mutually_exclusive_group()
    w.add_argument("--scheduler", metavar="ADDRESS",
                   help="run on the Dask cluster whose scheduler is at tcp://HOST:PORT "
                   "(it must answer, and have a worker, within 10 s each)")
    w.add_argument("--workers", type=int, metavar="K",
                   help="worker processes of the local cluster (default: one per core; at "
                   "most 4 per core); the cluster listens on 127.0.0.1 with TLS and "
                   "temporary credentials, so only this sweep can use it")
    r.add_argument("--shared-store", action="store_true",
                   help="with --scheduler: the workers write the chunks into --out themselves "
                   "(they reach it at the same absolute path, e.g. on a shared file system); "
                   "by default a local cluster's workers do, a remote one's send their "
                   "results to this process, which writes them")
    r.add_argument("--chunk", type=int, metavar="N",
                   help="configurations per chunk (default for a new store: about 1.5 s of "
                   "work, from the scenario and joint count, e.g. 12288 for 3-joint wheels, "
                   "cut to give each worker at least 4 chunks; a resumed store keeps its "
                   "own)")
    r.add_argument("--limit", type=int, default=None, metavar="N",
                   help=f"refuse sweeps of more than N configurations (default {LIMIT:,})")
    r.add_argument("--force", action="store_true", help="run a sweep above --limit")
    r.add_argument("--json", action="store_true",
                   help=f"print JSON (schema {SCHEMA}, or the summary's with --summary)")
    m = p.add_mutually_exclusive_group()
    m.add_argument("--summary", metavar="STORE",
                   help="print the worst and best per-configuration maxima of a store "
                   "(Table 2 style) and the configurations attaining them")
    m.add_argument("--figure", metavar="STORE",
                   help="draw a store's maxima binned over |COM| and angle of COM (Fig. 5 style)")
    p.set_defaults(run=run)


def _split(name: str, text: str) -> list[str]:
    parts = [t.strip() for t in text.split(",")]
    if not text.strip() or any(not t for t in parts):
        raise InputError(f"{name} must be one value or values separated by commas, got {text!r}")
    return parts


def _number(name: str, text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise InputError(f"{name} takes numbers of degrees, got {text!r}") from None


def _per_joint(name: str, items: list, joints: int) -> list:
    if len(items) == 1:
        return items * joints
    if len(items) != joints:
        raise InputError(f"{name} has {len(items)} entries, expected one or {joints} "
                         f"(one per joint)")
    return items


def _ranges(text: str | None, joints: int, robot) -> list[tuple[float, float]]:
    if text is None:  # the robot's joint limits, or the paper's range
        from ..limits import default_joint_limits

        return [(math.degrees(lo), math.degrees(hi))
                for lo, hi in default_joint_limits(robot)[0]]
    out = []
    for tok in _split("--range", text):
        if ":" in tok:
            lo, _, hi = tok.partition(":")
            out.append((_number("--range", lo), _number("--range", hi)))
        else:
            r = _number("--range", tok)
            if r < 0:
                raise InputError(f"--range R means -R:R and needs R >= 0, got {tok!r}; "
                                 f"give LO:HI otherwise")
            out.append((-r, r))
    return _per_joint("--range", out, joints)


def run(args) -> int:
    if args.summary is not None or args.figure is not None:
        return _reduce(args)
    import math

    from ..sweeps.plan import PAPER_STEP_DEG, joint_count, joint_values
    from ..sweeps.run import sweep

    if not args.out:
        raise InputError("--out STORE is required: the Zarr store to write (e.g. sweep.zarr)")
    if args.every_shape:
        raise InputError("--every-shape goes with --summary or --figure; a sweep keeps every "
                         "shape unless --feasible-only is given")
    if args.clearance is not None and not args.feasible_only:
        raise InputError("--clearance M goes with --feasible-only (the least distance between "
                         "non-adjacent links of a feasible shape); without it every shape is "
                         "kept")
    scene = scene_from_args(args)
    joints = scene.robot.joints
    simulate = None
    if (args.simulate is None) != (args.tau is None):
        raise InputError("--simulate SECONDS and --tau TAU go together (a push of that "
                         "duration with those constant joint torques from every "
                         "configuration)")
    if args.simulate is not None:
        simulate = {"duration": args.simulate,
                    "tau": vector("--tau", args.tau, joints,
                                  what=f" (one torque per joint, n_a = {joints})")}
    ranges = _ranges(args.range, joints, scene.robot)
    for lo, hi in ranges:
        if not (math.isfinite(lo) and math.isfinite(hi)):
            raise InputError(f"--range must be finite degrees, got {args.range!r}")
    if args.samples is not None:
        if args.step is not None:
            raise InputError("--step makes a grid; --samples draws random configurations: "
                             "give one of them")
        if args.seed is None:
            raise InputError("--samples N needs --seed S (the random stream to draw from)")
        for lo, hi in ranges:
            if hi < lo:
                raise InputError(f"--range {lo:g}:{hi:g} is empty (LO > HI)")
        _check_size(args, args.samples, joints)
        kw = {"samples": args.samples, "seed": args.seed,
              "bounds": None if args.range is None else
              [(math.radians(lo), math.radians(hi)) for lo, hi in ranges]}
    else:
        if args.seed is not None:
            raise InputError("--seed goes with --samples N; a grid has no seed")
        steps = _per_joint("--step", [_number("--step", s) for s in
                                      _split("--step", args.step)], joints) \
            if args.step is not None else [PAPER_STEP_DEG] * joints
        if args.range is None and args.step is None:  # the robot's limits, or the paper's
            from ..sweeps.plan import default_grid

            size = math.prod(len(v) for v in default_grid(scene.robot)[0])
            _check_size(args, size, joints)
            kw = {"grid": None}
        else:
            # the grid's size from the arguments, before any value is made
            size = math.prod(joint_count(lo, hi, st) for (lo, hi), st in zip(ranges, steps))
            _check_size(args, size, joints)
            kw = {"grid": [joint_values(lo, hi, st) for (lo, hi), st in zip(ranges, steps)]}
    res = sweep(scene, store=args.out, chunk=args.chunk, scheduler=args.scheduler,
                workers=args.workers, limit=None if args.force else _limit(args),
                feasible=args.feasible_only, clearance=args.clearance,
                shared_store=True if args.shared_store else None, simulate=simulate, **kw)
    if args.json:
        out = {"schema": SCHEMA, **res.to_dict(), "joints": joints,
               "scenario": scene.scenario, "kappa": scene.kappa, "mu": scene.mu}
        print_json(out)
    else:
        print(f"{res.store}: {res.configurations:,} configurations in {res.chunks} chunks of "
              f"{res.chunk}; computed {res.computed_chunks}, found complete "
              f"{res.reused_chunks}; {res.seconds:.1f} s"
              + (f"; feasible shapes only (clearance {res.clearance:g} m)"
                 if res.feasible_only else ""))
        print(f"  limits: {limits_line(res.limits)}")
    return 0


def _limit(args) -> int:
    """--limit, or the default where it is not given (left None there, so that --summary and
    --figure can refuse it when it is)."""
    from ..sweeps.run import LIMIT

    return LIMIT if args.limit is None else args.limit


def _check_size(args, size: int, joints: int) -> None:
    """Refuse a sweep above --limit (unless --force) or too large for one store, from its
    size alone (as snakecg.sweep does once the configurations are made)."""
    from ..sweeps.plan import check_size

    if size < 1:
        return  # refused with its reason by the sweep
    limit = _limit(args)
    if not args.force and isinstance(limit, int) and limit >= 1 and size > limit:
        raise InputError(f"{size:,} configurations exceed the limit of {limit:,}; "
                         f"lift it (limit=None, or --force) to run them")
    check_size(size, joints)


def _reduce(args) -> int:
    from ..sweeps.reduce import figure, summary, summary_text

    for flag in ("range", "step", "samples", "seed", "scheduler", "workers", "chunk",
                 "simulate", "tau", "limit", "force", "shared_store",
                 "joints", "robot", "scenario", "kappa", "mu", "contact_link", "side"):
        value = getattr(args, flag)
        if value is not None and value is not False:
            raise InputError(f"--{flag.replace('_', '-')} describes a sweep to run; "
                             f"--summary and --figure read everything from the store")
    if args.clearance is not None:
        raise InputError("--clearance is the store's, recorded when the sweep was made; "
                         "--summary and --figure --feasible-only use it (sweep into a new "
                         "store for another clearance)")
    feasible = True if args.feasible_only else False if args.every_shape else None
    if args.summary is not None:
        if args.out is not None:
            raise InputError("--out goes with a sweep or --figure, not with --summary")
        s = summary(args.summary, feasible=feasible)
        if args.json:
            print_json(s)
        else:
            print(summary_text(s))
        if not s["complete"]:
            sys.stderr.write(f"snakecg sweep: warning: {args.summary} is incomplete "
                             f"({s['completed_chunks']} of {s['chunks']} chunks); rerun the "
                             f"sweep to finish it\n")
        return 0
    path = figure(args.figure, args.out, feasible=feasible)
    if args.json:
        print_json({"figure": str(path)})
    else:
        print(path)
    return 0
