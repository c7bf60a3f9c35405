"""Symbolic inspection of the spatial chain, by name (``snakecg show --spatial``, the docs).

Names: every generated function; each gives its structured program (every named intermediate
and the outputs: the straight-line code the C evaluates). The closed form of :mod:`.closed`
is not offered: with symbolic axes, placements and inertias even one joint's ``M`` prints as
tens of thousands of characters (it is a check of the structured form in the tests).
"""

from __future__ import annotations

import sympy as sp

from .catalog import SPATIAL_CONTACT_FUNCTIONS, SPATIAL_FUNCTIONS

__all__ = ["spatial_names", "spatial_expression", "program_lines"]


def spatial_names(n_joints: int) -> list[str]:
    return list(SPATIAL_FUNCTIONS)


def _spec(n_joints: int, name: str):
    from .model import derive_spatial_model

    return derive_spatial_model(n_joints + 1).spec.function(name)


def spatial_expression(n_joints: int, what: str) -> dict:
    """``{label: expression}`` for ``what`` (see the module doc)."""
    if what in SPATIAL_CONTACT_FUNCTIONS:
        raise ValueError(f"{what} is composed in CasADi from the functions above and has no "
                         f"SymPy program; its C: snakecg show --spatial --joints {n_joints} "
                         f"--c {what}")
    if what not in SPATIAL_FUNCTIONS:
        raise ValueError(f"unknown name {what!r}; choose one of: "
                         f"{', '.join(spatial_names(n_joints))}")
    f = _spec(n_joints, what)
    out: dict = {str(sym): expr for sym, expr in f.assignments}
    out.update({f"{what}: {name}": mat for name, mat, _ in f.outputs})
    return out


def program_lines(n_joints: int, what: str) -> list[str]:
    """The structured program of function ``what`` as plain lines ``name = expression``."""
    f = _spec(n_joints, what)
    lines = [f"{sym} = {sp.sstr(expr)}" for sym, expr in f.assignments]
    for name, mat, _ in f.outputs:
        for r in range(mat.rows):
            for c in range(mat.cols):
                if mat[r, c] != 0:
                    lines.append(f"{name}[{r},{c}] = {sp.sstr(mat[r, c])}")
    return lines
