"""Print SymPy expressions as Python that builds CasADi ``SX`` expressions.

The description of the computation (:class:`~.spec.FunctionSpec`) is kept apart from this
printer, as in SymPy's ``utilities.codegen``.
"""

from __future__ import annotations

import re

import sympy as sp
from sympy.printing.pycode import PythonCodePrinter

from .spec import FunctionSpec

__all__ = ["CasadiPrinter", "function_body"]

_IDENT = re.compile(r"[^0-9a-zA-Z_]")


class CasadiPrinter(PythonCodePrinter):
    """``cos(x)`` etc. resolve to CasADi's functions imported by the generated module."""

    _kf = {"sin": "sin", "cos": "cos", "tan": "tan", "sqrt": "sqrt", "exp": "exp", "log": "log"}

    def __init__(self):
        # order="none": terms in SymPy's own argument order (sorting them for print costs more
        # than the whole derivation at 20 joints)
        super().__init__({"standard": "python3", "fully_qualified_modules": False,
                          "order": "none"})

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
    """Straight-line code for ``f`` (for reading): ``(lines, outputs)``.

    The same program that :func:`.build.build_function` turns into CasADi expressions: SymPy's
    common-subexpression elimination over the assignments and outputs together, in
    topological order. ``outputs`` holds ``(name, rows, cols, column-major element code)``.
    """
    from .build import cse_program

    printer = CasadiPrinter()
    ordered, outs = cse_program(f)
    lines = [f"{printer.doprint(s)} = {printer.doprint(e)}" for s, e in ordered]
    return lines, [(name, r, c, [printer.doprint(e) for e in el]) for name, r, c, el in outs]
