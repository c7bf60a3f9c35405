"""Print SymPy expressions as Python that builds CasADi ``SX`` expressions.

The description of the computation (:class:`~.spec.FunctionSpec`) is kept apart from this
printer, as in SymPy's ``utilities.codegen``.
"""

from __future__ import annotations

import re

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

from .spec import FunctionSpec, topological_assignments

__all__ = ["CasadiPrinter", "function_body"]

_IDENT = re.compile(r"[^0-9a-zA-Z_]")


class CasadiPrinter(PythonCodePrinter):
    """``cos(x)`` etc. resolve to CasADi's functions imported by the generated module."""

    _kf = {"sin": "sin", "cos": "cos", "tan": "tan", "sqrt": "sqrt", "exp": "exp", "log": "log"}

    def __init__(self):
        super().__init__({"standard": "python3", "fully_qualified_modules": False})

    def _print_Function(self, expr):
        name = expr.func.__name__
        if name in self._kf:
            return f"{self._kf[name]}({', '.join(self._print(a) for a in expr.args)})"
        raise ValueError(f"no CasADi mapping for function {name}")

    def _print_Pow(self, expr, rational=False):
        b, e = expr.as_base_exp()
        if e == 2:
            return f"sq({self._print(b)})"
        if e == -1:
            return f"(1/{self.parenthesize(b, 0)})"
        if e == sp.Rational(1, 2):
            return f"sqrt({self._print(b)})"
        return super()._print_Pow(expr, rational)

    def _print_Symbol(self, expr):
        return _IDENT.sub("_", expr.name)

    def _print_Rational(self, expr):
        return f"({expr.p}/{expr.q})"


def function_body(f: FunctionSpec) -> tuple[list[str], list[tuple[str, int, int, list[str]]]]:
    """Straight-line code for ``f``: ``(lines, outputs)``.

    Runs SymPy's common-subexpression elimination over the function's assignments and
    outputs together (generation time), orders everything topologically and prints each
    assignment. ``outputs`` holds ``(name, rows, cols, column-major element code)``.
    """
    printer = CasadiPrinter()
    inputs = set(f.input_symbols())
    rhs = [e for _, e in f.assignments]
    flat_outputs = []
    for _, mat, _ in f.outputs:
        flat_outputs.extend(mat[r, c] for c in range(mat.cols) for r in range(mat.rows))
    tmp = sp.numbered_symbols("cse", real=True)
    repl, reduced = sp.cse(rhs + flat_outputs, symbols=tmp, order="none")
    assigns = list(repl) + [(s, r) for (s, _), r in zip(f.assignments, reduced[: len(rhs)])]
    ordered = topological_assignments(assigns, inputs)
    lines = [f"{printer.doprint(s)} = {printer.doprint(e)}" for s, e in ordered]
    outs = []
    k = len(rhs)
    for name, mat, _ in f.outputs:
        n = mat.rows * mat.cols
        outs.append((name, mat.rows, mat.cols, [printer.doprint(e) for e in reduced[k : k + n]]))
        k += n
    return lines, outs
