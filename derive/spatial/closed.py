"""The closed form of a short spatial chain: poses written out and differentiated.

Independent of the recursion of :mod:`.chain` (no axis frames, no composite bodies): each
link's rotation is the product of the base quaternion's matrix, the joints' roll-pitch-yaw
placements and Rodrigues' rotations ``cos q 1 + sin q [a]x + (1 - cos q) a a^T`` about the raw
(unit) axes; the Jacobians are the derivatives of the poses times ``qdot = G(q) v``, and
``M = sum_i m_i Jc_i^T Jc_i + Jw_i^T R_i I_i R_i^T Jw_i`` (``Jc`` of the COM, ``Jw`` angular).
Meant for a few links (inspection, and a check of the structured form); the expressions
grow quickly with the link count.
"""

from __future__ import annotations

import sympy as sp

from .chain import inertia_matrix, quaternion_rotation
from .model import _kinematic_map
from .parameters import rpy_rotation
from .symbols import SpatialSymbols

__all__ = ["closed_form_poses", "closed_form_jacobians", "closed_form_mass_matrix"]


def _rodrigues(a, angle):
    a = sp.Matrix(a)
    K = sp.Matrix([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return sp.cos(angle) * sp.eye(3) + sp.sin(angle) * K + (1 - sp.cos(angle)) * a * a.T


def closed_form_poses(s: SpatialSymbols):
    """``[(R_i, o_i)]``: each link frame's rotation and origin as explicit expressions of
    ``q`` and the raw parameters (axes taken as unit vectors)."""
    R = sp.Matrix(quaternion_rotation(*s.quaternion))
    o = sp.Matrix(s.base_position)
    out = [(R, o)]
    for j in range(s.n_joints):
        o = o + R * sp.Matrix(s.joint_xyz[j])
        R = R * sp.Matrix(rpy_rotation(*s.joint_rpy[j])) * _rodrigues(s.joint_axis[j],
                                                                      s.angles[j])
        out.append((R, o))
    return out


def closed_form_jacobians(s: SpatialSymbols):
    """``[(Jc_i, Jw_i)]``: ``3 x n_v`` Jacobians of each COM's velocity and each link's
    angular velocity (world axes), by differentiating :func:`closed_form_poses`."""
    G = _kinematic_map(s, ("q", s.q, "")).outputs[0][1]
    q = sp.Matrix(s.q)
    out = []
    for i, (R, o) in enumerate(closed_form_poses(s)):
        c = o + R * sp.Matrix(s.link_com[i])
        Jc = c.jacobian(q) * G
        Jw = sp.zeros(3, s.nv)
        for col in range(s.nv):
            Rdot = sum((R.diff(s.q[k]) * G[k, col] for k in range(s.nq) if G[k, col] != 0),
                       sp.zeros(3, 3))
            W = Rdot * R.T  # [w]x for a unit rate of velocity coordinate col
            Jw[:, col] = sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
        out.append((Jc, Jw))
    return out


def closed_form_mass_matrix(s: SpatialSymbols) -> sp.Matrix:
    """``M(q)`` in the raw parameters (unexpanded)."""
    M = sp.zeros(s.nv, s.nv)
    for i, ((Jc, Jw), (R, _)) in enumerate(zip(closed_form_jacobians(s), closed_form_poses(s))):
        Iw = R * sp.Matrix(inertia_matrix(s.link_inertia[i])) * R.T
        M += s.link_mass[i] * Jc.T * Jc + Jw.T * Iw * Jw
    return M
