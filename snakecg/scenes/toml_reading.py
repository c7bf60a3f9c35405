"""Reading a general scene from a TOML file (``--scene FILE``)::

    [robot]                # as a robot file's, plus the links' capsule radius
    joints = 3
    radius = 0.02
    [ground]               # one model for every link, or lists of one per link
    model = "coulomb"      # frictionless | wheels | ideal_wheels | coulomb | anisotropic
    mu = 0.3               # (mu_forward, mu_backward, mu_lateral: anisotropic)
    [[object]]
    shape = "box"          # box (size = [a, b]) | disc (radius)
    size = [0.1, 0.1]
    mass = 100.0
    touching = { link = 1, offset = 0.075, side = "left" }   # or pose = [x, y, theta]
    [[obstacle]]
    shape = "peg"          # peg (center, radius) | wall (point, normal) | box (center, size, angle)
    center = [0.3, 0.12]
    radius = 0.03
    mu_contact = 0.5       # its own Coulomb coefficient at contacts (optional)
    [contacts]
    tolerance = 1e-8       # relative to the scene's size
    mu = 0.2               # Coulomb friction at the contacts between bodies (default 0)

Every problem of the file is collected and raised at once, naming the key and the form.
"""

from __future__ import annotations

import math

from ..errors import InputError
from ..robot import _robot_from_table
from ..toml_file import read_toml
from .description import GeneralScene, Ground, Obstacle, SceneObject

__all__ = ["read_scene", "scene_from_data"]

_GROUND_KEYS = {"model", "mu", "mu_forward", "mu_backward", "mu_lateral", "wheel_offset",
                "gravity"}
_OBJECT_KEYS = {"shape", "size", "radius", "mass", "inertia", "pose", "touching", "mu", "name",
                "mu_contact"}
_OBSTACLE_KEYS = {"shape", "center", "radius", "point", "normal", "size", "angle", "name",
                  "mu_contact"}
_CONTACT_KEYS = {"tolerance", "mu"}
_TOP = {"robot", "ground", "object", "obstacle", "contacts"}


def _tuple(v):
    return tuple(v) if isinstance(v, list) else v


def scene_from_data(data: dict, where: str = "scene file") -> GeneralScene:
    """The scene of a parsed TOML document (every problem raised at once)."""
    problems: list[str] = []
    unknown = set(data) - _TOP
    if unknown:
        problems.append(f"unknown tables {sorted(unknown)} (expected [robot], [ground], "
                        f"[[object]], [[obstacle]], [contacts])")
    rtable = data.get("robot")
    radius = 0.0
    if isinstance(rtable, dict):
        rtable = dict(rtable)
        radius = rtable.pop("radius", 0.0)
    robot, more, n_links = _robot_from_table({**data, "robot": rtable} if rtable is not None
                                             else data)
    problems += more
    g = data.get("ground", {})
    grounds, gravity = None, 9.81
    if not isinstance(g, dict):
        problems.append(f"[ground] must be a table, got {g!r:.60}")
    else:
        bad = set(g) - _GROUND_KEYS
        if bad:
            problems.append(f"unknown keys in [ground]: {sorted(bad)} (allowed: "
                            f"{sorted(_GROUND_KEYS)})")
        gravity = g.get("gravity", 9.81)
        fields = {k: v for k, v in g.items() if k in _GROUND_KEYS - {"gravity"}}
        lists = {k: v for k, v in fields.items() if isinstance(v, list)}
        if lists and n_links is not None:
            wrong = [k for k, v in lists.items() if len(v) != n_links]
            if wrong:
                problems.append(f"[ground] lists {sorted(wrong)} must have {n_links} entries "
                                f"(one per link)")
            else:
                grounds = tuple(Ground(**{k: (v[i] if k in lists else v)
                                          for k, v in fields.items()})
                                for i in range(n_links))
        elif not lists:
            grounds = Ground(**fields)
    objects, obstacles = [], []
    for name, keys, cls, out in (("object", _OBJECT_KEYS, SceneObject, objects),
                                 ("obstacle", _OBSTACLE_KEYS, Obstacle, obstacles)):
        items = data.get(name, [])
        if not isinstance(items, list):
            problems.append(f"[[{name}]] must be an array of tables, got {items!r:.60}")
            continue
        for i, t in enumerate(items):
            if not isinstance(t, dict):
                problems.append(f"{name}[{i + 1}] must be a table")
                continue
            bad = set(t) - keys
            if bad:
                problems.append(f"unknown keys in {name}[{i + 1}]: {sorted(bad)} (allowed: "
                                f"{sorted(keys)})")
            out.append(cls(**{k: _tuple(v) for k, v in t.items() if k in keys}))
    contacts = data.get("contacts", {})
    if not isinstance(contacts, dict):
        problems.append(f"[contacts] must be a table, got {contacts!r:.60}")
        contacts = {}
    elif set(contacts) - _CONTACT_KEYS:
        problems.append(f"unknown keys in [contacts]: {sorted(set(contacts) - _CONTACT_KEYS)} "
                        f"(allowed: {sorted(_CONTACT_KEYS)})")
    tolerance = contacts.get("tolerance", 1e-8)
    mu_c = contacts.get("mu", 0.0)
    if not (isinstance(mu_c, (int, float)) and not isinstance(mu_c, bool)
            and math.isfinite(mu_c) and mu_c >= 0):
        problems.append(f"[contacts] mu must be a finite number >= 0 (Coulomb's coefficient at the "
                        f"contacts), got {mu_c!r:.60}")
        mu_c = 0.0
    if robot is None or grounds is None or problems:
        # the rest checked too, so that one message names every problem
        if robot is not None:
            try:
                GeneralScene(robot, radius=radius, ground=grounds or Ground(),
                             objects=tuple(objects), obstacles=tuple(obstacles),
                             gravity=gravity, tolerance=tolerance, mu_contact=mu_c)
            except InputError as exc:
                problems.append(str(exc).removeprefix("invalid scene: "))
        raise InputError(f"{where}: " + "; ".join(problems))
    try:
        return GeneralScene(robot, radius=radius, ground=grounds, objects=tuple(objects),
                            obstacles=tuple(obstacles), gravity=gravity, tolerance=tolerance,
                            mu_contact=mu_c)
    except InputError as exc:
        raise InputError(f"{where}: {str(exc).removeprefix('invalid scene: ')}") from None


def read_scene(path) -> GeneralScene:
    """The general scene of the TOML file ``path``."""
    return scene_from_data(read_toml(path), where=f"scene file {str(path)!r}")
