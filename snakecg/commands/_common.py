"""Shared pieces of the sub-commands: argument parsing, JSON output and progress display.

Every option is checked when the command line is parsed or, where the check needs the robot
(vector lengths, link numbers), right after the robot and scene are built: always before a
model is generated, loaded or evaluated and before anything is written. Option values are
never empty; numbers are finite and within the limits each option states.

``--json`` output is strict JSON (RFC 8259): a value that is not finite (an overflowing
result) is printed as ``null`` and its path listed under ``"nonfinite"`` (docs/reference/cli.md).

Progress goes to standard error, standard output keeps the result: a line when a model's
generation or compilation (or a stage of work) starts and one when it ends, on every stream;
bars only on a terminal (``--quiet`` or ``SNAKECG_PROGRESS=0`` silences all of it). Commands
that derive or compile pass :func:`~snakecg.progress.progress_reporter` to the library's
``progress`` argument; sweeps use :func:`~snakecg.progress.progress_bar` (tqdm).
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

from .._inputs import short_repr
from ..errors import InputError
from ..progress import progress_enabled, progress_reporter
from ..robot import SCENARIOS, Robot, Scene

#: The schema of ``snakecg show --json`` (planar and spatial chains).
SHOW_SCHEMA = "snakecg.show/1"

__all__ = [
    "parse_vector",
    "vector",
    "real",
    "count",
    "text",
    "out_dir",
    "strict_json",
    "add_robot_args",
    "robot_from_args",
    "scene_from_args",
    "print_json",
    "progress_enabled",
    "progress_reporter",
]


def parse_vector(name: str, text: str) -> list[float]:
    """``"0.1, 0.2 0.3"`` -> ``[0.1, 0.2, 0.3]``; degrees with a ``deg`` suffix on an entry."""
    out = []
    for tok in text.replace(",", " ").split():
        scale = 1.0
        if tok.endswith("deg"):
            tok, scale = tok[:-3], np.pi / 180
        try:
            out.append(float(tok) * scale)
        except ValueError:
            raise InputError(
                f"{name} must be numbers separated by commas or spaces (e.g. '0,0,0,-135deg'),"
                f" got {text!r}"
            ) from None
    if not out:
        raise InputError(f"{name} is empty; give numbers separated by commas")
    return out


def vector(name: str, text: str | None, size: int | None = None, *, what: str = "",
           sizes: tuple[int, ...] | None = None, positive: bool = False) -> list[float] | None:
    """A list option parsed and checked: ``size`` (or one of ``sizes``) finite numbers.

    ``None`` (option not given) stays None. The message names the option, the expected
    count and what the values mean.
    """
    if text is None:
        return None
    values = parse_vector(name, text)
    allowed = sizes if sizes is not None else ((size,) if size is not None else None)
    if allowed is not None and len(values) not in allowed:
        want = " or ".join(str(k) for k in allowed)
        raise InputError(f"{name} has {len(values)} values, expected {want}{what}")
    bad = [v for v in values if not math.isfinite(v)]
    if bad:
        raise InputError(f"{name} must be finite numbers{what}, got {text!r:.80}")
    if positive and any(v <= 0 for v in values):
        raise InputError(f"{name} must be positive numbers{what}, got {text!r:.80}")
    return values


def _type_error(message: str):
    return argparse.ArgumentTypeError(message)


def real(lo=None, hi=None, *, lo_open=False, unit: str = "", name: str = "number"):
    """argparse ``type``: a finite float within ``[lo, hi]`` (``lo_open``: ``> lo``)."""
    u = f" ({unit})" if unit else ""

    def convert(text: str) -> float:
        if not text.strip():
            raise _type_error(f"empty value; expected a {name}{u}")
        try:
            v = float(text)
        except ValueError:
            raise _type_error(f"expected a {name}{u}, got {text!r:.60}") from None
        if not math.isfinite(v):
            raise _type_error(f"expected a finite {name}{u}, got {text!r:.60}")
        if lo is not None and (v < lo or (lo_open and v == lo)):
            raise _type_error(f"must be {'>' if lo_open else '>='} {lo:g}{u}, got {text!r:.60}")
        if hi is not None and v > hi:
            raise _type_error(f"must be <= {hi:g}{u} (the limit), got {text!r:.60}")
        return v

    convert.__name__ = name
    return convert


def count(lo: int, hi: int | None = None, *, why: str = "", name: str = "integer"):
    """argparse ``type``: an integer within ``[lo, hi]`` (``why`` explains the limit)."""

    def convert(text: str) -> int:
        t = text.strip()
        if not t:
            raise _type_error(f"empty value; expected an {name} >= {lo}")
        try:
            v = int(t)
        except ValueError:
            raise _type_error(f"invalid int value: {text!r:.60}") from None
        if v < lo:
            raise _type_error(f"must be an integer >= {lo}, got {short_repr(v)}")
        if hi is not None and v > hi:
            raise _type_error(f"must be at most {hi}{why}, got {short_repr(v)}")
        return v

    convert.__name__ = name
    return convert


def text(what: str):
    """argparse ``type``: a non-empty string (an empty value is refused, not ignored)."""

    def convert(value: str) -> str:
        if not value.strip():
            raise _type_error(f"empty value; expected {what}")
        if "\0" in value:
            raise _type_error(f"contains a NUL character; expected {what}")
        return value

    convert.__name__ = "text"
    return convert


def out_dir(name: str, value: str):
    """The output folder ``value`` as a Path: refused if it exists and is not a folder."""
    from pathlib import Path

    out = Path(value)
    if out.exists() and not out.is_dir():
        raise InputError(f"{name} {value!r} exists and is not a directory")
    for parent in out.parents:
        if parent.exists():
            if not parent.is_dir():
                raise InputError(f"{name} {value!r}: {str(parent)!r} is not a directory")
            break
    return out


def add_robot_args(p, *, scene: bool = True) -> None:
    p.add_argument("--joints", type=int, metavar="N",
                   help="number of joints n_a (default 2, or the robot file's)")
    p.add_argument("--robot", metavar="FILE", type=text("a robot description file"),
                   help="robot description file (TOML, see docs/explanation/model.md); the "
                   "options below override its [scene] table")
    if scene:
        p.add_argument("--scene", metavar="FILE", type=text("a scene file"),
                       help="general scene file (TOML: [robot], [ground], [[object]], "
                       "[[obstacle]]; see docs/how-to/scenes.md): forward, optimize, simulate "
                       "and plot take it; or a 3-D snake's ([robot] with joint_axis or a "
                       "URDF/MJCF file, [scene]; docs/how-to/spatial.md): forward, optimize "
                       "and plot")
        p.add_argument("--scenario", choices=SCENARIOS, type=lambda s: s.replace("-", "_"),
                       help="ground scenario (default frictionless)")
        p.add_argument("--kappa", type=float, help="object mass / mean link mass (default 100)")
        p.add_argument("--mu", type=float,
                       help="wheel friction coefficient, scenario wheels (default 0.1)")
        p.add_argument("--contact-link", type=int, metavar="K",
                       help="link touching the object, 1 = tail (default 1)")
        p.add_argument("--side", choices=("left", "right"),
                       help="object side of the contact link (default left)")


def _is_urdf(path) -> bool:
    """A robot file without a [scene] table: URDF, or MJCF (``.xml``)."""
    return str(path).lower().endswith((".urdf", ".xml"))


def check_vector(name: str, values, size: int, what: str = ""):
    """A parsed vector option checked against the robot's sizes, as the library checks it
    (``q has shape (4,), expected (5,) ...``), before any model is loaded."""
    from .._inputs import as_batch

    if values is None:
        return None
    as_batch(name, values, size, what=what)
    return values


def robot_from_args(args) -> Robot:
    if args.robot:
        name = str(args.robot).lower()
        read = (Robot.from_urdf if name.endswith(".urdf") else Robot.from_mjcf
                if name.endswith(".xml") else Robot.from_toml)
        robot = read(args.robot)
        if not isinstance(robot, Robot):  # a 3-D chain: snakecg.SpatialRobot
            raise InputError(f"--robot {args.robot}: a 3-D chain (its joints are not the "
                             f"planar snake's); forward, optimize and plot take it in a spatial "
                             f"scene file: --scene FILE with [robot] file = "
                             f"\"{Path(args.robot).name}\" (docs/how-to/spatial.md)")
        if args.joints is not None and args.joints != robot.joints:
            raise InputError(
                f"--joints {args.joints} contradicts the robot file ({robot.joints} joints)"
            )
        return robot
    joints = 2 if args.joints is None else args.joints
    return Robot(joints=joints)


def general_scene_from_args(args):
    """The general scene of ``--scene FILE`` (None without it); refused beside the options
    of the paper's scene."""
    path = getattr(args, "scene", None)
    if not path:
        return None
    given = [f"--{k.replace('_', '-')}" for k in ("robot", "joints", "scenario", "kappa", "mu",
                                                   "contact_link", "side")
             if getattr(args, k, None) is not None]
    if given:
        raise InputError(f"--scene FILE describes the whole scene; drop {', '.join(given)}")
    from ..spatial.scene_file import is_spatial_scene_data, read_spatial_scene
    from ..toml_file import read_toml

    if is_spatial_scene_data(read_toml(path)):  # a 3-D snake (snakecg.spatial)
        return read_spatial_scene(path)
    from ..scenes.toml_reading import read_scene

    return read_scene(path)


def scene_from_args(args) -> Scene:
    if getattr(args, "scene", None):
        raise InputError(f"--scene: {args.command if hasattr(args, 'command') else 'this'} "
                         f"command does not take a general scene yet (forward, optimize, plot "
                         f"and simulate do)")
    overrides = {
        "scenario": args.scenario, "kappa": args.kappa, "mu": args.mu,
        "contact_link": args.contact_link, "side": args.side,
    }
    if args.robot and _is_urdf(args.robot):  # a URDF has no [scene]: the options alone
        scene = Scene(robot_from_args(args), **{k: v for k, v in overrides.items()
                                                if v is not None})
    elif args.robot:
        scene = Scene.from_toml(args.robot, **overrides)
        if args.joints is not None and args.joints != scene.robot.joints:
            raise InputError(
                f"--joints {args.joints} contradicts the robot file ({scene.robot.joints} joints)"
            )
        return scene
    return Scene(robot_from_args(args), **{k: v for k, v in overrides.items() if v is not None})


def strict_json(obj, path: str = "", found: list | None = None):
    """``obj`` with every non-finite float replaced by None; the paths replaced are appended
    to ``found`` (``"lam[2]"``, ``"analysis.qdd[0]"``)."""
    if found is None:
        found = []
    if isinstance(obj, dict):
        return {k: strict_json(v, f"{path}.{k}" if path else str(k), found)
                for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [strict_json(v, f"{path}[{i}]", found) for i, v in enumerate(obj)]
    if isinstance(obj, np.ndarray):
        return strict_json(obj.tolist(), path, found)
    if isinstance(obj, (np.bool_,)):
        return bool(obj)
    if isinstance(obj, np.integer):
        return int(obj)
    if isinstance(obj, (float, np.floating)):
        x = float(obj)
        if math.isfinite(x):
            return x
        found.append(path)
        return None
    return obj


def print_json(obj) -> list[str]:
    """Print ``obj`` as strict JSON; returns the paths of non-finite values (printed as null,
    listed under ``"nonfinite"`` when there are any)."""
    found: list[str] = []
    clean = strict_json(obj, found=found)
    if found and isinstance(clean, dict):
        clean["nonfinite"] = found
    json.dump(clean, sys.stdout, indent=2, sort_keys=False, allow_nan=False)
    sys.stdout.write("\n")
    return found


def print_optimum(res, objective: str, value_name: str, *, timed: bool = True,
                  between=()) -> None:
    """The lines every ``snakecg optimize`` answer starts with: the status (and the solver,
    with its time when ``timed``), the reason, the lines ``between``, the torque, the
    objective's value (``value_name``) and the binding limits."""
    how = [res.solver] if res.solver else []  # (no solver ran where the input was refused)
    how += [f"{res.time * 1e3:.2f} ms"] if timed else []
    print(f"{objective}: {res.status}" + (f" ({'; '.join(how)})" if how else ""))
    if res.reason:
        print(f"  reason: {res.reason}")
    for line in between:
        print(line)
    print(f"  tau    = {res.tau}  (N m)")
    print(f"  {value_name} = {res.objective_value:.9g}")
    if res.binding:
        print(f"  binding: {', '.join(res.binding)}")
