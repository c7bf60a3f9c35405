"""``snakecg export``: the model as a self-contained C library (header, Makefile, example)."""

from __future__ import annotations

import argparse

from ._common import add_robot_args, out_dir, print_json, scene_from_args, text

#: Version of the JSON printed by ``snakecg export --json`` (docs/how-to/export.md).
SCHEMA = "snakecg.export/1"

EXAMPLES = """\
examples:
  snakecg export --joints 3 --out snake3        # the paper's Table 1 robot baked in
  snakecg export --robot examples/robot.toml --out snake3 && make -C snake3 && snake3/example
"""


def register(sub) -> None:
    p = sub.add_parser(
        "export",
        help="write the model as a C library: header, sources, Makefile, example",
        description="Write a self-contained C library of the N-joint model into DIR: the C of "
        "every generated function, a header with prototypes, sizes, the parameter layout and "
        "plain wrappers, robot_params.c with the robot's parameter vector K and the scene's "
        "constants baked in (from --robot, else the paper's Table 1 robot and the default "
        "scene), a Makefile and an example main.c. Every file is written atomically. "
        "Build with `make -C DIR`; see docs/how-to/export.md.",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    add_robot_args(p)
    p.add_argument("--out", required=True, metavar="DIR", type=text("an output folder"),
                   help="folder to write (created)")
    p.add_argument("--json", action="store_true",
                   help=f"print the files written as JSON (schema {SCHEMA})")
    p.set_defaults(run=run)


def run(args) -> int:
    import shlex
    from pathlib import Path

    from ..export import export_library
    from ..spatial.export import spatial_robot_from_args

    out = out_dir("--out", args.out)
    scene = spatial_robot_from_args(args) or scene_from_args(args)  # a 3-D file: spatial
    files = export_library(scene, out, source=Path(args.robot).name if args.robot else None)
    robot = getattr(scene, "robot", scene)
    stem = f"snakecg_{'sp' if robot is scene else 'na'}{robot.joints}"
    if args.json:
        print_json({"schema": SCHEMA, "joints": robot.joints, "folder": str(out),
                    "header": str(out / f"{stem}.h"), "files": [str(f) for f in files]})
        return 0
    print(f"wrote {len(files)} files into {out}: {stem}.h, {stem}.c, robot_params.c, "
          f"main.c, Makefile and the C of {len(files) - 6} functions")
    # the hint is pasted into a shell: the folder quoted (spaces, quotes, `$(...)`)
    print(f"build: make -C {shlex.quote(str(out))}   run: {shlex.quote(str(out / 'example'))}")
    return 0
