"""``snakecg reproduce``: the paper's case studies, Table 2 and Figures 4-6."""

from __future__ import annotations

import argparse

from ..reproduce import FORMATS, MAX_TORQUE_GRID
from ._common import count, out_dir, print_json, real, text

#: Version of the JSON printed by ``snakecg reproduce --json`` (docs/reference/cli.md).
SCHEMA = "snakecg.reproduce/1"


def register(sub) -> None:
    p = sub.add_parser(
        "reproduce",
        help="reproduce the paper's case studies: Figures 4-6 and Table 2",
        description="Case study 1 (2 joints): Fig. 4 torque-plane maps for kappa = 1, 10, 100 "
        "and the 784-configuration sweep; case study 2 (3 joints): Fig. 5 polar maps, Fig. 6 "
        "best/worst shapes and Table 2 beside the paper's values. Choices the paper leaves "
        "open are documented in docs/how-to/reproduction.md.",
        epilog="examples:\n  snakecg reproduce --out snakecg-output\n"
        "  snakecg reproduce --out snakecg-output --json > summary.json",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--out", default="snakecg-output", metavar="DIR", type=text("an output folder"),
                   help="output folder (default: snakecg-output)")
    p.add_argument("--kappa", type=real(0, lo_open=True), default=100.0,
                   help="object/link mass ratio for case study 2 and the sweep (default 100)")
    p.add_argument("--torque-grid", type=count(11, MAX_TORQUE_GRID, why=" (the limit: the "
                                               "Fig. 4 maps hold grid^2 results)"), default=181,
                   help=f"points per axis of the Fig. 4 torque grid, 11 to {MAX_TORQUE_GRID} "
                   "(default 181)")
    p.add_argument("--formats", default="png,svg", type=text("png, svg or pdf"),
                   help="figure formats (default png,svg)")
    p.add_argument("--feasible-only", action="store_true",
                   help="Table 2 and Figs. 5-6 over physically possible shapes only (no links "
                   "crossing or closer than 1 cm, none inside the object); default: every shape "
                   "of the grid, as in the paper, with the infeasible ones marked in the figures")
    p.add_argument("--alternatives", action="store_true",
                   help="also write alternatives.md: Table 2 under alternative readings")
    p.add_argument("--json", action="store_true",
                   help=f"print the summary as JSON (schema {SCHEMA}, docs/reference/cli.md); the "
                   "human-readable report goes to standard error")
    p.set_defaults(run=run)


def run(args) -> int:
    import sys

    from .._files import write_text
    from ..errors import InputError
    from ..reproduce import ReproduceOptions, reproduce

    formats = tuple(f.strip() for f in args.formats.split(",") if f.strip())
    bad = [f for f in formats if f not in FORMATS]
    if bad or not formats:
        raise InputError(f"--formats takes png, svg or pdf separated by commas, got "
                         f"{args.formats!r:.80}")
    out = out_dir("--out", args.out)
    opts = ReproduceOptions(out=out, kappa_case2=args.kappa,
                            torque_grid=args.torque_grid, formats=formats,
                            feasible_only=args.feasible_only)
    echo = (lambda text: print(text, file=sys.stderr)) if args.json else print
    report = reproduce(opts, echo=echo)
    files = [str(f) for f in report.files]
    alternatives = None
    if args.alternatives:
        from ..reproduce import alternative_readings

        alternatives = alternative_readings(opts)
        write_text(opts.out / "alternatives.md", alternatives)
        files.append(str(opts.out / "alternatives.md"))
        echo(alternatives)
    if args.json:
        from ..reproduce import PAPER_TABLE2

        print_json({
            "schema": SCHEMA,
            "out": str(opts.out),
            "table2": {k: list(v) for k, v in report.table2.items()},
            "table2_shape_feasible": {k: list(v)
                                      for k, v in report.table2_shape_feasible.items()},
            "table2_feasible_only": {k: list(v)
                                     for k, v in report.table2_feasible_only.items()},
            "paper_table2": {k: list(v) for k, v in PAPER_TABLE2.items()},
            "options": {"kappa": args.kappa, "torque_grid": args.torque_grid,
                        "formats": list(formats), "alternatives": bool(args.alternatives)},
            "timings_s": dict(report.timings),
            "files": files,
        })
    return 0
