"""``snakecg show``: print a closed form of the model (or the generated C of a function).

The expressions come from :mod:`snakecg_derive.inspection`, i.e. from the same derivation that
the generated code is printed from. On a terminal, a matrix too wide for the window is
printed entry by entry; ``--latex`` prints one ``aligned`` block for one equation
environment, one line per entry, long entries broken after sums to fit a page (the symbol
names that the documentation uses, see :func:`latex_symbol_names`); ``--simplify`` passes
each entry through ``trigsimp`` and collection first (display only); ``--json`` gives the
text and LaTeX of each expression and the block; ``--c`` the C that the compiled backend
runs.
"""

from __future__ import annotations

import argparse
import shutil
import sys
import textwrap

from ..errors import ArtifactError, BuildError, InputError
from ._common import SHOW_SCHEMA, print_json, progress_reporter

#: Version of the JSON printed by ``snakecg show --json`` (docs/reference/cli.md).
SCHEMA = SHOW_SCHEMA
#: Largest joint count for symbolic inspection (the closed forms grow as n^3).
MAX_SHOW_JOINTS = 8

EXAMPLES = """\
examples:
  snakecg show --joints 1 M                # M_s of a one-joint snake, pretty-printed
  snakecg show --joints 2                  # list the expressions and functions
  snakecg show --joints 2 M --latex        # the same for two joints, as LaTeX (aligned)
  snakecg show --joints 2 h --latex --simplify   # trigsimp and collection on each entry
  snakecg show --joints 2 wheel3 --json    # wheel row of link 3 as text and LaTeX
  snakecg show --joints 2 mass_matrix --c  # the generated C of mass_matrix()
  snakecg show --spatial --joints 2 mass_matrix  # a 3-D chain's structured program
"""


def register(sub) -> None:
    p = sub.add_parser(
        "show",
        help="inspect a closed form (M, J_i, h, contact and wheel rows) or the generated C",
        description="Print the closed form that the generated code evaluates: M (eq. 4, in "
        "absolute link angles), M_expanded (sum J_i^T D_i J_i), h (eq. 4), K (derived "
        "parameters), J1..J<n+1> (eq. 3), contact (link-level contact row), contact<k> "
        "(contact row on link k, eq. 10) and wheel<i> (wheel row of link i); or, with --c, "
        "the generated C of a function. Without NAME, list what there is.",
        epilog=EXAMPLES,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("--joints", type=int, default=2, metavar="N",
                   help="number of joints n_a >= 1 (default 2)")
    p.add_argument("what", nargs="?", metavar="NAME",
                   help="expression name (M, M_expanded, h, K, J1, contact, contact1, wheel2, "
                   "...) or, with --c, a function name (mass_matrix, constrained_dynamics, ...)")
    fmt = p.add_mutually_exclusive_group()
    fmt.add_argument("--latex", action="store_true", help="print LaTeX")
    fmt.add_argument("--json", action="store_true",
                     help=f"print JSON: text and LaTeX of each expression (schema {SCHEMA}, "
                     "docs/reference/cli.md)")
    fmt.add_argument("--c", action="store_true", help="print the generated C of a function")
    p.add_argument("--simplify", action="store_true",
                   help="trigsimp and collect each entry before printing (display only; "
                   "seconds for 2 joints, minutes for 6-8)")
    p.add_argument("--spatial", action="store_true",
                   help="the spatial chain with N joints (3-D snakes, docs/how-to/spatial.md)")
    p.set_defaults(run=run)


def run(args) -> int:
    if args.joints < 1:
        raise InputError(f"--joints must be >= 1, got {args.joints}")
    if getattr(args, "spatial", False):
        from ..spatial.show import run_spatial

        return run_spatial(args)
    if args.c:
        if args.simplify:
            raise InputError("--simplify goes with an expression, not with --c (the "
                             "generated C is shown as it is compiled)")
        return _show_c(args)
    if args.joints > MAX_SHOW_JOINTS:
        raise InputError(
            f"symbolic inspection is limited to --joints <= {MAX_SHOW_JOINTS} (closed forms "
            "grow as n^3); use --c to read the generated code of larger models"
        )
    from snakecg_derive.inspection import expression, latex_block, names, simplified

    if args.what is None:
        if args.simplify:
            raise InputError("--simplify goes with an expression NAME")
        return _list(args.joints, names(args.joints))
    try:
        exprs = expression(args.joints, args.what)
    except ValueError as exc:
        raise InputError(str(exc)) from None
    if args.simplify:
        exprs = {label: simplified(e) for label, e in exprs.items()}
    if args.json:
        import sympy as sp

        print_json({
            "schema": SCHEMA,
            "joints": args.joints,
            "what": args.what,
            "simplified": bool(args.simplify),
            "expressions": [
                {"label": label, "text": str(e),
                 "latex": sp.latex(e, symbol_names=latex_symbol_names(e))}
                for label, e in exprs.items()
            ],
            "latex_aligned": latex_block(exprs),
        })
        return 0
    if args.latex:
        print(latex_block(exprs))
        return 0
    for label, e in exprs.items():
        print(_pretty(label, e))
        print()
    return 0


def _function_names(joints: int) -> list[str]:
    """The generated functions for ``joints``: the packaged manifest's where there is one,
    else the generator's catalog for that joint count (what its manifest will list)."""
    from ..artifacts import model_dir

    try:
        _, manifest = model_dir(joints, generate=False)
    except (ArtifactError, BuildError):  # not generated yet, or damaged: the catalog says
        from snakecg_derive.catalog import function_names

        return list(function_names(joints))
    return [f["name"] for f in manifest["functions"]]


def _list(joints: int, expression_names: list[str]) -> int:
    print(f"expressions for {joints} joints (snakecg show --joints {joints} NAME):")
    print("  " + " ".join(expression_names))
    print(f"generated functions (snakecg show --joints {joints} NAME --c):")
    print("  " + " ".join(_function_names(joints)))
    return 0


def _show_c(args) -> int:
    from ..artifacts import model_dir

    folder, manifest = model_dir(args.joints, progress=progress_reporter())
    fns = [f["name"] for f in manifest["functions"]]
    if args.what is None:
        print(f"generated functions for {args.joints} joints ({folder / 'c'}):")
        print("  " + " ".join(fns))
        return 0
    if args.what not in fns:
        raise InputError(f"unknown function {args.what!r}; choose one of: {', '.join(fns)}")
    sys.stdout.write((folder / "c" / f"{args.what}.c").read_text())
    return 0


# ------------------------------------------------------------------------------------------
# printing
# ------------------------------------------------------------------------------------------
def _unicode_ok() -> bool:
    enc = getattr(sys.stdout, "encoding", None) or "ascii"
    try:
        "⎡θ₁".encode(enc)
    except (UnicodeEncodeError, LookupError):
        return False
    return True


def _pretty(label: str, e) -> str:
    """Pretty form of ``e``; a matrix too wide for the terminal is listed entry by entry."""
    import sympy as sp

    width = shutil.get_terminal_size((100, 24)).columns
    uni = _unicode_ok()
    text = sp.pretty(e, use_unicode=uni, wrap_line=False)
    if not isinstance(e, sp.MatrixBase) or max(map(len, text.splitlines())) <= width:
        return f"{label} =\n{text}"
    rows, cols = e.shape
    symmetric = rows == cols and e == e.T
    lines = [f"{label}: {rows} x {cols} matrix"
             + (", symmetric: upper triangle" if symmetric else "")
             + ", zero entries omitted (1-based indices)"]
    entries = [(f"[{i + 1},{j + 1}] = ", e[i, j]) for i in range(rows)
               for j in range(i if symmetric else 0, cols) if e[i, j] != 0]
    bodies = [sp.pretty(x, use_unicode=uni, wrap_line=False) for _, x in entries]
    if all(len(b.splitlines()) == 1 and len(h) + len(b) <= width
           for (h, _), b in zip(entries, bodies)):
        return "\n".join(lines + [h + b for (h, _), b in zip(entries, bodies)])
    # one entry too wide (or on several lines): every entry in one style, plain one-line
    # text wrapped between terms (not pretty symbols for some and m2**2 for others)
    for head, x in entries:
        lines.extend(textwrap.wrap(sp.sstr(x), width=max(40, width), initial_indent=head,
                                   subsequent_indent=" " * len(head), break_on_hyphens=False))
    return "\n".join(lines)


def latex_symbol_names(*exprs) -> dict:
    """LaTeX names of the derivation's symbols (``snakecg_derive.inspection``'s, which the
    documentation uses too): ``beta1 -> beta_1``, ``thetad -> dot theta``, ..."""
    from snakecg_derive.inspection import latex_symbol_names as names

    return names(*exprs)
