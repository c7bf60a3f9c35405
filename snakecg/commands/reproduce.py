"""``snakecg reproduce``: the paper's case studies, Table 2 and Figures 4-6."""

from __future__ import annotations

from pathlib import Path


def register(sub) -> None:
    p = sub.add_parser(
        "reproduce",
        help="reproduce the paper's case studies: Figures 4-6 and Table 2",
        description="Case study 1 (2 joints): Fig. 4 torque-plane maps for kappa = 1, 10, 100 "
        "and the 784-configuration sweep; case study 2 (3 joints): Fig. 5 polar maps, Fig. 6 "
        "best/worst shapes and Table 2 beside the paper's values. Choices the paper leaves "
        "open are documented in docs/reproduction.md.",
        epilog="example: snakecg reproduce --out snakecg-output",
    )
    p.add_argument("--out", default="snakecg-output", metavar="DIR",
                   help="output folder (default: snakecg-output)")
    p.add_argument("--kappa", type=float, default=100.0,
                   help="object/link mass ratio for case study 2 and the sweep (default 100)")
    p.add_argument("--torque-grid", type=int, default=181,
                   help="points per axis of the Fig. 4 torque grid (default 181)")
    p.add_argument("--formats", default="png,svg", help="figure formats (default png,svg)")
    p.add_argument("--feasible-only", action="store_true",
                   help="Table 2 and Figs. 5-6 over physically possible shapes only (no links "
                   "crossing or closer than 1 cm, none inside the object); default: every shape "
                   "of the grid, as in the paper, with the infeasible ones marked in the figures")
    p.add_argument("--alternatives", action="store_true",
                   help="also write alternatives.md: Table 2 under alternative readings")
    p.set_defaults(run=run)


def run(args) -> int:
    from ..errors import InputError
    from ..reproduce import ReproduceOptions, reproduce

    if args.kappa <= 0:
        raise InputError(f"--kappa must be > 0, got {args.kappa}")
    if args.torque_grid < 11:
        raise InputError(f"--torque-grid must be >= 11, got {args.torque_grid}")
    formats = tuple(f.strip() for f in args.formats.split(",") if f.strip())
    bad = [f for f in formats if f not in ("png", "svg", "pdf")]
    if bad or not formats:
        raise InputError(f"--formats takes png, svg or pdf separated by commas, got {args.formats!r}")
    opts = ReproduceOptions(out=Path(args.out), kappa_case2=args.kappa,
                            torque_grid=args.torque_grid, formats=formats,
                            feasible_only=args.feasible_only)
    reproduce(opts)
    if args.alternatives:
        from ..reproduce import alternative_readings

        text = alternative_readings(opts)
        (opts.out / "alternatives.md").write_text(text, encoding="utf-8")
        print(text)
    return 0
