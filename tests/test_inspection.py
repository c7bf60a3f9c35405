"""Symbolic inspection (snakecg_derive.inspection) and ``snakecg show --latex/--simplify``:
paper-ready LaTeX and substitution by name.

References: SymPy's own LaTeX of each whole entry (the block's lines, put back together, must
be it: nothing lost, nothing reordered); the entries evaluated numerically at random points
before and after ``--simplify``; ``math.sin`` for a substituted row; and, where a LaTeX
installation is present, pdflatex itself (A4, 10 pt: no overfull line, one page). The block's
longest line and its structure are checked in every case.
"""

from __future__ import annotations

import io
import json
import math
import re
import shutil
import subprocess
from contextlib import redirect_stdout

import numpy as np
import pytest

sp = pytest.importorskip("sympy")

from snakecg_derive.inspection import (  # noqa: E402
    LATEX_WIDTH,
    expression,
    latex_block,
    latex_symbol_names,
    simplified,
    substitute,
)

#: A line of the block may pass LATEX_WIDTH by one term it does not cut.
LONGEST = LATEX_WIDTH + 25


def _structure(block: str, longest: int = LONGEST) -> list[str]:
    """The block's lines, checked: one aligned environment, no blank line, every equation
    line but the last ends the row, each line closes what it opens, none longer than
    ``longest`` characters."""
    lines = block.splitlines()
    assert lines[0] == r"\begin{aligned}" and lines[-1] == r"\end{aligned}"
    assert block.count(r"\begin{aligned}") == 1 and "\n\n" not in block
    eq = [ln for ln in lines[1:-1] if not ln.startswith("%")]
    assert all(ln.endswith(r" \\") for ln in eq[:-1]) and not eq[-1].endswith(r"\\")
    for ln in eq:
        assert ln.count("{") == ln.count("}"), ln
        assert ln.count(r"\left") == ln.count(r"\right"), ln  # never split inside \left..\right
        assert ln.count("&") == 1, ln
    assert max(map(len, lines)) <= longest
    return lines


def _entries(block: str) -> dict[str, str]:
    """``{lhs: rhs}`` with the layout taken out (continuation lines joined, the big
    brackets back to \\left( \\right)), without whitespace."""
    out, key = {}, None
    for ln in block.splitlines()[1:-1]:
        if ln.startswith("%"):
            continue
        ln = ln.removesuffix(r" \\")
        lhs, _, rhs = ln.partition("&")
        if lhs.strip():
            key = lhs.strip()
            out[key] = rhs.removeprefix("=")
        else:
            out[key] += re.sub(r"^(\\quad)+", "", rhs)
    norm = {r"\Bigl(": r"\left(", r"\Bigr)": r"\right)", r"\bigl(": r"\left(",
            r"\bigr)": r"\right)"}
    for k, v in out.items():
        for a, b in norm.items():
            v = v.replace(a, b)
        out[k] = re.sub(r"\s+", "", v)
    return out


@pytest.mark.parametrize("joints, name, simplify", [(2, "M", False), (2, "M", True),
                                                    (2, "h", True), (2, "contact", False)])
def test_the_block_is_every_entry_as_sympy_prints_it(joints, name, simplify):
    """(the raw link-level contact row nests sums four deep: its lines may be longer)"""
    exprs = expression(joints, name)
    block = latex_block(exprs, simplify=simplify)
    _structure(block, 2 * LONGEST if name == "contact" else LONGEST)
    got = _entries(block)
    names = latex_symbol_names(*exprs.values())
    want = {}
    for label, e in exprs.items():
        e = simplified(e) if simplify else e
        if isinstance(e, sp.MatrixBase):
            rows, cols = e.shape
            sym = rows == cols and e == e.T
            for i in range(rows):
                for j in range(i if sym else 0, cols):
                    if e[i, j] != 0:
                        want[(label, i, j)] = re.sub(r"\s+", "", sp.latex(e[i, j],
                                                                          symbol_names=names))
        else:
            want[(label, 0, 0)] = re.sub(r"\s+", "", sp.latex(e, symbol_names=names))
    assert sorted(got.values()) == sorted(want.values())


def test_the_two_joint_mass_matrix_fits_an_a4_page(tmp_path):
    """One line per entry of the upper triangle (M_{ij}), none wider than a page; with
    pdflatex present it is typeset on A4 at 10 pt: no overfull line, one page."""
    block = latex_block(expression(2, "M"))
    lines = _structure(block)
    M = expression(2, "M")["M_s (eq. 4)"]
    heads = [ln.split("&")[0].strip() for ln in lines if re.match(r"M_\{\d\d\} &=", ln)]
    assert heads == [f"M_{{{i + 1}{j + 1}}}" for i in range(5) for j in range(i, 5)
                     if M[i, j] != 0]
    if shutil.which("pdflatex") is None:
        return  # the measurement above is the check on a machine without LaTeX
    tex = tmp_path / "m.tex"
    tex.write_text("\\documentclass[a4paper,10pt]{article}\\usepackage{amsmath}\n"
                   "\\begin{document}\n\\begin{equation*}\n" + block
                   + "\n\\end{equation*}\n\\end{document}\n")
    res = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                          tex.name], cwd=tmp_path, capture_output=True, text=True,
                         timeout=120, check=False)
    log = (tmp_path / "m.log").read_text(errors="replace")
    assert res.returncode == 0, log[-2000:]
    assert "Overfull \\hbox" not in log and "Output written on m.pdf (1 page" in log


def test_simplify_removes_sin2_plus_cos2_and_keeps_the_values(rng):
    M = expression(2, "M_expanded")["M_s = sum_i J_i^T diag(m_i, m_i, I_i) J_i (eq. 4)"]
    S = simplified(M)

    def sq_pairs(x):
        pw = [a for a in x.atoms(sp.Pow) if a.exp == 2 and isinstance(a.base, (sp.sin,
                                                                                 sp.cos))]
        args = [(type(a.base), a.base.args[0]) for a in pw]
        return {arg for f, arg in args if (sp.sin, arg) in args and (sp.cos, arg) in args}

    assert any(sq_pairs(M[i, j]) for i in range(5) for j in range(5))  # c sin^2 + c cos^2
    assert not any(sq_pairs(S[i, j]) for i in range(5) for j in range(5))
    assert sp.count_ops(S) < sp.count_ops(M)
    syms = sorted(M.free_symbols, key=lambda s: s.name)
    f, g = sp.lambdify(syms, M, "numpy"), sp.lambdify(syms, S, "numpy")
    for _ in range(3):
        x = rng.uniform(0.1, 2.0, len(syms))
        np.testing.assert_allclose(g(*x), f(*x), rtol=1e-12, atol=1e-12)


def test_plain_symbols_and_names_substitute_and_unknown_ones_are_refused():
    A_w = expression(2, "wheel2")["A row, wheel on link 2"]
    plain_q1 = sp.Symbol("q1")                     # no assumptions: another symbol to SymPy
    assert A_w.subs(plain_q1, 0.3) == A_w          # what silently happened before
    row = substitute(A_w, {plain_q1: 0.3, "theta": 0.1})
    assert float(row[0]) == pytest.approx(-math.sin(0.4), rel=1e-15)
    with pytest.raises(ValueError, match=r"q7 is not a symbol of this expression; its "
                                         r"symbols: .*q1.*theta"):
        substitute(A_w, {"q7": 0.0})


def _show(argv):
    from snakecg.cli import main

    buf = io.StringIO()
    with redirect_stdout(buf):
        code = main(["show", *argv])
    return code, buf.getvalue()


def test_cli_latex_is_one_block_and_json_carries_it():
    code, out = _show(["--joints", "2", "contact1", "--latex"])
    assert code == 0
    block = out.rstrip("\n")
    _structure(block)  # two parts, one environment, no blank line between them
    assert "% -J_s row, contact on link 1 (eq. 10)" in block and "% G^T row (eq. 9)" in block
    code, out = _show(["--joints", "2", "contact1", "--json", "--simplify"])
    data = json.loads(out)
    assert code == 0 and data["simplified"] is True
    assert data["latex_aligned"] == latex_block(
        {k: simplified(v) for k, v in expression(2, "contact1").items()})
    code, _ = _show(["--joints", "1", "mass_matrix", "--c", "--simplify"])
    assert code == 2
