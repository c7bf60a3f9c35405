"""MkDocs hook: render the symbolic pages from ``derive/`` when the site is built.

A page asks for a formula with a directive (on a line of its own, except ``versions``)::

    <!-- snakecg-symbolic: mass-matrix joints=1 form=compact -->
    <!-- snakecg-symbolic: mass-matrix-entries joints=2 -->
    <!-- snakecg-symbolic: constants joints=2 -->
    <!-- snakecg-symbolic: expression NAME joints=1 skip="Adot v" -->
    <!-- snakecg-symbolic: operation-counts -->
    <!-- snakecg-symbolic: functions-table joints=2 -->
    <!-- snakecg-symbolic: versions -->
    <!-- snakecg-symbolic: spatial-program NAME joints=1 -->
    <!-- snakecg-symbolic: spatial-functions-table joints=2 -->

and gets display math typeset from the same SymPy expressions that the code generator prints
(``snakecg_derive.kinematics.readable_mass_matrix``, ``snakecg_derive.inspection.expression``),
with the symbol names of ``snakecg show --latex``. Entries are passed through
``sympy.trigsimp`` for display only (``c sin^2 + c cos^2 -> c``); the text says so. The
operation counts are read from the checked-in ``generated/na*/manifest.json``: nothing here
is a number typed by hand. A malformed or unknown directive fails the build.
"""

from __future__ import annotations

import json
import re
import shlex
from functools import lru_cache
from pathlib import Path

from mkdocs.exceptions import PluginError

DIRECTIVE = re.compile(r"<!--\s*snakecg-symbolic:\s*(?P<body>.*?)\s*-->")

_ROOT: Path | None = None


def on_config(config):
    global _ROOT
    _ROOT = Path(config.config_file_path).resolve().parent
    return config


def on_page_markdown(markdown, page, config, files):
    if "snakecg-symbolic:" not in markdown:
        return markdown

    def replace(m: re.Match) -> str:
        try:
            return _render(m.group("body"))
        except PluginError:
            raise
        except Exception as exc:  # report which directive of which page failed
            raise PluginError(
                f"{page.file.src_uri}: directive 'snakecg-symbolic: {m.group('body')}' "
                f"failed: {type(exc).__name__}: {exc}"
            ) from exc

    return DIRECTIVE.sub(replace, markdown)


# ------------------------------------------------------------------------------------------
def _parse(body: str) -> tuple[str, list[str], dict[str, str]]:
    words = shlex.split(body)
    if not words:
        raise PluginError("empty snakecg-symbolic directive")
    kind, rest = words[0], words[1:]
    pos = [w for w in rest if "=" not in w]
    opts = dict(w.split("=", 1) for w in rest if "=" in w)
    return kind, pos, opts


def _render(body: str) -> str:
    kind, pos, opts = _parse(body)
    joints = int(opts.get("joints", "0"))
    if kind == "mass-matrix":
        return _mass_matrix(joints, opts.get("form", "compact"))
    if kind == "mass-matrix-entries":
        return _mass_matrix_entries(joints)
    if kind == "constants":
        return _constants(joints)
    if kind == "expression":
        if len(pos) != 1:
            raise PluginError(f"'expression' needs one NAME, got {pos}")
        return _expression(joints, pos[0], opts.get("skip", ""))
    if kind == "operation-counts":
        return _operation_counts()
    if kind == "functions-table":
        return _functions_table(joints)
    if kind == "versions":
        return _versions()
    if kind == "spatial-program":  # a spatial chain's structured program, as code
        if len(pos) != 1:
            raise PluginError(f"'spatial-program' needs one NAME, got {pos}")
        from snakecg_derive.spatial.inspection import program_lines

        return "```text\n" + "\n".join(program_lines(joints, pos[0])) + "\n```\n"
    if kind == "spatial-functions-table":
        return _functions_table(joints, folder=_ROOT / "generated" / "spatial" / f"na{joints}")
    raise PluginError(
        f"unknown snakecg-symbolic directive {kind!r}; known: mass-matrix, "
        "mass-matrix-entries, constants, expression, operation-counts, functions-table, "
        "versions, spatial-program, spatial-functions-table"
    )


def _latex(e) -> str:
    import sympy as sp

    from snakecg.commands.show import latex_symbol_names

    return sp.latex(e, symbol_names=latex_symbol_names(e), mat_str="bmatrix", mat_delim="")


def _display(e):
    import sympy as sp

    if isinstance(e, sp.MatrixBase):
        return e.applyfunc(sp.trigsimp)
    return sp.trigsimp(e)


def _math(tex: str) -> str:
    return f"\n$$\n{tex}\n$$\n"


@lru_cache(maxsize=None)
def _symbols(joints: int):
    from snakecg_derive.symbols import SnakeSymbols

    if joints < 1:
        raise PluginError("the directive needs joints=N with N >= 1")
    return SnakeSymbols(joints)


def _mass_matrix(joints: int, form: str) -> str:
    from snakecg_derive.kinematics import readable_mass_matrix

    if form not in ("compact", "expanded"):
        raise PluginError(f"form must be compact or expanded, got {form!r}")
    M = readable_mass_matrix(_symbols(joints), substitute=(form == "expanded"))
    return _math(r"M_s = " + _latex(M))


def _mass_matrix_entries(joints: int) -> str:
    """Upper triangle of the compact ``M_s``, one aligned line per non-zero entry."""
    from snakecg_derive.kinematics import readable_mass_matrix

    M = readable_mass_matrix(_symbols(joints), substitute=False)
    lines = []
    for i in range(M.shape[0]):
        for j in range(i, M.shape[1]):
            if M[i, j] != 0:
                lines.append(rf"M_{{{i + 1}{j + 1}}} &= {_latex(M[i, j])}")
    return _math(r"\begin{aligned}" + r" \\ ".join(lines) + r"\end{aligned}")


def _constants(joints: int) -> str:
    import sympy as sp

    from snakecg_derive.kinematics import derived_parameter_values

    values = derived_parameter_values(_symbols(joints))
    lines = [rf"{_latex(k)} &= {_latex(sp.factor_terms(v))}" for k, v in values.items()]
    return _math(r"\begin{aligned}" + r" \\ ".join(lines) + r"\end{aligned}")


def _expression(joints: int, name: str, skip: str = "") -> str:
    """The expressions of ``snakecg show --joints N NAME`` (labels in ``skip`` left out, a
    comma-separated list); a row with more than two entries is typeset as a transposed
    column, which fits the page."""
    import sympy as sp

    from snakecg_derive.inspection import expression

    skipped = {s.strip() for s in skip.split(",") if s.strip()}
    exprs = expression(joints, name)
    unknown = skipped - set(exprs)
    if unknown:
        raise PluginError(f"skip names no expression of {name!r}: {sorted(unknown)}; "
                          f"labels: {list(exprs)}")
    out = []
    for label, e in exprs.items():
        if label in skipped:
            continue
        e = _display(e)
        if isinstance(e, sp.MatrixBase) and e.rows == 1 and e.cols > 2:
            tex = _latex(e.T) + r"^{\mathsf{T}}"
        else:
            tex = _latex(e)
        out.append(f"`{label}`:\n" + _math(tex))
    return "\n".join(out)


def _operation_counts() -> str:
    """Table of CasADi operation counts per generated function, from the manifests."""
    root = _ROOT / "generated"
    manifests = {}
    for p in root.glob("na*/manifest.json"):
        m = re.fullmatch(r"na(\d+)", p.parent.name)
        if m:
            manifests[int(m[1])] = json.loads(p.read_text(encoding="utf-8"))
    if not manifests:
        raise PluginError(f"no generated/na*/manifest.json under {root}")
    counts = sorted(manifests)
    first = manifests[counts[0]]
    names = []  # every function of any joint count, in manifest order (some exist only for
    for n in counts:  # small n_a, e.g. the closed-form metric_extremes for n_a <= 3)
        names += [f["name"] for f in manifests[n]["functions"] if f["name"] not in names]
    del first
    head = "| function | " + " | ".join(f"$n_a = {n}$" for n in counts) + " |"
    sep = "|---|" + "---:|" * len(counts)
    rows = []
    for name in names:
        cells = []
        for n in counts:
            fn = {f["name"]: f for f in manifests[n]["functions"]}.get(name)
            if fn is None:
                cells.append("–")
                continue
            cell = f"{fn['operations']:,}"
            cells.append(f"**{cell}**" if fn.get("large") else cell)
        rows.append(f"| `{name}` | " + " | ".join(cells) + " |")
    sympy_rows = []
    for form in ("structured", "suffix_sums", "closed"):
        cells = []
        for n in counts:
            v = manifests[n].get("mass_matrix_operation_counts_casadi", {}).get(form)
            cells.append(f"{v:,}" if isinstance(v, int) else "–")
        sympy_rows.append(f"| $M_s$, {form} form (CasADi operations) | "
                          + " | ".join(cells) + " |")
    chosen = "| form generated for `mass_matrix` | " + " | ".join(
        manifests[n]["mass_matrix_form"] for n in counts) + " |"
    return "\n".join([head, sep, *rows]) + "\n\n" + "\n".join(
        ["| mass matrix forms | " + " | ".join(f"$n_a = {n}$" for n in counts) + " |", sep,
         *sympy_rows, chosen]) + "\n"


def _versions() -> str:
    import sympy

    return f"SymPy {sympy.__version__}"


def _functions_table(joints: int, folder: Path | None = None) -> str:
    """The generated functions of ``generated/na<N>/`` (or ``folder``): name, arguments and
    the first paragraph of the function's docstring, all read from its manifest (so the table
    cannot drift from what was generated)."""
    folder = folder or _ROOT / "generated" / f"na{joints}"
    manifest = json.loads((folder / "manifest.json").read_text(encoding="utf-8"))
    rows = ["| function | inputs → outputs | what it computes |", "|---|---|---|"]
    for f in manifest["functions"]:
        first = re.sub(r"\s*Reyes & Ma 2017, eq\..*$", "", f.get("doc", "")).strip()
        if not first:
            raise PluginError(f"{folder / 'manifest.json'}: {f['name']} has no description")
        ins = ", ".join(i["name"] for i in f["inputs"])
        outs = ", ".join(o["name"] for o in f["outputs"])
        rows.append(f"| `{f['name']}` | {ins} → {outs} | {_escape_cell(first)} |")
    return "\n".join(rows) + "\n"


def _escape_cell(text: str) -> str:
    return text.replace("|", "\\|")
