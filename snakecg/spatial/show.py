"""``snakecg show --spatial``: the spatial chain's structured programs (as text, LaTeX or
JSON), or the generated C of a spatial function."""

from __future__ import annotations

import sys

from ..errors import InputError

__all__ = ["run_spatial"]


def run_spatial(args) -> int:
    from ..commands._common import print_json, progress_reporter

    if args.c:
        from .artifacts import spatial_model_dir

        folder, manifest = spatial_model_dir(args.joints, progress=progress_reporter())
        fns = [f["name"] for f in manifest["functions"]]
        if args.what is None:
            print(f"generated spatial functions for {args.joints} joints ({folder / 'c'}):")
            print("  " + " ".join(fns))
            return 0
        if args.what not in fns:
            raise InputError(f"unknown function {args.what!r}; choose one of: {', '.join(fns)}")
        sys.stdout.write((folder / "c" / f"{args.what}.c").read_text())
        return 0
    from snakecg_derive.spatial.inspection import program_lines, spatial_expression, spatial_names

    if args.what is None:
        print(f"spatial chain with {args.joints} joints (snakecg show --spatial --joints "
              f"{args.joints} NAME [--c]):")
        print("  " + " ".join(spatial_names(args.joints)))
        return 0
    try:
        exprs = spatial_expression(args.joints, args.what)
    except ValueError as exc:
        raise InputError(str(exc)) from None
    from snakecg_derive.inspection import latex_symbol_names

    from ..commands._common import SHOW_SCHEMA as SCHEMA

    if args.json:
        import sympy as sp

        print_json({"schema": SCHEMA, "joints": args.joints, "spatial": True,
                    "what": args.what,
                    "expressions": [{"label": k, "text": str(e), "latex": sp.latex(e)}
                                    for k, e in exprs.items()]})
        return 0
    if args.latex:
        import sympy as sp

        for label, e in exprs.items():
            print(f"% {label}")
            print(sp.latex(e, symbol_names=latex_symbol_names(e)))
        return 0
    print("\n".join(program_lines(args.joints, args.what)))
    return 0
