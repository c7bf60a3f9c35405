"""``snakecg generate``: derive, render and compile the model of an n-joint snake."""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from ..errors import InputError
from ._common import print_json, progress_reporter, text

#: Version of the JSON printed by ``snakecg generate --json`` (docs/reference/cli.md).
SCHEMA = "snakecg.generate/1"

EXAMPLES = """\
examples:
  snakecg generate --joints 8               # into the user cache, compiled, ready to load
  snakecg generate --joints 3 --out models  # write models/na3/ (sources only, not compiled)
"""


def register(sub) -> None:
    p = sub.add_parser(
        "generate",
        help="derive + render + compile the model for a joint count",
        description="Derive the model of an N-joint snake with SymPy, render the CasADi "
        "builder and its C (CasADi's code generator) and compile it into the user cache "
        "(SNAKECG_CACHE_DIR), where snakecg.load finds it; models for 1-6 joints ship with "
        "the package. With --out, write the folder na<N>/ into DIR instead (not compiled). "
        "Progress is shown on a terminal.",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--joints", type=int, required=True, metavar="N",
                   help="number of joints n_a >= 1 (at most SNAKECG_MAX_JOINTS, default 50)")
    p.add_argument("--out", metavar="DIR", type=text("an output folder"),
                   help="write na<N>/ into DIR instead of the cache (not compiled)")
    p.add_argument("--json", action="store_true",
                   help=f"print the result as JSON (schema {SCHEMA}, docs/reference/cli.md)")
    p.set_defaults(run=run)


def run(args) -> int:
    if args.joints < 1:
        raise InputError(f"--joints must be >= 1, got {args.joints}")
    progress = progress_reporter()
    t0 = time.perf_counter()
    if args.out is not None:
        from ..artifacts import max_joints

        if args.joints > max_joints():
            raise InputError(f"--joints {args.joints} exceeds the generation limit of "
                             f"{max_joints()} (set SNAKECG_MAX_JOINTS to raise it)")
        out = Path(args.out)
        if out.exists() and not out.is_dir():
            raise InputError(f"--out {args.out!r} exists and is not a directory")
        from snakecg_derive.render import render_model, write_model

        from ..progress import stage

        with stage(progress, f"generating the {args.joints}-joint model into {str(out)!r}",
                   f"generated the {args.joints}-joint model"):
            folder = write_model(render_model(args.joints, progress=progress,
                                              max_joints=max_joints()), out)
        seconds = time.perf_counter() - t0
        if args.json:
            print_json({"schema": SCHEMA, "joints": args.joints, "folder": str(folder),
                        "library": None, "backend": None, "seconds": seconds})
        else:
            print(f"wrote {folder} in {seconds:.1f} s")
        return 0
    from .. import Robot, load

    model = load(Robot(joints=args.joints), progress=progress)
    library = getattr(model.backend, "path", None)
    seconds = time.perf_counter() - t0
    if args.json:
        print_json({"schema": SCHEMA, "joints": args.joints, "folder": str(model.folder),
                    "library": None if library is None else str(library),
                    "backend": model.backend_kind, "seconds": seconds})
    else:
        print(f"model for {args.joints} joints ready ({model.backend_kind}): "
              f"{library or model.folder} in {seconds:.1f} s")
    return 0
