"""``snakecg plot``: draw a configuration (snake, object, contact, wheels; forces with --tau)."""

from __future__ import annotations

import argparse
from pathlib import Path

from .._files import save_figure
from ..errors import InputError
from ._common import add_robot_args, count, parse_vector, progress_reporter, scene_from_args, text

FORMATS = ("png", "pdf", "svg")
#: Version of the JSON printed by ``snakecg plot --json``.
SCHEMA = "snakecg.plot/1"

EXAMPLES = """\
examples:
  snakecg plot --joints 3 --q 0,0,0,30deg,-45deg,60deg --out shape.png
  snakecg plot --joints 3 --q 0,0,0,30deg,-45deg,60deg --tau 0.05,0,-0.02 --scenario wheels --out forces.png
"""


def register(sub) -> None:
    p = sub.add_parser(
        "plot",
        help="draw a configuration: snake, object, contact normal, wheels, forces",
        description="Draw configuration --q of the scene: the links, the object, the contact "
        "point and normal and the wheels' rolling directions; with --tau, the constraint "
        "forces and the accelerations of the forward solve at rest as arrows. The figure is "
        "written atomically to --out (PNG, PDF or SVG by its suffix).",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_robot_args(p)
    p.add_argument("--q", required=True, metavar="Q", type=text("numbers x,y,theta,q1..qn"),
                   help="configuration x,y,theta,q1..qn (m and rad; NNdeg for degrees)")
    p.add_argument("--tau", metavar="TAU", type=text("numbers tau1..tau_n"),
                   help="joint torques tau1..tau_n (N m): draw the "
                   "forces and accelerations")
    p.add_argument("--out", required=True, metavar="FILE", type=text("a figure file"),
                   help=f"figure file ({', '.join(FORMATS)})")
    p.add_argument("--dpi", type=count(10, 1200), default=150,
                   help="resolution of a PNG, 10 to 1200 (default 150)")
    p.add_argument("--json", action="store_true",
                   help=f"print what was drawn as JSON (schema {SCHEMA})")
    p.set_defaults(run=run)


def run(args) -> int:
    out = Path(args.out)
    fmt = out.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise InputError(f"--out must end in .{', .'.join(FORMATS)}, got {args.out!r}")
    if out.is_dir():
        raise InputError(f"--out {args.out!r} is a directory, expected a file name")
    if not out.parent.is_dir():
        raise InputError(f"--out {args.out!r}: the folder {str(out.parent)!r} does not exist")
    q = parse_vector("--q", args.q)
    tau = parse_vector("--tau", args.tau) if args.tau else None
    from ._common import general_scene_from_args

    scene = general_scene_from_args(args)
    if scene is not None and scene.__class__.__name__ == "SpatialScene":
        from ._spatial import plot_command

        return plot_command(args, scene, out, fmt, SCHEMA)
    if scene is not None:  # a general scene (snakecg.scenes): its vectors checked first
        from ._scene import _vectors

        _vectors(args, scene)
        about = {"scene": str(args.scene)}
    else:
        scene = scene_from_args(args)
        about = {"scenario": scene.scenario}
    from matplotlib.figure import Figure

    from .. import load
    from ..figures import plot

    model = load(scene, progress=progress_reporter())
    fig = Figure(figsize=(6.4, 5.2), constrained_layout=True)
    ax = plot(model, q, tau, ax=fig.add_subplot())
    save_figure(fig, out, fmt, args.dpi)
    if args.json:
        from ._common import print_json

        print_json({"schema": SCHEMA, "file": str(out), "format": fmt, "joints":
                    scene.robot.joints, **about, "q": q, "tau": tau,
                    "title": ax.get_title()})
        return 0
    print(f"wrote {out}")
    return 0
