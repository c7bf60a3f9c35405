"""Ordered SymPy symbols of a spatial serial chain on a floating base.

Conventions (Pinocchio's, so that comparisons are direct; also in ``docs/spatial.md``):

* ``n_l`` rigid links, ``n_a = n_l - 1`` revolute joints; link 1 is the base (the tail).
  Joint ``j`` joins link ``j`` (parent) to link ``j + 1`` (child).
* Configuration ``q = (x, y, z, qx, qy, qz, qw, q1 .. q_na)``, ``n_q = n_a + 7``: the base
  frame's origin in the world, its orientation as a unit quaternion (Pinocchio's order, the
  scalar last) and the joint angles.
* Velocity ``v = (vx, vy, vz, wx, wy, wz, qd1 .. qd_na)``, ``n_v = n_a + 6``: the base's twist
  in its own frame (Pinocchio's free-flyer convention: the linear velocity of the base
  origin and the angular velocity, both in base coordinates), then the joint rates.
* Link ``j + 1``'s frame is link ``j``'s frame moved by the joint's placement (translation
  ``t_j``, rotation from roll-pitch-yaw ``r_j`` as in URDF: ``Rz(yaw) Ry(pitch) Rx(roll)``),
  then turned by ``q_j`` about the unit axis ``a_j`` (in the moved frame).
* Per link: mass ``m_i``, COM ``c_i`` (link frame) and the inertia about the COM
  ``(Ixx, Iyy, Izz, Ixy, Ixz, Iyz)`` in link-frame axes. Gravity ``g`` is a world vector.

Argument order is data: every tuple is built by explicit loops, never from a set.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy as sp

__all__ = ["SpatialSymbols", "INERTIA_ORDER", "MAX_SPATIAL_LINKS"]

#: Order of the six inertia entries of a link (about its COM, link-frame axes).
INERTIA_ORDER = ("xx", "yy", "zz", "xy", "xz", "yz")
#: Largest link count the derivation accepts by default.
MAX_SPATIAL_LINKS = 64


def _real(names) -> tuple[sp.Symbol, ...]:
    return tuple(sp.Symbol(n, real=True) for n in names)


@dataclass(frozen=True)
class SpatialSymbols:
    """Every symbol of the spatial chain with ``n_links`` links, in argument order."""

    n_links: int

    def __post_init__(self) -> None:
        if isinstance(self.n_links, bool) or not isinstance(self.n_links, int):
            raise TypeError(f"n_links must be an int, got {type(self.n_links).__name__}")
        if self.n_links < 2:
            raise ValueError(f"n_links must be >= 2 (one joint at least), got {self.n_links}")

    # sizes ---------------------------------------------------------------------------------
    @property
    def n_joints(self) -> int:
        return self.n_links - 1

    @property
    def nq(self) -> int:
        return self.n_joints + 7

    @property
    def nv(self) -> int:
        return self.n_joints + 6

    # state ---------------------------------------------------------------------------------
    @cached_property
    def q(self) -> tuple[sp.Symbol, ...]:
        return _real(["x", "y", "z", "qx", "qy", "qz", "qw"]
                     + [f"q{j}" for j in range(1, self.n_links)])

    @cached_property
    def v(self) -> tuple[sp.Symbol, ...]:
        return _real(["vx", "vy", "vz", "wx", "wy", "wz"]
                     + [f"qd{j}" for j in range(1, self.n_links)])

    @property
    def base_position(self):
        return self.q[0:3]

    @property
    def quaternion(self):
        """``(qx, qy, qz, qw)``."""
        return self.q[3:7]

    @property
    def angles(self):
        return self.q[7:]

    # raw parameters --------------------------------------------------------------------------
    @cached_property
    def link_mass(self) -> tuple[sp.Symbol, ...]:
        return tuple(sp.Symbol(f"m{i}", positive=True) for i in range(1, self.n_links + 1))

    @cached_property
    def link_com(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        return tuple(_real([f"c{i}{a}" for a in "xyz"]) for i in range(1, self.n_links + 1))

    @cached_property
    def link_inertia(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        return tuple(_real([f"I{i}{k}" for k in INERTIA_ORDER])
                     for i in range(1, self.n_links + 1))

    @cached_property
    def joint_xyz(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        return tuple(_real([f"t{j}{a}" for a in "xyz"]) for j in range(1, self.n_links))

    @cached_property
    def joint_rpy(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        return tuple(_real([f"r{j}{a}" for a in ("roll", "pitch", "yaw")])
                     for j in range(1, self.n_links))

    @cached_property
    def joint_axis(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        return tuple(_real([f"a{j}{a}" for a in "xyz"]) for j in range(1, self.n_links))

    @cached_property
    def gravity(self) -> tuple[sp.Symbol, ...]:
        return _real(["gx", "gy", "gz"])

    @cached_property
    def raw_inputs(self) -> tuple[tuple[str, tuple[sp.Symbol, ...], str], ...]:
        """The inputs of ``derived_parameters``: ``(name, symbols, description)``."""
        flat = lambda groups: tuple(s for g in groups for s in g)  # noqa: E731
        return (
            ("link_mass", self.link_mass, "m_i [kg], link 1 (base) first"),
            ("link_com", flat(self.link_com), "COM of each link in its frame [m], 3 per link"),
            ("link_inertia", flat(self.link_inertia),
             "inertia about each COM, (xx, yy, zz, xy, xz, yz) per link [kg m^2]"),
            ("joint_xyz", flat(self.joint_xyz),
             "joint origin in the parent frame [m], 3 per joint"),
            ("joint_rpy", flat(self.joint_rpy), "joint origin roll, pitch, yaw [rad], 3 per joint"),
            ("joint_axis", flat(self.joint_axis), "joint axis in the joint frame, 3 per joint"),
            ("gravity", self.gravity, "gravity in the world frame [m/s^2]"),
        )

    @cached_property
    def raw_parameters(self) -> tuple[sp.Symbol, ...]:
        return tuple(s for _, syms, _ in self.raw_inputs for s in syms)

    # derived parameters (in each link's *axis frame*: the joint axis along z) ---------------
    # Link i's axis frame is its frame turned by P_i, a fixed rotation with P_i e_z = a_{i-1}
    # (P_1 = 1 for the base). In it a joint turns about z, so a link's rotation costs one
    # constant 3x3 product and one planar rotation (docs/spatial.md).
    @cached_property
    def axis_frame(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        """``P_i`` (column-major, 9 each) for links 2..n_l."""
        return tuple(_real([f"P{i}_{k}" for k in range(9)]) for i in range(2, self.n_links + 1))

    @cached_property
    def joint_rotation(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        """``Q_j = P_j^T E_j P_{j+1}`` (column-major): from link j's axis frame to link j+1's
        at a zero joint angle (``E_j`` the placement's rotation)."""
        return tuple(_real([f"Q{j}_{k}" for k in range(9)]) for j in range(1, self.n_links))

    @cached_property
    def joint_offset(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        """``P_j^T t_j``: joint j's origin in link j's axis frame."""
        return tuple(_real([f"o{j}{a}" for a in "xyz"]) for j in range(1, self.n_links))

    @cached_property
    def axis_com(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        """``P_i^T c_i``: the COM in the axis frame."""
        return tuple(_real([f"d{i}{a}" for a in "xyz"]) for i in range(1, self.n_links + 1))

    @cached_property
    def axis_inertia(self) -> tuple[tuple[sp.Symbol, ...], ...]:
        """``P_i^T I_i P_i`` (about the COM) in :data:`INERTIA_ORDER`."""
        return tuple(_real([f"J{i}{k}" for k in INERTIA_ORDER]) for i in range(1, self.n_links + 1))

    @cached_property
    def derived_parameters(self) -> tuple[sp.Symbol, ...]:
        out: list[sp.Symbol] = []
        for group in (self.axis_frame, self.joint_rotation, self.joint_offset, self.axis_com,
                      self.axis_inertia):
            for g in group:
                out.extend(g)
        return tuple(out)

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """The parameter vector ``K``: raw parameters, then derived ones."""
        return self.raw_parameters + self.derived_parameters
