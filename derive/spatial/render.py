"""Render a spatial model into files: the readable record, CasADi's C with batched drivers,
CasADi's serialization and a manifest with hashes; written atomically into ``<out>/na<N>/``.

The same steps and conventions as the planar models (:mod:`snakecg_derive.render`): nothing
written carries a timestamp, every file says it is generated and names the one regenerate
command, and the manifest lists every file's SHA-256.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import casadi as ca
import jinja2

from ..build import operation_count, signature
from ..printer import CasadiPrinter
from ..render import (LARGE_FUNCTION_OPERATIONS, RenderedModel, _env, comment_text,
                      first_paragraph, tool_versions, write_model)
from ..sample_c import sample_function_c
from .block_c import BLOCK, block_function_c
from .build import N_BASE_COORDINATES, build_spatial_function, build_spatial_sincos
from .catalog import CHECKED_IN_SPATIAL_JOINTS, SPATIAL_FUNCTIONS, spatial_dirname
from .contact import CONTACT_DOCS, contact_functions
from .model import derive_spatial_model
from .symbols import MAX_SPATIAL_LINKS

__all__ = ["render_spatial_model", "write_spatial_model", "spatial_build_hash",
           "SPATIAL_MANIFEST_FORMAT", "REGENERATE_SPATIAL", "CHECKED_IN_SPATIAL_JOINTS"]

SPATIAL_MANIFEST_FORMAT = 1
#: The one regenerate command printed in every generated header.
REGENERATE_SPATIAL = "python -m snakecg_derive.spatial --checked-in"
_HERE = Path(__file__).parent
_DERIVE = _HERE.parent


def _sources_digest() -> str:
    """Hash of what the spatial generator's output depends on: its own sources and template,
    the shared expression builder, C printer and batch template."""
    h = hashlib.sha256()
    files = (sorted(_HERE.glob("*.py")) + sorted((_HERE / "templates").glob("*.j2"))
             + [_DERIVE / "build.py", _DERIVE / "sample_c.py", _DERIVE / "spec.py",
                _DERIVE / "templates" / "batch.c.j2"])
    for p in files:
        h.update(p.name.encode())
        h.update(p.read_bytes())
    return h.hexdigest()


def spatial_build_hash(spec) -> str:
    h = hashlib.sha256()
    h.update(spec.digest().encode())
    h.update(_sources_digest().encode())
    h.update(json.dumps(tool_versions(), sort_keys=True).encode())
    h.update(f"spatial-{SPATIAL_MANIFEST_FORMAT}".encode())
    return h.hexdigest()


class _Printer(CasadiPrinter):
    def _print_Piecewise(self, expr):
        (a, cond), (b, _) = expr.args
        return f"if_else({self._print(cond)}, {self._print(a)}, {self._print(b)})"


def _record_env() -> jinja2.Environment:
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(_HERE / "templates")),
                             undefined=jinja2.StrictUndefined, keep_trailing_newline=True,
                             trim_blocks=True, lstrip_blocks=True)
    env.filters["comment"] = comment_text
    env.filters["pystr"] = repr
    return env


def render_record(spec, functions) -> str:
    """``model.py``: every function's signature and its straight-line program (never run)."""
    pr = _Printer()
    ctx = []
    for f, fn in zip(spec.functions, functions):
        sig = signature(fn, spec.prefix)
        ctx.append({
            **sig, "doc": f.doc,
            "input_names": [i["name"] for i in sig["inputs"]],
            "output_names": [o["name"] for o in sig["outputs"]],
            "input_docs": [d for _, _, d in f.inputs],
            "input_symbols": [[str(s) for s in syms] for _, syms, _ in f.inputs],
            "output_docs": [d for _, _, d in f.outputs],
            "lines": [f"{pr.doprint(s)} = {pr.doprint(e)}" for s, e in f.assignments],
            "output_elements": [[pr.doprint(m[r, c]) for c in range(m.cols) for r in range(m.rows)]
                                for _, m, _ in f.outputs],
        })
    versions = tool_versions()
    return _record_env().get_template("record.py.j2").render(
        n_links=spec.meta["n_links"], n_joints=spec.n_joints, nq=spec.meta["nq"],
        nv=spec.meta["nv"], n_parameters=spec.meta["n_parameters"], prefix=spec.prefix,
        spec_hash=spec.digest(), tools=", ".join(f"{k} {v}" for k, v in versions.items()),
        regenerate=REGENERATE_SPATIAL, functions=ctx)


def _signature(fn, prefix: str, doc: str) -> dict:
    ops = operation_count(fn)
    return {**signature(fn, prefix), "doc": first_paragraph(doc), "n_in": fn.n_in(),
            "n_out": fn.n_out(), "nnz_out": [fn.nnz_out(k) for k in range(fn.n_out())],
            "sz_arg": fn.sz_arg(), "sz_res": fn.sz_res(), "sz_iw": fn.sz_iw(),
            "sz_w": fn.sz_w(), "algebra": "sx", "operations": ops,
            "large": ops is not None and ops > LARGE_FUNCTION_OPERATIONS}


#: Functions whose batched driver evaluates blocks of samples with vector instructions
#: (:mod:`.block_c`): the dynamics the engine calls for every sample.
BLOCK_BATCHED = ("mass_matrix", "bias_forces")
#: Symmetric outputs whose block kernel computes the upper triangle only.
SYMMETRIC_OUTPUTS = {"mass_matrix": "M"}


def _block_driver(spec, sig, variant, sincos) -> str:
    """The block driver of ``sig``'s function (``<prefix>batch_<name>``) and its kernel.

    A symmetric output (:data:`SYMMETRIC_OUTPUTS`) leaves the kernel as its upper triangle
    (half the stores), and the scatter writes each entry from its place there."""
    names = [i["name"] for i in sig["inputs"]]
    broadcast = [names.index("K")]
    sizes = [i["rows"] * i["cols"] for i in sig["inputs"]]
    kernel_fn, triangle, entry = variant, "", []
    out_names = [o["name"] for o in sig["outputs"]]
    kernel_nnz = list(sig["nnz_out"])
    sym = SYMMETRIC_OUTPUTS.get(sig["name"])
    if sym is not None:
        k = out_names.index(sym)
        n = sig["outputs"][k]["rows"]
        upper = [(r, c) for c in range(n) for r in range(c + 1)]
        where = {rc: t for t, rc in enumerate(upper)}
        entry = [where[(min(r, c), max(r, c))] for c in range(n) for r in range(n)]
        args = [ca.SX.sym(variant.name_in(i), variant.sparsity_in(i))
                for i in range(variant.n_in())]
        outs = variant.call(args)
        outs[k] = ca.vertcat(*[outs[k][r, c] for r, c in upper])
        kernel_fn = ca.Function(variant.name(), args, outs, variant.name_in(),
                                variant.name_out())
        triangle, kernel_nnz[k] = sym, len(upper)
    work = BLOCK * (2 * sincos["n"] + sum(s for k, s in enumerate(sizes) if k not in broadcast)
                    + sum(kernel_nnz))
    # the gather copies only what is read: the kernel's input entries and the joint angles
    read = {k: set() for k in range(len(sizes)) if k not in broadcast}
    read[names.index("q")].update(range(N_BASE_COORDINATES, N_BASE_COORDINATES + sincos["n"]))
    for t in range(kernel_fn.n_instructions()):
        if kernel_fn.instruction_id(t) == ca.OP_INPUT:
            k, e = kernel_fn.instruction_input(t)[:2]
            if k in read:
                read[k].add(e)
    gather = {k: _runs(sorted(entries)) for k, entries in read.items()}
    symbol = variant.name() + "_block"
    ctx = {**sig, "broadcast": broadcast, "in_sizes": sizes, "q": names.index("q"),
           "gather": gather,
           "block_symbol": symbol, "block_work": work, "kernel_nnz": kernel_nnz,
           "triangle": triangle, "entry": entry,
           "triangle_index": out_names.index(triangle) if triangle else -1,
           "block_code": block_function_c(kernel_fn, symbol, set(broadcast))}
    return _record_env().get_template("block.c.j2").render(
        prefix=spec.prefix, f=ctx, B=BLOCK, na=sincos["n"], offset=N_BASE_COORDINATES,
        broadcast_names=", ".join(names[k] for k in broadcast))


def _runs(entries: list[int]) -> list[tuple[int, int]]:
    """Sorted entries as half-open runs of consecutive ones: [1, 2, 3, 7] -> [(1, 4), (7, 8)]."""
    runs: list[list[int]] = []
    for e in entries:
        if runs and runs[-1][1] == e:
            runs[-1][1] = e + 1
        else:
            runs.append([e, e + 1])
    return [(a, b) for a, b in runs]


def _printable(fn) -> bool:
    """Whether :func:`..sample_c.sample_function_c` prints every operation of ``fn`` (the
    four arithmetic operations, negation and squares; a square root keeps CasADi's C)."""
    try:
        sample_function_c(fn, fn.name())
    except ValueError:
        return False
    return True


def render_c(spec, functions, variants, docs) -> tuple[dict[str, str], list[dict]]:
    """CasADi's C of each function with its batched driver (one translation unit each);
    ``docs``: each function's description."""
    versions = ", ".join(f"{k} {v}" for k, v in tool_versions().items())
    files, sigs = {}, []
    for doc, fn in zip(docs, functions):
        f = type("F", (), {"name": fn.name()[len(spec.prefix):], "doc": doc})
        sig = _signature(fn, spec.prefix, f.doc)
        sigs.append(sig)
        cg = ca.CodeGenerator(fn.name(), {"with_header": False})
        cg.add(fn)
        variant = variants.get(f.name)
        sincos = None
        if variant is not None:
            names = [fn.name_in(k) for k in range(fn.n_in())]
            sincos = {"symbol": variant.name(), "q": names.index("q"),
                      "offset": N_BASE_COORDINATES, "n": variant.size1_in(variant.n_in() - 1),
                      "code": sample_function_c(variant, variant.name())}
        header = (
            "/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for "
            f"{sig['name']}() of\n * generated/spatial/{spatial_dirname(spec.meta['n_links'])}/ "
            "(see its model.py), plus its batched driver.\n"
            f" * Regenerate with: {REGENERATE_SPATIAL}\n"
            f" * spec sha256: {spec.digest()}\n"
            f" * tools: {comment_text(versions)}\n"
            " */\n")
        batch = _env().get_template("batch.c.j2").render(prefix=spec.prefix,
                                                         functions=[{**sig, "sincos": sincos}])
        if sincos is not None and f.name in BLOCK_BATCHED:
            # the per-sample driver (with the vectorized sines and cosines it shares) keeps
            # its code under another name and answers where the block driver cannot; the
            # sines and cosines get the block kernel's AVX2 + FMA copy (a fifth of the time
            # of a 16-link mass matrix, measured in benchmarks/bench_spatial.py)
            exported = f"{spec.prefix}batch_{sig['name']}("
            batch = batch.replace(exported, f"{spec.prefix}sample_batch_{sig['name']}(")
            batch = batch.replace('target_clones("avx2", "default")',
                                  'target_clones("arch=x86-64-v3", "default")')
            batch = batch.replace("__GNUC__ >= 6 && defined(__x86_64__)",
                                  "__GNUC__ >= 11 && defined(__x86_64__)")
            batch += _block_driver(spec, sig, variant, sincos)
        files[f"c/{sig['name']}.c"] = header + cg.dump() + batch
    return files, sigs


def render_spatial_model(n_links: int, *, progress=None,
                         max_links: int = MAX_SPATIAL_LINKS) -> RenderedModel:
    """Derive, build and emit the spatial model with ``n_links`` links (nothing written)."""
    step = progress or (lambda msg: None)
    step(f"deriving the spatial model of a {n_links}-link chain (SymPy)")
    derivation = derive_spatial_model(n_links, max_links=max_links)
    spec = derivation.spec
    step("building the CasADi functions")
    functions = [build_spatial_function(f, spec.prefix) for f in spec.functions]
    built = tuple(fn.name()[len(spec.prefix):] for fn in functions)
    if built != SPATIAL_FUNCTIONS:  # pragma: no cover - a programming error
        raise RuntimeError(f"built {built}, the catalog says {SPATIAL_FUNCTIONS}")
    variants = {}
    for f in spec.functions:
        g = build_spatial_sincos(f, spec.prefix)
        if g is not None and _printable(g):
            variants[f.name] = g
    step("rendering the readable record model.py (Jinja2)")
    record = render_record(spec, functions)
    step("composing the contact problem (CasADi)")
    built = {f.name: fn for f, fn in zip(spec.functions, functions)}
    composed = contact_functions(built, derivation.symbols, spec.prefix)
    step("emitting C (CasADi code generator)")
    functions = functions + composed
    docs = [f.doc for f in spec.functions] + [CONTACT_DOCS[fn.name()[len(spec.prefix):]]
                                               for fn in composed]
    files, sigs = render_c(spec, functions, variants, docs)
    files.update({f"casadi/{fn.name()[len(spec.prefix):]}.casadi": fn.serialize()
                  for fn in functions})
    digest = lambda text: hashlib.sha256(text.encode()).hexdigest()  # noqa: E731
    manifest = {
        "format": SPATIAL_MANIFEST_FORMAT,
        "kind": "spatial",
        "generated_by": "snakecg_derive.spatial (derive/spatial/render.py); do not edit",
        "n_joints": spec.n_joints,
        "n_links": spec.meta["n_links"],
        "nq": spec.meta["nq"],
        "nv": spec.meta["nv"],
        "n_parameters": spec.meta["n_parameters"],
        "prefix": spec.prefix,
        "spec_hash": spec.digest(),
        "build_hash": spatial_build_hash(spec),
        "tools": tool_versions(),
        "files": {name: digest(text) for name, text in
                  [("model.py", record), *sorted(files.items())]},
        "functions": sigs,
    }
    text = json.dumps(manifest, indent=2) + "\n"
    return RenderedModel(spec.n_joints, {"model.py": record, **files, "manifest.json": text},
                         manifest)


def write_spatial_model(rendered: RenderedModel, out_dir) -> Path:
    """Write ``out_dir/na<N>/`` atomically (as the planar models)."""
    return write_model(rendered, out_dir)
