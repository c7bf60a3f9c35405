"""Shared pieces of the sub-commands: argument parsing, JSON output and progress display.

Progress goes to standard error and only when it is a terminal, so pipes, files and CI logs
stay clean (``SNAKECG_PROGRESS=1`` forces it on, ``SNAKECG_PROGRESS=0`` off). Commands that
derive, compile or sweep pass :func:`progress_reporter` to the library's ``progress``
argument, or count work with :class:`ProgressCounter`.
"""

from __future__ import annotations

import json
import os
import sys
import time

import numpy as np

from ..errors import InputError
from ..robot import SCENARIOS, Robot, Scene

__all__ = [
    "parse_vector",
    "add_robot_args",
    "robot_from_args",
    "scene_from_args",
    "print_json",
    "progress_enabled",
    "progress_reporter",
    "ProgressCounter",
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


def robot_from_args(args) -> Robot:
    if args.robot:
        robot = Robot.from_toml(args.robot)
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
    if args.robot:
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


# ------------------------------------------------------------------------------------------
# progress
# ------------------------------------------------------------------------------------------
def progress_enabled(stream=None) -> bool:
    """Whether to show progress on ``stream`` (default stderr): a terminal, unless
    ``SNAKECG_PROGRESS`` says otherwise (``1`` on, ``0`` off)."""
    forced = os.environ.get("SNAKECG_PROGRESS", "").strip()
    if forced in ("0", "1"):
        return forced == "1"
    stream = sys.stderr if stream is None else stream
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


def progress_reporter(stream=None):
    """A ``progress(message)`` callable for the library's long steps (derivation, rendering,
    compilation), printing ``  [  3.2 s] message`` lines; ``None`` when progress is off."""
    stream = sys.stderr if stream is None else stream
    if not progress_enabled(stream):
        return None
    t0 = time.perf_counter()

    def step(message: str) -> None:
        stream.write(f"  [{time.perf_counter() - t0:6.1f} s] {message}\n")
        stream.flush()

    return step


class ProgressCounter:
    """``done / total`` of a sweep on one terminal line (rewritten in place), silent when
    progress is off. Use as a context manager and call :meth:`advance` per finished chunk."""

    def __init__(self, label: str, total: int, stream=None, *, min_interval: float = 0.2):
        self.label = label
        self.total = max(int(total), 0)
        self.done = 0
        self.stream = sys.stderr if stream is None else stream
        self.enabled = progress_enabled(self.stream)
        self._t0 = time.perf_counter()
        self._last = -1.0
        self._min_interval = min_interval

    def advance(self, n: int = 1) -> None:
        self.done += n
        if not self.enabled:
            return
        now = time.perf_counter()
        if now - self._last < self._min_interval and self.done < self.total:
            return
        self._last = now
        pct = 100.0 * self.done / self.total if self.total else 100.0
        self.stream.write(f"\r  {self.label}: {self.done}/{self.total} ({pct:5.1f} %)"
                          f" {now - self._t0:6.1f} s")
        self.stream.flush()

    def close(self) -> None:
        if self.enabled and self._last >= 0:
            self.stream.write("\n")
            self.stream.flush()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False
