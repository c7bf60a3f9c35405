"""Constraint rows of the contact and of the passive wheels, eqs. (8)-(13).

Both rows are derived at the level of one link, in terms of the link's pose, twist and bias
acceleration; the chain enters only through the link Jacobian ``J_k`` (eq. 10:
``J_s`` row = ``T_k^T J_k``). So a row costs ``O(1)`` to derive and ``O(n)`` to evaluate,
whichever link it sits on.

Sign conventions (the paper's ``A = [-J_s, G^T]``, eq. 9, ``A v >= 0`` eq. 8):

* **Contact** on link ``k``: the gap ``g = n^T (P - r_k)`` between the object's contact point
  ``P = p_o + R(psi) rho`` (``rho`` fixed in the object) and the rear end ``r_k`` of the link,
  along the link normal ``n = sigma (-sin phi_k, cos phi_k)`` (``sigma = +1``: object on the
  left of the link). ``A_c v = d g / dt >= 0``; ``lambda_c >= 0`` pushes the object along
  ``+n`` and the link along ``-n``. ``G^T`` row is ``(n, (R rho) x n)``.
* **Wheel** on link ``i`` at distance ``w`` from its COM along the link: the lateral velocity
  ``u = n_i^T v_wheel = (-sin phi_i, cos phi_i, w) . (v_x, v_y, omega)`` must vanish;
  ``A_w = [a_w J_i, 0]`` and ``lambda_w`` is the lateral force on the link along ``+n_i``.

``Adot v`` of each row (eq. 13) is the time derivative of the row times the velocity, so that
``A a + Adot v`` is the row's acceleration.
"""

from __future__ import annotations

import sympy as sp

__all__ = ["ContactSymbols", "contact_row_local", "wheel_row_local", "ROTATION_ANGLES"]


class ContactSymbols:
    """Symbols of the link-level rows (fixed names, independent of the joint count)."""

    link_pose = sp.symbols("lx ly lphi", real=True)
    link_twist = sp.symbols("lvx lvy lw", real=True)
    link_bias = sp.symbols("lbx lby lbw", real=True)
    link_com = sp.Symbol("lc", positive=True)
    object_pose = sp.symbols("ox oy opsi", real=True)
    object_twist = sp.symbols("ovx ovy ow", real=True)
    rho = sp.symbols("rhox rhoy", real=True)
    side = sp.Symbol("sigma", real=True)
    wheel_offset = sp.Symbol("woff", real=True)


#: The angles of each row whose cosine and sine the composed functions give (see
#: :func:`derive.build.build_rotation_function`): the link's and the object's orientation.
ROTATION_ANGLES = {
    "contact_row_local": (ContactSymbols.link_pose[2], ContactSymbols.object_pose[2]),
    "wheel_row_local": (ContactSymbols.link_pose[2],),
}


def contact_row_local() -> dict[str, sp.Expr | sp.Matrix]:
    """Contact row of a link against a point fixed in the object.

    Returns ``a_link`` (1x3, multiplies ``J_k``), ``g_obj`` (1x3, the ``G^T`` row), ``adot_v``
    (scalar, ``Adot v`` of eq. 13), the ``gap`` ``g`` and the contact position ``s`` along the
    link measured from its rear end.
    """
    S = ContactSymbols
    lx, ly, lphi = S.link_pose
    ox, oy, opsi = S.object_pose
    e = sp.Matrix([sp.cos(lphi), sp.sin(lphi)])
    n = S.side * sp.Matrix([-sp.sin(lphi), sp.cos(lphi)])
    R = sp.Matrix([[sp.cos(opsi), -sp.sin(opsi)], [sp.sin(opsi), sp.cos(opsi)]])
    P = sp.Matrix([ox, oy]) + R * sp.Matrix(S.rho)
    rear = sp.Matrix([lx, ly]) - S.link_com * e
    gap = (n.T * (P - rear))[0]
    s_along = (e.T * (P - rear))[0]
    pose = sp.Matrix(list(S.link_pose) + list(S.object_pose))
    twist = sp.Matrix(list(S.link_twist) + list(S.object_twist))
    grad = sp.Matrix([gap]).jacobian(pose)  # 1 x 6
    a_link = grad[:, 0:3]
    g_obj = grad[:, 3:6]
    # d/dt (grad . twist) at fixed twist, plus the link's own bias acceleration
    hess_term = (grad * twist).jacobian(pose) * twist
    adot_v = hess_term[0] + (a_link * sp.Matrix(S.link_bias))[0]
    return {
        "a_link": a_link,
        "g_obj": g_obj,
        "adot_v": adot_v,
        "gap": gap,
        "s": s_along,
    }


def wheel_row_local() -> dict[str, sp.Expr | sp.Matrix]:
    """Lateral (non-holonomic) wheel row of a link: ``a_w`` (1x3) and ``adot_v``."""
    S = ContactSymbols
    lphi = S.link_pose[2]
    a_w = sp.Matrix([[-sp.sin(lphi), sp.cos(lphi), S.wheel_offset]])
    # d/dt a_w = (-cos phi, -sin phi, 0) omega; row acceleration bias = adot . twist + a_w . bias
    a_w_dot = sp.Matrix([[-sp.cos(lphi) * S.link_twist[2], -sp.sin(lphi) * S.link_twist[2], 0]])
    adot_v = (a_w_dot * sp.Matrix(S.link_twist))[0] + (a_w * sp.Matrix(S.link_bias))[0]
    return {"a_w": a_w, "adot_v": adot_v}
