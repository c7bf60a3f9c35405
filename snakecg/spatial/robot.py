"""The description of a spatial snake: an immutable, validated serial chain on a floating base.

Link 1 is the base (the tail); joint ``j`` joins link ``j`` to link ``j + 1``. Per link: mass,
COM (in the link frame) and inertia about the COM (link-frame axes). Per joint: its origin in
the parent link's frame (``joint_xyz``, ``joint_rpy`` as URDF's ``<origin xyz rpy>``) and its
axis (in the joint frame). The defaults are the paper's links (1 kg, 0.15 m) as yaw-pitch
alternating modules: joint ``j`` turns about ``z`` for odd ``j`` and about ``y`` for even ``j``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .._inputs import MAX_PARAMETER, beyond_parameter_limit
from .._inputs import short_repr as _r
from ..errors import InputError

__all__ = ["SpatialRobot", "DEFAULT_LINK_LENGTH", "MAX_SPATIAL_JOINTS"]

DEFAULT_LINK_LENGTH = 0.15
#: Largest joint count generated on demand (the derivation's limit is 63).
MAX_SPATIAL_JOINTS = 63
_MAX_PROBLEMS = 20


def _array(name, value, n, width, problems, *, default_row=None):
    """``(n, width)`` floats from one row (repeated) or ``n`` rows; problems appended."""
    try:
        a = np.array(value, dtype=float)
    except (TypeError, ValueError):
        problems.append(f"{name} must be numbers, got {_r(value)}")
        return None
    if width == 1 and a.ndim == 0:
        a = np.full((n, 1), float(a))
    elif width == 1 and a.ndim == 1:
        a = a.reshape(-1, 1)
    if a.ndim == 1 and a.shape == (width,):
        a = np.tile(a, (n, 1))
    if a.shape != (n, width):
        form = "one number" if width == 1 else f"{width} numbers"
        problems.append(f"{name} must be {form} for all, or {n} of them (one per "
                        f"{'link' if name in _PER_LINK else 'joint'}), got shape {a.shape}")
        return None
    bad = np.isnan(a) if name in _MAY_BE_INFINITE else ~np.isfinite(a)
    if np.any(bad):
        problems.append(f"{name} must be {'numbers' if name in _MAY_BE_INFINITE else 'finite'}"
                        f", got {_r(value)}")
        return None
    if name not in _MAY_BE_INFINITE + ("joint_axis", "effort_limits") and np.any(
            np.abs(a) > MAX_PARAMETER):  # (an axis is only a direction)
        problems.append(beyond_parameter_limit(name, _r(value)))
        return None
    return a


_PER_LINK = ("mass", "com", "inertia")
#: Limits may be infinite (a continuous joint, an effort the file does not bound).
_MAY_BE_INFINITE = ("joint_limits", "effort_limits")


def _inertia_rows(value, n, problems):
    """Six numbers ``(xx, yy, zz, xy, xz, yz)`` or a 3x3 symmetric matrix, one or per link."""
    try:
        a = np.array(value, dtype=float)
    except (TypeError, ValueError):
        problems.append(f"inertia must be numbers, got {_r(value)}")
        return None
    if a.shape == (3, 3) or (a.ndim == 3 and a.shape[1:] == (3, 3)):
        mats = a.reshape(-1, 3, 3)
        if not np.allclose(mats, mats.transpose(0, 2, 1), rtol=1e-12, atol=1e-15):
            problems.append("inertia matrices must be symmetric")
            return None
        a = np.stack([mats[:, 0, 0], mats[:, 1, 1], mats[:, 2, 2], mats[:, 0, 1],
                      mats[:, 0, 2], mats[:, 1, 2]], axis=1)
        if a.shape[0] == 1:
            a = np.tile(a, (n, 1))
    return _array("inertia", a, n, 6, problems)


@dataclass(frozen=True)
class SpatialRobot:
    """A spatial snake: ``joints`` revolute joints about any axes, ``joints + 1`` links.

    Arrays are given per link (``mass`` ``(n_l,)``, ``com`` ``(n_l, 3)``, ``inertia``
    ``(n_l, 6)`` as ``(xx, yy, zz, xy, xz, yz)`` or ``(n_l, 3, 3)``) or per joint
    (``joint_xyz``, ``joint_rpy``, ``joint_axis``: ``(n_a, 3)``), or once for all. Limits:
    ``joint_limits`` a list of ``(lower, upper)`` in rad and ``effort_limits`` of efforts in
    N m, one per joint, or None.
    """

    joints: int
    mass: object = 1.0
    com: object = (DEFAULT_LINK_LENGTH / 2, 0.0, 0.0)
    inertia: object = (0.0002, 0.002, 0.002, 0.0, 0.0, 0.0)
    joint_xyz: object = (DEFAULT_LINK_LENGTH, 0.0, 0.0)
    joint_rpy: object = (0.0, 0.0, 0.0)
    joint_axis: object = None
    gravity: object = (0.0, 0.0, -9.81)
    joint_limits: object = None
    effort_limits: object = None
    name: str = field(default="snake", compare=False)
    link_names: tuple | None = field(default=None, compare=False)
    joint_names: tuple | None = field(default=None, compare=False)

    def __post_init__(self):
        problems: list[str] = []
        j = self.joints
        if isinstance(j, bool) or not isinstance(j, (int, np.integer)) or j < 1:
            raise InputError(f"invalid spatial robot: joints must be an integer >= 1, got {_r(j)}")
        if j > MAX_SPATIAL_JOINTS:
            raise InputError(f"invalid spatial robot: joints={j} exceeds the limit of "
                             f"{MAX_SPATIAL_JOINTS} joints")
        j = int(j)
        nl = j + 1
        axis = self.joint_axis
        if axis is None:  # yaw-pitch alternating modules
            axis = [(0.0, 0.0, 1.0) if k % 2 == 0 else (0.0, 1.0, 0.0) for k in range(j)]
        mass = _array("mass", self.mass, nl, 1, problems)
        if mass is not None:
            mass = mass[:, 0]
            if np.any(mass < 0):
                problems.append(f"mass must be >= 0, got {_r(self.mass)}")
            elif not mass.sum() > 0:
                problems.append("the links' total mass must be positive")
        com = _array("com", self.com, nl, 3, problems)
        inertia = _inertia_rows(self.inertia, nl, problems)
        if inertia is not None:
            for i, row in enumerate(inertia, start=1):
                problem = _inertia_problem(row)
                if problem:
                    problems.append(f"inertia of link {i} {problem}")
        xyz = _array("joint_xyz", self.joint_xyz, j, 3, problems)
        rpy = _array("joint_rpy", self.joint_rpy, j, 3, problems)
        ax = _array("joint_axis", axis, j, 3, problems)
        if ax is not None:  # (scaled by its largest entry first: |(1e300, 1e300, 0)|
            # overflows, and the axis divided by it read as zero)
            big = np.abs(ax).max(axis=1, keepdims=True)
            unit = ax / np.where(big > 0, big, 1.0)
            zero = [str(k + 1) for k in np.flatnonzero(~(big[:, 0] > 1e-12))]
            if zero:
                problems.append(f"joint_axis of joint(s) {', '.join(zero)} is zero")
            else:
                ax = unit / np.linalg.norm(unit, axis=1, keepdims=True)
        g = _array("gravity", [self.gravity], 1, 3, problems)
        limits = efforts = None
        if self.joint_limits is not None:
            limits = _array("joint_limits", self.joint_limits, j, 2, problems)
            if limits is not None and np.any(limits[:, 0] > limits[:, 1]):
                problems.append("joint_limits must be (lower, upper) with lower <= upper")
        if self.effort_limits is not None:
            efforts = _array("effort_limits", self.effort_limits, j, 1, problems)
            if efforts is not None:
                efforts = efforts[:, 0]
                if np.any(efforts <= 0):
                    problems.append("effort_limits must be positive")
        if not isinstance(self.name, str):
            problems.append(f"name must be a string, got {_r(self.name)}")
        for key, count in (("link_names", nl), ("joint_names", j)):
            names = getattr(self, key)
            if names is not None and (len(names) != count
                                      or not all(isinstance(x, str) for x in names)):
                problems.append(f"{key} must be {count} strings, got {_r(names)}")
        if problems:
            more = len(problems) - _MAX_PROBLEMS
            raise InputError("invalid spatial robot: " + "; ".join(problems[:_MAX_PROBLEMS])
                             + (f"; and {more} more problems" if more > 0 else ""))
        tup = lambda a: tuple(tuple(float(x) for x in row) for row in a)  # noqa: E731
        fields = {"joints": j, "mass": tuple(float(x) for x in mass), "com": tup(com),
                  "inertia": tup(inertia), "joint_xyz": tup(xyz), "joint_rpy": tup(rpy),
                  "joint_axis": tup(ax), "gravity": tuple(float(x) for x in g[0]),
                  "joint_limits": None if limits is None else tup(limits),
                  "effort_limits": None if efforts is None else tuple(float(x) for x in efforts),
                  "link_names": None if self.link_names is None else tuple(self.link_names),
                  "joint_names": None if self.joint_names is None else tuple(self.joint_names)}
        for key, value in fields.items():
            object.__setattr__(self, key, value)

    # sizes ----------------------------------------------------------------------------------
    @property
    def n_links(self) -> int:
        return self.joints + 1

    @property
    def nq(self) -> int:
        """``7 + joints``: base position, quaternion ``(qx, qy, qz, qw)``, joint angles."""
        return self.joints + 7

    @property
    def nv(self) -> int:
        """``6 + joints``: base twist in the base frame (linear, angular), joint rates."""
        return self.joints + 6

    @property
    def total_mass(self) -> float:
        return float(sum(self.mass))

    def neutral(self) -> np.ndarray:
        """The configuration with the base at the origin, unrotated, every joint at zero."""
        q = np.zeros(self.nq)
        q[6] = 1.0
        return q

    # files ----------------------------------------------------------------------------------
    @classmethod
    def from_urdf(cls, path, *, name: str | None = None) -> SpatialRobot:
        """The spatial form of the serial chain in a URDF file (any chain, planar or not);
        see :mod:`snakecg.spatial.files`. Needs the ``urdf`` extra."""
        from .files import spatial_from_urdf

        return spatial_from_urdf(path, robot_type=cls, name=name)

    @classmethod
    def from_mjcf(cls, path, *, name: str | None = None) -> SpatialRobot:
        """The spatial form of the serial chain in a MuJoCo XML (MJCF) file, read with
        MuJoCo's own parser; see :mod:`snakecg.spatial.files`. Needs the ``mjcf`` extra."""
        from .files import spatial_from_mjcf

        return spatial_from_mjcf(path, robot_type=cls, name=name)

    def parameters(self) -> dict[str, np.ndarray]:
        """The inputs of the generated ``derived_parameters``, by name."""
        flat = lambda a: np.ascontiguousarray(np.ravel(np.asarray(a, dtype=float)))  # noqa: E731
        return {"link_mass": flat(self.mass), "link_com": flat(self.com),
                "link_inertia": flat(self.inertia), "joint_xyz": flat(self.joint_xyz),
                "joint_rpy": flat(self.joint_rpy), "joint_axis": flat(self.joint_axis),
                "gravity": flat(self.gravity)}

    def __repr__(self) -> str:
        return (f"SpatialRobot(joints={self.joints}, name={self.name!r}, "
                f"total_mass={self.total_mass:g})")


def _inertia_problem(row) -> str | None:
    """Why ``(xx, yy, zz, xy, xz, yz)`` is not a physical inertia about a COM, or None."""
    xx, yy, zz, xy, xz, yz = row
    I = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    ev = np.linalg.eigvalsh(I)
    scale = max(abs(ev).max(), 1e-300)
    if ev[0] < -1e-12 * scale:
        return f"is not positive semidefinite (eigenvalues {', '.join(f'{e:.3g}' for e in ev)})"
    a, b, c = ev
    if a + b < c - 1e-9 * scale:
        return (f"breaks the triangle inequality of principal moments "
                f"({a:.3g} + {b:.3g} < {c:.3g})")
    if not math.isfinite(scale):
        return "is not finite"
    return None
