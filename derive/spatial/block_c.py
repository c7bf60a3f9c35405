"""C of a CasADi ``SX`` function over a block of samples at once (SIMD across samples).

The straight-line program of one sample becomes the body of a loop over ``B`` samples whose
inputs and outputs are laid out sample-innermost (entry ``e`` of sample ``s`` at
``[e * B + s]``): the loop has no calls and no branches, so the compiler turns it into vector
instructions that evaluate several samples per instruction (a second copy for processors with
AVX2 is chosen at load time). Inputs listed as broadcast are read once (``[e]``), for every
sample. The same instructions in the same order as CasADi's own (read from its instruction
list, nothing re-derived), as :func:`snakecg_derive.sample_c.sample_function_c` prints them for
one sample.
"""

from __future__ import annotations

import casadi as ca

# The instruction printing below follows snakecg_derive.sample_c's line for line (with the
# block's indexing); it is not shared by a change there because every planar model's build
# hash covers derive/*.py, and the planar models stay byte for byte as they are.
from ..sample_c import _BINARY, _constant

__all__ = ["block_function_c", "BLOCK"]

#: Samples per block: 16 (the sines and cosines come in blocks of 16 too).
BLOCK = 16


def block_function_c(fn: ca.Function, cname: str, broadcast: set[int]) -> str:
    """``fn`` as ``static void cname(const casadi_real* restrict arg0, ...,
    casadi_real* restrict res0, ...)`` over :data:`BLOCK` samples, inputs and outputs
    sample-innermost (entry ``e`` of sample ``s`` at ``[e * BLOCK + s]``); the inputs in
    ``broadcast`` (indices) are shared by every sample (``[e]``)."""
    if not fn.is_a("SXFunction"):
        raise ValueError(f"{fn.name()} is not an SX function")
    B = BLOCK
    body, declared = [], set()
    for k in range(fn.n_instructions()):
        op = fn.instruction_id(k)
        ins, outs = fn.instruction_input(k), fn.instruction_output(k)
        if op == ca.OP_OUTPUT:
            body.append(f"    res{outs[0]}[{outs[1] * B} + s] = w{ins[0]};")
            continue
        if op == ca.OP_INPUT:
            expr = (f"arg{ins[0]}[{ins[1]}]" if ins[0] in broadcast
                    else f"arg{ins[0]}[{ins[1] * B} + s]")
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
        w = f"w{outs[0]}"
        body.append(f"    {w} = {expr};" if w in declared else f"    casadi_real {w} = {expr};")
        declared.add(w)
    params = [f"const casadi_real* restrict arg{j}" for j in range(fn.n_in())]
    params += [f"casadi_real* restrict res{j}" for j in range(fn.n_out())]
    head = [f"/* {fn.name()} over {B} samples: {fn.n_instructions()} CasADi instructions, one "
            "per line, in a loop the compiler vectorizes across the samples */",
            "#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 11 "
            "&& defined(__x86_64__) \\\n    && defined(__linux__)",
            "/* a second copy for processors with AVX2 and FMA, chosen at load time */",
            '__attribute__((target_clones("arch=x86-64-v3", "default")))',
            "#endif",
            f"static void {cname}("]
    lines = ["    " + p + ("," if i < len(params) - 1 else ") {") for i, p in enumerate(params)]
    return "\n".join([*head, *lines, "  int s;", f"  for (s = 0; s < {B}; ++s) {{", *body,
                      "  }", "}", ""])
