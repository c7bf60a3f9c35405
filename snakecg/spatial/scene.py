"""A spatial snake lying on the ground, pushing an object: the paper's three scenarios in 3-D.

:class:`SpatialScene` is the spatial counterpart of :class:`snakecg.Scene`, with the same
fields and meanings where they apply; ``snakecg.load(scene)`` gives its
:class:`~snakecg.spatial.analysis.SpatialSceneModel`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._inputs import short_repr as _r
from ..errors import InputError
from .robot import SpatialRobot

__all__ = ["SCENARIOS", "SpatialScene"]

SCENARIOS = ("frictionless", "wheels", "ideal_wheels")


def _number(problems, name, value, *, positive=False, nonnegative=False):
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) \
            or not math.isfinite(float(value)):
        problems.append(f"{name} must be a finite number, got {_r(value)}")
        return None
    v = float(value)
    if positive and not v > 0:
        problems.append(f"{name} must be > 0, got {v!r}")
    if nonnegative and not v >= 0:
        problems.append(f"{name} must be >= 0, got {v!r}")
    return v


@dataclass(frozen=True)
class SpatialScene:
    """A :class:`SpatialRobot` lying on the ground ``z = 0`` (world ``z`` up), an object on
    the ground touching one of its links, and the ground's kind (the paper's scenarios).

    * ``scenario``: ``"frictionless"`` (scenario 1: no wheels), ``"wheels"`` (2: each wheel's
      lateral force bounded by ``mu`` times its link's solved normal force) or
      ``"ideal_wheels"`` (3: no lateral motion of a wheel);
    * ``kappa``: object mass over the mean link mass; ``object_inertia`` about its vertical
      axis (default: a 0.1 m square plate);
    * ``contact_link`` (1-based), ``contact_offset``: the contact point on the link's edge, along
      its frame's x axis from its origin (default: beside the link's COM); ``side``:
      ``"left"`` or ``"right"`` of the link's heading; ``object_distance``: from the contact
      point to the object's COM along the normal;
    * ``wheel_links``: links with a passive wheel (default: every link but the contacting
      one); ``wheel_offset``: the wheel's place from the link's COM along its x axis.

    Every link lies on the ground along its axis: bilateral rows hold its height at the COM
    and its axis's slope, and leave it free to roll about its axis (see docs/how-to/spatial.md).
    """

    robot: SpatialRobot
    scenario: str = "frictionless"
    kappa: float = 100.0
    mu: float = 0.1
    contact_link: int = 1
    contact_offset: float | None = None
    side: str = "left"
    object_distance: float = 0.05
    object_inertia: float | None = None
    wheel_links: tuple | None = None
    wheel_offset: float | tuple = 0.0

    def __post_init__(self):
        if not isinstance(self.robot, SpatialRobot):
            raise InputError(f"robot must be a snakecg.SpatialRobot, got "
                             f"{type(self.robot).__name__}")
        problems = []
        nl = self.robot.n_links
        if not isinstance(self.scenario, str) or self.scenario not in SCENARIOS:
            problems.append(f"scenario must be one of {', '.join(SCENARIOS)}, got "
                            f"{_r(self.scenario)}")
        _number(problems, "kappa", self.kappa, positive=True)
        _number(problems, "mu", self.mu, nonnegative=True)
        k = self.contact_link
        if isinstance(k, bool) or not isinstance(k, (int, np.integer)) or not 1 <= k <= nl:
            problems.append(f"contact_link must be an integer from 1 to {nl}, got {_r(k)}")
            k = None
        if self.contact_offset is None:
            if k is not None:
                object.__setattr__(self, "contact_offset", float(self.robot.com[k - 1][0]))
        else:
            _number(problems, "contact_offset", self.contact_offset)
        if self.side not in ("left", "right"):
            problems.append(f"side must be 'left' or 'right', got {_r(self.side)}")
        _number(problems, "object_distance", self.object_distance, nonnegative=True)
        if self.object_inertia is not None:
            _number(problems, "object_inertia", self.object_inertia, positive=True)
        wl = self.wheel_links
        if wl is None:
            wl = tuple(i for i in range(1, nl + 1) if i != k)
        try:
            wl = tuple(sorted({int(i) for i in wl}))
            if any(not 1 <= i <= nl for i in wl) or any(isinstance(i, bool)
                                                       for i in self.wheel_links or ()):
                raise ValueError
        except (TypeError, ValueError):
            problems.append(f"wheel_links must be link numbers from 1 to {nl}, got "
                            f"{_r(self.wheel_links)}")
            wl = ()
        object.__setattr__(self, "wheel_links", wl)
        try:
            off = np.broadcast_to(np.asarray(self.wheel_offset, dtype=float), (nl,))
            if not np.all(np.isfinite(off)):
                raise ValueError
            object.__setattr__(self, "wheel_offset", tuple(float(x) for x in off))
        except (TypeError, ValueError):
            problems.append(f"wheel_offset must be one finite number or {nl} of them, got "
                            f"{_r(self.wheel_offset)}")
        if problems:
            raise InputError("invalid spatial scene: " + "; ".join(problems))
        if self.object_inertia is None:
            object.__setattr__(self, "object_inertia", self.object_mass * 0.02 / 12)

    @property
    def object_mass(self) -> float:
        return float(self.kappa) * self.robot.total_mass / self.robot.n_links

    @property
    def side_sign(self) -> float:
        return 1.0 if self.side == "left" else -1.0

    @property
    def has_wheels(self) -> bool:
        return self.scenario != "frictionless"

    def __repr__(self) -> str:
        return (f"SpatialScene({self.robot!r}, scenario={self.scenario!r}, "
                f"contact_link={self.contact_link})")
