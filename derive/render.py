"""Render a derived model into files: CasADi-building Python, CasADi's C, and a manifest.

Steps, each its own function (as in acados' templates): derive -> render Python (Jinja2)
-> build the CasADi functions from that Python -> emit C (CasADi's code generator plus the
batched drivers) -> manifest with hashes -> write the folder atomically.
Nothing written carries a timestamp: rendering is reproducible byte for byte.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import tempfile
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path

import jinja2

from . import coupled
from .catalog import function_names
from .build import (build_function, build_rotation_function, build_sincos_function,
                    operation_count, signature)
from .constraints import ROTATION_ANGLES
from .sample_c import sample_function_c
from .coupled import COUPLED_FUNCTIONS, coupled_functions
from .model import derive_model
from .printer import function_body
from .spec import ModelSpec
from .symbols import MAX_SYMBOLIC_JOINTS

__all__ = [
    "RenderedModel",
    "render_model",
    "write_model",
    "write_index",
    "model_dirname",
    "build_hash",
    "MANIFEST_FORMAT",
    "CHECKED_IN_JOINTS",
]

MANIFEST_FORMAT = 1
#: Joint counts whose generated files are checked in under ``generated/``.
CHECKED_IN_JOINTS = (1, 2, 3, 4, 5, 6)
_TEMPLATES = Path(__file__).parent / "templates"


def model_dirname(n_joints: int) -> str:
    return f"na{n_joints}"


def _env() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(_TEMPLATES)),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
    )
    env.filters["comment"] = comment_text
    env.filters["pystr"] = repr
    return env


def tool_versions() -> dict[str, str]:
    out = {}
    for dist in ("sympy", "casadi", "jinja2"):
        try:
            out[dist] = metadata.version(dist)
        except metadata.PackageNotFoundError:  # pragma: no cover - core dependencies
            out[dist] = "unknown"
    return out


def _template_digest() -> str:
    """Hash of the templates and of the generator's Python sources (the composition of
    eqs. 12-31 lives in :mod:`.coupled`)."""
    h = hashlib.sha256()
    here = Path(__file__).parent
    for p in sorted(_TEMPLATES.glob("*.j2")) + sorted(here.glob("*.py")):
        h.update(p.name.encode())
        h.update(p.read_bytes())
    return h.hexdigest()


def build_hash(spec: ModelSpec) -> str:
    """Cache key of a model: spec, templates and tool versions."""
    h = hashlib.sha256()
    h.update(spec.digest().encode())
    h.update(_template_digest().encode())
    h.update(json.dumps(tool_versions(), sort_keys=True).encode())
    h.update(str(MANIFEST_FORMAT).encode())
    return h.hexdigest()


@dataclass(frozen=True)
class RenderedModel:
    n_joints: int
    files: dict[str, str]
    """Relative file name -> text: ``model.py``, ``c/<function>.c``, ``manifest.json``
    (the manifest is written last)."""
    manifest: dict


def _function_context(spec: ModelSpec) -> list[dict]:
    ctx = []
    for f in spec.functions:
        lines, outs = function_body(f)
        ctx.append(
            {
                "name": f.name,
                "doc": f.doc,
                "equation": f.equation,
                "inputs": [
                    {"name": n, "size": len(syms), "doc": d, "symbols": [str(s) for s in syms]}
                    for n, syms, d in f.inputs
                ],
                "input_names": [n for n, _, _ in f.inputs],
                "outputs": [
                    {"name": n, "rows": r, "cols": c, "doc": d, "elements": el}
                    for (n, r, c, el), (_, _, d) in zip(outs, f.outputs)
                ],
                "output_names": [n for n, _, _ in f.outputs],
                "lines": lines,
            }
        )
    return ctx


#: The one regenerate command printed in every generated header. It names no path: user-derived
#: text (an output folder, the cache folder) never enters a generated file.
REGENERATE = "python -m snakecg_derive --checked-in"


def comment_text(value) -> str:
    """Text safe inside a ``#`` or ``/* */`` comment: printable characters only, no comment
    terminator. Anything interpolated into a generated file goes through this or ``repr``."""
    text = "".join(ch if ch.isprintable() else "?" for ch in str(value))
    return text.replace("*/", "*?")


def first_paragraph(doc: str) -> str:
    """The first paragraph of a docstring, on one line."""
    return " ".join((doc or "").strip().split("\n\n")[0].split())


def _signature_context(fn, prefix: str, doc: str, equation: str = "") -> dict:
    """What a template prints about one function, read from the CasADi function itself."""
    sig = signature(fn, prefix)
    return {**sig, "doc": doc, "equation": equation,
            "doc_lines": [line.strip() for line in (doc or "").strip().splitlines()],
            "input_names": [i["name"] for i in sig["inputs"]],
            "output_names": [o["name"] for o in sig["outputs"]]}


def render_python(spec: ModelSpec, link_functions, coupled) -> str:
    """Jinja2 step: ``model.py``, the readable record of the model (never imported or run).

    It lists every function with the signature read from the CasADi function, prints the
    straight-line programs of the per-link functions and names the module that builds the
    composed ones. Templates receive printed strings only.
    """
    versions = tool_versions()
    links = []
    for f, fn in zip(spec.functions, link_functions):
        ctx = _signature_context(fn, spec.prefix, f.doc, f.equation)
        lines, outs = function_body(f)
        ctx["lines"] = lines
        ctx["input_docs"] = [d for _, _, d in f.inputs]
        ctx["input_symbols"] = [[str(s) for s in syms] for _, syms, _ in f.inputs]
        ctx["output_docs"] = [d for _, _, d in f.outputs]
        ctx["output_elements"] = [el for _, _, _, el in outs]
        links.append(ctx)
    composed = [_signature_context(fn, spec.prefix, doc) for fn, doc in coupled]
    return _env().get_template("model.py.j2").render(
        n_joints=spec.n_joints,
        n_links=spec.meta["n_links"],
        n_coordinates=spec.meta["n_coordinates"],
        n_parameters=spec.meta["n_parameters"],
        prefix=spec.prefix,
        spec_hash=spec.digest(),
        tools=", ".join(f"{k} {v}" for k, v in versions.items()),
        regenerate=REGENERATE,
        functions=links,
        composed=composed,
    )


def build_functions(spec: ModelSpec, algebra: str = "sx"):
    """The CasADi functions of a model, built in Python (nothing rendered is run):
    ``(per-link functions, [(composed function, docstring)])``."""
    link_functions = [build_function(f, spec.prefix) for f in spec.functions]
    by_name = {fn.name()[len(spec.prefix):]: fn for fn in link_functions}
    # the rows with their angles' rotations given: composition blocks, not emitted themselves
    by_name.update({f"{f.name}_rotation": build_rotation_function(f, spec.prefix,
                                                                   ROTATION_ANGLES[f.name])
                    for f in spec.functions if f.name in ROTATION_ANGLES})
    composed = coupled_functions(by_name, spec.n_joints, spec.meta["n_parameters"],
                                 prefix=spec.prefix, algebra=algebra)
    docs = {name: getattr(coupled, name).__doc__ for name in COUPLED_FUNCTIONS}
    return link_functions, [(fn, docs[fn.name()[len(spec.prefix):]]) for fn in composed]


#: Functions with more operations than this are compiled with GCC's partial-redundancy
#: elimination and code hoisting off: on straight-line code of that size those two passes are
#: superlinear (33 s instead of 8 s for ``interaction_maps`` at n_a = 10, docs/performance.md).
LARGE_FUNCTION_OPERATIONS = 5000


def _signature(f, prefix: str, doc: str = "") -> dict:
    ops = operation_count(f)
    return {
        **signature(f, prefix),
        "doc": first_paragraph(doc),
        "n_in": f.n_in(),
        "n_out": f.n_out(),
        "nnz_out": [f.nnz_out(k) for k in range(f.n_out())],
        "sz_arg": f.sz_arg(),
        "sz_res": f.sz_res(),
        "sz_iw": f.sz_iw(),
        "sz_w": f.sz_w(),
        "algebra": "sx" if f.is_a("SXFunction") else "mx",
        "operations": ops,
        "large": ops is not None and ops > LARGE_FUNCTION_OPERATIONS,
    }


#: Per-link functions whose batched driver computes the sines and cosines of a block of
#: samples at once (vectorized) and calls the function's ``_sincos`` variant per sample
#: (:func:`.build.build_sincos_function`): about 85 % of the time of ``mass_matrix`` at
#: n_a = 3 was its C library ``sincos`` calls (docs/performance.md).
SINCOS_BATCHED = ("mass_matrix",)


def _sincos_context(g, f_public) -> dict:
    """What the batch template needs of a ``_sincos`` variant ``g`` of ``f_public``: its C
    (:func:`.sample_c.sample_function_c`, a static function of the file) and where the
    angles are."""
    names = [f_public.name_in(k) for k in range(f_public.n_in())]
    n = g.size1_in(g.n_in() - 1)
    return {"symbol": g.name(), "q": names.index("q"), "offset": 2, "n": n,
            "code": sample_function_c(g, g.name())}


def render_c(spec: ModelSpec, functions, docs=None, sincos=None
             ) -> tuple[dict[str, str], list[dict]]:
    """CasADi's C, one translation unit per function (compiled in parallel), each with its
    batched driver; returns ``({file name: text}, signatures)``. ``sincos`` maps a function's
    name to its ``_sincos`` variant, printed in the same file and called by its driver."""
    import casadi as ca

    versions = tool_versions()
    files = {}
    sigs = []
    sincos = sincos or {}
    for k, f in enumerate(functions):
        sig = _signature(f, spec.prefix, docs[k] if docs else "")
        sigs.append(sig)
        cg = ca.CodeGenerator(f.name(), {"with_header": False})
        cg.add(f)
        variant = sincos.get(sig["name"])
        header = (
            "/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for "
            f"{sig['name']}() of\n * generated/{model_dirname(spec.n_joints)}/ (see its model.py), "
            "plus its batched driver.\n"
            f" * Regenerate with: {REGENERATE}\n"
            f" * spec sha256: {spec.digest()}\n"
            f" * tools: {comment_text(', '.join(f'{k} {v}' for k, v in versions.items()))}\n"
            " */\n"
        )
        ctx = {**sig, "sincos": _sincos_context(variant, f) if variant is not None else None}
        batch = _env().get_template("batch.c.j2").render(prefix=spec.prefix, functions=[ctx])
        files[f"c/{sig['name']}.c"] = header + cg.dump() + batch
    return files, sigs


def serialize_functions(spec: ModelSpec, functions) -> dict[str, str]:
    """``casadi/<function>.casadi``: ``Function.serialize()`` text, deterministic and data only
    (loaded with ``casadi.Function.deserialize``, never executed)."""
    return {f"casadi/{f.name()[len(spec.prefix):]}.casadi": f.serialize() for f in functions}


def _sha(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()


#: Up to this joint count the composed functions are unrolled scalar (SX) code, above it they
#: keep their matrices (MX: linear-solve nodes and loops). Measured (docs/performance.md): at
#: n_a = 6 both evaluate in CasADi's VM within a factor two of each other, while at n_a = 20
#: the MX form emits 1.4 MB of C instead of 12 MB; the checked-in 1..6 stay SX so that small
#: robots keep their unrolled speed.
SX_MAX_JOINTS = 8


def choose_algebra(n_joints: int) -> str:
    """``"sx"`` (unrolled) or ``"mx"`` (matrix structure) for the composed functions."""
    return "sx" if n_joints <= SX_MAX_JOINTS else "mx"


def render_model(n_joints: int, *, progress=None, max_joints: int = MAX_SYMBOLIC_JOINTS,
                 algebra: str | None = None) -> RenderedModel:
    """Derive, render and emit C for one joint count (nothing written). ``algebra``
    overrides :func:`choose_algebra` (for measurements)."""
    step = progress or (lambda msg: None)
    algebra = algebra or choose_algebra(n_joints)
    if algebra not in ("sx", "mx"):
        raise ValueError(f"algebra must be 'sx' or 'mx', got {algebra!r}")
    step(f"deriving the model of a {n_joints}-joint snake (SymPy)")
    spec = derive_model(n_joints, max_joints=max_joints).spec
    step(f"building the CasADi functions ({algebra.upper()} composition)")
    link_functions, coupled_fns = build_functions(spec, algebra)
    functions = link_functions + [fn for fn, _ in coupled_fns]
    built = tuple(fn.name()[len(spec.prefix):] for fn in functions)
    if built != function_names(n_joints):
        raise RuntimeError(f"the generator built {built}, its catalog says "
                           f"{function_names(n_joints)} (derive/catalog.py)")
    docs = [f.doc for f in spec.functions] + [doc for _, doc in coupled_fns]
    step("rendering the readable record model.py (Jinja2)")
    py = render_python(spec, link_functions, coupled_fns)
    step("emitting C (CasADi code generator)")
    sincos = {}
    for f in spec.functions:
        if f.name in SINCOS_BATCHED:
            variant = build_sincos_function(f, spec.prefix)
            if variant is not None:
                sincos[f.name] = variant
    c_files, sigs = render_c(spec, functions, docs, sincos)
    # CasADi's own serialization of every function: what the no-compiler fallback loads, so
    # that nothing generated is ever executed at run time.
    c_files.update(serialize_functions(spec, functions))
    manifest = {
        "format": MANIFEST_FORMAT,
        "generated_by": "snakecg_derive (derive/render.py); do not edit",
        "n_joints": n_joints,
        "n_links": spec.meta["n_links"],
        "n_coordinates": spec.meta["n_coordinates"],
        "n_parameters": spec.meta["n_parameters"],
        "n_constraints": spec.meta["n_links"] + 1,
        "prefix": spec.prefix,
        "spec_hash": spec.digest(),
        "build_hash": build_hash(spec),
        "tools": tool_versions(),
        "algebra": {"composed": algebra, "sx_max_joints": SX_MAX_JOINTS,
                    "rule": "composed functions unrolled (sx) up to sx_max_joints, matrix "
                            "structure (mx) above; measured in benchmarks/bench_pipeline.py"},
        "mass_matrix_form": spec.meta["mass_matrix_form"],
        "mass_matrix_operation_counts_sympy": spec.meta["mass_matrix_operation_counts"],
        "mass_matrix_operation_counts_casadi": spec.meta["mass_matrix_operation_counts_casadi"],
        "files": {name: _sha(text) for name, text in [("model.py", py), *sorted(c_files.items())]},
        "functions": sigs,
    }
    text = json.dumps(manifest, indent=2, sort_keys=False) + "\n"
    return RenderedModel(n_joints, {"model.py": py, **c_files, "manifest.json": text}, manifest)


def _fsync_dir(path: Path) -> None:
    try:
        fd = os.open(path, os.O_RDONLY)
    except OSError:  # pragma: no cover - platforms without directory fds
        return
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def write_model(rendered: RenderedModel, out_dir: Path | str) -> Path:
    """Write ``out_dir/na<N>/`` atomically and return it.

    The files go to a temporary sibling folder first (manifest last), which is then renamed
    into place. If another process got there first with the same build, its folder is kept.
    """
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    final = out_dir / model_dirname(rendered.n_joints)
    tmp = Path(tempfile.mkdtemp(prefix=f".{final.name}.tmp-", dir=out_dir))
    try:
        names = [n for n in rendered.files if n != "manifest.json"] + ["manifest.json"]
        for name in names:
            p = tmp / name
            p.parent.mkdir(parents=True, exist_ok=True)
            with open(p, "w", encoding="utf-8", newline="\n") as fh:
                fh.write(rendered.files[name])
                fh.flush()
                os.fsync(fh.fileno())
        os.chmod(tmp, 0o755)
        _fsync_dir(tmp)
        if final.exists():
            try:
                old = json.loads((final / "manifest.json").read_text())
            except (OSError, ValueError):
                old = None
            same = (
                old is not None
                and old.get("build_hash") == rendered.manifest["build_hash"]
                and all(
                    (final / n).is_file() and (final / n).read_text() == rendered.files[n]
                    for n in rendered.files
                )
            )
            if same:
                shutil.rmtree(tmp, ignore_errors=True)
                return final
            trash = Path(tempfile.mkdtemp(prefix=f".{final.name}.old-", dir=out_dir))
            try:
                os.replace(final, trash / "old")
            except FileNotFoundError:
                pass
            shutil.rmtree(trash, ignore_errors=True)
        try:
            os.replace(tmp, final)
        except OSError:
            # a concurrent writer won the rename: keep its (identical or newer) folder
            shutil.rmtree(tmp, ignore_errors=True)
        _fsync_dir(out_dir)
        return final
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


def write_index(out_dir: Path | str, joint_counts=CHECKED_IN_JOINTS) -> Path:
    """``generated/__init__.py``: the package index of the checked-in models."""
    out_dir = Path(out_dir)
    text = _env().get_template("index.py.j2").render(joint_counts=list(joint_counts))
    p = out_dir / "__init__.py"
    tmp = p.with_name(f".__init__.py.tmp-{os.getpid()}")
    try:
        with open(tmp, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, p)  # atomic: a reader sees the old index or the new one
    finally:
        tmp.unlink(missing_ok=True)
    _fsync_dir(out_dir)
    return p
