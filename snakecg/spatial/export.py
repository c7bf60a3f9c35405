"""``snakecg export`` of a spatial robot: the generated spatial model as a C library.

The folder written holds ``c/<function>.c`` (CasADi's C of every spatial function with its
batched drivers), ``snakecg_sp<N>.h`` (sizes, CasADi's prototypes, a plain
``<prefix><function>_eval`` wrapper per function and ``<prefix>robot_<function>`` with the
robot's ``K`` baked in), ``snakecg_sp<N>.c`` (the wrappers), ``robot_params.c`` (``K`` and the
baked wrappers), a ``Makefile`` (a static library and the example) and ``main.c`` (the mass
matrix and bias forces at a bent configuration, printed). Every file is written atomically.
"""

from __future__ import annotations

from pathlib import Path

from .._files import write_bytes
from ..errors import InputError
from .robot import SpatialRobot

__all__ = ["export_spatial_library", "spatial_robot_from_args"]


def _num(x: float) -> str:
    return repr(float(x))


def _layout(model) -> dict:
    from ..casadi_api import _backend
    from ..c_text import STACK_LIMIT
    from ..c_text import c_comment as _comment
    from ..c_text import c_ident as _ident

    man = model.manifest
    prefix = _ident(man["prefix"], "prefix")
    be = _backend(model)
    functions = []
    for sig in man["functions"]:
        name = _ident(sig["name"], "function name")
        f = be.casadi_function(name)
        sizes = {k: getattr(f, k)() for k in ("sz_arg", "sz_res", "sz_iw", "sz_w")}
        ins = [dict(name=_ident(i["name"], "input name"), rows=i["rows"], cols=i["cols"],
                    size=i["rows"] * i["cols"]) for i in sig["inputs"]]
        outs = [dict(name=_ident(o["name"], "output name"), rows=o["rows"], cols=o["cols"],
                     size=o["rows"] * o["cols"]) for o in sig["outputs"]]
        baked = ["K"] if any(i["name"] == "K" for i in ins) else []
        functions.append(dict(name=name, symbol=prefix + name, inputs=ins, outputs=outs,
                              sizes=sizes, heap=sizes["sz_w"] > STACK_LIMIT, baked=baked,
                              large=bool(sig.get("large")),
                              free_inputs=[i for i in ins if i["name"] != "K"]))
    stem = prefix.rstrip("_")
    return dict(prefix=prefix, upper=stem.upper(), stem=stem, header=f"{stem}.h",
                n_joints=man["n_joints"], n_links=man["n_links"], nq=man["nq"], nv=man["nv"],
                n_parameters=man["n_parameters"], functions=functions,
                K=[_num(v) for v in model.parameters],
                robot_name=_comment(model.robot.name),
                tools=_comment(", ".join(f"{k} {v}" for k, v in man.get("tools", {}).items())),
                c_files=sorted(n for n in man["files"] if n.endswith(".c")))


_PARAMS = """/* robot_params.c: the robot "{robot_name}" baked into the {n_joints}-joint spatial
 * library.
 * Written by `snakecg export`; do not edit (export again for another robot). */
#include "{header}"

const casadi_real {prefix}robot_K[{n_parameters}] = {{
    {K}}};
"""

_MAIN = """/* main.c: an example of the {n_joints}-joint spatial library.
 * Written by `snakecg export`. */
#include <stdio.h>
#include "{header}"

int main(void) {{
  casadi_real q[{nq}] = {{0}}, v[{nv}] = {{0}}, M[{nv} * {nv}], h[{nv}];
  int i;
  q[6] = 1.0; /* the identity quaternion (qx, qy, qz, qw) */
  for (i = 7; i < {nq}; ++i) q[i] = 0.3 * ((i % 3) - 1);
  if ({prefix}robot_mass_matrix(q, M) || {prefix}robot_bias_forces(q, v, h)) return 1;
  printf("M[0][0] = %.17g (the total mass)\\n", M[0]);
  for (i = 0; i < {nv}; ++i) printf("h[%d] = %.17g\\n", i, h[i]);
  return 0;
}}
"""

_MAKEFILE = """# Makefile of the {n_joints}-joint spatial snakecg library.
# Written by `snakecg export`.
CC ?= cc
CFLAGS ?= -O2 -std=gnu99 -Wall
AR ?= ar
SOURCES = {sources} {stem}.c robot_params.c
OBJECTS = $(SOURCES:.c=.o)

all: lib{stem}.a example

lib{stem}.a: $(OBJECTS)
\t$(AR) rcs $@ $(OBJECTS)

example: main.c lib{stem}.a {header}
\t$(CC) $(CFLAGS) -o $@ main.c lib{stem}.a -lm

.c.o:
\t$(CC) $(CFLAGS) -c $< -o $@
{large}
clean:
\trm -f $(OBJECTS) lib{stem}.a example

.PHONY: all clean
"""


def _baked_wrappers(layout) -> str:
    out = []
    for f in layout["functions"]:
        if not f["baked"]:
            continue
        params = [f"const casadi_real* {i['name']}" for i in f["free_inputs"]]
        params += [f"casadi_real* {o['name']}" for o in f["outputs"]]
        args = [f"{layout['prefix']}robot_K" if i["name"] == "K" else i["name"]
                for i in f["inputs"]] + [o["name"] for o in f["outputs"]]
        out.append(f"\nint {layout['prefix']}robot_{f['name']}({', '.join(params)}) {{\n"
                   f"  return {f['symbol']}_eval({', '.join(args)});\n}}\n")
    return "".join(out)


def export_spatial_library(robot: SpatialRobot, out, *, source: str | None = None) -> list[Path]:
    """Write the C library of ``robot`` (its ``K`` baked in) into the folder ``out``."""
    import jinja2

    from .model import SpatialModel

    if not isinstance(robot, SpatialRobot):
        raise InputError(f"robot must be a snakecg.SpatialRobot, got {type(robot).__name__}")
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise InputError(f"out {str(out)!r} exists and is not a directory")
    model = SpatialModel(robot)
    lay = _layout(model)
    env = jinja2.Environment(
        loader=jinja2.ChoiceLoader([jinja2.PackageLoader("snakecg.spatial", "templates"),
                                    jinja2.PackageLoader("snakecg", "data/export")]),
        autoescape=False, keep_trailing_newline=True, trim_blocks=True, lstrip_blocks=True,
        undefined=jinja2.StrictUndefined)
    large = "".join(f"\nc/{f['name']}.o: CFLAGS += -fno-tree-pre -fno-code-hoisting\n"
                    for f in lay["functions"] if f["large"])
    text = {
        lay["header"]: env.get_template("header.h.j2").render(**lay),
        f"{lay['stem']}.c": env.get_template("eval.c.j2").render(**lay),
        "robot_params.c": _PARAMS.format(**{**lay, "K": ",\n    ".join(lay["K"])})
        + _baked_wrappers(lay),
        "main.c": _MAIN.format(**lay),
        "Makefile": _MAKEFILE.format(**lay, sources=" ".join(lay["c_files"]), large=large),
    }
    files = {f"c/{Path(n).name}": (model.folder / n).read_bytes() for n in lay["c_files"]}
    files.update({k: v.encode() for k, v in text.items()})
    written = []
    for rel, data in files.items():
        (out / rel).parent.mkdir(parents=True, exist_ok=True)
        write_bytes(out / rel, data)
        written.append(out / rel)
    return written


def spatial_robot_from_args(args) -> SpatialRobot | None:
    """The CLI's ``--robot FILE`` or ``--scene FILE``: a spatial chain when the file is a URDF
    or MJCF (``.xml``) chain that is not planar, or a spatial scene file (``[robot]`` with
    ``joint_axis`` or ``file``; its robot), else None (the planar path reads the file)."""
    from .scene_file import is_spatial_scene_data, read_spatial_scene

    scene_path = getattr(args, "scene", None)
    path = getattr(args, "robot", None)
    toml = scene_path or (path if path and str(path).lower().endswith(".toml") else None)
    if toml:
        from ..toml_file import read_toml

        if not is_spatial_scene_data(read_toml(toml)):
            return None
        if scene_path and path:
            raise InputError("--scene FILE describes the robot; drop --robot")
        robot = read_spatial_scene(toml).robot
    elif not path or not str(path).lower().endswith((".urdf", ".xml")):
        return None
    else:
        from ..robot import Robot

        robot = (Robot.from_urdf if str(path).lower().endswith(".urdf")
                 else Robot.from_mjcf)(path)
    if not isinstance(robot, SpatialRobot):
        return None
    joints = getattr(args, "joints", None)
    if joints is not None and joints != robot.joints:
        raise InputError(f"--joints {joints} contradicts the robot file ({robot.joints} joints)")
    return robot
