"""CasADi ``SX`` functions of the spatial chain's straight-line programs.

The programs of :mod:`.chain` are already structured (every intermediate a small named
expression), so they are built as they stand, assignment by assignment, with no SymPy CSE
(CasADi's ``cse`` merges what is left); a ``Piecewise`` assignment (the axis frames of
:mod:`.parameters`) becomes ``if_else``. The ``_sincos`` variant takes the joint angles'
cosines and sines as inputs, for the batched drivers that compute them for a block of samples
at once.
"""

from __future__ import annotations

import casadi as ca
import sympy as sp

from ..build import to_sx
from ..spec import FunctionSpec

__all__ = ["build_spatial_function", "build_spatial_sincos", "N_BASE_COORDINATES"]

#: ``q[:7]`` is the base (position, quaternion); the joint angles follow.
N_BASE_COORDINATES = 7


def _condition(cond, env):
    if cond is sp.true or cond is True:
        return ca.SX(1)
    ops = {sp.GreaterThan: ca.ge, sp.StrictGreaterThan: ca.gt, sp.LessThan: ca.le,
           sp.StrictLessThan: ca.lt}
    for kind, op in ops.items():
        if isinstance(cond, kind):
            return op(to_sx(cond.lhs, env), to_sx(cond.rhs, env))
    raise ValueError(f"no CasADi mapping for the condition {cond}")


def _expr(expr, env):
    if isinstance(expr, sp.Piecewise):
        out = None
        for value, cond in reversed(expr.args):
            v = to_sx(value, env)
            out = v if out is None else ca.if_else(_condition(cond, env), v, out)
        return out
    return to_sx(expr, env)


def _program(f: FunctionSpec, given: dict):
    # the inputs as in snakecg_derive.build._inputs (not reused: that module's variant runs
    # SymPy's CSE first, which the structured programs do without)
    env: dict = {}
    args = []
    for name, syms, _ in f.inputs:
        x = ca.SX.sym(name, len(syms))
        args.append(x)
        for k, s in enumerate(syms):
            env[s] = x[k]
    used = False
    for sym, expr in f.assignments:
        if expr in given:
            env[sym] = given[expr]
            used = True
        else:
            env[sym] = _expr(expr, env)
    outs = []
    for _, mat, _ in f.outputs:
        col = [to_sx(mat[r, c], env) for c in range(mat.cols) for r in range(mat.rows)]
        outs.append(ca.reshape(ca.vertcat(*col), mat.rows, mat.cols) if col
                    else ca.SX(mat.rows, mat.cols))
    return args, outs, used


def build_spatial_function(f: FunctionSpec, prefix: str) -> ca.Function:
    """The ``SX`` function ``<prefix><f.name>``."""
    args, outs, _ = _program(f, {})
    return ca.Function(prefix + f.name, args, [ca.densify(o) for o in ca.cse(outs)],
                       [n for n, _, _ in f.inputs], [n for n, _, _ in f.outputs])


def build_spatial_sincos(f: FunctionSpec, prefix: str) -> ca.Function | None:
    """``<prefix><f.name>_sincos``: the same program with ``cos_q``, ``sin_q`` (of the joint
    angles ``q[7:]``) as two more inputs; ``None`` when ``f`` has no ``q``, no joint angle
    trigonometry or another trigonometric call."""
    names = [n for n, _, _ in f.inputs]
    if "q" not in names:
        return None
    angles = f.inputs[names.index("q")][1][N_BASE_COORDINATES:]
    cos_q, sin_q = ca.SX.sym("cos_q", len(angles)), ca.SX.sym("sin_q", len(angles))
    given = {}
    for k, a in enumerate(angles):
        given[sp.cos(a)], given[sp.sin(a)] = cos_q[k], sin_q[k]
    args, outs, used = _program(f, given)
    if not used:
        return None
    fn = ca.Function(prefix + f.name + "_sincos", args + [cos_q, sin_q],
                     [ca.densify(o) for o in ca.cse(outs)],
                     names + ["cos_q", "sin_q"], [n for n, _, _ in f.outputs])
    trig = {ca.OP_SIN, ca.OP_COS, ca.OP_TAN}
    if any(fn.instruction_id(k) in trig for k in range(fn.n_instructions())):
        return None
    return fn
