"""A plain, frozen description of what to generate: functions as straight-line programs.

A :class:`FunctionSpec` is a routine in the sense of SymPy's codegen: a name, ordered named
inputs (each a tuple of symbols), ordered named outputs (SymPy matrices) and the intermediate
assignments that keep the derivation's structure (cumulative sums instead of expanded
expressions). The printer in :mod:`.render` turns it into CasADi-building Python.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass, field

import sympy as sp

__all__ = ["FunctionSpec", "ModelSpec", "topological_assignments"]


@dataclass(frozen=True)
class FunctionSpec:
    """One generated function (routine): ``outputs = f(inputs)``."""

    name: str
    doc: str
    inputs: tuple[tuple[str, tuple[sp.Symbol, ...], str], ...]
    """``(name, symbols, description)`` in argument order; each input is a column vector."""
    outputs: tuple[tuple[str, sp.Matrix, str], ...]
    """``(name, matrix, description)`` in result order."""
    assignments: tuple[tuple[sp.Symbol, sp.Expr], ...] = ()
    """Intermediate symbols, in an order where each one only uses earlier ones."""
    equation: str = ""
    """Equation number(s) in Reyes & Ma 2017 that the function implements, if any."""

    def input_symbols(self) -> tuple[sp.Symbol, ...]:
        return tuple(s for _, syms, _ in self.inputs for s in syms)

    def check_closed(self) -> None:
        """Raise if an output uses a free symbol that is neither an input nor assigned."""
        known = set(self.input_symbols())
        problems = []
        for sym, expr in self.assignments:
            missing = expr.free_symbols - known
            if missing:
                problems.append(f"assignment {sym} uses {sorted(map(str, missing))}")
            known.add(sym)
        for name, mat, _ in self.outputs:
            missing = set().union(*(e.free_symbols for e in mat)) - known if len(mat) else set()
            if missing:
                problems.append(f"output {name} uses {sorted(map(str, missing))}")
        if problems:
            raise ValueError(
                f"function {self.name!r}: free symbols belong to no input: " + "; ".join(problems)
            )

    def closed_form(self, output: str) -> sp.Matrix:
        """Output ``output`` with every intermediate substituted back (for inspection)."""
        mats = {name: mat for name, mat, _ in self.outputs}
        if output not in mats:
            raise KeyError(f"{self.name} has no output {output!r}; outputs: {list(mats)}")
        subs: dict[sp.Symbol, sp.Expr] = {}
        for sym, expr in self.assignments:
            subs[sym] = expr.xreplace(subs)
        return mats[output].xreplace(subs)


@dataclass(frozen=True)
class ModelSpec:
    """Everything generated for one joint count."""

    n_joints: int
    prefix: str
    functions: tuple[FunctionSpec, ...]
    meta: dict = field(default_factory=dict)
    """Extra facts for the manifest (operation counts of the candidate forms, ...)."""

    def function(self, name: str) -> FunctionSpec:
        for f in self.functions:
            if f.name == name:
                return f
        raise KeyError(f"no function {name!r} in the spec for n_joints={self.n_joints}")

    def digest(self) -> str:
        """SHA-256 over a canonical text of the spec (srepr of every expression); computed
        once per spec (it prints every expression)."""
        cached = self.__dict__.get("_digest")
        if cached is None:
            cached = self._compute_digest()
            object.__setattr__(self, "_digest", cached)
        return cached

    def _compute_digest(self) -> str:
        h = hashlib.sha256()
        h.update(json.dumps({"n_joints": self.n_joints, "prefix": self.prefix}).encode())
        for f in self.functions:
            h.update(f.name.encode())
            for name, syms, _ in f.inputs:
                h.update(name.encode())
                h.update(" ".join(map(str, syms)).encode())
            for sym, expr in f.assignments:
                h.update(f"{sym}={sp.srepr(expr)}".encode())
            for name, mat, _ in f.outputs:
                h.update(f"{name}{mat.shape}={sp.srepr(mat)}".encode())
        return h.hexdigest()


def topological_assignments(
    assignments: list[tuple[sp.Symbol, sp.Expr]], inputs: set[sp.Symbol]
) -> list[tuple[sp.Symbol, sp.Expr]]:
    """Order assignments so that each one follows everything it uses (stable, deterministic)."""
    defined = dict(assignments)
    order: list[tuple[sp.Symbol, sp.Expr]] = []
    done: set[sp.Symbol] = set()
    for root, _ in assignments:
        stack = [(root, False)]
        while stack:
            sym, expanded = stack.pop()
            if sym in done:
                continue
            if expanded:
                done.add(sym)
                order.append((sym, defined[sym]))
                continue
            stack.append((sym, True))
            deps = sorted(
                (s for s in defined[sym].free_symbols if s in defined and s not in done),
                key=str,
                reverse=True,
            )
            for d in deps:
                stack.append((d, False))
    return order
