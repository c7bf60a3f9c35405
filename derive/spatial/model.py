"""Derive every generated function of a spatial chain with ``n_links`` links: one
:class:`~snakecg_derive.spec.ModelSpec`.

Functions (inputs -> outputs; every matrix column-major, ``n_l`` links, ``n_v = n_l + 5``):

* ``derived_parameters(link_mass, link_com, link_inertia, joint_xyz, joint_rpy, joint_axis,
  gravity) -> K``, once per robot;
* ``link_poses(q, K) -> position (3 x n_l), rotation (3 x 3 n_l)``: each link frame in the
  world;
* ``link_jacobians(q, K) -> J (6 n_l x n_v)``: rows ``6i..6i+5`` map ``v`` to link ``i + 1``'s
  (linear velocity of its origin, angular velocity) in world axes;
* ``link_bias_accelerations(q, v, K) -> bias (6 x n_l)``: ``Jdot v`` of the same rows (the
  classical acceleration of each origin and the angular acceleration at zero ``vdot``);
* ``point_jacobian(q, K, link, point) -> position (3), J (3 x n_v)`` and
  ``point_bias_acceleration(q, v, K, link, point) -> bias (3)``: a point given in the frame of
  the link selected by the one-hot ``link``;
* ``mass_matrix(q, K) -> M``, ``bias_forces(q, v, K) -> h`` (Coriolis, centrifugal, gravity);
* ``kinematic_map(q) -> G (n_q x n_v)``: ``qdot = G(q) v``;
* constraint rows (:mod:`.rows`): ``ground_rows``, ``wheel_rows``, ``contact_row``.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..model import _fn
from ..spec import FunctionSpec, ModelSpec
from .catalog import SPATIAL_FUNCTIONS, spatial_prefix
from .chain import SpatialChain, quaternion_rotation
from .parameters import derived_parameter_program
from .rows import contact_row, ground_rows, point_terms, wheel_rows
from .symbols import MAX_SPATIAL_LINKS, SpatialSymbols
from .vectors import cross

__all__ = ["derive_spatial_model", "SpatialDerivation", "spatial_prefix", "SPATIAL_FUNCTIONS"]



@dataclass(frozen=True)
class SpatialDerivation:
    symbols: SpatialSymbols
    spec: ModelSpec


def _link_jacobian_rows(ch: SpatialChain, i: int):
    """The ``6 x n_v`` Jacobian of link ``i``'s frame (linear; angular, world axes)."""
    s = ch.s
    J = sp.zeros(6, s.nv)
    Rb = ch.base_rotation()
    o = ch.origin(i)
    r = ch.p.vec(f"rb{i}", tuple(a - b for a, b in zip(o, s.base_position)))
    for c in range(3):
        col = tuple(Rb[k][c] for k in range(3))
        lin = ch.p.vec(f"Jw{i}_{c}", cross(col, r))
        for k in range(3):
            J[k, c] = Rb[k][c]
            J[3 + k, 3 + c] = Rb[k][c]
            J[k, 3 + c] = lin[k]
    for j in range(1, i):
        u = ch.axis(j)
        d = tuple(a - b for a, b in zip(o, ch.origin(j + 1)))
        lin = cross(u, d) if j + 1 < i else (0, 0, 0)
        for k in range(3):
            J[k, 6 + j - 1] = lin[k]
            J[3 + k, 6 + j - 1] = u[k]
    return J


def derive_spatial_model(n_links: int, *, max_links: int = MAX_SPATIAL_LINKS) -> SpatialDerivation:
    """Derive every function of :data:`SPATIAL_FUNCTIONS` for ``n_links`` links."""
    if isinstance(n_links, bool) or not isinstance(n_links, int) or not 2 <= n_links <= max_links:
        raise ValueError(f"n_links must be an integer between 2 and {max_links}, got {n_links!r}")
    s = SpatialSymbols(n_links)
    nl = n_links
    q_in = ("q", s.q, f"configuration (x, y, z, qx, qy, qz, qw, q1..q{s.n_joints})")
    v_in = ("v", s.v, "velocity (base twist in the base frame: linear, angular; joint rates)")
    K_in = ("K", s.parameters, "parameter vector from derived_parameters")
    link_sym = tuple(sp.Symbol(f"sel{i}", real=True) for i in range(1, nl + 1))
    point_sym = tuple(sp.Symbol(f"r{a}", real=True) for a in "xyz")
    link_in = ("link", link_sym, "one-hot selection of the link (n_l entries)")
    point_in = ("point", point_sym, "the point in the selected link's frame [m]")
    functions: list[FunctionSpec] = []

    prog, derived = derived_parameter_program(s)
    functions.append(_fn(
        "derived_parameters", "Parameter vector K from the link and joint parameters "
        "(computed once per robot).", list(s.raw_inputs),
        [("K", sp.Matrix(list(s.raw_parameters) + derived), "parameter vector")],
        prog.assignments))

    ch = SpatialChain(s, "world")
    pos = sp.Matrix([list(ch.origin(i)) for i in range(1, nl + 1)]).T
    rot = sp.Matrix.hstack(*(sp.Matrix(ch.link_rotation(i)) for i in range(1, nl + 1)))
    functions.append(_fn("link_poses", "Origin and rotation of every link frame in the world.",
                         [q_in, K_in], [("position", pos, "3 x n_l, column i = origin of link i"),
                                        ("rotation", rot, "3 x 3 n_l, block i = R_i")],
                         ch.assignments))

    ch = SpatialChain(s, "world")
    J = sp.Matrix.vstack(*(_link_jacobian_rows(ch, i) for i in range(1, nl + 1)))
    functions.append(_fn("link_jacobians", "Jacobian of every link frame (linear velocity of "
                         "the origin, angular velocity; world axes).", [q_in, K_in],
                         [("J", J, "6 n_l x n_v; rows 6(i-1)..6i-1 for link i")],
                         ch.assignments))

    ch = SpatialChain(s, "world")
    cols = []
    for i in range(1, nl + 1):
        al, a = ch.bias(i)
        cols.append(list(a) + list(al))
    functions.append(_fn("link_bias_accelerations", "Jdot v of every link frame: classical "
                         "acceleration of the origin and angular acceleration at zero vdot.",
                         [q_in, v_in, K_in], [("bias", sp.Matrix(cols).T, "6 x n_l")],
                         ch.assignments))

    ch = SpatialChain(s, "world")
    p, Jp, _ = point_terms(ch, link_sym, point_sym, "pt", velocity=False)
    functions.append(_fn("point_jacobian", "World position and Jacobian of a point of a link.",
                         [q_in, K_in, link_in, point_in],
                         [("position", sp.Matrix(p), "the point in the world [m]"),
                          ("J", Jp, "3 x n_v: v -> the point's velocity, world axes")],
                         ch.assignments))
    ch = SpatialChain(s, "world")
    _, _, terms = point_terms(ch, link_sym, point_sym, "pt", velocity=True)
    functions.append(_fn("point_bias_acceleration", "Jdot v of a point of a link (its "
                         "classical acceleration at zero vdot, world axes).",
                         [q_in, v_in, K_in, link_in, point_in],
                         [("bias", sp.Matrix(terms["bias"]), "3")], ch.assignments))

    ch = SpatialChain(s, "base")
    M = ch.mass_matrix()
    functions.append(_fn("mass_matrix", "Inertia matrix M(q) (composite-rigid-body algorithm "
                         "about the base origin).", [q_in, K_in],
                         [("M", M, "n_v x n_v, symmetric positive definite")], ch.assignments))
    ch = SpatialChain(s, "base")
    h = ch.bias_forces()
    functions.append(_fn("bias_forces", "Bias forces h(q, v): Coriolis, centrifugal and "
                         "gravity (recursive Newton-Euler at zero acceleration).",
                         [q_in, v_in, K_in], [("h", h, "n_v")], ch.assignments))

    functions.append(_kinematic_map(s, q_in))
    for build in (ground_rows, wheel_rows, contact_row):
        functions.append(build(s, q_in, v_in, K_in, link_in, point_in))

    names = tuple(f.name for f in functions)
    if names != SPATIAL_FUNCTIONS:  # pragma: no cover - a programming error
        raise RuntimeError(f"derived {names}, expected {SPATIAL_FUNCTIONS}")
    spec = ModelSpec(n_joints=s.n_joints, prefix=spatial_prefix(nl), functions=tuple(functions),
                     meta={"kind": "spatial", "n_links": nl, "nq": s.nq, "nv": s.nv,
                           "n_parameters": len(s.parameters)})
    return SpatialDerivation(symbols=s, spec=spec)


def _kinematic_map(s: SpatialSymbols, q_in) -> FunctionSpec:
    """``qdot = G(q) v``: ``pdot = R_b v_lin``, ``quatdot = 1/2 quat (x) (w, 0)``, the joint
    rates unchanged."""
    G = sp.zeros(s.nq, s.nv)
    R = quaternion_rotation(*s.quaternion)
    qx, qy, qz, qw = s.quaternion
    half = sp.Rational(1, 2)
    # d(qx, qy, qz)/dt = 1/2 (qw w + qv x w), d(qw)/dt = -1/2 qv . w
    Q = ((qw, -qz, qy), (qz, qw, -qx), (-qy, qx, qw), (-qx, -qy, -qz))
    for r in range(3):
        for c in range(3):
            G[r, c] = R[r][c]
    for r in range(4):
        for c in range(3):
            G[3 + r, 3 + c] = half * Q[r][c]
    for j in range(s.n_joints):
        G[7 + j, 6 + j] = 1
    return _fn("kinematic_map", "The map of the velocity to the configuration's rate, "
               "qdot = G(q) v.", [q_in], [("G", G, "n_q x n_v")])
