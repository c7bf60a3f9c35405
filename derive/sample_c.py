"""Plain C of a CasADi ``SX`` function: its straight-line program as one static function.

CasADi's code generator writes every function for the general calling convention (any input
or output pointer may be null, checked at each read and write). The batched driver of
``mass_matrix`` calls its ``_sincos`` variant (:func:`.build.build_sincos_function`) once per
sample with every pointer set, so it uses this printing instead: the same instructions in the
same order, read from the CasADi function's own instruction list (nothing re-derived), as
``static void name(const casadi_real* restrict arg0, ..., casadi_real* restrict res0, ...)``,
which the compiler can inline into the driver's loop.
"""

from __future__ import annotations

import casadi as ca

__all__ = ["sample_function_c"]

_BINARY = {ca.OP_ADD: "+", ca.OP_SUB: "-", ca.OP_MUL: "*", ca.OP_DIV: "/"}


def _constant(x: float) -> str:
    """A C99 ``double`` literal that reads back as ``x`` (``repr`` round-trips)."""
    text = repr(float(x))
    if text in ("inf", "-inf", "nan"):
        raise ValueError(f"constant {text} has no C99 literal")
    if "." not in text and "e" not in text:
        text += ".0"
    return f"({text})" if text.startswith("-") else text


def sample_function_c(fn: ca.Function, cname: str) -> str:
    """``fn`` (an ``SX`` function) as the static C function ``cname``.

    Input ``j`` is read as ``arg<j>[k]`` (nonzero ``k``, dense column-major), output ``j``
    written as ``res<j>[k]``. Raises ``ValueError`` for an operation it does not print.
    """
    if not fn.is_a("SXFunction"):
        raise ValueError(f"{fn.name()} is not an SX function")
    body = []
    used = set()
    for k in range(fn.n_instructions()):
        op = fn.instruction_id(k)
        ins, outs = fn.instruction_input(k), fn.instruction_output(k)
        if op == ca.OP_OUTPUT:
            body.append(f"  res{outs[0]}[{outs[1]}] = w{ins[0]};")
            continue
        if op == ca.OP_INPUT:
            expr = f"arg{ins[0]}[{ins[1]}]"
        elif op == ca.OP_CONST:
            expr = _constant(fn.instruction_constant(k))
        elif op in _BINARY:
            expr = f"w{ins[0]} {_BINARY[op]} w{ins[1]}"
        elif op == ca.OP_NEG:
            expr = f"-w{ins[0]}"
        elif op == ca.OP_SQ:
            expr = f"w{ins[0]} * w{ins[0]}"
        elif op == ca.OP_TWICE:
            expr = f"w{ins[0]} + w{ins[0]}"
        else:
            raise ValueError(f"{fn.name()}: CasADi operation {op} is not printed")
        used.add(outs[0])
        body.append(f"  w{outs[0]} = {expr};")
    params = [f"const casadi_real* restrict arg{j}" for j in range(fn.n_in())]
    params += [f"casadi_real* restrict res{j}" for j in range(fn.n_out())]
    work = [f"w{w}" for w in sorted(used)]
    decl = ["  casadi_real " + ", ".join(work[s:s + 10]) + ";" for s in range(0, len(work), 10)]
    head = [f"/* {fn.name()}: {fn.n_instructions()} CasADi instructions, printed one per line */",
            f"static void {cname}("]
    lines = ["    " + p + ("," if i < len(params) - 1 else ") {") for i, p in enumerate(params)]
    return "\n".join([*head, *lines, *decl, *body, "}", ""])
