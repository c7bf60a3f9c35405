"""3-vectors and 3x3 matrices as tuples of SymPy expressions, every result named.

A :class:`Program` collects the assignments of one straight-line program: each operation
assigns its non-trivial components to new symbols (``<name>_<k>``), so that expressions stay
small (SymPy never expands a product of rotations) and the program keeps the recursion's
structure. Zeros and ones of known structure (the base frame's identity rotation) fold away.
Matrices are tuples of three rows.
"""

from __future__ import annotations

import sympy as sp

__all__ = ["Program", "cross", "dot", "matvec", "matTvec", "matmul", "column", "transpose",
           "identity", "ZERO3"]

ZERO3 = (sp.Integer(0),) * 3


def identity():
    one, zero = sp.Integer(1), sp.Integer(0)
    return ((one, zero, zero), (zero, one, zero), (zero, zero, one))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sp.Add(*(x * y for x, y in zip(a, b)))


def matvec(R, x):
    return tuple(dot(row, x) for row in R)


def matTvec(R, x):
    """``R^T x``."""
    return tuple(sp.Add(*(R[r][c] * x[r] for r in range(3))) for c in range(3))


def matmul(A, B):
    return tuple(tuple(sp.Add(*(A[r][k] * B[k][c] for k in range(3))) for c in range(3))
                 for r in range(3))


def transpose(A):
    return tuple(tuple(A[r][c] for r in range(3)) for c in range(3))


def column(A, c):
    return tuple(A[r][c] for r in range(3))


def _atomic(e) -> bool:
    return e.is_Symbol or e.is_Number or (e.could_extract_minus_sign() and (-e).is_Symbol)


class Program:
    """Assignments ``(symbol, expression)`` in order; names are unique."""

    def __init__(self):
        self.assignments: list[tuple[sp.Symbol, sp.Expr]] = []
        self._names: set[str] = set()

    def let(self, name: str, expr) -> sp.Expr:
        """``expr`` itself if it is a symbol or a number, else a new symbol assigned to it."""
        expr = sp.sympify(expr)
        if _atomic(expr):
            return expr
        if name in self._names:
            raise ValueError(f"assignment {name} exists already")
        self._names.add(name)
        sym = sp.Symbol(name, real=True)
        self.assignments.append((sym, expr))
        return sym

    def vec(self, name: str, v):
        return tuple(self.let(f"{name}_{a}", e) for a, e in zip("xyz", v))

    def mat(self, name: str, M):
        return tuple(tuple(self.let(f"{name}_{r}{c}", M[r][c]) for c in range(3))
                     for r in range(3))

    def sym_mat(self, name: str, M):
        """A symmetric matrix: the upper triangle named, the lower one mirrored."""
        out = [[None] * 3 for _ in range(3)]
        for r in range(3):
            for c in range(r, 3):
                out[r][c] = out[c][r] = self.let(f"{name}_{r}{c}", M[r][c])
        return tuple(tuple(row) for row in out)
