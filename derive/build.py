"""Build CasADi functions directly from the derivation (generation time, no rendered code run).

A :class:`~.spec.FunctionSpec` (SymPy assignments and outputs) becomes a CasADi ``SX``
function by walking the expressions after SymPy's common-subexpression elimination: the same
straight-line program that :func:`.printer.function_body` prints for reading, built here as
CasADi expressions. Signatures (names, shapes, order of inputs and outputs) are read back from
the CasADi functions themselves (:func:`signature`).
"""

from __future__ import annotations

import casadi as ca
import sympy as sp

from .spec import FunctionSpec, topological_assignments

__all__ = ["cse_program", "build_function", "build_sincos_function", "build_rotation_function",
           "to_sx", "signature", "operation_count"]

_UNARY = {"sin": ca.sin, "cos": ca.cos, "tan": ca.tan, "sqrt": ca.sqrt, "exp": ca.exp,
          "log": ca.log}


def cse_program(f: FunctionSpec):
    """``(assignments, outputs)`` of ``f`` after SymPy's CSE over assignments and outputs
    together, assignments in topological order; ``outputs`` holds
    ``(name, rows, cols, column-major expressions)``. Computed once per routine (building
    and printing share it)."""
    cached = f.__dict__.get("_cse_program")
    if cached is not None:
        return cached
    inputs = set(f.input_symbols())
    rhs = [e for _, e in f.assignments]
    flat = []
    for _, mat, _ in f.outputs:
        flat.extend(mat[r, c] for c in range(mat.cols) for r in range(mat.rows))
    tmp = sp.numbered_symbols("cse", real=True)
    repl, reduced = sp.cse(rhs + flat, symbols=tmp, order="none")
    assigns = list(repl) + [(s, r) for (s, _), r in zip(f.assignments, reduced[: len(rhs)])]
    ordered = topological_assignments(assigns, inputs)
    outs = []
    k = len(rhs)
    for name, mat, _ in f.outputs:
        n = mat.rows * mat.cols
        outs.append((name, mat.rows, mat.cols, list(reduced[k: k + n])))
        k += n
    object.__setattr__(f, "_cse_program", (ordered, outs))
    return ordered, outs


def to_sx(expr: sp.Expr, env: dict):
    """CasADi ``SX`` of a SymPy expression whose symbols are keys of ``env`` (memoized in it:
    a subexpression met twice is built once)."""
    hit = env.get(expr)
    if hit is not None:
        return hit
    if expr.is_Symbol:
        raise KeyError(f"symbol {expr} is neither an input nor an assignment")
    if expr.is_Integer:
        out = ca.SX(int(expr))
    elif expr.is_Float:
        out = ca.SX(float(expr))
    elif expr.is_Rational:
        out = ca.SX(expr.p) / expr.q
    elif expr.is_Add:
        # a term -x is subtracted (one operation, not a negation and an addition)
        terms = []
        for a in expr.args:
            coeff, rest = a.as_coeff_Mul()
            terms.append((True, rest) if coeff == -1 else (False, a))
        terms.sort(key=lambda t: t[0])  # stable: positive terms first, order kept
        out = None
        for negative, a in terms:
            x = to_sx(a, env)
            if out is None:
                out = -x if negative else x
            else:
                out = out - x if negative else out + x
    elif expr.is_Mul:
        coeff, rest = expr.as_coeff_Mul()
        if coeff == -1:
            out = -to_sx(rest, env)
        else:
            args = [to_sx(a, env) for a in expr.args]
            out = args[0]
            for a in args[1:]:
                out = out * a
    elif expr.is_Pow:
        b, e = expr.as_base_exp()
        base = to_sx(b, env)
        if e == 2:
            out = base**2  # CasADi emits OP_SQ
        elif e == -1:
            out = 1 / base
        elif e == sp.Rational(1, 2):
            out = ca.sqrt(base)
        elif e.is_Integer:
            out = base ** int(e)
        else:
            out = base ** to_sx(e, env)
    elif isinstance(expr, sp.Function) and expr.func.__name__ in _UNARY:
        (arg,) = expr.args
        out = _UNARY[expr.func.__name__](to_sx(arg, env))
    else:
        raise ValueError(f"no CasADi mapping for {type(expr).__name__}: {expr}")
    env[expr] = out
    return out


def _inputs(f: FunctionSpec):
    """The ``SX`` inputs of ``f`` and the map from its SymPy symbols to their entries."""
    env: dict = {}
    args = []
    for name, syms, _ in f.inputs:
        x = ca.SX.sym(name, len(syms))
        args.append(x)
        for k, s in enumerate(syms):
            env[s] = x[k]
    return args, env


def _outputs(f: FunctionSpec, env: dict, given: dict) -> tuple[list, bool]:
    """``f``'s outputs as ``SX`` matrices, its CSE program's assignments built in order, an
    assignment whose expression is a key of ``given`` taken from there instead; and whether
    one was."""
    ordered, outs = cse_program(f)
    used = False
    for sym, expr in ordered:
        if expr in given:
            env[sym] = given[expr]
            used = True
        else:
            env[sym] = to_sx(expr, env)
    results = []
    for _, rows, cols, elements in outs:
        col = ca.vertcat(*[to_sx(e, env) for e in elements]) if elements else ca.SX(0, 1)
        results.append(ca.reshape(col, rows, cols))
    return results, used


def build_function(f: FunctionSpec, prefix: str) -> ca.Function:
    """The CasADi ``SX`` function ``<prefix><f.name>`` of a derived routine."""
    args, env = _inputs(f)
    results, _ = _outputs(f, env, {})
    return ca.Function(prefix + f.name, args, [ca.densify(o) for o in ca.cse(results)],
                       [n for n, _, _ in f.inputs], [n for n, _, _ in f.outputs])


def _trig_given_function(f: FunctionSpec, name: str, angles, cos_name: str, sin_name: str):
    """The program of :func:`build_function` as the function ``name``, with the cosine and
    sine of each angle in ``angles`` (input symbols of ``f``) given as two more inputs,
    ``cos_name`` and ``sin_name``, instead of computed. Returns the function, whether one
    was given, and whether it still computes a trigonometric function."""
    args, env = _inputs(f)
    cos_a = ca.SX.sym(cos_name, len(angles))
    sin_a = ca.SX.sym(sin_name, len(angles))
    given = {}
    for k, a in enumerate(angles):
        given[sp.cos(a)] = cos_a[k]
        given[sp.sin(a)] = sin_a[k]
    results, used = _outputs(f, env, given)
    fn = ca.Function(name, args + [cos_a, sin_a], [ca.densify(o) for o in ca.cse(results)],
                     [n for n, _, _ in f.inputs] + [cos_name, sin_name],
                     [n for n, _, _ in f.outputs])
    trig = {ca.OP_SIN, ca.OP_COS, ca.OP_TAN}
    left = any(fn.instruction_id(k) in trig for k in range(fn.n_instructions()))
    return fn, used, left


def build_sincos_function(f: FunctionSpec, prefix: str) -> ca.Function | None:
    """``<prefix><f.name>_sincos``: the program of :func:`build_function` with the cosines and
    sines of the rotational coordinates given as two more inputs, ``cos_q`` and ``sin_q``
    (``cos``/``sin`` of ``q[2:]``), instead of computed; ``None`` when ``f`` has no input ``q``
    or computes another trigonometric function.

    The batched driver computes those for a whole block of samples at once (vectorized, see
    ``derive/templates/batch.c.j2``) and calls this per sample: same arithmetic otherwise.
    """
    names = [name for name, _, _ in f.inputs]
    if "q" not in names:
        return None
    angles = list(f.inputs[names.index("q")][1][2:])
    fn, used, left = _trig_given_function(f, prefix + f.name + "_sincos", angles, "cos_q",
                                          "sin_q")
    return fn if used and not left else None


def build_rotation_function(f: FunctionSpec, prefix: str, angles) -> ca.Function:
    """``<prefix><f.name>_rotation``: the program of :func:`build_function` with the cosine and
    sine of each angle in ``angles`` (input symbols of ``f``) given as two more inputs,
    ``cos_angles`` and ``sin_angles``, instead of computed.

    For composition only (never emitted on its own): the composed functions give a link's
    rotation as a product of its joints' rotations, so a row on that link needs no sine or
    cosine of its own. Raises if ``f`` still computes a trigonometric function.
    """
    fn, _, left = _trig_given_function(f, prefix + f.name + "_rotation", list(angles),
                                       "cos_angles", "sin_angles")
    if left:
        raise ValueError(f"{f.name}: a sine or cosine of an angle other than {angles} is left")
    return fn


def operation_count(fn: ca.Function) -> int | None:
    """Arithmetic operations of a CasADi ``SX`` function (inputs, outputs, constants
    excluded); ``None`` for an ``MX`` function (its loops are not straight-line code)."""
    if not fn.is_a("SXFunction"):
        return None
    skip = {ca.OP_INPUT, ca.OP_OUTPUT, ca.OP_CONST, ca.OP_PARAMETER}
    return sum(1 for k in range(fn.n_instructions()) if fn.instruction_id(k) not in skip)


def signature(fn: ca.Function, prefix: str) -> dict:
    """Name, symbol and the ordered inputs and outputs (name, rows, cols) of ``fn``."""
    return {
        "name": fn.name()[len(prefix):],
        "symbol": fn.name(),
        "inputs": [{"name": fn.name_in(k), "rows": fn.size1_in(k), "cols": fn.size2_in(k)}
                   for k in range(fn.n_in())],
        "outputs": [{"name": fn.name_out(k), "rows": fn.size1_out(k), "cols": fn.size2_out(k)}
                    for k in range(fn.n_out())],
    }
