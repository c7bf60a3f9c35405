"""The linear algebra of the composed functions: unrolled (SX) or kept as matrices (MX).

:class:`Algebra` carries the symbolic type of one build and its factorizations. ``"sx"``
unrolls every LDL^T factorization and solve into scalar operations (fastest for a few joints);
``"mx"`` keeps the matrices (a linear solve is a node of CasADi's ``ldl`` solver, the pivots
come from a loop of fixed-size elimination steps), so the generated code of a composed
function grows like ``n^2`` instead of ``n^3``. Used by :mod:`.coupled`.
"""

from __future__ import annotations

from dataclasses import dataclass

import casadi as ca

__all__ = ["Algebra"]


def _ldl_unrolled(A):
    """``A = L diag(d) L^T`` of a symmetric positive definite ``SX`` matrix, no pivoting;
    ``(L, d)`` as nested lists, ``d[j]`` the j-th pivot."""
    n = A.shape[0]
    L = [[ca.SX(0)] * n for _ in range(n)]
    d = [ca.SX(0)] * n
    for j in range(n):
        s = A[j, j]
        for k in range(j):
            s = s - L[j][k] * L[j][k] * d[k]
        d[j] = s
        for i in range(j + 1, n):
            t = A[i, j]
            for k in range(j):
                t = t - L[i][k] * L[j][k] * d[k]
            L[i][j] = t / d[j]
    return L, d


def _ldl_solve_unrolled(L, d, B):
    """Solve ``(L diag(d) L^T) X = B`` column by column (``SX``)."""
    n = len(d)
    cols = []
    for c in range(B.shape[1]):
        y = [ca.SX(0)] * n
        for i in range(n):
            t = B[i, c]
            for k in range(i):
                t = t - L[i][k] * y[k]
            y[i] = t
        x = [ca.SX(0)] * n
        for i in reversed(range(n)):
            t = y[i] / d[i]
            for k in range(i + 1, n):
                t = t - L[k][i] * x[k]
            x[i] = t
        cols.append(ca.vertcat(*x))
    return ca.horzcat(*cols)


@dataclass(frozen=True)
class Algebra:
    """The symbolic type and the factorizations of one build.

    ``kind = "sx"``: everything scalar and unrolled. ``kind = "mx"``: ``MX`` matrices; a
    linear solve is a node of CasADi's ``ldl`` linear solver (a loop in the generated C) and
    the pivots of the masked Delassus matrix come from a loop over one elimination step
    (``Function.mapaccum`` of a fixed ``O(n^2)``-sized kernel), so the code of a composed
    function grows like ``n^2`` and not like ``n^3``.
    """

    kind: str
    prefix: str

    @property
    def T(self):
        return ca.SX if self.kind == "sx" else ca.MX

    def sym(self, name, rows, cols=1):
        return self.T.sym(name, rows, cols)

    def zeros(self, rows, cols=1):
        return self.T(rows, cols)

    def eye(self, n):
        return self.T.eye(n)

    def ldl(self, A, *, pivots: bool = False):
        """Factors of ``A`` for :meth:`solve`, and (``pivots``) its LDL^T pivots ``d`` as a
        column. ``MX``: the factorization is CasADi's ``ldl`` linear solver at each solve;
        the pivots come from a loop of elimination steps."""
        if self.kind == "sx":
            L, d = _ldl_unrolled(A)
            return (L, d), ca.vertcat(*d)
        if not pivots:
            return A, None
        n = A.shape[0]
        eye, below = _step_constants(n)
        _, _, d = _ldl_loop(n, self.prefix)(A, eye, below)
        return A, d.T

    def solve(self, factors, B):
        """``X`` with ``A X = B`` for the factors of ``A`` from :meth:`ldl`."""
        if self.kind == "sx":
            return _ldl_solve_unrolled(*factors, B)
        if B.shape[1] == 0:
            return self.zeros(B.shape[0], 0)
        return ca.solve(factors, B, "ldl")


def _step_constants(n):
    """``eye`` (column j = e_j) and ``below`` (column j = 1 on the rows after j)."""
    below = ca.DM(n, n)
    for j in range(n):
        for i in range(j + 1, n):
            below[i, j] = 1
    return ca.MX(ca.DM.eye(n)), ca.MX(below)


_KERNELS: dict = {}


def _ldl_loop(n: int, prefix: str) -> ca.Function:
    """Right-looking LDL^T as a loop of ``n`` elimination steps (``mapaccum``).

    Step ``j`` of ``S`` (the not yet eliminated part): pivot ``d_j = S_jj``, column
    ``l_j = S e_j / d_j`` below the diagonal, ``S <- S - d_j l_j l_j^T``. Returns the final
    ``S`` (zero), ``L`` (strictly lower; its columns are the ``l_j``) and ``d`` as a row.
    """
    key = ("ldl", n, prefix)
    if key not in _KERNELS:
        S = ca.SX.sym("S", n, n)
        e = ca.SX.sym("e", n)
        below = ca.SX.sym("below", n)
        c = ca.mtimes(S, e)
        d = ca.dot(e, c)
        l_col = below * c / d
        S_next = S - d * ca.mtimes(l_col, l_col.T)
        step = ca.Function(f"{prefix}ldl_step_{n}", [S, e, below], [S_next, l_col, d],
                           ["S", "e", "below"], ["S_next", "l", "d"])
        _KERNELS[key] = step.mapaccum(f"{prefix}ldl_{n}", n)
    return _KERNELS[key]
