"""``snakecg generate``: derive, render and compile the model of an n-joint snake."""

from __future__ import annotations

import sys
import time
from pathlib import Path

from ..errors import InputError


def register(sub) -> None:
    p = sub.add_parser(
        "generate",
        help="derive + render + compile the model for a joint count",
        description="Derive the model of an N-joint snake with SymPy, render the CasADi builder "
        "and C with Jinja2/CasADi into --out (default: the user cache) and compile it.",
        epilog="example: snakecg generate --joints 8",
    )
    p.add_argument("--joints", type=int, required=True, help="number of joints n_a >= 1")
    p.add_argument("--out", metavar="DIR",
                   help="write na<N>/ into DIR instead of the cache (not compiled)")
    p.set_defaults(run=run)


def run(args) -> int:
    if args.joints < 1:
        raise InputError(f"--joints must be >= 1, got {args.joints}")
    progress = _progress()
    t0 = time.perf_counter()
    if args.out:
        from snakecg_derive.render import render_model, write_model

        from ..artifacts import max_joints

        if args.joints > max_joints():
            raise InputError(f"--joints {args.joints} exceeds the generation limit of "
                             f"{max_joints()} (set SNAKECG_MAX_JOINTS to raise it)")
        out = Path(args.out)
        if out.exists() and not out.is_dir():
            raise InputError(f"--out {args.out!r} exists and is not a directory")
        folder = write_model(render_model(args.joints, regen_out=str(out), progress=progress,
                                          max_joints=max_joints()), out)
        print(f"wrote {folder} in {time.perf_counter() - t0:.1f} s")
        return 0
    from .. import Robot, load

    model = load(Robot(joints=args.joints), progress=progress)
    where = getattr(model.backend, "path", model.folder)
    print(f"model for {args.joints} joints ready ({model.backend_kind}): {where}"
          f" in {time.perf_counter() - t0:.1f} s")
    return 0


def _progress():
    if not sys.stderr.isatty():
        return None

    def step(msg: str) -> None:
        sys.stderr.write(f"  ... {msg}\n")
        sys.stderr.flush()

    return step
