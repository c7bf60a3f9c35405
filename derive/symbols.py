"""Ordered SymPy symbols of a planar snake with ``n_a`` joints.

Conventions (also in ``docs/model.md``):

* ``n_l = n_a + 1`` rigid links; link 1 is the tail. Generalized coordinates
  ``q_s = (x, y, theta, q_1 ... q_na)``, ``n_s = n_a + 3``: ``(x, y)`` is the COM of link 1 in
  the world frame, ``theta`` the absolute orientation of link 1 and ``q_j`` the relative angle
  of joint ``j`` (between link ``j`` and link ``j + 1``). Absolute link angles are cumulative:
  ``phi_1 = theta``, ``phi_{j+1} = phi_j + q_j``.
* Link ``i`` runs from its rear end (towards the tail) to its front end, length ``l_i``; its
  COM lies on the link axis at distance ``c_i`` from the rear end (``l_i / 2`` by default).
  Joint ``j`` sits at the front end of link ``j``, which is the rear end of link ``j + 1``.
* Per-link parameters: mass ``m_i``, length ``l_i``, rotational inertia about the COM ``I_i``
  and COM position ``c_i``. Argument order is data: every sequence here is a tuple built
  from explicit loops, never from a set.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy as sp

__all__ = ["SnakeSymbols", "MAX_SYMBOLIC_JOINTS"]

#: Largest joint count the derivation accepts by default (configurable by the caller).
MAX_SYMBOLIC_JOINTS = 50


def _syms(names: list[str]) -> tuple[sp.Symbol, ...]:
    return tuple(sp.Symbol(n, real=True) for n in names)


@dataclass(frozen=True)
class SnakeSymbols:
    """All symbols of the snake model for a joint count, in argument order (each tuple is
    built once per instance: the derivation reads them thousands of times)."""

    n_joints: int

    def __post_init__(self) -> None:
        if not isinstance(self.n_joints, int) or isinstance(self.n_joints, bool):
            raise TypeError(f"n_joints must be an int, got {type(self.n_joints).__name__}")
        if self.n_joints < 1:
            raise ValueError(f"n_joints must be >= 1, got {self.n_joints}")

    # sizes -------------------------------------------------------------------------------
    @property
    def n_links(self) -> int:
        return self.n_joints + 1

    @property
    def n_coordinates(self) -> int:
        return self.n_joints + 3

    # state --------------------------------------------------------------------------------
    @cached_property
    def q(self) -> tuple[sp.Symbol, ...]:
        """Generalized coordinates ``(x, y, theta, q1 ... q_na)``."""
        return _syms(["x", "y", "theta"] + [f"q{j}" for j in range(1, self.n_joints + 1)])

    @cached_property
    def v(self) -> tuple[sp.Symbol, ...]:
        """Generalized velocities, same order as :attr:`q`."""
        return _syms(["xd", "yd", "thetad"] + [f"qd{j}" for j in range(1, self.n_joints + 1)])

    # raw per-link parameters ----------------------------------------------------------------
    def _per_link(self, stem: str) -> tuple[sp.Symbol, ...]:
        return tuple(sp.Symbol(f"{stem}{i}", positive=True) for i in range(1, self.n_links + 1))

    @cached_property
    def link_mass(self) -> tuple[sp.Symbol, ...]:
        return self._per_link("m")

    @cached_property
    def link_length(self) -> tuple[sp.Symbol, ...]:
        return self._per_link("l")

    @cached_property
    def link_inertia(self) -> tuple[sp.Symbol, ...]:
        return self._per_link("I")

    @cached_property
    def link_com(self) -> tuple[sp.Symbol, ...]:
        """COM position of each link, measured from its rear end along the link."""
        return self._per_link("c")

    @cached_property
    def raw_parameters(self) -> tuple[sp.Symbol, ...]:
        """``(m_1..m_nl, l_1..l_nl, I_1..I_nl, c_1..c_nl)``."""
        return self.link_mass + self.link_length + self.link_inertia + self.link_com

    # derived (configuration independent) parameters -----------------------------------------
    @cached_property
    def total_mass(self) -> sp.Symbol:
        return sp.Symbol("mtot", positive=True)

    @cached_property
    def first_moments(self) -> tuple[sp.Symbol, ...]:
        """``beta_j = sum_{i >= j} m_i a_ij`` (first mass moment carried by link axis j)."""
        return tuple(sp.Symbol(f"beta{j}", real=True) for j in range(1, self.n_links + 1))

    def second_moment(self, j: int, k: int) -> sp.Symbol:
        """``gamma_jk = sum_{i >= max(j,k)} m_i a_ij a_ik`` (symmetric; ``j, k`` 1-based)."""
        j, k = min(j, k), max(j, k)
        return sp.Symbol(f"gamma{j}_{k}", real=True)

    @cached_property
    def second_moments(self) -> tuple[sp.Symbol, ...]:
        """Upper triangle of ``gamma`` row by row, diagonal included."""
        n = self.n_links
        return tuple(self.second_moment(j, k) for j in range(1, n + 1) for k in range(j, n + 1))

    @cached_property
    def rotational_diagonal(self) -> tuple[sp.Symbol, ...]:
        """``gamma_jj + I_j``: the diagonal of the inertia in absolute link angles."""
        return tuple(sp.Symbol(f"Jrot{j}", positive=True) for j in range(1, self.n_links + 1))

    @cached_property
    def derived_parameters(self) -> tuple[sp.Symbol, ...]:
        return (
            (self.total_mass,)
            + self.first_moments
            + self.second_moments
            + self.rotational_diagonal
        )

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """The parameter vector ``K`` every model function takes: raw, then derived."""
        return self.raw_parameters + self.derived_parameters

    def lever(self, i: int, j: int) -> sp.Expr:
        """``a_ij``: COM of link ``i`` is ``p_1 + sum_{j<=i} a_ij e_j`` (1-based, ``j <= i``).

        ``e_j = (cos phi_j, sin phi_j)`` is the axis of link ``j``.
        """
        if not 1 <= j <= i <= self.n_links:
            raise ValueError(f"lever needs 1 <= j <= i <= n_links, got i={i}, j={j}")
        l, c = self.link_length, self.link_com
        if i == 1:
            return sp.Integer(0)
        if j == i:
            return c[i - 1]
        if j == 1:
            return l[0] - c[0]
        return l[j - 1]
