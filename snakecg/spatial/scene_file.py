"""Reading a spatial scene (a 3-D snake lying on the ground, pushing an object) from a TOML
file (``snakecg forward|optimize|plot --scene FILE``)::

    [robot]                          # the robot: a file ...
    file = "snake.urdf"              # a URDF or MJCF (.xml) file, beside this one
    # ... or the table of a SpatialRobot, with its joint axes
    joints = 3
    joint_axis = [[0, 0, 1], [0, 1, 0], [0, 0, 1]]
    mass = 1.0                       # one for all, or one per link; com, inertia likewise
    joint_xyz = [0.15, 0, 0]
    effort_limits = [1.0, 2.0, 1.0]

    [scene]                          # the SpatialScene's fields, as a planar robot file's
    scenario = "wheels"              # frictionless | wheels | ideal_wheels
    kappa = 100.0
    mu = 0.1
    contact_link = 4
    side = "left"

A scene file is spatial when its ``[robot]`` table has ``file`` or ``joint_axis``; every
problem of the file is collected and raised at once, naming the key and the form.
"""

from __future__ import annotations

from pathlib import Path

from ..errors import InputError
from ..toml_file import read_toml
from .robot import SpatialRobot
from .scene import SpatialScene

__all__ = ["is_spatial_scene_data", "read_spatial_scene", "spatial_scene_from_data"]

_ROBOT_KEYS = {"joints", "mass", "com", "inertia", "joint_xyz", "joint_rpy", "joint_axis",
               "gravity", "joint_limits", "effort_limits", "name"}
_SCENE_KEYS = {"scenario", "kappa", "mu", "contact_link", "contact_offset", "side",
               "object_distance", "object_inertia", "wheel_links", "wheel_offset"}


def is_spatial_scene_data(data) -> bool:
    """A parsed scene file describes a spatial scene: its ``[robot]`` has ``file`` or
    ``joint_axis``."""
    robot = data.get("robot") if isinstance(data, dict) else None
    return isinstance(robot, dict) and ("file" in robot or "joint_axis" in robot)


def _robot(table, base: Path, problems: list[str]):
    table = dict(table)
    if "file" in table:
        path = table.pop("file")
        name = table.pop("name", None)
        if table:
            problems.append(f"[robot] with file takes only name beside it, got "
                            f"{sorted(table)}")
        if not isinstance(path, str) or not path:
            problems.append(f"[robot] file must be the path of a URDF or MJCF (.xml) file, "
                            f"got {path!r:.60}")
            return None
        p = Path(path) if Path(path).is_absolute() else base / path
        kind = p.suffix.lower()
        if kind not in (".urdf", ".xml", ".mjcf"):
            problems.append(f"[robot] file must end in .urdf or .xml (MJCF), got {path!r:.80}")
            return None
        try:
            read = SpatialRobot.from_urdf if kind == ".urdf" else SpatialRobot.from_mjcf
            return read(p, name=name)
        except InputError as exc:
            problems.append(f"[robot] file {path!r:.80}: {exc}")
            return None
    unknown = set(table) - _ROBOT_KEYS
    if unknown:
        problems.append(f"[robot] has unknown keys {sorted(unknown)} (expected file, or "
                        f"{', '.join(sorted(_ROBOT_KEYS))})")
        return None
    if "joints" not in table:
        problems.append("[robot] needs joints (the number of joints), or file")
        return None
    try:
        return SpatialRobot(**table)
    except (InputError, TypeError) as exc:
        problems.append(f"[robot]: {exc}")
        return None


def spatial_scene_from_data(data: dict, base: Path = Path("."),
                            where: str = "scene file") -> SpatialScene:
    """The :class:`SpatialScene` of a parsed TOML document (file paths relative to
    ``base``); every problem raised at once."""
    problems: list[str] = []
    unknown = set(data) - {"robot", "scene"}
    if unknown:
        problems.append(f"unknown tables {sorted(unknown)} (a spatial scene file has [robot] "
                        f"and [scene])")
    robot = _robot(data.get("robot", {}), base, problems)
    scene = data.get("scene", {})
    if not isinstance(scene, dict):
        problems.append(f"[scene] must be a table, got {scene!r:.60}")
        scene = {}
    bad = set(scene) - _SCENE_KEYS
    if bad:
        problems.append(f"[scene] has unknown keys {sorted(bad)} (expected "
                        f"{', '.join(sorted(_SCENE_KEYS))})")
    out = None
    if robot is not None and not bad:
        kw = {k: (tuple(v) if isinstance(v, list) else v) for k, v in scene.items()}
        try:
            out = SpatialScene(robot, **kw)
        except InputError as exc:
            problems.append(f"[scene]: {exc}")
    if problems:
        raise InputError(f"invalid spatial {where}: " + "; ".join(problems))
    return out


def read_spatial_scene(path) -> SpatialScene:
    """The :class:`SpatialScene` of a TOML scene file."""
    p = Path(path)
    return spatial_scene_from_data(read_toml(p), p.parent, where=f"scene file {str(p)!r}")
