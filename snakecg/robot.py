"""Robot and scene descriptions: immutable, validated at the boundary.

A robot description file (TOML) looks like ``examples/robot.toml``::

    [robot]
    joints = 3                 # n_a >= 1
    mass = 1.0                 # kg: one number, or a list of n_a + 1 numbers
    length = 0.15              # m
    inertia = 0.002            # kg m^2 about each link's COM
    # com = 0.075              # m from each link's rear end (default: length / 2)

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
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from .errors import InputError

__all__ = ["Robot", "Scene", "SCENARIOS", "DEFAULT_GRAVITY"]

#: Ground scenarios of the paper: 1 frictionless, 2 wheels with bounded friction, 3 ideal wheels.
SCENARIOS = ("frictionless", "wheels", "ideal_wheels")
DEFAULT_GRAVITY = 9.81


def _per_link(name: str, value, n_links: int, problems: list[str], *, positive=True):
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        values = [float(value)] * n_links
    elif isinstance(value, Sequence) and not isinstance(value, (str, bytes)):
        values = []
        for v in value:
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                problems.append(f"{name} must hold numbers, got {v!r}")
                return None
            values.append(float(v))
        if len(values) != n_links:
            problems.append(
                f"{name} has {len(values)} values, expected one number or {n_links}"
                f" (= joints + 1, one per link)"
            )
            return None
    else:
        problems.append(f"{name} must be a number or a list of {n_links} numbers, got {value!r}")
        return None
    bad = [v for v in values if not math.isfinite(v) or (positive and v <= 0)]
    if bad:
        kind = "positive finite" if positive else "finite"
        problems.append(f"{name} must be {kind}, got {bad[0]!r}")
        return None
    return tuple(values)


@dataclass(frozen=True)
class Robot:
    """A planar snake robot: ``joints`` revolute joints, ``joints + 1`` rigid links.

    Parameters are one number for every link or a sequence with one per link, tail first
    (link 1 is the tail). Defaults are the paper's Table 1: ``m = 1 kg``, ``l = 0.15 m``,
    ``I = 0.002 kg m^2``; ``com`` is each COM's distance from the link's rear end
    (default: the middle of the link).
    """

    joints: int
    mass: tuple = 1.0
    length: tuple = 0.15
    inertia: tuple = 0.002
    com: tuple | None = None
    name: str = field(default="snake", compare=False)

    def __post_init__(self):
        problems: list[str] = []
        j = self.joints
        if isinstance(j, bool) or not isinstance(j, int) or j < 1:
            raise InputError(f"joints must be an integer >= 1, got {j!r}")
        n = j + 1
        mass = _per_link("mass", self.mass, n, problems)
        length = _per_link("length", self.length, n, problems)
        inertia = _per_link("inertia", self.inertia, n, problems)
        com = None
        if self.com is not None:
            com = _per_link("com", self.com, n, problems)
            if com is not None and length is not None:
                for i, (c, l_) in enumerate(zip(com, length), start=1):
                    if c > l_:
                        problems.append(f"com of link {i} is {c} m, beyond its length {l_} m")
        if problems:
            raise InputError("invalid robot: " + "; ".join(problems))
        if com is None:
            com = tuple(l_ / 2 for l_ in length)
        object.__setattr__(self, "mass", mass)
        object.__setattr__(self, "length", length)
        object.__setattr__(self, "inertia", inertia)
        object.__setattr__(self, "com", com)

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
        """Read the ``[robot]`` table of a robot description file (format in the module doc)."""
        data = _read_toml(path)
        return _robot_from_table(data, path)


_ROBOT_KEYS = {"joints", "mass", "length", "inertia", "com", "name"}
_SCENE_KEYS = {
    "scenario", "kappa", "mu", "gravity", "contact_link", "contact_offset", "side",
    "object_distance", "object_inertia", "wheel_links", "wheel_offset",
}


def _read_toml(path) -> dict:
    try:
        import tomllib
    except ModuleNotFoundError:  # pragma: no cover - Python 3.10
        import tomli as tomllib
    p = Path(path)
    try:
        with open(p, "rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise InputError(f"robot file {str(p)!r} does not exist") from None
    except IsADirectoryError:
        raise InputError(f"robot file {str(p)!r} is a directory, expected a TOML file") from None
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"robot file {str(p)!r} is not valid TOML: {exc}") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"robot file {str(p)!r} cannot be read: {exc}") from None


def _robot_from_table(data: dict, path) -> Robot:
    problems = []
    unknown_top = set(data) - {"robot", "scene"}
    if unknown_top:
        problems.append(f"unknown tables {sorted(unknown_top)} (expected [robot] and [scene])")
    table = data.get("robot")
    if not isinstance(table, dict):
        problems.append("missing [robot] table")
        raise InputError(f"robot file {str(path)!r}: " + "; ".join(problems))
    unknown = set(table) - _ROBOT_KEYS
    if unknown:
        problems.append(f"unknown keys in [robot]: {sorted(unknown)} (allowed: "
                        f"{sorted(_ROBOT_KEYS)})")
    if "joints" not in table:
        problems.append("missing key joints in [robot]")
    kwargs = {k: table[k] for k in _ROBOT_KEYS & set(table)}
    if problems:
        # still validate the values we have to report everything at once
        try:
            if "joints" in kwargs:
                Robot(**kwargs)
        except InputError as exc:
            problems.append(str(exc))
        raise InputError(f"robot file {str(path)!r}: " + "; ".join(problems))
    try:
        return Robot(**kwargs)
    except InputError as exc:
        raise InputError(f"robot file {str(path)!r}: {exc}") from None
    except TypeError as exc:  # pragma: no cover
        raise InputError(f"robot file {str(path)!r}: {exc}") from None


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
        problems: list[str] = []
        if not isinstance(self.robot, Robot):
            raise InputError(f"robot must be a snakecg.Robot, got {type(self.robot).__name__}")
        r = self.robot
        if self.scenario not in SCENARIOS:
            problems.append(f"scenario must be one of {', '.join(SCENARIOS)}; got {self.scenario!r}")

        def num(name, value, *, positive=False, nonneg=False):
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                problems.append(f"{name} must be a number, got {value!r}")
                return None
            v = float(value)
            if not math.isfinite(v):
                problems.append(f"{name} must be finite, got {value!r}")
            elif positive and v <= 0:
                problems.append(f"{name} must be > 0, got {value!r}")
            elif nonneg and v < 0:
                problems.append(f"{name} must be >= 0, got {value!r}")
            return v

        kappa = num("kappa", self.kappa, positive=True)
        mu = num("mu", self.mu, nonneg=True)
        gravity = num("gravity", self.gravity, nonneg=True)
        dist = num("object_distance", self.object_distance, positive=True)
        k = self.contact_link
        if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k <= r.n_links:
            problems.append(f"contact_link must be a link number 1..{r.n_links}, got {k!r}")
            k = None
        offset = self.contact_offset
        if offset is not None:
            offset = num("contact_offset", offset)
            if offset is not None and k is not None and not 0 <= offset <= r.length[k - 1]:
                problems.append(
                    f"contact_offset must lie on link {k}: 0..{r.length[k - 1]} m from its rear"
                    f" end, got {offset}"
                )
        side = self.side
        if side in ("left", 1, +1):
            side = "left"
        elif side in ("right", -1):
            side = "right"
        else:
            problems.append(f"side must be 'left' or 'right', got {self.side!r}")
        inertia = self.object_inertia
        if inertia is not None:
            inertia = num("object_inertia", inertia, positive=True)
        wheels = self.wheel_links
        if wheels is not None:
            if isinstance(wheels, (str, bytes)) or not isinstance(wheels, Sequence):
                problems.append(f"wheel_links must be a list of link numbers, got {wheels!r}")
                wheels = None
            else:
                bad = [w for w in wheels if isinstance(w, bool) or not isinstance(w, int)
                       or not 1 <= w <= r.n_links]
                if bad:
                    problems.append(f"wheel_links must be link numbers 1..{r.n_links}, got {bad[0]!r}")
                    wheels = None
                elif k is not None and k in wheels:
                    problems.append(
                        f"link {k} touches the object and cannot carry a wheel (assumption 4);"
                        f" remove it from wheel_links"
                    )
                    wheels = None
                else:
                    wheels = tuple(sorted(set(wheels)))
        woff = _per_link("wheel_offset", self.wheel_offset, r.n_links, problems, positive=False)
        if problems:
            raise InputError("invalid scene: " + "; ".join(problems))
        if offset is None:
            offset = r.length[k - 1] / 2
        if inertia is None:
            inertia = kappa * self.link_mass_scale_of(r) * (0.1**2 + 0.1**2) / 12
        if wheels is None:
            wheels = tuple(i for i in range(1, r.n_links + 1) if i != k)
        for name, value in (("kappa", kappa), ("mu", mu), ("gravity", gravity),
                            ("contact_offset", offset), ("side", side),
                            ("object_distance", dist), ("object_inertia", inertia),
                            ("wheel_links", wheels), ("wheel_offset", woff)):
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
        if "robot" in changes or "contact_link" in changes:
            # offsets and wheel sets follow the new robot/contact unless given
            for f in ("contact_offset", "wheel_links"):
                if f not in changes:
                    fields[f] = None
        if "kappa" in changes and "object_inertia" not in changes:
            fields["object_inertia"] = None
        fields.update(changes)
        return Scene(**fields)

    @classmethod
    def from_toml(cls, path: str | Path, **overrides) -> Scene:
        """Robot and ``[scene]`` table of a description file; keyword overrides win."""
        data = _read_toml(path)
        robot = _robot_from_table(data, path)
        table = data.get("scene", {})
        if not isinstance(table, dict):
            raise InputError(f"robot file {str(path)!r}: [scene] must be a table")
        unknown = set(table) - _SCENE_KEYS
        if unknown:
            raise InputError(
                f"robot file {str(path)!r}: unknown keys in [scene]: {sorted(unknown)}"
                f" (allowed: {sorted(_SCENE_KEYS)})"
            )
        kwargs = dict(table)
        if "wheel_links" in kwargs and isinstance(kwargs["wheel_links"], list):
            kwargs["wheel_links"] = tuple(kwargs["wheel_links"])
        kwargs.update({k: v for k, v in overrides.items() if v is not None})
        try:
            return cls(robot, **kwargs)
        except InputError as exc:
            raise InputError(f"robot file {str(path)!r}: {exc}") from None
