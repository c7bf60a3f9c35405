"""Robot and scene descriptions: immutable, validated at the boundary.

A robot description file (TOML) looks like ``examples/robot.toml``::

    [robot]
    joints = 3                 # n_a >= 1
    mass = 1.0                 # kg: one number, or a list of n_a + 1 numbers
    length = 0.15              # m
    inertia = 0.002            # kg m^2 about each link's COM
    # com = 0.075              # m from each link's rear end (default: length / 2)
    # joint_limits = [-2.0, 2.0]   # rad: one (lower, upper) pair, or one pair per joint
    # effort_limits = 2.0          # N m: largest |tau_j|, one number or one per joint

    [scene]                    # optional; used by `snakecg forward/optimize/simulate`
    scenario = "wheels"        # "frictionless" | "wheels" | "ideal_wheels"
    kappa = 100.0              # object mass = kappa * mean link mass
    mu = 0.1
    contact_link = 1
    side = "left"              # object to the left ("left") or right ("right") of the link

Every problem in a file is collected and reported at once.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from ._inputs import MAX_PARAMETER, beyond_parameter_limit
from ._inputs import short_repr as _r
from ._inputs import to_float as _to_float
from .errors import InputError
from .limits import check_effort_limits, check_joint_limits
from .toml_file import read_toml as _read_toml

__all__ = ["Robot", "Scene", "SCENARIOS", "DEFAULT_GRAVITY"]

#: Ground scenarios of the paper: 1 frictionless, 2 wheels with bounded friction, 3 ideal wheels.
SCENARIOS = ("frictionless", "wheels", "ideal_wheels")
DEFAULT_GRAVITY = 9.81


_MISSING = object()
#: At most this many offending values are quoted per parameter (the count of the rest follows).
_MAX_QUOTED = 4
#: At most this many problems are listed in one message (the count of the rest follows).
_MAX_PROBLEMS = 20


def _is_number(v) -> bool:
    return isinstance(v, numbers.Real) and not isinstance(v, bool)


def _is_sequence(v) -> bool:
    return (isinstance(v, Sequence) and not isinstance(v, (str, bytes))) or (
        type(v).__module__ == "numpy" and getattr(v, "ndim", None) == 1
    )


def _quote(items: list[str]) -> str:
    shown = ", ".join(items[:_MAX_QUOTED])
    more = len(items) - _MAX_QUOTED
    return shown + (f" and {more} more" if more > 0 else "")


def _keys(keys) -> str:
    """``['a', 'b']`` for a few keys; the first few and the count of the rest for many."""
    keys = sorted(keys, key=str)
    shown = "[" + ", ".join(_r(k) for k in keys[:_MAX_QUOTED]) + "]"
    more = len(keys) - _MAX_QUOTED
    return shown + (f" and {more} more" if more > 0 else "")


def _joined(problems: list[str]) -> str:
    """The problems separated by ``; ``: the first few, then how many more there are."""
    text = "; ".join(problems[:_MAX_PROBLEMS])
    more = len(problems) - _MAX_PROBLEMS
    return text + (f"; and {more} more problems" if more > 0 else "")


def _per_link(name: str, value, n_links: int | None, problems: list[str], *, positive=True):
    """One number per link (a scalar is repeated); every problem is appended to ``problems``.

    ``n_links`` is None when the joint count itself is invalid: the values are still checked,
    their count is not. Returns the tuple of floats, or None if anything was wrong.
    """
    if _is_number(value):
        values = [(_to_float(value), None, value)]
    elif _is_sequence(value):
        values, wrong = [], []
        for i, v in enumerate(value, start=1):
            if _is_number(v):
                values.append((_to_float(v), i, v))
            else:
                wrong.append(f"{_r(v)} (link {i})")
        if wrong:
            problems.append(f"{name} must hold numbers, got {_quote(wrong)}")
        if n_links is not None and len(value) != n_links:
            problems.append(
                f"{name} has {len(value)} values, expected one number or {n_links}"
                f" (= joints + 1, one per link)"
            )
            wrong.append("count")
        if wrong:
            values = [v for v in values if v[1] is not None]
            _check_values(name, values, positive, problems)
            return None
    else:
        expected = f"a list of {n_links} numbers" if n_links is not None else "a list of numbers"
        problems.append(f"{name} must be a number or {expected}, got {_r(value)}")
        return None
    if not _check_values(name, values, positive, problems):
        return None
    if n_links is None:
        return None
    if len(values) == 1 and values[0][1] is None:
        return (values[0][0],) * n_links
    return tuple(v[0] for v in values)


def _check_values(name, values, positive, problems) -> bool:
    # quoted as floats, but an integer beyond float range as itself (cut), not as inf
    bad = [(orig if isinstance(orig, numbers.Integral) and math.isinf(v) else v, i)
           for v, i, orig in values if not math.isfinite(v) or (positive and v <= 0)]
    if bad:
        kind = "positive finite" if positive else "finite"
        quoted = [f"{_r(v)}" if i is None else f"{_r(v)} (link {i})" for v, i in bad]
        problems.append(f"{name} must be {kind}, got {_quote(quoted)}")
        return False
    big = [(v, i) for v, i, _ in values if abs(v) > MAX_PARAMETER]
    if big:
        quoted = [f"{_r(v)}" if i is None else f"{_r(v)} (link {i})" for v, i in big]
        problems.append(beyond_parameter_limit(name, _quote(quoted)))
    return not big


def _joint_count(joints, problems: list[str]) -> int | None:
    """The number of links for a valid ``joints`` (within the generation limit), else None."""
    if isinstance(joints, bool) or not isinstance(joints, numbers.Integral) or joints < 1:
        problems.append(f"joints must be an integer >= 1, got {_r(joints)}")
        return None
    from .artifacts import max_joints

    try:
        limit = max_joints()
    except InputError as exc:
        problems.append(str(exc))
        return None
    if joints > limit:
        # refused here, before any per-link tuple of that length is built
        problems.append(
            f"joints={_r(joints)} exceeds the generation limit of {limit} joints"
            " (raise it with SNAKECG_MAX_JOINTS if you accept the derivation and compile time)"
        )
        return None
    return int(joints) + 1


def _robot_problems(joints, mass, length, inertia, com, name, joint_limits=None,
                    effort_limits=None) -> tuple[list[str], dict]:
    """Every problem of a robot's fields, and the normalized fields (valid only if none)."""
    problems: list[str] = []
    n = None if joints is _MISSING else _joint_count(joints, problems)
    mass = _per_link("mass", mass, n, problems)
    length = _per_link("length", length, n, problems)
    inertia = _per_link("inertia", inertia, n, problems)
    if com is not None:
        com = _per_link("com", com, n, problems)
        if com is not None and length is not None:
            for i, (c, l_) in enumerate(zip(com, length), start=1):
                if c > l_:
                    problems.append(f"com of link {i} is {c} m, beyond its length {l_} m")
    elif length is not None:
        com = tuple(l_ / 2 for l_ in length)
    if not isinstance(name, str):
        problems.append(f"name must be a string, got {_r(name)}")
    na = None if n is None else n - 1
    joint_limits = check_joint_limits(joint_limits, na, problems)
    effort_limits = check_effort_limits(effort_limits, na, problems)
    fields = {"joints": na, "mass": mass, "length": length, "inertia": inertia, "com": com,
              "joint_limits": joint_limits, "effort_limits": effort_limits}
    return problems, fields


@dataclass(frozen=True)
class Robot:
    """A planar snake robot: ``joints`` revolute joints, ``joints + 1`` rigid links.

    Parameters are one number for every link or a sequence with one per link, tail first
    (link 1 is the tail). Defaults are the paper's Table 1: ``m = 1 kg``, ``l = 0.15 m``,
    ``I = 0.002 kg m^2``; ``com`` is each COM's distance from the link's rear end
    (default: the middle of the link).

    ``joint_limits``: ``lower < q_j < upper`` (rad), one ``(lower, upper)`` pair for every
    joint or one pair per joint; ``effort_limits``: ``|tau_j| <= effort_j`` (N m), one
    positive number or one per joint. None (the default, as the paper's Table 1): not
    stated. They are the default joint range and torque box of the queries
    (:mod:`snakecg.limits`).
    """

    joints: int
    mass: tuple = 1.0
    length: tuple = 0.15
    inertia: tuple = 0.002
    com: tuple | None = None
    name: str = field(default="snake", compare=False)
    joint_limits: tuple | None = None
    effort_limits: tuple | None = None

    def __post_init__(self):
        problems, fields = _robot_problems(self.joints, self.mass, self.length, self.inertia,
                                           self.com, self.name, self.joint_limits,
                                           self.effort_limits)
        if problems:
            raise InputError("invalid robot: " + _joined(problems))
        for key, value in fields.items():
            object.__setattr__(self, key, value)

    @property
    def n_links(self) -> int:
        return self.joints + 1

    @property
    def n_coordinates(self) -> int:
        return self.joints + 3

    @property
    def total_mass(self) -> float:
        return float(sum(self.mass))

    @classmethod
    def from_toml(cls, path: str | Path) -> Robot:
        """Read the ``[robot]`` table of a robot description file (format in the module doc).

        Every problem of the file is reported at once, in one :class:`~snakecg.InputError`.
        """
        data = _read_toml(path)
        robot, problems, _ = _robot_from_table(data)
        _unknown_tables(data, problems)
        if problems:
            raise _file_error(path, problems)
        return robot

    @classmethod
    def from_urdf(cls, path: str | Path, *, tol: float = 1e-6, name: str | None = None):
        """Read a serial chain of revolute joints from a URDF file: a planar chain (parallel
        axes, COMs on the links' axes) gives a planar :class:`Robot` (masses, joint-to-joint
        lengths, COM offsets, inertias about the joint axis), any other chain a
        :class:`~snakecg.SpatialRobot`; branches and other joints are refused naming the
        element. Needs the ``urdf`` extra; see :mod:`snakecg.urdf`, docs/how-to/urdf.md and
        docs/how-to/spatial.md."""
        from .spatial.files import spatial_chain_or_planar
        from .spatial.robot import SpatialRobot
        from .urdf import robot_from_urdf

        return spatial_chain_or_planar("urdf", path, name, lambda: robot_from_urdf(
            path, robot_type=cls, tol=tol, name=name), planar_type=cls,
            spatial_type=SpatialRobot)

    @classmethod
    def from_mjcf(cls, path: str | Path, *, tol: float = 1e-6, name: str | None = None):
        """Read a serial chain of hinges on a free root from a MuJoCo XML file (MuJoCo's own
        parser, the ``mjcf`` extra): a planar :class:`Robot` when the chain is planar, else a
        :class:`~snakecg.SpatialRobot`; see docs/how-to/spatial.md."""
        from .spatial.files import spatial_chain_or_planar
        from .spatial.robot import SpatialRobot

        return spatial_chain_or_planar("mjcf", path, name, None, planar_type=cls,
                                       spatial_type=SpatialRobot, tol=tol)

    def __repr__(self) -> str:
        return f"Robot({_fields_repr(self, _ROBOT_REPR)})"


_ROBOT_REPR = ("joints", "mass", "length", "inertia", "com", "joint_limits", "effort_limits")
_ROBOT_KEYS = {"joints", "mass", "length", "inertia", "com", "name", "joint_limits",
               "effort_limits"}
_SCENE_KEYS = {
    "scenario", "kappa", "mu", "gravity", "contact_link", "contact_offset", "side",
    "object_distance", "object_inertia", "wheel_links", "wheel_offset",
}


def _file_error(path, problems: list[str]) -> InputError:
    return InputError(f"robot file {str(path)!r}: " + _joined(problems))


def _unknown_tables(data: dict, problems: list[str]) -> None:
    unknown_top = set(data) - {"robot", "scene"}
    if unknown_top:
        problems.append(f"unknown tables or keys {_keys(unknown_top)} at the top level"
                        " (expected the tables [robot] and [scene])")


def _robot_from_table(data: dict) -> tuple[Robot | None, list[str], int | None]:
    """The ``[robot]`` table as a Robot (None if invalid), every problem found in it, and the
    number of links if at least the joint count is valid (to check the scene's lists)."""
    problems: list[str] = []
    table = data.get("robot", _MISSING)
    if table is _MISSING:
        return None, ["missing [robot] table"], None
    if not isinstance(table, dict):
        return None, [f"[robot] must be a table, got {_r(table)}"], None
    unknown = set(table) - _ROBOT_KEYS
    if unknown:
        problems.append(f"unknown keys in [robot]: {_keys(unknown)} (allowed: "
                        f"{sorted(_ROBOT_KEYS)})")
    if "joints" not in table:
        problems.append("missing key joints in [robot]")
    defaults = {f.name: f.default for f in Robot.__dataclass_fields__.values()}
    kw = {k: table.get(k, defaults[k]) for k in ("mass", "length", "inertia", "com", "name",
                                                 "joint_limits", "effort_limits")}
    more, fields = _robot_problems(table.get("joints", _MISSING), **kw)
    problems += more
    n_links = None if fields["joints"] is None else fields["joints"] + 1
    if problems:
        return None, problems, n_links
    return Robot(joints=table["joints"], **kw), [], n_links


@dataclass(frozen=True)
class Scene:
    """Robot + object + contact + ground, as in the paper's three scenarios.

    * ``scenario``: ``"frictionless"`` (paper scenario 1), ``"wheels"`` (2: lateral wheel force
      bounded by ``mu m_i g``) or ``"ideal_wheels"`` (3: bilateral, unbounded).
    * ``kappa``: object mass over the mean link mass (``m_obj = kappa m``).
    * ``contact_link`` (1-based) and ``contact_offset`` (m from the link's rear end, default
      the middle); ``side``: ``"left"`` puts the object on the side of
      ``n = (-sin phi_k, cos phi_k)``, ``"right"`` on the other.
    * ``object_distance``: the object's COM lies on the contact normal at this distance from
      the contact point (default 0.05 m: a 0.1 m square plate touched at a face's middle).
    * ``object_inertia``: rotational inertia of the object about its COM (default: that of a
      0.1 m x 0.1 m square plate of mass ``m_obj``).
    * ``wheel_links``: links with a passive wheel (default: every link but the contacting one,
      assumption 4); ``wheel_offset``: wheel position from each link's COM along the link.
    """

    robot: Robot
    scenario: str = "frictionless"
    kappa: float = 100.0
    mu: float = 0.1
    gravity: float = DEFAULT_GRAVITY
    contact_link: int = 1
    contact_offset: float | None = None
    side: str = "left"
    object_distance: float = 0.05
    object_inertia: float | None = None
    wheel_links: tuple | None = None
    wheel_offset: float | tuple = 0.0

    def __post_init__(self):
        if not isinstance(self.robot, Robot):
            raise InputError(f"robot must be a snakecg.Robot, got {type(self.robot).__name__}")
        values = {f: getattr(self, f) for f in self.__dataclass_fields__ if f != "robot"}
        problems, fields = _scene_problems(self.robot, values)
        if problems:
            raise InputError("invalid scene: " + _joined(problems))
        for name, value in fields.items():
            object.__setattr__(self, name, value)

    @staticmethod
    def link_mass_scale_of(robot: Robot) -> float:
        """``m`` in ``m_obj = kappa m``: the mean link mass (the paper's links are equal)."""
        return robot.total_mass / robot.n_links

    @property
    def object_mass(self) -> float:
        return self.kappa * self.link_mass_scale_of(self.robot)

    @property
    def side_sign(self) -> float:
        return 1.0 if self.side == "left" else -1.0

    @property
    def has_wheels(self) -> bool:
        return self.scenario != "frictionless"

    def wheel_bounds(self) -> tuple[float, ...]:
        """Lateral force bound ``mu m_i g`` of every link (inf for ideal wheels)."""
        if self.scenario == "ideal_wheels":
            return tuple(math.inf for _ in self.robot.mass)
        return tuple(self.mu * m * self.gravity for m in self.robot.mass)

    def replace(self, **changes) -> Scene:
        """A copy with some fields changed (validated again)."""
        fields = {f: getattr(self, f) for f in self.__dataclass_fields__}
        unknown = set(changes) - set(fields)
        if unknown:
            raise InputError(f"Scene.replace: unknown fields {_keys(unknown)} (allowed: "
                             f"{', '.join(sorted(fields))})")
        if "robot" in changes or "contact_link" in changes:
            # offsets and wheel sets follow the new robot/contact unless given
            for f in ("contact_offset", "wheel_links"):
                if f not in changes:
                    fields[f] = None
        if "kappa" in changes and "object_inertia" not in changes:
            fields["object_inertia"] = None
        fields.update(changes)
        return Scene(**fields)

    def __repr__(self) -> str:
        fields = _fields_repr(self, _SCENE_REPR)
        return f"Scene({self.robot!r}{', ' if fields else ''}{fields})"

    @classmethod
    def from_toml(cls, path: str | Path, **overrides) -> Scene:
        """Robot and ``[scene]`` table of a description file; keyword overrides win.

        Every problem of the file (robot and scene) is reported at once.
        """
        unknown = set(overrides) - _SCENE_KEYS
        if unknown:
            raise InputError(f"Scene.from_toml: unknown keyword overrides {_keys(unknown)}"
                             f" (allowed: {', '.join(sorted(_SCENE_KEYS))})")
        data = _read_toml(path)
        robot, problems, n_links = _robot_from_table(data)
        _unknown_tables(data, problems)
        table = data.get("scene", {})
        if not isinstance(table, dict):
            problems.append(f"[scene] must be a table, got {_r(table)}")
            table = {}
        unknown = set(table) - _SCENE_KEYS
        if unknown:
            problems.append(f"unknown keys in [scene]: {_keys(unknown)}"
                            f" (allowed: {sorted(_SCENE_KEYS)})")
        kwargs = {k: v for k, v in table.items() if k in _SCENE_KEYS}
        if "wheel_links" in kwargs and isinstance(kwargs["wheel_links"], list):
            kwargs["wheel_links"] = tuple(kwargs["wheel_links"])
        kwargs.update({k: v for k, v in overrides.items() if v is not None})
        values = {f: fld.default for f, fld in cls.__dataclass_fields__.items() if f != "robot"}
        values.update(kwargs)
        problems += _scene_problems(robot, values, n_links=n_links)[0]
        if problems:
            raise _file_error(path, problems)
        return cls(robot, **kwargs)


def _scene_problems(r: Robot | None, f: dict, *, n_links: int | None = None
                    ) -> tuple[list[str], dict]:
    """Every problem of a scene's fields, and the normalized fields (valid only if none).

    ``r`` None: the robot itself is invalid, so only what does not depend on it is checked
    (with ``n_links``, if the joint count alone is known, the link numbers and list lengths).
    """
    problems: list[str] = []
    n_links = r.n_links if r is not None else n_links
    links = f"1..{n_links}" if n_links is not None else ">= 1"
    if isinstance(f["scenario"], str):  # "ideal-wheels" as the command line may spell it
        f["scenario"] = f["scenario"].replace("-", "_")
    if not isinstance(f["scenario"], str) or f["scenario"] not in SCENARIOS:
        problems.append(f"scenario must be one of {', '.join(SCENARIOS)} (got {_r(f['scenario'])})")

    def num(name, value, *, positive=False, nonneg=False):
        if not _is_number(value):
            problems.append(f"{name} must be a number, got {_r(value)}")
            return None
        v = _to_float(value)
        if not math.isfinite(v):
            problems.append(f"{name} must be finite, got {_r(value)}")
            return None
        if positive and v <= 0:
            problems.append(f"{name} must be > 0, got {_r(value)}")
            return None
        if nonneg and v < 0:
            problems.append(f"{name} must be >= 0, got {_r(value)}")
            return None
        return v

    kappa = num("kappa", f["kappa"], positive=True)
    mu = num("mu", f["mu"], nonneg=True)
    gravity = num("gravity", f["gravity"], nonneg=True)
    dist = num("object_distance", f["object_distance"], positive=True)
    k = f["contact_link"]
    if (isinstance(k, bool) or not isinstance(k, numbers.Integral) or k < 1
            or (n_links is not None and k > n_links)):
        problems.append(f"contact_link must be a link number {links}, got {_r(k)}")
        k = None
    else:
        k = int(k)
    offset = f["contact_offset"]
    if offset is not None:
        offset = num("contact_offset", offset)
        if (offset is not None and k is not None and r is not None
                and not 0 <= offset <= r.length[k - 1]):
            problems.append(
                f"contact_offset must lie on link {k}: 0..{r.length[k - 1]} m from its rear"
                f" end, got {offset}"
            )
    side = f["side"]
    if isinstance(side, str) and side == "left" or _is_number(side) and side == 1:
        side = "left"
    elif isinstance(side, str) and side == "right" or _is_number(side) and side == -1:
        side = "right"
    else:
        problems.append(f"side must be 'left' or 'right', got {_r(f['side'])}")
    inertia = f["object_inertia"]
    if inertia is not None:
        inertia = num("object_inertia", inertia, positive=True)
    wheels = f["wheel_links"]
    if wheels is not None:
        if not _is_sequence(wheels):
            problems.append(f"wheel_links must be a list of link numbers, got {_r(wheels)}")
            wheels = None
        else:
            bad = [w for w in wheels if isinstance(w, bool) or not isinstance(w, numbers.Integral)
                   or w < 1 or (n_links is not None and w > n_links)]
            if bad:
                problems.append(f"wheel_links must be link numbers {links}, got "
                                f"{_quote([repr(w) for w in bad])}")
                wheels = None
            elif k is not None and k in wheels:
                problems.append(
                    f"link {k} touches the object and cannot carry a wheel (assumption 4);"
                    f" remove it from wheel_links"
                )
                wheels = None
            else:
                wheels = tuple(sorted({int(w) for w in wheels}))
    woff = _per_link("wheel_offset", f["wheel_offset"], n_links, problems, positive=False)
    if r is not None and kappa is not None:
        m_obj = kappa * Scene.link_mass_scale_of(r)
        if not math.isfinite(m_obj):
            problems.append(f"kappa * mean link mass = {m_obj} (object mass) is not finite")
        elif inertia is None and not math.isfinite(m_obj * (0.1**2 + 0.1**2) / 12):
            problems.append("the default object inertia (kappa * mean link mass * 0.02 / 12)"
                            " is not finite; give object_inertia")
    if problems or r is None:
        return problems, {}
    if offset is None:
        offset = r.length[k - 1] / 2
    if inertia is None:
        inertia = kappa * Scene.link_mass_scale_of(r) * (0.1**2 + 0.1**2) / 12
    if wheels is None:
        wheels = tuple(i for i in range(1, r.n_links + 1) if i != k)
    return problems, {
        "scenario": f["scenario"], "kappa": kappa, "mu": mu, "gravity": gravity,
        "contact_link": k, "contact_offset": offset, "side": side, "object_distance": dist,
        "object_inertia": inertia, "wheel_links": wheels, "wheel_offset": woff,
    }


_SCENE_REPR = ("scenario", "kappa", "mu", "gravity", "contact_link", "contact_offset", "side",
               "object_distance", "object_inertia", "wheel_links", "wheel_offset")


def _fields_repr(obj, names) -> str:
    """``name=value`` for the fields that differ from their defaults (what ``Robot(...)`` or
    ``Scene(...)`` would fill in itself), one number for a per-link tuple of equal values;
    the text evaluates back to an equal object."""
    if isinstance(obj, Robot):
        base = Robot(joints=obj.joints, length=obj.length)  # com defaults to length / 2
        defaults = {k: getattr(Robot(joints=obj.joints), k) for k in names}
        defaults["com"] = base.com
    else:
        defaults = {k: getattr(Scene(obj.robot), k) for k in names}
        linked = Scene(obj.robot, contact_link=obj.contact_link, kappa=obj.kappa)
        for k in ("contact_offset", "wheel_links", "object_inertia"):
            defaults[k] = getattr(linked, k)
    parts = []
    for k in names:
        v = getattr(obj, k)
        if k != "joints" and v == defaults[k]:
            continue
        if isinstance(v, tuple) and v and k != "wheel_links" and len(set(v)) == 1:
            v = v[0]
        parts.append(f"{k}={v!r}")
    if isinstance(obj, Robot) and obj.name != "snake":
        parts.append(f"name={obj.name!r}")
    return ", ".join(parts)
