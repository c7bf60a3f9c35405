"""The derived parameters of the spatial chain: each link's axis frame and what lives in it.

For joint ``j`` with unit axis ``a`` (normalized here), ``P_{j+1}`` is a rotation with
``P e_z = a``: the smallest rotation taking ``e_z`` to ``a`` when ``a_z >= 0``, and for
``a_z < 0`` the smallest one taking ``e_z`` to ``-a`` turned half a turn about ``x`` (each
formula divides by ``1 + |a_z|`` >= 1, so neither is singular where it is used), then turned
about ``e_z`` by the angle ``phi`` that leaves no ``xy`` product in the link's inertia
(``tan 2 phi = 2 J_xy / (J_xx - J_yy)``): the chain rotates an inertia with fewer operations.
Then

* ``Q_j = P_j^T E_j P_{j+1}`` with ``E_j = Rz(yaw) Ry(pitch) Rx(roll)`` (URDF's rpy);
* ``P_j^T t_j``, ``P_i^T c_i`` and ``P_i^T I_i P_i`` (``P_1 = 1``).
"""

from __future__ import annotations

import sympy as sp

from .chain import inertia_matrix
from .symbols import INERTIA_ORDER, SpatialSymbols
from .vectors import Program, identity, matmul, matTvec, transpose

__all__ = ["derived_parameter_program", "rpy_rotation", "axis_frame"]


def rpy_rotation(roll, pitch, yaw):
    """``Rz(yaw) Ry(pitch) Rx(roll)``."""
    cr, sr, cp, spp, cy, sy = (sp.cos(roll), sp.sin(roll), sp.cos(pitch), sp.sin(pitch),
                               sp.cos(yaw), sp.sin(yaw))
    return ((cy * cp, cy * spp * sr - sy * cr, cy * spp * cr + sy * sr),
            (sy * cp, sy * spp * sr + cy * cr, sy * spp * cr - cy * sr),
            (-spp, cp * sr, cp * cr))


def axis_frame(x, y, z):
    """``P`` with ``P e_z = (x, y, z)`` (a unit vector) as a matrix of ``Piecewise`` entries."""
    up = z >= 0
    k_up, k_dn = 1 / (1 + z), 1 / (1 - z)
    c0 = (sp.Piecewise((1 - x * x * k_up, up), (1 - x * x * k_dn, True)),
          sp.Piecewise((-x * y * k_up, up), (-x * y * k_dn, True)),
          sp.Piecewise((-x, up), (x, True)))
    c1 = (sp.Piecewise((-x * y * k_up, up), (x * y * k_dn, True)),
          sp.Piecewise((1 - y * y * k_up, up), (y * y * k_dn - 1, True)),
          sp.Piecewise((-y, up), (-y, True)))
    return tuple((c0[r], c1[r], (x, y, z)[r]) for r in range(3))


def derived_parameter_program(s: SpatialSymbols) -> tuple[Program, list[sp.Expr]]:
    """The assignments and the expressions of ``K``'s derived part, in ``s.parameters``'
    order."""
    p = Program()
    frames = [identity()]
    for j in range(1, s.n_links):
        ax, ay, az = s.joint_axis[j - 1]
        norm = p.let(f"an{j}", 1 / sp.sqrt(ax**2 + ay**2 + az**2))
        u = p.vec(f"au{j}", (ax * norm, ay * norm, az * norm))
        P = p.mat(f"P0{j + 1}", axis_frame(*u))
        # turned about the axis by phi so that the inertia has no xy product in it: tan 2 phi
        # = 2 J_xy / (J_xx - J_yy) for J = P^T I P (chain.SpatialChain.inertia uses it)
        I = inertia_matrix(s.link_inertia[j])
        Jxx, Jyy, Jxy = (sum(P[a][r] * I[a][b] * P[b][c] for a in range(3) for b in range(3))
                         for r, c in ((0, 0), (1, 1), (0, 1)))
        # |phi| <= pi/4 (a quarter turn more would do as well): cos 2 phi = |a| / r >= 0,
        # cos phi = sqrt((1 + cos 2 phi) / 2) >= sqrt(1/2), sin phi = sin 2 phi / (2 cos phi)
        a = p.let(f"Ja{j + 1}", Jxx - Jyy)
        b = p.let(f"Jb{j + 1}", 2 * Jxy)
        r = p.let(f"Jr{j + 1}", sp.sqrt(a * a + b * b))
        a_abs = p.let(f"Jaa{j + 1}", sp.Piecewise((a, a >= 0), (-a, True)))
        b_sgn = p.let(f"Jbs{j + 1}", sp.Piecewise((b, a >= 0), (-b, True)))
        c2 = p.let(f"c2phi{j + 1}", sp.Piecewise((a_abs / r, r > 0), (1, True)))
        s2 = p.let(f"s2phi{j + 1}", sp.Piecewise((b_sgn / r, r > 0), (0, True)))
        cf = p.let(f"cphi{j + 1}", sp.sqrt((1 + c2) / 2))
        sf = p.let(f"sphi{j + 1}", s2 / (2 * cf))
        P = tuple((P[r][0] * cf + P[r][1] * sf, P[r][1] * cf - P[r][0] * sf, P[r][2])
                  for r in range(3))
        frames.append(tuple(tuple(p.let(f"P{j + 1}_{3 * c + r}", P[r][c]) for c in range(3))
                            for r in range(3)))
    out: list[sp.Expr] = []
    for i in range(2, s.n_links + 1):
        P = frames[i - 1]
        out.extend(P[r][c] for c in range(3) for r in range(3))
    for j in range(1, s.n_links):
        E = p.mat(f"E{j}", rpy_rotation(*s.joint_rpy[j - 1]))
        Q = matmul(matmul(transpose(frames[j - 1]), E), frames[j])
        out.extend(Q[r][c] for c in range(3) for r in range(3))
    for j in range(1, s.n_links):
        out.extend(matTvec(frames[j - 1], s.joint_xyz[j - 1]))
    for i in range(1, s.n_links + 1):
        out.extend(matTvec(frames[i - 1], s.link_com[i - 1]))
    for i in range(1, s.n_links + 1):
        P = frames[i - 1]
        J = matmul(matmul(transpose(P), inertia_matrix(s.link_inertia[i - 1])), P)
        index = {"xx": (0, 0), "yy": (1, 1), "zz": (2, 2), "xy": (0, 1), "xz": (0, 2),
                 "yz": (1, 2)}
        out.extend(J[index[k][0]][index[k][1]] for k in INERTIA_ORDER)
    return p, out
