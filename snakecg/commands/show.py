"""``snakecg show``: print a symbolic expression (or the generated C) of the model."""

from __future__ import annotations

from ..errors import InputError


def register(sub) -> None:
    p = sub.add_parser(
        "show",
        help="inspect a closed-form expression (M, J_i, h, contact and wheel rows)",
        description="Print the closed form that the generated code evaluates: M (eq. 4), "
        "J1..Jn (eq. 3), h, K (derived parameters), contact (link-level row), contact<k>, "
        "wheel<i>; or, with --c, the generated C of a function.",
        epilog="example: snakecg show --joints 2 M --latex",
    )
    p.add_argument("--joints", type=int, required=True, help="number of joints n_a >= 1")
    p.add_argument("what", help="expression name (M, h, K, J1, contact, contact1, wheel2, ...) "
                   "or, with --c, a function name (mass_matrix, constrained_dynamics, ...)")
    fmt = p.add_mutually_exclusive_group()
    fmt.add_argument("--latex", action="store_true", help="print LaTeX")
    fmt.add_argument("--c", action="store_true", help="print the generated C of a function")
    p.set_defaults(run=run)


def run(args) -> int:
    if args.joints < 1:
        raise InputError(f"--joints must be >= 1, got {args.joints}")
    if args.c:
        from ..artifacts import model_dir

        folder, manifest = model_dir(args.joints)
        fns = [f["name"] for f in manifest["functions"]]
        if args.what not in fns:
            raise InputError(f"unknown function {args.what!r}; choose one of: {', '.join(fns)}")
        print((folder / "c" / f"{args.what}.c").read_text(), end="")
        return 0
    if args.joints > 8:
        raise InputError("symbolic inspection is limited to --joints <= 8 (closed forms grow "
                         "as n^3); use --c to read the generated code of larger models")
    import sympy as sp
    from snakecg_derive.inspect import expression

    try:
        exprs = expression(args.joints, args.what)
    except ValueError as exc:
        raise InputError(str(exc)) from None
    for label, e in exprs.items():
        if args.latex:
            print(f"% {label}")
            print(sp.latex(e))
        else:
            print(f"{label} =")
            print(sp.pretty(e, use_unicode=True, wrap_line=False))
        print()
    return 0
