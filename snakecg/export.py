"""``snakecg export``: the generated model as a self-contained C library for controllers.

The folder written holds

* ``c/<function>.c``: the C that CasADi emitted for every generated function (CasADi's
  standard calling convention: ``int f(const casadi_real** arg, casadi_real** res,
  casadi_int* iw, casadi_real* w, int mem)``);
* ``snakecg_na<N>.h``: sizes, the layout of the parameter vector ``K``, the index and size of
  every input and output, the CasADi prototypes and a plain wrapper per function,
  ``<prefix><function>_eval(inputs..., outputs...)`` (work arrays on the stack);
* ``snakecg_na<N>.c``: those wrappers;
* ``robot_params.h`` / ``robot_params.c``: the robot's ``K`` and the scene's constants baked
  in, and ``<prefix>robot_<function>(...)`` wrappers that take only what varies (``q``,
  ``tau``, the active set, ...); from the robot file when one is given, else the paper's
  Table 1 robot and the default scene;
* ``Makefile`` (a static library ``libsnakecg_na<N>.a`` and the example) and ``main.c``, an
  example that evaluates the mass matrix and one forward solve and prints them.

Everything is derived from the model's manifest (function names, symbols, input and output
names and shapes) and from CasADi's work sizes, so the export follows the generated layer.
Every file is written atomically (a unique temporary name, then ``os.replace``).
"""

from __future__ import annotations

import math
import os
from pathlib import Path

from ._files import write_bytes
from .c_text import STACK_LIMIT
from .c_text import c_comment as _comment
from .c_text import c_ident as _ident
from .errors import InputError

__all__ = ["export_library", "c_layout"]

_TEMPLATES = ("header.h.j2", "eval.c.j2", "robot_params.h.j2", "robot_params.c.j2",
              "main.c.j2", "Makefile.j2")


def _num(x: float) -> str:
    """A double literal that C reads back exactly (``repr`` round-trips)."""
    x = float(x)
    if math.isinf(x):
        return "INFINITY" if x > 0 else "-INFINITY"
    if math.isnan(x):
        raise InputError("a baked parameter is NaN")
    return repr(x)


def _cycle(values, n):
    return [values[k % len(values)] for k in range(n)]


def c_layout(model) -> dict:
    """Everything the templates need, from ``model.manifest`` and CasADi's work sizes."""
    from .casadi_api import _backend, function_inputs, parameter_names

    man = model.manifest
    prefix = _ident(man["prefix"], "prefix")
    be = _backend(model)
    functions = []
    baked_names = ("K", "contact_link", "side", "object_mass", "object_inertia",
                   "wheel_offset", "contact_offset", "object_distance")
    for sig in man["functions"]:
        name = _ident(sig["name"], "function name")
        symbol = _ident(sig.get("symbol", prefix + name), "symbol")
        f = be.casadi_function(name)
        sizes = {k: sig.get(k) if isinstance(sig.get(k), int) else getattr(f, k)()
                 for k in ("sz_arg", "sz_res", "sz_iw", "sz_w")}
        ins = [dict(name=_ident(i["name"], "input name"), rows=i["rows"], cols=i["cols"],
                    size=i["rows"] * i["cols"]) for i in sig["inputs"]]
        outs = [dict(name=_ident(o["name"], "output name"), rows=o["rows"], cols=o["cols"],
                     size=o["rows"] * o["cols"]) for o in sig["outputs"]]
        try:
            fixed = function_inputs(model, name)
        except InputError:
            fixed = {}
        baked = [i["name"] for i in ins if i["name"] in baked_names and i["name"] in fixed]
        functions.append(dict(
            name=name, symbol=symbol, upper=symbol.upper(), inputs=ins, outputs=outs,
            sizes=sizes, heap=sizes["sz_w"] > STACK_LIMIT, baked=baked,
            large=bool(sig.get("large")),
            free_inputs=[i for i in ins if i["name"] not in baked],
        ))
    names = parameter_names(model.n_joints)
    if len(names) != man["n_parameters"]:
        names = [f"K{i}" for i in range(man["n_parameters"])]  # layout unknown: indices only
    scene = model.scene
    fixed = function_inputs(model, "constrained_dynamics") if any(
        f["name"] == "constrained_dynamics" for f in functions) else {}
    constants = []
    for k in ("contact_link", "side", "object_mass", "object_inertia", "wheel_offset",
              "contact_offset", "object_distance", "free", "lam_fixed", "regularization"):
        if k in fixed:
            vals = fixed[k]
        elif k in ("contact_offset", "object_distance"):
            vals = [getattr(scene, k)]
        else:
            continue
        constants.append(dict(name=k, vals=[_num(v) for v in vals], size=len(vals)))
    # row 0 is the contact (no friction bound: INFINITY); a link without a wheel (the
    # contact link, or every link in the frictionless scenario) has none: 0
    bounds = [b if i == 0 or model.present[i] else 0.0 for i, b in enumerate(model.bounds)]
    constants.append(dict(name="wheel_bound", vals=[_num(v) for v in bounds],
                          size=len(bounds)))
    r = model.robot
    return dict(
        prefix=prefix, upper=prefix.upper().rstrip("_"), stem=prefix.rstrip("_"),
        n_joints=man["n_joints"], n_links=man["n_links"], n_coordinates=man["n_coordinates"],
        n_constraints=man["n_constraints"], n_parameters=man["n_parameters"],
        parameters=[dict(index=i, name=n, macro=_ident(n.upper(), "parameter name"),
                         value=_num(v)) for i, (n, v) in enumerate(zip(names, model.parameters))],
        functions=functions, by_name={f["name"]: f for f in functions}, constants=constants,
        constant_names=[f"scene_{c['name']}" for c in constants],
        default_q=[_num(v) for v in [0.0, 0.0, 0.0] + [math.radians(a) for a in
                                                        _cycle((30, -45, 60), man["n_joints"])]],
        default_tau=[_num(v) for v in _cycle((0.05, 0.0, -0.02), man["n_joints"])],
        robot=dict(name=_comment(r.name), mass=[_num(v) for v in r.mass],
                   length=[_num(v) for v in r.length], inertia=[_num(v) for v in r.inertia],
                   com=[_num(v) for v in r.com]),
        scene=dict(scenario=scene.scenario, kappa=_num(scene.kappa), mu=_num(scene.mu),
                   contact_link=scene.contact_link, side=scene.side,
                   wheel_links=list(scene.wheel_links)),
        tools=_comment(", ".join(f"{k} {v}" for k, v in man.get("tools", {}).items())),
        c_files=sorted(n for n in man["files"] if n.endswith(".c")),
    )


def _render(layout: dict, source: str | None) -> dict[str, str]:
    import jinja2

    env = jinja2.Environment(
        loader=jinja2.PackageLoader("snakecg", "data/export"),
        autoescape=False, keep_trailing_newline=True, trim_blocks=True, lstrip_blocks=True,
        undefined=jinja2.StrictUndefined,
    )
    stem = layout["stem"]
    ctx = dict(layout, source=_comment(source or "the paper's Table 1 robot, default scene"),
               header=f"{stem}.h")
    names = {"header.h.j2": f"{stem}.h", "eval.c.j2": f"{stem}.c",
             "robot_params.h.j2": "robot_params.h", "robot_params.c.j2": "robot_params.c",
             "main.c.j2": "main.c", "Makefile.j2": "Makefile"}
    return {names[t]: env.get_template(t).render(**ctx) for t in _TEMPLATES}


def export_library(scene, out, *, source: str | None = None) -> list[Path]:
    """Write the C library of ``scene`` (a :class:`~snakecg.Scene`, its robot's parameters
    baked in) into the folder ``out``; returns the files written.

    ``source`` is a short description of where the robot comes from (a file name), quoted in
    the generated comments.
    """
    from .loading import load
    from .robot import Scene
    from .spatial import SpatialRobot

    if isinstance(scene, SpatialRobot):  # a 3-D chain: its own layout (snakecg.spatial.export)
        from .spatial.export import export_spatial_library

        return export_spatial_library(scene, out, source=source)
    if not isinstance(scene, Scene):
        raise InputError(f"scene must be a snakecg.Scene, got {type(scene).__name__}")
    if isinstance(out, bytes) or not isinstance(out, (str, os.PathLike)):
        raise InputError(f"out must be a folder path (str or os.PathLike), got "
                         f"{type(out).__name__}")
    if not str(out).strip() or "\0" in str(out):
        raise InputError(f"out must name a folder, got {str(out)!r} (an empty name would "
                         "write into the working directory)")
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise InputError(f"out {str(out)!r} exists and is not a directory")
    model = load(scene)
    layout = c_layout(model)
    files = {f"c/{Path(n).name}": (model.folder / n).read_bytes() for n in layout["c_files"]}
    files.update({k: v.encode() for k, v in _render(layout, source).items()})
    written = []
    for rel, data in files.items():
        (out / rel).parent.mkdir(parents=True, exist_ok=True)
        write_bytes(out / rel, data)  # unique temporary name, then os.replace
        written.append(out / rel)
    return written
