"""Shared pieces of the sub-commands: argument parsing, JSON output and progress display.

Progress goes to standard error and only when it is a terminal, so pipes, files and CI logs
stay clean (``SNAKECG_PROGRESS=1`` forces it on, ``SNAKECG_PROGRESS=0`` off). Commands that
derive or compile pass :func:`~snakecg.progress.progress_reporter` to the library's
``progress`` argument; sweeps use :func:`~snakecg.progress.progress_bar` (tqdm).
"""

from __future__ import annotations

import json
import sys

import numpy as np

from ..errors import InputError
from ..progress import progress_enabled, progress_reporter
from ..robot import SCENARIOS, Robot, Scene

__all__ = [
    "parse_vector",
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


def add_robot_args(p, *, scene: bool = True) -> None:
    p.add_argument("--joints", type=int, metavar="N",
                   help="number of joints n_a (default 2, or the robot file's)")
    p.add_argument("--robot", metavar="FILE",
                   help="robot description file (TOML, see docs/model.md); the options below "
                   "override its [scene] table")
    if scene:
        p.add_argument("--scenario", choices=SCENARIOS,
                       help="ground scenario (default frictionless)")
        p.add_argument("--kappa", type=float, help="object mass / mean link mass (default 100)")
        p.add_argument("--mu", type=float,
                       help="wheel friction coefficient, scenario wheels (default 0.1)")
        p.add_argument("--contact-link", type=int, metavar="K",
                       help="link touching the object, 1 = tail (default 1)")
        p.add_argument("--side", choices=("left", "right"),
                       help="object side of the contact link (default left)")


def _is_urdf(path) -> bool:
    return str(path).lower().endswith(".urdf")


def robot_from_args(args) -> Robot:
    if args.robot:
        robot = (Robot.from_urdf if _is_urdf(args.robot) else Robot.from_toml)(args.robot)
        if args.joints is not None and args.joints != robot.joints:
            raise InputError(
                f"--joints {args.joints} contradicts the robot file ({robot.joints} joints)"
            )
        return robot
    joints = 2 if args.joints is None else args.joints
    return Robot(joints=joints)


def scene_from_args(args) -> Scene:
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


def print_json(obj) -> None:
    json.dump(obj, sys.stdout, indent=2, sort_keys=False)
    sys.stdout.write("\n")

